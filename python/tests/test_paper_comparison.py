"""The paper-comparison tables: frequencies as omega / omega_1B of each model, the resonance as the
limit point of most negative leading-edge extreme, births and merges from the tracking extrema;
limit points named as `hbtrack plot` names them."""
import re

from conftest import DUFFING

import hbtrack
from hbtrack import branch_figures
from hbtrack import paper_comparison as pc
from hbtrack.plots import plt
from hbtrack.special_points import limit_point_label

PAPER = {"table2_rad_s": {"1B": 2000.0, "2B": 6000.0, "1T": 10000.0},
         "fig3": {"limit_points": 4, "resonance": "LP3", "min_le_m": -1.42e-3, "min_te_m": -0.89e-3},
         "table3_births": [{"family": "I1", "omega": 2200.0, "amplitude": 4.5}],
         "table4_merges": [{"family": "I2", "omega": 2100.0, "amplitude": 50.0}]}


def test_the_resonance_is_the_limit_point_reaching_furthest_in():
    nfrc = {"special_points": [{"type": "LP", "omega": 2300.0, "min_le": -0.5e-3, "min_te": -0.3e-3},
                               {"type": "NS", "omega": 2250.0, "min_le": -2e-3, "min_te": -1e-3},
                               {"type": "LP", "omega": 2200.0, "min_le": -1.1e-3, "min_te": -0.9e-3}]}
    rows = pc.nfrc_table(PAPER, nfrc, 2300.0, "model")
    # Numbered in omega order (the lower-frequency LP is LP1, though listed second).
    assert "| LP1 | | 2200.00 | 0.9565 | -1.100 | -0.900 |" in rows
    assert any(r.startswith("| resonance (LP1) | 2 | 2200.00") for r in rows)  # the NS point is no LP
    assert rows[-1] == "| paper, resonance (LP3) | 4 | | | -1.420 | -0.890 |"


def test_births_and_merges_use_each_models_own_first_bending_frequency():
    entry = {"extrema": [{"type": "max", "value": 17.0, "omega": 2400.0}, {"type": "min", "value": 5.0, "omega": 2300.0}]}
    rows = pc.events_table(PAPER, entry, 2300.0, 2000.0)
    assert "| birth | this model | 2300.00 | 1.0000 | 5.00 |" in rows
    assert "| birth I1 | paper | 2200.00 | 1.1000 | 4.50 |" in rows
    assert "| merge | this model | 2400.00 | 1.0435 | 17.00 |" in rows
    assert rows.index("| merge I2 | paper | 2100.00 | 1.0500 | 50.00 |") > rows.index("| merge | this model | 2400.00 | 1.0435 | 17.00 |")


def test_tables_and_the_nfrc_figure_name_the_limit_points_alike(tmp_path):
    # Duffing swept upward meets its upper fold first (the hardening branch bends right), then
    # turns back to the lower one: summary.json lists the folds from high to low omega, as on
    # rotor 67. Its output doubled as the le and te the tables read.
    with open(DUFFING) as f:
        text = f.read().replace('name = "x"', 'name = "le"') + '\n[[outputs]]\nname = "te"\ndof = "x"\n'
    case = tmp_path / "duffing_down.toml"
    case.write_text(text)
    nfrc = hbtrack.frc(hbtrack.load_case(str(case)))
    listed = [p["omega"] for p in nfrc["special_points"] if p["type"] == "LP"]
    assert len(listed) == 2 and listed[0] > listed[1], listed  # else this test tells the orders apart no more

    tabled = {}
    for row in pc.nfrc_table(PAPER, nfrc, 1.0, "model"):
        if m := re.match(r"\| (LP\d+) \| \| ([\d.]+) \|", row):
            tabled[m.group(1)] = float(m.group(2))
    figure = branch_figures.nfrc_figure(nfrc, zoom=None)
    drawn = {}
    for ax in figure.get_axes():
        for t in ax.texts:
            for name in t.get_text().split(", "):
                if name.startswith("LP"):
                    drawn[name] = t.xy[0]
    plt.close(figure)
    assert sorted(tabled) == sorted(drawn) == ["LP1", "LP2"]
    for name, omega in tabled.items():
        assert abs(drawn[name] - omega) <= 0.005, (name, drawn, tabled)  # the table prints omega to 2 decimals
    # A tracking result written before lp_order, started with `track --lp 1` (then the first
    # listed, the higher omega), is LP2; since then --lp 1 and limit_point(nfrc, 1) are LP1.
    assert limit_point_label(nfrc["special_points"], 1) == "LP2" and tabled["LP2"] > tabled["LP1"]
    assert limit_point_label(nfrc["special_points"], 1, "omega") == "LP1"
    assert hbtrack.limit_point(nfrc, 1)[0] == min(listed) and hbtrack.limit_point(nfrc, 2)[0] == max(listed)
    track = hbtrack.track(hbtrack.load_case(str(case)), nfrc, lp=1, param="amplitude", range=(0.1, 2.0))
    assert track["summary"]["options"]["tracking"]["lp_order"] == "omega"
    assert abs(track["branch"]["omega"][0] - min(listed)) < 1e-9 * min(listed)  # the curve starts at LP1
