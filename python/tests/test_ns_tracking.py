"""NS tracking from Python (hbtrack.track(..., ns=K)) is the CLI's `track --ns K`: same columns,
same numbers (1e-12: test_same_as_cli.py says why), and its bad keywords fail with the CLI's
messages."""
import pytest

import hbtrack
from hbtrack import plots
from hbtrack.results import read_result

from conftest import DUFFING, NLTVA, assert_same_columns, run_cli
from test_same_as_cli import assert_same_special_points


@pytest.fixture(scope="module")
def nltva_frc_cli(results_dir):
    folder = str(results_dir / "nltva_frc_for_ns")
    run_cli("frc", NLTVA, "-o", folder)
    return read_result(folder)


@pytest.fixture(scope="module")
def nltva_ns_api(nltva_frc_cli):
    return hbtrack.track(hbtrack.load_case(NLTVA), nltva_frc_cli, ns=1, param="amplitude", range=(0.05, 0.35))


def test_nltva_ns_tracking_matches_cli(results_dir, nltva_frc_cli, nltva_ns_api):
    folder = str(results_dir / "nltva_ns1")
    run_cli("track", NLTVA, "--from", nltva_frc_cli["folder"], "--ns", "1", "--param", "amplitude", "--range", "0.05:0.35", "-o", folder)
    cli = read_result(folder)
    api = nltva_ns_api
    assert_same_columns(api["branch"], cli["branch"])
    assert_same_special_points(api["special_points"], cli["special_points"])
    assert "ns_frequency" in api["branch"]
    assert [sp["type"] for sp in api["special_points"]].count("resonance_1_1") == 2  # both ends on the fold curve
    assert api["summary"]["options"]["tracking"]["ns"] == 1
    assert api["summary"]["options"]["tracking"]["point"] == "NS"


def test_the_tracking_figure_names_the_ns_curve_and_marks_its_ends(nltva_frc_cli, nltva_ns_api):
    figure = plots.tracking_plane_figure(nltva_ns_api, validations=[nltva_frc_cli])
    axes = figure.get_axes()[0]
    labels = [t.get_text() for t in axes.get_legend().get_texts()]
    assert "NS point 1 tracked" in labels and "NSs of NFRCs" in labels
    assert "NS curve ends on a fold (NS frequency 0)" in labels
    assert axes.get_title() == "NS tracking"  # the start marker is in the legend


def test_bad_points_name_the_keyword(nltva_frc_cli, nltva_ns_api):
    case = hbtrack.load_case(NLTVA)
    with pytest.raises(ValueError, match="ns: 3 is beyond the 2 NS points"):
        hbtrack.track(case, nltva_frc_cli, ns=3, param="amplitude", range=(0.05, 0.35))
    with pytest.raises(ValueError, match="pd: the frc result has no PD points"):
        hbtrack.track(case, nltva_frc_cli, pd=1, param="amplitude", range=(0.05, 0.35))
    with pytest.raises(ValueError, match="give exactly one point to track, got lp, ns"):
        hbtrack.track(case, nltva_frc_cli, lp=1, ns=1, param="amplitude", range=(0.05, 0.35))
    with pytest.raises(ValueError, match="method: ns tracks on the bordered Hill pencil only"):
        hbtrack.track(case, nltva_frc_cli, ns=1, param="amplitude", range=(0.05, 0.35), method="extended")
    with pytest.raises(ValueError, match="tracks: a curve of NS points; isolas takes limit-point curves"):
        hbtrack.isolas(case, nltva_ns_api, at=0.13)
    duffing = hbtrack.load_case(DUFFING)
    with pytest.raises(ValueError, match="ns: the frc result has no NS points"):
        hbtrack.track(duffing, hbtrack.frc(duffing), ns=1, param="amplitude", range=(0.1, 2))
