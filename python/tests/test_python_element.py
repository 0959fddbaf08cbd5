"""Elements written in Python (hbtrack.add_python_element) against the built-in elements."""
import numpy as np
import pytest

import hbtrack


def duffing(elements=()):
    """examples/duffing.toml as arrays, with the given case-file elements."""
    return hbtrack.case_from_arrays(
        M=np.array([[1.0]]), K=np.array([[1.0]]), C=np.array([[0.05]]), dofs=["x"],
        forcing=[{"dof": "x", "harmonic": 1, "cos": 0.18}], parameters={"amplitude": 1.0},
        elements=list(elements), harmonic_balance={"harmonics": 7, "samples": 64},
        continuation={"omega_start": 0.5, "omega_end": 1.6, "step": 0.02})


def cubic_with_derivative(x, v):
    return 0.1 * x**3, (0.3 * x**2)[:, :, None]


def test_python_cubic_spring_gives_the_builtin_branch():
    builtin = hbtrack.frc(duffing([{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}]))
    python = hbtrack.frc(hbtrack.add_python_element(duffing(), ["x"], cubic_with_derivative))
    assert python["summary"]["stop_reason"] == "reached_end"
    # Same law and derivative, computed in numpy instead of C++: the branches differ by the
    # round-off of x**3 (a few ulps) amplified by Newton's convergence test, far below 1e-10.
    assert python["states"].shape == builtin["states"].shape
    scale = np.abs(builtin["states"]).max()
    assert np.abs(python["states"] - builtin["states"]).max() <= 1e-10 * scale


def test_finite_difference_derivatives_give_the_same_branch():
    builtin = hbtrack.frc(duffing([{"type": "cubic_spring", "dofs": ["x"], "cubic_stiffness": 0.1}]))
    case = hbtrack.add_python_element(duffing(), ["x"], lambda x, v: 0.1 * x**3)
    python = hbtrack.frc(case)
    assert python["summary"]["stop_reason"] == "reached_end"
    # A central-difference Jacobian (error ~1e-12 relative) only changes Newton's path: the
    # converged points meet the same residual tolerance (1e-9 of the forcing). Compare the
    # amplitude curves where both have points: the peak amplitude to 1e-6.
    assert python["branch"]["max_x"].max() == pytest.approx(builtin["branch"]["max_x"].max(), rel=1e-6)


def test_a_python_error_is_reported():
    def broken(x, v):
        raise ZeroDivisionError("boom")
    case = hbtrack.add_python_element(duffing(), ["x"], broken)
    with pytest.raises(Exception, match="boom"):
        hbtrack.frc(case)


def test_bad_shapes_and_dofs_are_value_errors():
    with pytest.raises(ValueError, match="unknown dof 'y'"):
        hbtrack.add_python_element(duffing(), ["y"], cubic_with_derivative)
    with pytest.raises(ValueError, match="must be callable"):
        hbtrack.add_python_element(duffing(), ["x"], 3.0)
    case = hbtrack.add_python_element(duffing(), ["x"], lambda x, v: np.zeros((3, 3)))
    with pytest.raises(Exception, match="shape"):
        hbtrack.frc(case)


def test_the_documented_example_script_gives_the_builtin_branch():
    """examples/python/python_element.py as a user runs it: the Duffing case's cubic spring as a
    Python callable reaches the end of the range on the built-in element's branch (the same
    Newton iterates, so to round-off: 1e-10 of the largest state)."""
    import os
    import re
    import subprocess
    import sys
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    done = subprocess.run([sys.executable, os.path.join(root, "examples", "python", "python_element.py")],
                          capture_output=True, text=True, check=True)
    match = re.search(r"(\d+) points, (\w+); largest difference from the built-in cubic_spring's branch (\S+)", done.stdout)
    assert match, done.stdout
    assert match.group(2) == "reached_end"
    assert float(match.group(3)) <= 1e-10
