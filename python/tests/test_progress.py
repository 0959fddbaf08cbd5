"""Progress of `frc`: the callback of hbtrack.frc, and the CLI's line on a terminal (and its
plain lines in a log, none for a run shorter than their interval); `study` relaying its steps'
progress to its own line, or as plain lines in a log."""
import os
import pty
import re
import subprocess

import numpy as np
import pytest

import hbtrack

from conftest import DUFFING, cli_path


def test_progress_callback_sees_every_point_and_can_stop(duffing_case):
    seen = []
    full = hbtrack.frc(duffing_case, progress=lambda fraction, point, omega: seen.append((fraction, point, omega)))
    assert [p for _, p, _ in seen] == list(range(len(full["branch"]["omega"])))
    np.testing.assert_array_equal([o for _, _, o in seen], full["branch"]["omega"])
    fractions = np.array([f for f, _, _ in seen])
    assert fractions[0] == 0.0 and fractions[-1] == 1.0 and np.all((fractions >= 0) & (fractions <= 1))

    stopped = hbtrack.frc(duffing_case, progress=lambda fraction, point, omega: point < 4)
    assert stopped["summary"]["stop_reason"] == "stopped_by_callback"
    assert len(stopped["branch"]["omega"]) == 5

    def fails(*_):
        raise RuntimeError("from the callback")
    with pytest.raises(RuntimeError, match="from the callback"):
        hbtrack.frc(duffing_case, progress=fails)
    with pytest.raises(ValueError, match="progress"):
        hbtrack.frc(duffing_case, progress=3)


def run_on_a_terminal(*args, env=None):
    """`hbtrack ARGS` with stderr a pseudo-terminal: its exit code and the updates of its line,
    read as they come (a full terminal buffer would block a long run)."""
    leader, follower = pty.openpty()
    process = subprocess.Popen([cli_path(), *args], stdout=subprocess.DEVNULL, stderr=follower, env=env)
    os.close(follower)
    text = b""
    while True:
        try:
            chunk = os.read(leader, 65536)
        except OSError:  # EIO: nothing more to read from a closed pseudo-terminal
            break
        if not chunk:
            break
        text += chunk
    os.close(leader)
    return process.wait(timeout=300), text.decode().split("\r")


def test_cli_progress_line_on_a_terminal_only(tmp_path):
    # stderr a pseudo-terminal: the line carries the percentage of the range and ends at 100 %.
    code, updates = run_on_a_terminal("frc", DUFFING, "-o", str(tmp_path / "tty"))
    assert code == 0
    assert len(updates) > 20, updates
    percentages = [float(u.split("%")[0].split()[-1]) for u in updates if "%" in u]
    assert percentages[-1] == 100.0 and percentages == sorted(percentages), percentages
    assert any(" left" in u for u in updates), updates
    # stderr a file (a log), a run shorter than the interval between plain lines: no progress.
    quiet_env = {k: v for k, v in os.environ.items() if k != "HBTRACK_PROGRESS_INTERVAL"}
    logged = subprocess.run([cli_path(), "frc", DUFFING, "-o", str(tmp_path / "log")], capture_output=True, text=True, timeout=120, env=quiet_env)
    assert logged.returncode == 0 and "%" not in logged.stderr, logged.stderr


def test_track_progress_line_covers_the_parameter_range_on_a_terminal_only(duffing_frc_cli, tmp_path):
    # Both legs reach the ends of --range: the span of amplitudes seen grows to 100 %.
    track = ["track", DUFFING, "--from", duffing_frc_cli["folder"], "--lp", "1", "--param", "amplitude", "--range", "0.1:2"]
    code, updates = run_on_a_terminal(*track, "-o", str(tmp_path / "tty"))
    assert code == 0
    percentages = [float(u.split("%")[0].split()[-1]) for u in updates if "%" in u]
    assert len(percentages) > 10 and percentages[-1] == 100.0 and percentages == sorted(percentages), percentages
    assert all(" amplitude " in u for u in updates if "%" in u), updates
    assert any(" left" in u for u in updates), updates
    quiet_env = {k: v for k, v in os.environ.items() if k != "HBTRACK_PROGRESS_INTERVAL"}
    logged = subprocess.run([cli_path(), *track, "-o", str(tmp_path / "log")], capture_output=True, text=True, timeout=120, env=quiet_env)
    assert logged.returncode == 0 and "%" not in logged.stderr and "\r" not in logged.stderr, logged.stderr


