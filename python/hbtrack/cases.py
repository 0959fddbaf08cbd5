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


def toml_key(key):
    """A dict key as a TOML key: bare when it is one, else a quoted string (so that a key holding
    '=', brackets or a newline cannot change the document around it)."""
    key = str(key)
    if key and all(c.isascii() and (c.isalnum() or c in "_-") for c in key):
        return key
    return json.dumps(key)


def toml_value(value):
    """A Python value (number, string, bool, sequence, dict, numpy array) as TOML text."""
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
    """{NAME: value} or ["NAME=VALUE", ...] as the CLI's --set strings."""
    if overrides is None:
        return []
    if isinstance(overrides, dict):
        return [f"{name}={toml_value(value)}" for name, value in overrides.items()]
    if isinstance(overrides, str):
        raise TypeError("set: expected a dict {NAME: value} or a list of 'NAME=VALUE' strings, got a str")
    return [str(o) for o in overrides]


def load_case(path, set=None):  # noqa: A002 - `set` is the CLI's flag name
    """The case file at `path`, with overrides `set` = {NAME: value} (a named parameter such as
    "amplitude", or a dotted case key such as "harmonic_balance.harmonics"), as `--set NAME=VALUE`.
    Raises ValueError naming the file, the line and the field on bad input."""
    return require_core().load_case(os.fspath(path), override_strings(set))


def case_from_arrays(M, K, dofs, *, C=None, damping=None, forcing=(), elements=(), parameters=None,
                     harmonic_balance=None, continuation, stability=None, outputs=None):
    """A case from numpy arrays and plain dicts whose keys are the case file's.

    M, K, C: n x n arrays; dofs: n names; damping: {"rayleigh": [alpha, beta]} or
    {"modal_ratios": [...]} instead of C; forcing: [{"dof": "x", "cos": 0.18}, ...] (or "cos"/"sin"
    arrays of n entries); elements: [{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}];
    continuation: {"omega_start": ..., "omega_end": ..., ...}; outputs: [{"name": ..., "dof": ...}]
    (default: every dof under its own name)."""
    for name, array in (("M", M), ("K", K), ("C", C)):
        if array is not None and np.iscomplexobj(np.asarray(array)):
            raise ValueError(f"{name}: complex values (the model is real; the imaginary part would be lost)")
    M, K = np.asarray(M, dtype=float), np.asarray(K, dtype=float)
    if C is not None and damping is not None:
        raise ValueError("damping: give C or damping, not both")
    sections = [("model", {"dofs": list(dofs), "M": M, "K": K})]
    if C is not None:
        sections.append(("damping", {"C": np.asarray(C, dtype=float)}))
    elif damping is not None:
        sections.append(("damping", dict(damping)))
    for name, table in (("parameters", parameters), ("harmonic_balance", harmonic_balance),
                        ("continuation", continuation), ("stability", stability)):
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
