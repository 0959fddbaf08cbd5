"""The paper-comparison tables: frequencies as omega / omega_1B of each model, the resonance as the
limit point of most negative leading-edge extreme, births and merges from the tracking extrema."""
from hbtrack import paper_comparison as pc

PAPER = {"table2_rad_s": {"1B": 2000.0, "2B": 6000.0, "1T": 10000.0},
         "fig3": {"limit_points": 4, "resonance": "LP3", "min_le_m": -1.42e-3, "min_te_m": -0.89e-3},
         "table3_births": [{"family": "I1", "omega": 2200.0, "amplitude": 4.5}],
         "table4_merges": [{"family": "I2", "omega": 2100.0, "amplitude": 50.0}]}


def test_the_resonance_is_the_limit_point_reaching_furthest_in():
    nfrc = {"special_points": [{"type": "LP", "omega": 2300.0, "min_le": -0.5e-3, "min_te": -0.3e-3},
                               {"type": "NS", "omega": 2250.0, "min_le": -2e-3, "min_te": -1e-3},
                               {"type": "LP", "omega": 2200.0, "min_le": -1.1e-3, "min_te": -0.9e-3}]}
    rows = pc.nfrc_table(PAPER, nfrc, 2300.0, "model")
    assert "| LP2 | | 2200.00 | 0.9565 | -1.100 | -0.900 |" in rows
    assert any(r.startswith("| resonance (LP2) | 2 | 2200.00") for r in rows)  # the NS point is no LP
    assert rows[-1] == "| paper, resonance (LP3) | 4 | | | -1.420 | -0.890 |"


def test_births_and_merges_use_each_models_own_first_bending_frequency():
    entry = {"extrema": [{"type": "max", "value": 17.0, "omega": 2400.0}, {"type": "min", "value": 5.0, "omega": 2300.0}]}
    rows = pc.events_table(PAPER, entry, 2300.0, 2000.0)
    assert "| birth | this model | 2300.00 | 1.0000 | 5.00 |" in rows
    assert "| birth I1 | paper | 2200.00 | 1.1000 | 4.50 |" in rows
    assert "| merge | this model | 2400.00 | 1.0435 | 17.00 |" in rows
    assert rows.index("| merge I2 | paper | 2100.00 | 1.0500 | 50.00 |") > rows.index("| merge | this model | 2400.00 | 1.0435 | 17.00 |")
