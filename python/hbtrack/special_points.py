"""The special points' types, named once (SpecialPointType, CurveExtremumType: the names
summary.json writes), and their labels, one numbering for every figure and table: per type, in increasing
omega (LP1 is the limit point of lowest frequency, as the paper numbers them), whatever order
the continuation met them in. summary.json lists them in that order, which is reversed on a
sweep downward (rotor 67). `hbtrack track --lp K` counts in omega order too (its summary says
options.tracking.lp_order = "omega"); tracking results written before that counted in
summary.json's order, which limit_point_label translates.
"""

import enum


class SpecialPointType(enum.StrEnum):
    """A special point of a branch, by the name summary.json gives it (the C++ table's,
    include/hbtrack/util/special_point_type.hpp; python/tests/test_special_point_names.py checks
    they agree). Members are str: ``sp["type"] == SpecialPointType.LIMIT_POINT``.

    Examples
    --------
    >>> SpecialPointType("NS") is SpecialPointType.NEIMARK_SACKER
    True
    """

    LIMIT_POINT = "LP"
    BRANCH_POINT = "BP"
    PERIOD_DOUBLING = "PD"
    NEIMARK_SACKER = "NS"
    RESONANCE_1_1 = "R1"  # where an NS curve's frequency reaches 0: ends a tracking leg
    RESONANCE_1_2 = "R2"  # ... reaches w/2


class CurveExtremumType(enum.StrEnum):
    """A special point of a tracking curve (track's special_points), by its summary.json name.

    Examples
    --------
    >>> CurveExtremumType("min") is CurveExtremumType.PARAMETER_MIN
    True
    """

    PARAMETER_MIN = "min"  # a pair of special points is born
    PARAMETER_MAX = "max"  # a pair merges
    RESONANCE_1_1 = "resonance_1_1"  # an NS curve ends on a fold curve
    RESONANCE_1_2 = "resonance_1_2"  # an NS curve ends on a PD curve


def parse_special_point_type(name, field="special point type"):
    """The SpecialPointType named `name`, as the C++ parser reads it.

    Parameters
    ----------
    name : str
        A name of summary.json's special_points[].type.
    field : str, optional
        Where it was read, for the error.

    Returns
    -------
    SpecialPointType
        The type; ValueError "FIELD: must be LP, BP, PD, NS, R1 or R2, got 'x'" (the C++
        message) for another name.

    Examples
    --------
    >>> parse_special_point_type("BP")
    <SpecialPointType.BRANCH_POINT: 'BP'>
    """
    try:
        return SpecialPointType(name)
    except ValueError:
        names = [t.value for t in SpecialPointType]
        raise ValueError(f"{field}: must be {', '.join(names[:-1])} or {names[-1]}, got '{name}'") from None



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


def distinct_special_points(special_points, relative=1e-4):
    """The special points with the repeats of one point dropped: branches drawn together (the
    main branch that `isolas` reached from two crossings, an NFRC and its odd-harmonic twin)
    report the same fold each; numbered over all of them it was counted twice (LP1-LP8 for 4).

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points of all the branches (type, omega, outputs).
    relative : float, optional
        Two points of one type are one when omega and every max_/min_ value they share agree to
        this fraction (located points agree to the Newton tolerance, about 1e-8; distinct
        points of the examples lie 1e-3 apart or more).

    Returns
    -------
    list of dict
        The first of each group, in the given order.

    Examples
    --------
    >>> len(distinct_special_points([{"type": "LP", "omega": 1.0, "max_x": 2.0}, {"type": "LP", "omega": 1.0, "max_x": 2.0}]))
    1
    """
    kept = []
    for sp in special_points:
        def same(other):
            keys = [k for k in sp if k.startswith(("max_", "min_")) and k in other]
            return (other["type"] == sp["type"] and abs(other["omega"] - sp["omega"]) <= relative * abs(sp["omega"])
                    and all(abs(other[k] - sp[k]) <= relative * max(abs(sp[k]), abs(other[k]), 1e-300) for k in keys))
        if not any(same(other) for other in kept):
            kept.append(sp)
    return kept


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
    return [(label, sp) for label, sp in numbered_special_points(special_points) if sp["type"] == SpecialPointType.LIMIT_POINT]


def limit_point_label(special_points, lp, lp_order="summary"):
    """The label of the limit point that `hbtrack track --lp LP` started from.

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points of the NFRC tracked from.
    lp : int
        The track's --lp (its summary's options.tracking.lp).
    lp_order : {"summary", "omega"}, optional
        The track summary's options.tracking.lp_order: "omega" (hbtrack from 2026-11-26: LP K is
        the K-th in increasing omega) or, absent from older results, "summary" (the lp-th LP of
        summary.json).

    Returns
    -------
    str
        "LPk"; "LP?" when the NFRC has fewer limit points.

    Examples
    --------
    >>> limit_point_label([{"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 1.0}], 1)
    'LP2'
    >>> limit_point_label([{"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 1.0}], 1, "omega")
    'LP1'
    """
    lps = [sp for sp in special_points if sp["type"] == SpecialPointType.LIMIT_POINT]
    if not 1 <= lp <= len(lps):
        return "LP?"
    if lp_order == "omega":
        return f"LP{lp}"
    return next(label for label, sp in numbered_limit_points(special_points) if sp is lps[lp - 1])


def tracked_limit_point_label(special_points, tracking_options):
    """The label of a tracking result's starting limit point from its summary's
    options.tracking (its lp and, when written, lp_order).

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points of the NFRC tracked from.
    tracking_options : dict
        The track summary's options["tracking"].

    Returns
    -------
    str
        "LPk"; "LP?" when the NFRC has fewer limit points.

    Examples
    --------
    >>> tracked_limit_point_label([{"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 1.0}], {"lp": 2, "lp_order": "omega"})
    'LP2'
    """
    return limit_point_label(special_points, tracking_options.get("lp", 0), tracking_options.get("lp_order", "summary"))


def limit_points_on_curve(special_points, omega, values, value, relative=2e-3):
    """The limit points of an NFRC that a tracking curve passes through: where the curve crosses
    the NFRC's parameter value within `relative` of a limit point's omega. A limit-point curve
    often runs through more than one of the NFRC's folds (rotor 67 in amplitude: LP1 and LP3 are
    one curve), which the study then tracks once.

    Parameters
    ----------
    special_points : sequence of dict
        summary.json's special_points of the NFRC.
    omega, values : array_like
        The curve's omega and tracked parameter, in curve order (results.tracking_curve).
    value : float
        The NFRC's value of the parameter.
    relative : float, optional
        The tolerance on omega, relative to the limit point's.

    Returns
    -------
    list of (label, point dict)
        In omega order, labelled as numbered_limit_points labels them.

    Examples
    --------
    >>> lps = [{"type": "LP", "omega": 1.0}, {"type": "LP", "omega": 2.0}, {"type": "LP", "omega": 3.0}]
    >>> [label for label, _ in limit_points_on_curve(lps, [1.0, 2.5, 3.0], [1.0, 0.0, 1.0], 1.0)]
    ['LP1', 'LP3']
    """
    crossings = []
    for i in range(len(omega) - 1):
        a, b = values[i] - value, values[i + 1] - value
        if a == 0.0:
            crossings.append(omega[i])
        elif a * b < 0.0:
            crossings.append(omega[i] + (omega[i + 1] - omega[i]) * a / (a - b))
    if len(omega) and values[-1] == value:
        crossings.append(omega[-1])
    return [(label, sp) for label, sp in numbered_limit_points(special_points)
            if any(abs(w - sp["omega"]) <= relative * abs(sp["omega"]) for w in crossings)]