def test_study_relays_its_steps_progress_on_a_terminal_only(tmp_path):
    # Duffing at a 50 times finer step (about 2800 points, a second or more per NFRC): the study
    # polls its steps' progress files 4 times a second, so each NFRC is seen running.
    case = tmp_path / "case.toml"
    with open(DUFFING) as f:
        case.write_text(f.read() + '\n[study]\ntrack = [ { parameter = "amplitude", range = [0.5, 2.0] } ]\n'
                                   'max_points = 40\nsimulate_periods = 0\n')
    args = ["study", str(case), "--set", "continuation.step=0.0004", "--set", "continuation.step_max=0.002", "--jobs", "1"]
    # No figures: they are not what is tested here, and would double the time.
    env = {**os.environ, "HBTRACK_PYTHON": "/bin/false"}
    code, updates = run_on_a_terminal(*args, "-o", str(tmp_path / "tty"), env=env)
    relayed = [u for u in updates if re.search(r"study:   nfrc \d+\.\d %", u)]
    assert relayed, updates
    percentages = [float(re.search(r"nfrc (\d+\.\d) %", u).group(1)) for u in relayed]
    assert percentages == sorted(percentages) and all(0 <= p <= 100 for p in percentages), percentages
    # In a log: the stage and step lines, and the steps' progress as plain lines at most every
    # HBTRACK_PROGRESS_INTERVAL seconds (5 by default; 0.1 here, so that the NFRC shows).
    log_env = {**env, "HBTRACK_PROGRESS_INTERVAL": "0.1"}
    logged = subprocess.run([cli_path(), *args, "-o", str(tmp_path / "log")], capture_output=True, text=True, timeout=300, env=log_env)
    assert logged.returncode == code, logged.stderr
    assert "\r" not in logged.stderr, logged.stderr
    logged_percentages = [float(p) for p in re.findall(r"^study:   nfrc (\d+\.\d) %", logged.stderr, re.M)]
    assert logged_percentages and logged_percentages == sorted(logged_percentages), logged.stderr
    assert "stage 1 of 8" in logged.stderr, logged.stderr
    # The same results either way, and no progress file left behind.
    for step in ("nfrc", "track_amplitude_lp1"):
        for name in ("branch.csv", "states.csv"):
            tty_file, log_file = tmp_path / "tty" / step / name, tmp_path / "log" / step / name
            assert tty_file.read_bytes() == log_file.read_bytes(), (step, name)
    assert not list((tmp_path / "tty").rglob("progress.txt"))


COUPLED = os.path.join(os.path.dirname(DUFFING), "coupled_duffing.toml")


def run_with_progress(name, case, nfrc, curve, progress):
    """One computation of each kind on the Duffing case (coupled Duffing for switch: a BP)."""
    if name == "continuation":
        return hbtrack.continuation(case, param="amplitude", omega=1.2, range=(0.05, 1.0), progress=progress)
    if name == "backbone":
        return hbtrack.backbone(case, range=(0.01, 1.0), progress=progress)
    if name == "track":
        return hbtrack.track(case, nfrc, lp=1, param="amplitude", range=(0.1, 2.0), progress=progress)
    if name == "isolas":
        return hbtrack.isolas(case, curve, at=1.5, progress=progress)
    if name == "simulate":
        return hbtrack.simulate(case, 1.2, max_periods=60, progress=progress)
    coupled = hbtrack.load_case(COUPLED)
    start = hbtrack.frc(coupled)
    bp = 1 + [p["type"] for p in start["special_points"]].index("BP")
    return hbtrack.switch(coupled, start, point=bp, progress=progress)


RUNS = ["continuation", "backbone", "track", "isolas", "switch", "simulate"]


@pytest.mark.parametrize("name", RUNS)
def test_every_computation_reports_progress_and_can_be_stopped(name, duffing_case, duffing_frc, duffing_track):
    seen = []
    full = run_with_progress(name, duffing_case, duffing_frc, duffing_track, lambda *args: seen.append(args))
    assert len(seen) > 5, seen
    points = [p for _, p, _ in seen]
    assert points == list(range(len(points)))  # every point once, in order, across legs and branches
    fractions = np.array([f for f, _, _ in seen])
    assert np.all((fractions >= 0) & (fractions <= 1)), fractions
    if name in ("continuation", "backbone", "track"):  # one range covered to its end, never stepping back
        assert np.all(np.diff(fractions) >= 0) and fractions[-1] == 1.0, fractions
    if name == "continuation":
        np.testing.assert_array_equal([v for _, _, v in seen], full["branch"]["amplitude"])
    if name == "simulate":  # the time at the end of each period, 2 pi / omega long
        np.testing.assert_allclose([t for _, _, t in seen], 2 * np.pi / 1.2 * (1 + np.arange(len(seen))), rtol=1e-12)

    calls = []

    def stop_after_three(fraction, point, value):
        calls.append(point)
        return point < 3
    stopped = run_with_progress(name, duffing_case, duffing_frc, duffing_track, stop_after_three)
    assert stopped["summary"]["stop_reason"] == "stopped_by_callback"
    assert calls == [0, 1, 2, 3]  # not called again once it said stop, on any leg or branch
