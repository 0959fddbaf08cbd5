"""Cases: a case file with overrides (as `hbtrack --set`), or a case built from numpy arrays.

Overrides and array-built cases go through the case-file reader, so the keys, defaults and
error messages (ValueError naming the field) are those of the case file (docs/case-file.md).
"""
import json
import math
import os
import tempfile

import numpy as np

from ._core import require_core
from .arrays import as_matrix, is_sparse


def toml_key(key):
    """A dict key as TOML text.

    Bare when it is a bare key, else a quoted string, so that a key holding '=', brackets or a
    newline cannot change the document around it.

    Parameters
    ----------
    key : object
        The key (converted with str).

    Returns
    -------
    str
        Its TOML text.

    Examples
    --------
    >>> toml_key("amplitude"), toml_key("a = 1")
    ('amplitude', '"a = 1"')
    """
    key = str(key)
    if key and all(c.isascii() and (c.isalnum() or c in "_-") for c in key):
        return key
    return json.dumps(key)


def toml_value(value):
    """A Python value as TOML text (what case_from_arrays and `set` overrides write).

    Parameters
    ----------
    value : bool, int, float, str, sequence, dict, numpy.ndarray or scipy.sparse matrix
        The value; sparse matrices are written dense.

    Returns
    -------
    str
        Its TOML text: floats with the shortest repr that reads back to the same double.

    Examples
    --------
    >>> toml_value({"cos": 0.18, "dof": "x"})
    '{cos = 0.18, dof = "x"}'
    """
    if is_sparse(value):
        value = value.toarray()
    if isinstance(value, (bool, np.bool_)):
        return "true" if value else "false"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if math.isnan(x):
            return "nan"
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return repr(x)  # shortest text that reads back to the same double
    if isinstance(value, (complex, np.complexfloating)):
        raise ValueError(f"cannot write the complex number {value!r} into a case (models are real)")
    if isinstance(value, str):
        return json.dumps(value)  # a TOML basic string
    if isinstance(value, np.ndarray):
        return toml_value(value.tolist())
    if isinstance(value, dict):
        return "{" + ", ".join(f"{toml_key(key)} = {toml_value(v)}" for key, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {type(value).__name__} {value!r} into a case")


def override_strings(overrides):
    """Overrides as the CLI's ``--set NAME=VALUE`` strings.

    Parameters
    ----------
    overrides : dict or list of str or None
        {NAME: value} or ["NAME=VALUE", ...].

    Returns
    -------
    list of str
        One "NAME=VALUE" per override (empty for None).

    Examples
    --------
    >>> override_strings({"amplitude": 2.0})
    ['amplitude=2.0']
    """
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{name}={toml_value(value)}" for name, value in overrides.items()]
    if isinstance(overrides, str):
        raise TypeError("set: expected a dict {NAME: value} or a list of 'NAME=VALUE' strings, got a str")
    return [str(o) for o in overrides]


def load_case(path, set=None):  # noqa: A002 - `set` is the CLI's flag name
    """A case file, with overrides as ``hbtrack --set``.

    Parameters
    ----------
    path : str or os.PathLike
        The TOML case file (docs/case-file.md).
    set : dict or list of str, optional
        {NAME: value}: a named parameter such as "amplitude", or a dotted case key such as
        "harmonic_balance.harmonics"; or ["NAME=VALUE", ...].

    Returns
    -------
    hbtrack.Case
        The case; its options (``case.continuation``, ``case.stability``, ...) can be changed
        before computing.

    Raises
    ------
    ValueError
        Naming the file, the line and the field on bad input.

    Examples
    --------
    >>> case = hbtrack.load_case("examples/duffing.toml", set={"amplitude": 2.0})
    >>> case.continuation.step = 0.05
    """
    return require_core().load_case(os.fspath(path), override_strings(set))


def case_from_arrays(M, K, dofs, *, C=None, damping=None, forcing=(), forcing_growth=None, base_motion=None,
                     elements=(), parameters=None, harmonic_balance=None, continuation, stability=None, outputs=None):
    """A case from matrices and plain dicts whose keys are the case file's.

    Parameters
    ----------
    M, K : array_like or scipy.sparse matrix
        n x n mass and stiffness matrices (sparse ones are written dense).
    dofs : sequence of str
        The n dof names.
    C : array_like or scipy.sparse matrix, optional
        n x n damping matrix; or give `damping` instead.
    damping : dict, optional
        {"rayleigh": [alpha, beta]} or {"modal_ratios": [...]}.
    forcing : sequence of dict, optional
        [{"dof": "x", "cos": 0.18}, ...], or "cos"/"sin" arrays of n entries.
    forcing_growth : dict, optional
        {"exponent": k, "reference_frequency": w_ref}: the forcing times (omega / w_ref)^k
        (an unbalance: k = 2).
    base_motion : dict, optional
        {"kind": "displacement" | "velocity" | "acceleration", "dofs": [...], "cos": ...,
        "sin": ..., "harmonic": 1}: an imposed support motion instead of `forcing`; the results
        are the motion relative to the base.
    elements : sequence of dict, optional
        [{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}, ...].
    parameters, harmonic_balance, stability : dict, optional
        The case file's sections of those names.
    continuation : dict
        {"omega_start": ..., "omega_end": ..., ...}.
    outputs : sequence of dict, optional
        [{"name": ..., "dof": ...}]; default every dof under its own name.

    Returns
    -------
    hbtrack.Case
        As :func:`load_case` returns, with ``case.path == "<arrays>"``.

    Raises
    ------
    ValueError
        Naming the argument or the case key (a matrix that is not n x n, an unknown key, ...).

    Examples
    --------
    >>> import scipy.sparse
    >>> case = hbtrack.case_from_arrays(scipy.sparse.eye(1), [[1.0]], ["x"], C=[[0.05]],
    ...     forcing=[{"dof": "x", "cos": 0.18}], parameters={"amplitude": 1.0},
    ...     elements=[{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}],
    ...     continuation={"omega_start": 0.5, "omega_end": 1.6})
    >>> nfrc = hbtrack.frc(case)
    """
    M, K = as_matrix(M, "M"), as_matrix(K, "K")
    if C is not None and damping is not None:
        raise ValueError("damping: give C or damping, not both")
    sections = [("model", {"dofs": list(dofs), "M": M, "K": K})]
    if C is not None:
        sections.append(("damping", {"C": as_matrix(C, "C")}))
    elif damping is not None:
        sections.append(("damping", dict(damping)))
    for name, table in (("forcing_growth", forcing_growth), ("base_motion", base_motion), ("parameters", parameters),
                        ("harmonic_balance", harmonic_balance), ("continuation", continuation),
                        ("stability", stability)):
        if table:
            sections.append((name, dict(table)))
    if outputs is None:
        outputs = [{"name": d, "dof": d} for d in dofs]
    lines = []
    for name, table in sections:
        lines.append(f"[{name}]")
        lines += [f"{toml_key(key)} = {toml_value(value)}" for key, value in table.items()]
    for name, entries in (("forcing", forcing), ("elements", elements), ("outputs", outputs)):
        for entry in entries:
            lines.append(f"[[{name}]]")
            lines += [f"{toml_key(key)} = {toml_value(value)}" for key, value in entry.items()]
    with tempfile.TemporaryDirectory(prefix="hbtrack-") as folder:
        path = os.path.join(folder, "arrays.toml")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        try:
            case = load_case(path)
        except ValueError as error:  # name the call, not the temporary file
            raise ValueError(str(error).replace(path, "case_from_arrays")) from None
    case.path = "<arrays>"
    return case
