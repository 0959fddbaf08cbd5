"""The runs layer (src/runs/): each run's recipe exists once and serves the CLI and Python.

`solve` and `modes` are new in Python and must give the CLI's numbers (1e-12 relative, as
test_same_as_cli.py: the same library code on the same input). `simulate` from a solution with
friction sliders must start them where the CLI does (the Python binding once started them at
rest). `sweep` and `study` run the tool itself and read its folder back."""
import os

import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import DUFFING, ROOT, assert_same_columns, run_cli

RELATIVE = 1e-12
JENKINS = os.path.join(ROOT, "examples", "three_oscillators_jenkins.toml")


def test_solve_gives_the_cli_point_and_its_stability(duffing_case, results_dir):
    folder = os.path.join(results_dir, "solve_runs")
    run_cli("solve", DUFFING, "--omega", "1.2", "-o", folder)
    cli = read_result(folder)
    api = hbtrack.solve(duffing_case, 1.2)
    assert api["kind"] == "solve" and api["summary"]["converged"] and cli["summary"]["converged"]
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_columns(api["dof_states"], cli["dof_states"])
    np.testing.assert_allclose(api["states"], cli["states"], rtol=RELATIVE, atol=1e-300)
    assert api["summary"]["stable"] == cli["summary"]["stable"]
    np.testing.assert_allclose(api["summary"]["floquet_multipliers"], cli["summary"]["floquet_multipliers"], rtol=RELATIVE, atol=1e-15)


def test_solve_that_does_not_converge_says_so_without_rows(duffing_case):
    # One Newton iteration cannot reach the tolerance from the linear solution of a cubic spring
    # at large amplitude.
    api = hbtrack.solve(duffing_case, 1.2, continuation={"max_iterations": 1, "tolerance": 1e-15}, parameters={"amplitude": 5.0})
    assert api["summary"]["converged"] is False and api["summary"]["stop_reason"] == "no_convergence"
    assert "branch" not in api


def test_modes_gives_the_cli_frequencies(results_dir):
    case = hbtrack.load_case(JENKINS)
    folder = os.path.join(results_dir, "modes_runs")
    run_cli("modes", JENKINS, "--count", "2", "-o", folder)
    cli = read_result(folder)["summary"]
    api = hbtrack.modes(case, count=2)
    assert api["kind"] == "modes" and len(api["summary"]["natural_frequencies"]) == 2
    np.testing.assert_allclose(api["summary"]["natural_frequencies"], cli["natural_frequencies"], rtol=RELATIVE, atol=0)
    assert api["summary"]["dominant_dofs"] == cli["dominant_dofs"]
    # The chain of three unit masses and springs: omega_k = sqrt(2 - 2 cos(k pi / 4)), k = 1, 2
    # (the tridiagonal matrix's eigenvalues); rtol 1e-12 of a symmetric eigensolver on a 3 x 3.
    exact = [np.sqrt(2.0 - 2.0 * np.cos(k * np.pi / 4.0)) for k in (1, 2)]
    np.testing.assert_allclose(api["summary"]["natural_frequencies"], exact, rtol=1e-12)
    with pytest.raises(ValueError, match="count: must be >= 1"):
        hbtrack.modes(case, count=0)


def test_simulate_from_a_friction_orbit_starts_its_sliders_as_the_cli(results_dir):
    frc_folder = os.path.join(results_dir, "jenkins_frc")
    run_cli("frc", JENKINS, "--set", "continuation.max_points=15", "-o", frc_folder)
    sim_folder = os.path.join(results_dir, "jenkins_sim")
    # 30 periods: the motion has not settled (exit 1), which does not matter for the comparison.
    run_cli("simulate", JENKINS, "--from", frc_folder, "--point", "10", "--max-periods", "30", "-o", sim_folder, check=False)
    cli = read_result(sim_folder)
    api = hbtrack.simulate(hbtrack.load_case(JENKINS), start=read_result(frc_folder), point=10, max_periods=30)
    assert api["summary"]["periods"] == cli["summary"]["periods"] == 30
    assert_same_columns(api["signals"], cli["signals"])
    for key in ("h1_x1", "h1_x2", "h1_x3", "last_change"):
        assert api["summary"][key] == pytest.approx(cli["summary"][key], rel=RELATIVE, abs=0), key


def test_frc_summary_has_the_cli_warnings_and_advice_fields(duffing_frc, duffing_frc_cli):
    # One recipe: the summary's keys are the CLI's (warnings were CLI-only before the runs layer).
    assert "warnings" in duffing_frc["summary"] and "warnings" in duffing_frc_cli["summary"]
    assert set(duffing_frc["summary"]) == set(duffing_frc_cli["summary"])


def test_sweep_runs_the_tool_and_reads_its_table(results_dir):
    folder = os.path.join(results_dir, "sweep_runs")
    done = hbtrack.sweep(DUFFING, folder, grid={"amplitude": [0.5, 1.0]}, jobs=2)
    assert done["kind"] == "sweep" and done["summary"]["stop_reason"] == "completed"
    table = done["sweep"]
    np.testing.assert_array_equal(table["amplitude"], [0.5, 1.0])
    assert table["status"] == ["reached_end", "reached_end"]
    peak = hbtrack.frc(hbtrack.load_case(DUFFING), parameters={"amplitude": 1.0})["branch"]["max_x"].max()
    # sweep.csv holds the peak with 10 significant digits (sweep_table.cpp's number_text).
    assert table["peak_max_x"][1] == pytest.approx(peak, rel=1e-9)


def test_study_and_sweep_take_a_case_file_and_pass_bad_input_on(duffing_case, tmp_path):
    with pytest.raises(TypeError, match="give its path"):
        hbtrack.study(duffing_case, str(tmp_path / "study"))
    # The Duffing case has no [study] section: the tool's one-line message, as a ValueError.
    with pytest.raises(ValueError, match="study.track: missing"):
        hbtrack.study(DUFFING, str(tmp_path / "study"))
    with pytest.raises(ValueError, match="nosuch"):
        hbtrack.sweep(DUFFING, str(tmp_path / "sweep"), grid={"nosuch": [1.0]})


def test_the_tool_is_found_beside_the_build_without_the_environment(monkeypatch):
    monkeypatch.delenv("HBTRACK_CLI", raising=False)
    monkeypatch.setenv("PATH", "/nonexistent")
    path = hbtrack.tool_runs.tool_path()
    assert os.path.basename(path) == "hbtrack" and os.access(path, os.X_OK)


def python_block(page, heading):
    """The first ```python block after `heading` in the repository's `page`."""
    with open(os.path.join(ROOT, page)) as f:
        text = f.read()
    return text.split(heading, 1)[1].split("```python\n", 1)[1].split("```", 1)[0]


def test_the_readme_python_block_runs_as_written(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)  # its paths are the repository's
    exec(compile(python_block("README.md", "### Python"), "README.md", "exec"), {})
    printed = capsys.readouterr().out.split()
    assert printed[0] == "reached_end" and printed[-1] == "True"


def test_the_tutorial_python_block_runs_and_prints_what_the_page_says(capsys, monkeypatch):
    monkeypatch.chdir(ROOT)
    exec(compile(python_block("docs/tutorial.md", "## 8. The same from Python"), "docs/tutorial.md", "exec"), {})
    points, max_x1 = capsys.readouterr().out.split()
    # The page's numbers: the isola's 61 points and the simulation's 2.00 (2.00147 in section 6).
    assert int(points) == 61 and float(max_x1) == pytest.approx(2.00147, abs=5e-6)
