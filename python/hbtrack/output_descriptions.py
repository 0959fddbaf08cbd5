"""What the figures call each output: a description rather than a CSV column stem ("leading-edge
tip, radial", not "max_le").

Where a description comes from, first found wins:
  1. the figure's caller (`hbtrack plot DIR --label le="leading edge"`);
  2. summary.json's outputs, when an entry has a "description" (the case file's
     `[[outputs]] description = "..."`);
  3. the name itself, with its dof when that differs ("le (n1_r)").
"""


def parse_labels(pairs):
    """`NAME=TEXT` strings (the --label option) as {NAME: TEXT}.

    Parameters
    ----------
    pairs : sequence of str or None
        The strings.

    Returns
    -------
    dict
        {NAME: TEXT}; ValueError for a string without "=".

    Examples
    --------
    >>> parse_labels(["le=leading edge", "te=trailing edge"])
    {'le': 'leading edge', 'te': 'trailing edge'}
    """
    labels = {}
    for pair in pairs or ():
        name, sep, text = pair.partition("=")
        if not sep or not name.strip():
            raise ValueError(f"--label {pair!r}: expected NAME=TEXT")
        labels[name.strip()] = text.strip()
    return labels


def output_descriptions(result, labels=None):
    """A readable name of each output of a result.

    Parameters
    ----------
    result : dict
        Any result (read_result or the API).
    labels : dict, optional
        {output name: text}, which wins over everything else.

    Returns
    -------
    dict
        {output name: description}.

    Examples
    --------
    >>> output_descriptions(read_result("out/r67"))
    {'le': 'leading-edge tip, radial', 'te': 'trailing-edge tip, radial'}
    """
    from .results import output_names
    entries = {o["name"]: o for o in result.get("summary", {}).get("outputs", [])}
    descriptions = {}
    for name in output_names(result):
        entry = entries.get(name, {})
        dof = entry.get("dof")
        fallback = f"{name} ({dof})" if dof and dof != name else name
        descriptions[name] = (labels or {}).get(name) or entry.get("description") or fallback
    return descriptions
