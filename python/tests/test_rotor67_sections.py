"""The shipped rotor 67 section table is what scripts/derive-rotor67-sections.py derives from
NASA's published geometry (../shared/reference/rotor67/, when it is beside the repository), and
it reproduces NASA's points to 1e-6 m."""
import importlib.util
import os

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
NASA = os.path.join(ROOT, "..", "shared", "reference", "rotor67", "rotor67geometry.dat")
TABLE = os.path.join(ROOT, "data", "rotor67", "sections.csv")
FOOT = 0.3048

pytestmark = pytest.mark.skipif(not os.path.exists(NASA), reason="NASA's rotor 67 file is not beside the repository")


def derive_module():
    spec = importlib.util.spec_from_file_location("derive", os.path.join(ROOT, "scripts", "derive-rotor67-sections.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_shipped_table_is_rederived_byte_for_byte(tmp_path):
    out = tmp_path / "sections.csv"
    assert derive_module().main(["derive", NASA, str(out)]) == 0
    assert out.read_text() == open(TABLE).read()


def test_the_table_reproduces_nasas_points_to_a_micrometre():
    surfaces, (jm, ns, nb, jle, jte) = derive_module().read_nasa_geometry(NASA)
    rows = [line.split(",") for line in open(TABLE) if line[0].isdigit()]
    assert len(rows) == ns * (jte - jle + 1)
    worst = 0.0
    for row in rows:
        s, p = int(row[0]), int(row[1])
        nasa = surfaces[s - 1]
        j = jle - 2 + p
        axial, radius, rtheta, thickness = (float(v) for v in row[2:])
        for mine, theirs in ((axial, nasa["axial"][j]), (radius, nasa["radius"][j]),
                             (rtheta, nasa["rtheta"][j]), (rtheta - thickness, nasa["rtheta"][j] - nasa["thickness"][j])):
            worst = max(worst, abs(mine - theirs * FOOT))
    assert worst < 1e-6
