"""A case's settings changed for one computation: the case file's sections as keyword dicts, or
the CLI's ``--set`` strings, applied to a copy of the case by the case file's own reader (same
keys, defaults and ValueErrors as the case file and ``hbtrack --set``).
"""
from ._core import require_core
from .cases import override_strings, toml_value

# The case file's sections a computation may change (docs/case-file.md); the model, elements,
# forcing and outputs are the case's.
SECTIONS = ("parameters", "harmonic_balance", "continuation", "stability")


def settings_overrides(set=None, **sections):  # noqa: A002 - the CLI's flag name
    """Section dicts and ``set`` as the CLI's ``--set NAME=VALUE`` strings.

    Parameters
    ----------
    set : dict or list of str, optional
        {NAME: value} or ["NAME=VALUE", ...], as :func:`hbtrack.load_case` takes.
    **sections : dict, optional
        parameters={NAME: value}, harmonic_balance={KEY: value}, continuation={KEY: value},
        stability={KEY: value}: the case file's sections and keys.

    Returns
    -------
    list of str
        The sections' overrides in the order given, then set's.

    Raises
    ------
    TypeError
        A keyword that is not one of the sections, or a section that is not a dict.

    Examples
    --------
    >>> settings_overrides(continuation={"omega_start": 0.5}, parameters={"amplitude": 2})
    ['continuation.omega_start=0.5', 'amplitude=2']
    """
    overrides = []
    for section, table in sections.items():
        if section not in SECTIONS:
            raise TypeError(f"unexpected keyword argument {section!r} (the case file's sections a computation changes: "
                            f"{', '.join(SECTIONS)}; or set=)")
        if table is None:
            continue
        if not isinstance(table, dict):
            raise TypeError(f"{section}: expected a dict {{KEY: value}} of the case file's [{section}] keys, "
                            f"got {type(table).__name__}")
        prefix = "" if section == "parameters" else section + "."
        overrides += [f"{prefix}{key}={toml_value(value)}" for key, value in table.items()]
    return overrides + override_strings(set)


def case_with(case, overrides, caller):
    """`case` with overrides, a copy; `case` itself when there are none.

    Parameters
    ----------
    case : hbtrack.Case
        The case (unchanged).
    overrides : list of str
        "NAME=VALUE" strings (:func:`settings_overrides`).
    caller : str
        The function named in errors, in place of the CLI's "--set".

    Returns
    -------
    hbtrack.Case
        The case the computation runs on.

    Raises
    ------
    ValueError
        Naming the key and the rule, as the case file's reader does.

    Examples
    --------
    >>> run_case = case_with(case, ["continuation.step=0.01"], "frc")
    """
    if not overrides:
        return case
    try:
        return require_core().with_overrides(case, overrides)
    except ValueError as error:
        text = str(error)
        for prefix in ("--set: ", "--set "):
            if text.startswith(prefix):
                text = f"{caller}: {text[len(prefix):]}"
                break
        raise ValueError(text) from None


def with_settings(case, set=None, **sections):  # noqa: A002 - the CLI's flag name
    """A copy of `case` with some of its settings changed, as ``hbtrack --set`` changes a case file.

    Every computation (:func:`hbtrack.frc`, ``track``, ``continuation``, ``backbone``,
    ``isolas``, ``switch``, :func:`hbtrack.simulate`) takes the same keywords and calls this.

    Parameters
    ----------
    case : hbtrack.Case
        The case; it is not changed.
    set : dict or list of str, optional
        {NAME: value} or ["NAME=VALUE", ...]: a named parameter ("amplitude") or a dotted key
        ("continuation.omega_start"), as :func:`hbtrack.load_case` and the CLI's --set take.
    **sections : dict, optional
        parameters={NAME: value}, harmonic_balance={KEY: value}, continuation={KEY: value},
        stability={KEY: value}: the case file's sections and keys (docs/case-file.md).

    Returns
    -------
    hbtrack.Case
        The copy. Keys left out keep the case's values; defaults derived from another key (the
        step's bounds from the step, the samples from the harmonics) follow it as in the file.

    Raises
    ------
    ValueError
        An unknown key or parameter, a bad value (naming the key and the rule, as the case file's
        reader does), or a key of the model, elements, forcing or outputs (load_case changes those).

    Examples
    --------
    >>> case = hbtrack.load_case("examples/duffing.toml")
    >>> faster = hbtrack.with_settings(case, continuation={"omega_start": 0.7, "max_points": 400},
    ...                                harmonic_balance={"harmonics": 7})
    >>> faster.continuation.omega_start, case.continuation.omega_start
    """
    copy = case_with(case, settings_overrides(set, **sections), "with_settings")
    return require_core().with_overrides(case, []) if copy is case else copy
