"""hbtrack from Python: harmonic balance with arc-length continuation, stability, limit-point
tracking, isolated branches, time integration and Craig-Bampton reduction.

    import hbtrack
    case = hbtrack.load_case("examples/duffing.toml", set={"amplitude": 2.0})
    case.continuation.step = 0.05            # options are named as in the case file and the CLI
    nfrc = hbtrack.frc(case)                 # branch columns as branch.csv, summary as summary.json
    wide = hbtrack.frc(case, continuation={"omega_end": 2.5})   # settings for one run, case unchanged
    lp1 = hbtrack.track(case, nfrc, lp=1, param="amplitude", range=(0.5, 3.0))
    hbtrack.plots.save_figure(hbtrack.plots.nfrc_figure(nfrc), "out/nfrc")   # out/nfrc.png, .pdf

hbtrack.plots (matplotlib) is imported when first used, so `import hbtrack` works without it.
Import with PYTHONPATH=build/python (the build assembles the package and its compiled part
there); plotting and reading result folders also work from python/ without a build.
"""
import importlib
import os
import sys


def _interpreter_with_numpy():
    """The interpreter the compiled module was built for (written by the build beside this file),
    else Debian's, whose python3-numpy scripts/install-deps.sh installs."""
    try:
        with open(os.path.join(os.path.dirname(__file__), "_built_for.txt")) as f:
            return f.read().strip() or "/usr/bin/python3"
    except OSError:
        return "/usr/bin/python3"


try:
    import numpy  # noqa: F401  every run takes and returns numpy arrays
except ImportError:
    raise ImportError(f"hbtrack needs numpy, which {sys.executable} does not have: run it with {_interpreter_with_numpy()} "
                      "(or install numpy for this interpreter)") from None

from ._core import core as _core
from .analysis import backbone, continuation, frc, isolas, limit_point, solve, switch, track
from .cases import case_from_arrays, load_case
from .elements import add_python_element, element_types
from .model import campbell, modes, normal_modes, output_harmonics, reduce, residual
from .quasi_periodic import torus
from .results import read_result
from .settings import with_settings
from .timeint import simulate
from .tool_runs import study, sweep

if _core is not None:
    from ._hbtrack import (AdaptiveHarmonics, Case, ContinuationOptions, ContinuationSection, FoldTrackingOptions, HarmonicBalanceOptions,
                           NfrcOptions, StabilityOptions, SteadyStateOptions)

__all__ = ["load_case", "case_from_arrays", "frc", "solve", "modes", "campbell", "sweep", "study", "continuation", "backbone", "switch", "track", "isolas", "torus", "limit_point", "simulate",
           "with_settings", "reduce", "normal_modes", "output_harmonics", "residual", "add_python_element", "element_types", "read_result", "plots", "Case", "ContinuationSection", "ContinuationOptions",
           "StabilityOptions", "HarmonicBalanceOptions", "AdaptiveHarmonics", "NfrcOptions", "FoldTrackingOptions", "SteadyStateOptions"]


def __getattr__(name):
    """hbtrack.plots is imported on first use: computing needs no matplotlib."""
    if name == "plots":
        return importlib.import_module(".plots", __name__)
    raise AttributeError(f"module 'hbtrack' has no attribute {name!r}")
