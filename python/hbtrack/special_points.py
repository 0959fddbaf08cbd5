"""The names of special points, one numbering for every figure and table: per type, in increasing
omega (LP1 is the limit point of lowest frequency, as the paper numbers them), whatever order
the continuation met them in. summary.json lists them in that order, which is reversed on a
sweep downward (rotor 67), and `hbtrack track --lp K` counts in it: limit_point_label translates.
"""


def numbered_special_points(special_points):
    """The special points with a label each: per type, numbered in increasing omega.

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points (type, omega, ...).

    Returns
    -------
    list of (label, point dict), in omega order.

    Examples
    --------
    >>> [l for l, _ in numbered_special_points([{"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 1.0}])]
    ['LP1', 'LP2']
    """
    counts = {}
    numbered = []
    for sp in sorted(special_points, key=lambda p: p["omega"]):
        counts[sp["type"]] = counts.get(sp["type"], 0) + 1
        numbered.append((f"{sp['type']}{counts[sp['type']]}", sp))
    return numbered


def numbered_limit_points(special_points):
    """The limit points only, labelled as numbered_special_points labels them.

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points.

    Returns
    -------
    list of (label, point dict), in omega order.

    Examples
    --------
    >>> numbered_limit_points([{"type": "LP", "omega": 2.0}, {"type": "BP", "omega": 1.5}, {"type": "LP", "omega": 1.0}])
    [('LP1', {'type': 'LP', 'omega': 1.0}), ('LP2', {'type': 'LP', 'omega': 2.0})]
    """
    return [(label, sp) for label, sp in numbered_special_points(special_points) if sp["type"] == "LP"]


def limit_point_label(special_points, lp):
    """The label of the limit point that `hbtrack track --lp LP` starts from (the lp-th LP of
    summary.json, from 1), in the omega-order numbering.

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points of the NFRC tracked from.
    lp : int
        The track's --lp.

    Returns
    -------
    str
        "LPk"; "LP?" when the NFRC has fewer limit points.

    Examples
    --------
    >>> limit_point_label([{"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 1.0}], 1)
    'LP2'
    """
    lps = [sp for sp in special_points if sp["type"] == "LP"]
    if not 1 <= lp <= len(lps):
        return "LP?"
    return next(label for label, sp in numbered_limit_points(special_points) if sp is lps[lp - 1])
