"""Progress of `frc`: the callback of hbtrack.frc, and the CLI's line on a terminal (and its
silence in a log)."""
import os
import pty
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


def test_cli_progress_line_on_a_terminal_only(tmp_path):
    # stderr a pseudo-terminal: the line carries the percentage of the range and ends at 100 %.
    leader, follower = pty.openpty()
    done = subprocess.run([cli_path(), "frc", DUFFING, "-o", str(tmp_path / "tty")], stdout=subprocess.DEVNULL,
                          stderr=follower, timeout=120)
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
    assert done.returncode == 0
    updates = text.decode().split("\r")
    assert len(updates) > 20, text
    percentages = [float(u.split("%")[0].split()[-1]) for u in updates if "%" in u]
    assert percentages[-1] == 100.0 and percentages == sorted(percentages), percentages
    assert any(" left" in u for u in updates), text
    # stderr a file (a log): no progress at all.
    logged = subprocess.run([cli_path(), "frc", DUFFING, "-o", str(tmp_path / "log")], capture_output=True, text=True, timeout=120)
    assert logged.returncode == 0 and "%" not in logged.stderr, logged.stderr
