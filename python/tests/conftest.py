"""Shared fixtures: the CLI binary, runs of it into temporary folders, and the API's results of
the same runs, each computed once per session (the whole pytest run must stay near 30 s)."""
import os
import subprocess

import numpy as np
import pytest

import hbtrack
from hbtrack.results import read_result

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
DUFFING = os.path.join(ROOT, "examples", "duffing.toml")
NLTVA = os.path.join(ROOT, "examples", "nltva.toml")
BLADE = os.path.join(ROOT, "examples", "blade", "nominal.toml")
# The blade's nominal NFRC takes ~50 s. Three harmonics, 64 samples and 2100 down to 2010 rad/s
# (down the resonance that friction bends below the linear 1B, the leading edge beyond the 0.4 mm
# clearance from 2041 on) take ~1 s and still exercise the 9 tip contacts, Lanczos filtering and
# Hill's method on 39 dofs.
BLADE_CHEAP = {"harmonic_balance.harmonics": 3, "harmonic_balance.samples": 64,
               "continuation.omega_start": 2100.0, "continuation.omega_end": 2010.0}
BLADE_CLEARANCE = 4e-4  # m, examples/blade/nominal.toml


def cli_path():
    path = os.environ.get("HBTRACK_CLI", os.path.join(ROOT, "build", "hbtrack"))
    if not os.path.exists(path):
        pytest.fail(f"the hbtrack binary is not at {path}: build it, or set HBTRACK_CLI")
    return path


def assert_same_columns(api, cli, relative=1e-12):
    """The same columns in the same order, each non-empty and equal to `relative` (the API and the
    CLI run the same library code: test_same_as_cli.py says why 1e-12)."""
    assert list(api) == list(cli), "column names differ"
    for name in cli:
        assert len(api[name]) == len(cli[name]) > 0, name
        np.testing.assert_allclose(api[name], cli[name], rtol=relative, atol=0, err_msg=name)


def run_cli(*args, check=True):
    """Runs `hbtrack ARGS -q`; returns the completed process."""
    done = subprocess.run([cli_path(), *args, "-q"], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"hbtrack {' '.join(args)} exited {done.returncode}: {done.stderr}")
    return done


def set_flags(overrides):
    flags = []
    for text in hbtrack.cases.override_strings(overrides):
        flags += ["--set", text]
    return flags


@pytest.fixture(scope="session")
def results_dir(tmp_path_factory):
    return tmp_path_factory.mktemp("cli")


@pytest.fixture(scope="session")
def duffing_case():
    return hbtrack.load_case(DUFFING)


@pytest.fixture(scope="session")
def duffing_frc(duffing_case):
    return hbtrack.frc(duffing_case)


@pytest.fixture(scope="session")
def duffing_frc_cli(results_dir):
    folder = str(results_dir / "duffing")
    run_cli("frc", DUFFING, "-o", folder)
    return read_result(folder)


@pytest.fixture(scope="session")
def duffing_track(duffing_case, duffing_frc):
    return hbtrack.track(duffing_case, duffing_frc, lp=1, param="amplitude", range=(0.1, 2.0))


@pytest.fixture(scope="session")
def duffing_track_cli(results_dir, duffing_frc_cli):
    folder = str(results_dir / "duffing_lp1")
    run_cli("track", DUFFING, "--from", duffing_frc_cli["folder"], "--lp", "1", "--param", "amplitude",
            "--range", "0.1:2", "-o", folder)
    return read_result(folder)


@pytest.fixture(scope="session")
def duffing_isolas_cli(results_dir, duffing_track_cli):
    folder = str(results_dir / "duffing_isolas")
    run_cli("isolas", DUFFING, "--from", duffing_track_cli["folder"], "--at", "1.5", "-o", folder)
    return read_result(folder)


@pytest.fixture(scope="session")
def duffing_simulate_cli(results_dir, duffing_frc_cli):
    folder = str(results_dir / "duffing_simulate")
    run_cli("simulate", DUFFING, "--from", duffing_frc_cli["folder"], "--point", "20", "--max-periods", "200", "-o", folder)
    return read_result(folder)
