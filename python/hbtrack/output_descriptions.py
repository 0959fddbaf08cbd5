"""What the figures call each output: a description rather than a CSV column stem ("leading-edge
tip node", not "max_le").

Where a description comes from, first found wins:
  1. the figure's caller (`hbtrack plot DIR --label le="leading edge"`);
  2. summary.json's outputs, when an entry has a "description" (or "label");
  3. the comment after the output's `name = "..."` in the case file the summary names, up to its
     first comma or parenthesis (examples/rotor67/nominal.toml: `name = "le"   # leading-edge tip
     node, radial displacement (the paper's r_1)` gives "leading-edge tip node");
  4. the name itself, with its dof when that differs ("le (n1_r)").
"""
import os
import re

_NAME_LINE = re.compile(r"""^\s*name\s*=\s*["']([^"']+)["']\s*#\s*(.+)$""")
_LONGEST = 40  # characters: a longer comment is an explanation, not a name


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


def _case_comments(case_path):
    """{output name: its comment} from the [[outputs]] tables of a case file."""
    comments, in_outputs = {}, False
    try:
        with open(case_path) as f:
            for line in f:
                if line.lstrip().startswith("["):
                    in_outputs = line.strip().startswith("[[outputs]]")
                    continue
                match = _NAME_LINE.match(line) if in_outputs else None
                if match:
                    text = re.split(r"[,(;]", match.group(2))[0].strip()
                    if text and len(text) <= _LONGEST:
                        comments[match.group(1)] = text
    except OSError:
        pass
    return comments


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
    {'le': 'leading-edge tip node', 'te': 'trailing-edge tip node'}
    """
    from .results import output_names
    entries = {o["name"]: o for o in result.get("summary", {}).get("outputs", [])}
    case = result.get("summary", {}).get("options", {}).get("case")
    comments = _case_comments(case) if case and os.path.exists(case) else {}
    descriptions = {}
    for name in output_names(result):
        entry = entries.get(name, {})
        dof = entry.get("dof")
        fallback = f"{name} ({dof})" if dof and dof != name else name
        descriptions[name] = ((labels or {}).get(name) or entry.get("description") or entry.get("label")
                              or comments.get(name) or fallback)
    return descriptions
