"""The torus branch from Python (hbtrack.torus(..., ns=K)) is the CLI's `torus --ns K`: same
columns, same numbers (1e-12: test_same_as_cli.py says why), read_result reads its folder, and its
bad keywords fail with the CLI's messages."""
import pytest

import hbtrack
from hbtrack.results import read_result

from conftest import NLTVA, assert_same_columns, run_cli


@pytest.fixture(scope="module")
def nltva_frc(results_dir):
    folder = str(results_dir / "nltva_frc_for_torus")
    run_cli("frc", NLTVA, "-o", folder)
    return read_result(folder)


def test_nltva_torus_matches_cli(results_dir, nltva_frc):
    folder = str(results_dir / "nltva_torus")
    run_cli("torus", NLTVA, "--from", nltva_frc["folder"], "--ns", "1", "--range", "1.0:1.3", "-o", folder)
    cli = read_result(folder)
    api = hbtrack.torus(hbtrack.load_case(NLTVA), nltva_frc, ns=1, range=(1.0, 1.3))
    assert cli["kind"] == api["kind"] == "torus"
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_columns(api["dof_states"], cli["dof_states"])
    assert list(api["branch"])[:3] == ["omega", "omega2", "size"]
    assert api["summary"]["stop_reason"] == cli["summary"]["stop_reason"] == "reached_ns_point"
    assert api["summary"]["options"]["torus"]["ns"] == 1
    assert api["branch"]["size"][0] == 0.0  # row 0: the NS point


def test_bad_keywords_name_the_keyword(nltva_frc):
    case = hbtrack.load_case(NLTVA)
    with pytest.raises(ValueError, match="ns: 3 is beyond the 2 NS points"):
        hbtrack.torus(case, nltva_frc, ns=3, range=(1.0, 1.3))
    with pytest.raises(ValueError, match="range: must contain the NS point's omega"):
        hbtrack.torus(case, nltva_frc, ns=1, range=(1.2, 1.3))
    with pytest.raises(ValueError, match=r"harmonics: expected two integers \(A, B\), got 5"):
        hbtrack.torus(case, nltva_frc, ns=1, range=(1.0, 1.3), harmonics=5)
    with pytest.raises(ValueError, match="samples: must be N1 >= 2 H1 \\+ 1 = 11 and N2 >= 2 H2 \\+ 1 = 9"):
        hbtrack.torus(case, nltva_frc, ns=1, range=(1.0, 1.3), samples=(64, 5))


def test_hbtrack_plot_draws_a_torus_folder_over_its_nfrc(results_dir, nltva_frc):
    from hbtrack.plot import figures_for
    folder = str(results_dir / "nltva_torus_for_plot")
    run_cli("torus", NLTVA, "--from", nltva_frc["folder"], "--ns", "1", "--range", "1.0:1.3", "-o", folder)
    figures = figures_for(read_result(folder))
    assert list(figures) == ["torus"]
    axes = figures["torus"].get_axes()
    assert len(axes) == 2  # x1, x2
    labels = [t.get_text() for t in axes[0].get_legend().get_texts()]
    assert "NS (Neimark-Sacker)" in labels and "LP (fold)" in labels and "torus: max over the torus" in labels and "NFRC, unstable" in labels


def test_torus_figure_draws_the_least_values_when_asked(results_dir, nltva_frc):
    # extreme="min": the torus' min column, the NFRC's min, and negative axes (rotor 67's tips are
    # stopped above by the casing: their min is the motion that changes).
    import numpy as np
    from hbtrack.torus_figures import torus_figure
    folder = str(results_dir / "nltva_torus_for_min")
    run_cli("torus", NLTVA, "--from", nltva_frc["folder"], "--ns", "1", "--range", "1.0:1.3", "--harmonics", "5,2", "-o", folder)
    torus = read_result(folder)
    axes = torus_figure(torus, nfrc=nltva_frc, extreme="min").get_axes()
    drawn = [line for line in axes[1].get_lines() if line.get_label() == "torus: min over the torus"]
    assert len(drawn) == 1
    np.testing.assert_array_equal(drawn[0].get_ydata(), torus["branch"]["min_x2"])
    assert axes[1].get_ylim()[1] == 0.0 and axes[1].get_ylim()[0] < torus["branch"]["min_x2"].min()
    assert axes[1].get_ylabel().startswith("min x2")
    with pytest.raises(ValueError, match="extreme must be 'max' or 'min'"):
        torus_figure(torus, extreme="mean")


def test_study_draws_its_torus_over_the_nominal_nfrc(tmp_path):
    # [study] torus = true: the study's torus_ns1/ drawn as `hbtrack plot` draws a torus folder,
    # into figures/torus_ns1.png, which the summary lists (docs/study.md); on the least grid
    # alias-free for the cubic springs, a third of the default's time.
    from hbtrack.study_figures import study_figures
    with open(NLTVA) as f:
        (tmp_path / "case.toml").write_text(f.read() + "\n[study]\ntorus = { samples = [32, 17] }\nsimulate_periods = 0\n")
    out = str(tmp_path / "out")
    run_cli("study", str(tmp_path / "case.toml"), "--jobs", "1", "-o", out)
    summary = read_result(out)["summary"]
    assert "figures/torus_ns1.png" in summary["figures"]
    figures = study_figures(out)
    torus = read_result(out + "/torus_ns1")
    lines = {line.get_label(): line for line in figures["torus_ns1"].get_axes()[1].get_lines()}
    assert list(lines["torus: max over the torus"].get_ydata()) == list(torus["branch"]["max_x2"])
    assert "NFRC, unstable" in lines
