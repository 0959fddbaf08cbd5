"""NFRC, limit-point tracking and isolated branches: `hbtrack frc`, `track` and `isolas` as
functions. Results are dicts holding what the CLI writes to a result folder:

    branch          {column: 1-D array}, the columns and numbers of branch.csv
    states          2-D array, the rows of states.csv (omega or leg, omega, parameter; then x0, x1, ...)
    special_points  list of dicts, as summary.json's special_points
    special_states  2-D array, special_states.csv (frc only)
    summary         dict, as summary.json
    kind            "frc", "continue", "track", "isolas" (as hbtrack.results.read_result names folders)

A run that stops early (summary["stop_reason"]) still returns what it computed, as the CLI keeps
its points; bad arguments raise ValueError naming the argument.
"""
import numpy as np

from ._core import require_core


def frc(case, *, progress=None):
    """The NFRC of `case` over its frequency range, with stability and special points.
    progress(fraction, point, omega), when given, is called after every accepted point; False
    stops the run (stop_reason "stopped_by_callback"), an exception stops it and propagates."""
    core = require_core()
    if progress is not None and not callable(progress):
        raise ValueError(f"progress: must be callable, got {type(progress).__name__}")
    result = core.frc(case, progress)
    result["kind"] = "frc"
    return result


def continuation(case, *, param, omega, range):  # noqa: A002 - the CLI's --range
    """`hbtrack continue`: the periodic solution at fixed frequency `omega` followed in the named
    parameter `param` from range[0] towards range[1], with stability and special points (LPs in
    the parameter located). branch holds the parameter as a column beside omega."""
    try:
        start, end = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    result = require_core().continuation(case, param, float(omega), start, end)
    result["kind"] = "continue"
    return result


def backbone(case, *, mode=1, range):  # noqa: A002 - the CLI's --range
    """`hbtrack backbone`: the nonlinear mode of linear mode `mode` (from 1) by the extended
    periodic motion concept, from modal amplitude range[0] (near the linear mode) to range[1].
    branch holds amplitude, omega, damping_ratio, xi and the outputs' extremes and harmonics."""
    if isinstance(mode, bool) or not isinstance(mode, (int, np.integer)) or mode < 1:
        raise ValueError(f"mode: must be an integer >= 1, got {mode!r}")
    try:
        start, end = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    if not 0 < start < end:
        raise ValueError(f"range: must be (LO, HI) with 0 < LO < HI, got {range!r}")
    result = require_core().backbone(case, int(mode), start, end)
    result["kind"] = "backbone"
    return result


def limit_point(result, lp):
    """State row [omega, x0, ...] of the lp-th (from 1) limit point of an frc result."""
    if not isinstance(result, dict) or "special_points" not in result or "special_states" not in result:
        raise ValueError("start: expected an frc result (from hbtrack.frc, or read_result of an frc folder)")
    if isinstance(lp, bool) or not isinstance(lp, (int, np.integer)) or lp < 1:
        raise ValueError(f"lp: must be an integer >= 1, got {lp!r}")
    rows = [i for i, sp in enumerate(result["special_points"]) if sp["type"] == "LP"]
    if lp > len(rows):
        raise ValueError(f"lp: {lp} is beyond the {len(rows)} limit points of the frc result")
    return result["special_states"][rows[lp - 1]]


def track(case, start, *, lp, param, range, method="bordered"):  # noqa: A002 - the CLI's --range
    """The lp-th limit point of the frc result `start` (computed on the same case) followed while
    parameter `param` moves within range = (LO, HI); method "bordered" or "extended"."""
    state = limit_point(start, lp)
    try:
        low, high = (float(v) for v in range)
    except (TypeError, ValueError):
        raise ValueError(f"range: expected (LO, HI), got {range!r}") from None
    result = require_core().track(case, state[1:], state[0], param, low, high, method)
    result["summary"]["options"]["tracking"]["lp"] = lp
    result["kind"] = "track"
    return result


def isolas(case, tracks, *, at):
    """Isolated branches at parameter value `at`, from one or more track results of the case:
    {"summary": {... "crossings": [...]}, "branches": {"isola_1": branch result, ...}}."""
    if isinstance(tracks, dict):
        tracks = [tracks]
    if not tracks:
        raise ValueError("tracks: needs at least one track result")
    for t in tracks:
        if not isinstance(t, dict) or "states" not in t or "tracking" not in t.get("summary", {}).get("options", {}):
            raise ValueError("tracks: expected track results (from hbtrack.track, or read_result of a track folder)")
    names = {t["summary"]["options"]["tracking"]["parameter"] for t in tracks}
    if len(names) != 1:
        raise ValueError(f"tracks: the curves track different parameters: {', '.join(sorted(names))}")
    result = require_core().isolas(case, [np.asarray(t["states"]) for t in tracks], names.pop(), float(at))
    result["kind"] = "isolas"
    for name, branch in result["branches"].items():
        branch["kind"], branch["label"] = "isola_branch", name
    return result
