"""torus_against_simulation and python/compare_torus.py on the NLTVA's band: the torus row at a
simulation's omega against that simulation (extremes, omega2, no half-frequency lines), and the
one-line errors of an omega without a row."""
import os
import subprocess
import sys

import pytest

from hbtrack.results import read_result
from hbtrack.torus_comparison import torus_against_simulation

from conftest import NLTVA, ROOT, run_cli

OMEGA = "1.14"  # inside the NLTVA's band at A = 0.12 (NS points 1.10958 and 1.22470)


@pytest.fixture(scope="module")
def band(results_dir):
    nfrc, torus, sim = (str(results_dir / f"nltva_comparison_{name}") for name in ("frc", "torus", "sim"))
    run_cli("frc", NLTVA, "-o", nfrc)
    # The torus run ends on the range's end, so it has a row at exactly omega = 1.14.
    run_cli("torus", NLTVA, "--from", nfrc, "--ns", "1", "--range", f"1.0:{OMEGA}", "-o", torus)
    # From rest, as the C++ test (TorusCli.EnvelopeAgreesWithTimeIntegrationInsideTheBand): 2000
    # periods, the last 400 recorded; quasi-periodic, so simulate exits 1 (no periodic state).
    run_cli("simulate", NLTVA, "--omega", OMEGA, "--method", "dopri5", "--max-periods", "2000", "--record-periods", "400", "-o", sim,
            check=False)
    return read_result(torus), read_result(sim), torus, sim


def test_the_torus_row_agrees_with_the_simulation(band):
    torus, sim, _, _ = band
    c = torus_against_simulation(torus, sim)
    assert c["omega"] == pytest.approx(float(OMEGA), rel=1e-15)
    assert [(e["name"], e["extreme"]) for e in c["extremes"]] == [("x1", "max"), ("x1", "min"), ("x2", "max"), ("x2", "min")]
    # The C++ test's bound and its reason: measured within 0.03 % (the torus' H2 truncation and a
    # finite window of samples), 0.2 % leaves room, not more.
    for e in c["extremes"]:
        assert abs(e["difference"]) < 2e-3, e
    # omega2 from the record's sidebands: 400 periods resolve omega / 400; an isolated peak is
    # placed to about 1e-3 of that (test_modulation_lines.py) and the torus' H2 = 4 truncation
    # moves omega2 by less (measured: 1.2e-4 of the resolution apart), so 1 % of the resolution.
    resolution = float(OMEGA) / 400
    assert c["omega2_simulated"] == pytest.approx(c["omega2"], abs=0.01 * resolution)
    assert c["half_lines"] == []  # a torus: no line at omega +- (j + 1/2) omega2


def test_compare_torus_prints_the_table_and_refuses_an_omega_without_a_row(band, results_dir):
    _, _, torus, sim = band
    script = os.path.join(ROOT, "python", "compare_torus.py")
    ok = subprocess.run([sys.executable, script, torus, sim], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    lines = ok.stdout.splitlines()
    assert lines[0].startswith("| omega (rad/s) | output | simulate | torus | difference |") and len(lines) == 2 + 4
    assert lines[2].startswith("| 1.140 | max x1 |") and lines[2].endswith("| none |")
    other = str(results_dir / "nltva_comparison_sim_other")
    run_cli("simulate", NLTVA, "--omega", "1.15", "--max-periods", "10", "-o", other, check=False)
    bad = subprocess.run([sys.executable, script, torus, other], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stdout == ""
    assert bad.stderr.strip().startswith(f"compare_torus.py: {other}: omega: the torus has no row at the simulation's omega = 1.15")


def test_a_torus_without_outputs_is_refused_in_one_line(band):
    torus, sim, _, _ = band
    bare = dict(torus, branch={k: v for k, v in torus["branch"].items() if not k.startswith(("max_", "min_"))})
    with pytest.raises(ValueError, match="names: no output to compare"):
        torus_against_simulation(bare, sim)
