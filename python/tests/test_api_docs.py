"""Every public function of the package has a numpydoc docstring with Parameters, Returns and
Examples sections, and `import hbtrack` needs no matplotlib."""
import doctest
import importlib
import inspect
import os
import pkgutil
import re
import subprocess
import sys

import pytest

import hbtrack

# Every module of the package, so that a new one is checked without editing this list; except
# the private ones and paper_comparison, the internals of python/compare_with_paper.py (Markdown
# rows of the rotor 67 comparison), which is a script, not an API.
NOT_API = {"paper_comparison"}
MODULES = sorted(m.name for m in pkgutil.iter_modules(hbtrack.__path__) if not m.name.startswith("_") and m.name not in NOT_API)
# Functions whose examples need nothing but themselves: run as doctests, so that their outputs
# are the real ones.
SELF_CONTAINED = ["hbtrack.arrays.is_sparse", "hbtrack.arrays.as_matrix", "hbtrack.cases.toml_key", "hbtrack.cases.toml_value",
                  "hbtrack.figure_style.length_label", "hbtrack.figure_style.parameter_label", "hbtrack.plots.harmonic_signal",
                  "hbtrack.plots.harmonic_amplitudes", "hbtrack.overlay_figures.describe",
                  "hbtrack.special_points.numbered_special_points", "hbtrack.special_points.numbered_limit_points",
                  "hbtrack.special_points.limit_point_label", "hbtrack.special_points.parse_special_point_type",
                  "hbtrack.settings.settings_overrides", "hbtrack.starts.result_overrides", "hbtrack.starts.start_state",
                  "hbtrack.progress.checked_progress", "hbtrack.results.harmonic_label"]
# The computations: each takes progress= and the case's settings as keywords, documented.
COMPUTATIONS = ["frc", "continuation", "backbone", "track", "isolas", "switch", "simulate"]


def public_functions():
    found = []
    for name in MODULES:
        module = importlib.import_module(f"hbtrack.{name}")
        for attr, value in vars(module).items():
            if inspect.isfunction(value) and value.__module__ == module.__name__ and not attr.startswith("_"):
                found.append((f"hbtrack.{name}.{attr}", value))
    return found


def test_there_are_public_functions_to_check():
    names = [n for n, _ in public_functions()]
    assert "hbtrack.analysis.frc" in names and "hbtrack.plots.nfrc_figure" in names and len(names) > 30
    assert set(SELF_CONTAINED) <= set(names)


@pytest.mark.parametrize("name", SELF_CONTAINED)
def test_self_contained_examples_give_what_they_show(name):
    module_name, attr = name.rsplit(".", 1)
    function = getattr(importlib.import_module(module_name), attr)
    # `>>> import numpy as np` is not written in each example: the globals of its module hold it.
    globs = dict(vars(importlib.import_module(module_name)))
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    for test in doctest.DocTestFinder().find(function, name, globs=globs):
        runner.run(test)
    results = runner.summarize(verbose=False)
    assert results.attempted > 0 and results.failed == 0, f"{name}: {results.failed} of {results.attempted} examples differ"


@pytest.mark.parametrize("name, function", public_functions(), ids=lambda v: v if isinstance(v, str) else "")
def test_numpydoc_sections(name, function):
    doc = inspect.getdoc(function) or ""
    for section in ("Parameters", "Returns", "Examples"):
        assert re.search(rf"^{section}\n-{{{len(section)}}}$", doc, re.MULTILINE), f"{name}: no {section} section"
    documented = set()
    block = re.search(r"^Parameters\n-+\n(.*?)(?=^\w+\n-+$)", doc, re.MULTILINE | re.DOTALL).group(1)
    for line in block.splitlines():
        if line and not line.startswith(" "):
            documented.update(p.strip().lstrip("*") for p in line.split(":")[0].split(","))
    parameters = [p for p in inspect.signature(function).parameters if p not in ("self",)]
    missing = [p for p in parameters if p not in documented]
    assert not missing, f"{name}: parameters not documented: {missing}"


def test_import_without_numpy_names_the_interpreter_it_needs():
    # A Python without numpy (another interpreter than the one the module was built for): one
    # line, naming that interpreter, not numpy's bare "No module named" from inside the package.
    code = "import sys; sys.modules['numpy'] = None\nimport hbtrack\n"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=dict(os.environ))
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError: hbtrack needs numpy, which " + sys.executable + " does not have: run it with "), done.stderr
    built_for = os.path.join(os.path.dirname(hbtrack.__file__), "_built_for.txt")
    expected = open(built_for).read().strip() if os.path.exists(built_for) else "/usr/bin/python3"
    assert f"run it with {expected} " in last, last


def test_import_without_matplotlib():
    # A subprocess where `import matplotlib` fails: computing still works, plots say why not.
    code = ("import sys; sys.modules['matplotlib'] = None\n"
            "import hbtrack\n"
            "case = hbtrack.load_case(sys.argv[1])\n"
            "assert len(hbtrack.frc(case)['branch']['omega']) > 20\n"
            "try:\n    hbtrack.plots\nexcept ImportError:\n    print('no plots')\n")
    from conftest import DUFFING
    done = subprocess.run([sys.executable, "-c", code, DUFFING], capture_output=True, text=True, env=dict(os.environ))
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "no plots"


@pytest.mark.parametrize("name", COMPUTATIONS)
def test_every_computation_takes_progress_and_the_settings(name):
    function = getattr(hbtrack, name)
    parameters = inspect.signature(function).parameters
    assert "progress" in parameters
    last = list(parameters.values())[-1]
    assert (last.name, last.kind) == ("settings", inspect.Parameter.VAR_KEYWORD)
    doc = inspect.getdoc(function)
    assert "**settings : dict, optional" in doc and "stopped_by_callback" in doc
    assert re.search(r"^Examples\n-+\n(.|\n)*\b(continuation|harmonic_balance|stability|parameters)=", doc, re.MULTILINE), \
        f"{name}: no example of the settings keywords"
