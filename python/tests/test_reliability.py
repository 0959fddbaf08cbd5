"""Issue 24 ("Reliability, round 2"): the module when the interpreter exits while a thread
computes, deep nesting, and what case_from_arrays writes."""
import os
import signal
import subprocess
import sys
import textwrap
import time
import tomllib

import numpy as np
import pytest

import hbtrack
from hbtrack.cases import toml_key

from conftest import DUFFING

# A Duffing NFRC of thousands of points (several seconds): still running when the script ends.
SLOW_THREAD = f"""
    import threading, time, hbtrack
    case = hbtrack.load_case({DUFFING!r}, set={{"continuation.step": 0.0002, "continuation.step_max": 0.0002,
                                                "continuation.max_points": 100000}})
    started = threading.Event()
    def work():
        started.set()
        hbtrack.frc(case)
    threading.Thread(target=work, daemon=True).start()
    started.wait()
    print("started", flush=True)
    time.sleep(0.3)
    print("main done", flush=True)
"""


def python_process(code):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(p for p in sys.path if p))
    return subprocess.Popen([sys.executable, "-c", textwrap.dedent(code)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env)


def test_interpreter_exit_while_a_daemon_thread_computes():
    # Was exit 134: "terminate called without an active exception".
    process = python_process(SLOW_THREAD)
    out, err = process.communicate(timeout=120)
    assert "main done" in out, err
    assert process.returncode == 0, err
    assert "terminate called" not in err


def test_ctrl_c_while_a_worker_thread_computes():
    # Ctrl-C reaches the main thread (KeyboardInterrupt), which exits while the worker computes.
    process = python_process(SLOW_THREAD.replace("time.sleep(0.3)", "time.sleep(60)"))
    assert process.stdout.readline().strip() == "started"
    time.sleep(0.2)
    deadline = time.time() + 60
    while time.time() < deadline and process.poll() is None:
        process.send_signal(signal.SIGINT)
        try:
            out, err = process.communicate(timeout=5)
            break
        except subprocess.TimeoutExpired:
            continue
    else:
        out, err = process.communicate(timeout=60)
    assert process.returncode in (1, -signal.SIGINT, 130), err  # KeyboardInterrupt, not an abort (-6)
    assert "terminate called" not in err
    assert "KeyboardInterrupt" in err


def test_deep_nesting_in_an_override_is_a_value_error():
    # Was a segfault (exit 139) in the TOML parser.
    with pytest.raises(ValueError, match="nested deeper than 64"):
        hbtrack.load_case(DUFFING, set=["amplitude=" + "[" * 20000])
    # A dict key of 20 000 brackets was written unquoted into the TOML text: the same crash. Now
    # it is a quoted key, so the case loads or is refused with a ValueError, never a crash.
    try:
        hbtrack.case_from_arrays(np.eye(1), np.eye(1), ["x"], parameters={"[" * 20000: 1.0},
                                 continuation={"omega_start": 0.5, "omega_end": 1.6})
    except ValueError:
        pass


def test_case_from_arrays_refuses_complex_arrays():
    # The imaginary part was dropped.
    with pytest.raises(ValueError, match="K: complex values"):
        hbtrack.case_from_arrays(np.eye(1), np.eye(1) * (1 + 0.1j), ["x"], continuation={"omega_start": 0.5, "omega_end": 1.6})


def test_dict_keys_are_quoted_when_they_are_not_bare_keys():
    # A key holding '=' and a newline was written as is and rewrote the document around it.
    for key in ["amplitude", "a-b_c9", "a = 1\n[model]", 'say "hi"', ""]:
        assert tomllib.loads(f"{toml_key(key)} = 1\n") == {key: 1}
    assert toml_key("amplitude") == "amplitude"


def test_wrong_result_kinds_are_value_errors():
    # Was KeyError.
    case = hbtrack.load_case(DUFFING)
    with pytest.raises(ValueError, match="start: expected an frc result"):
        hbtrack.track(case, {"summary": {}}, lp=1, param="amplitude", range=(0.5, 2))
    with pytest.raises(ValueError, match="tracks: expected track results"):
        hbtrack.isolas(case, [{"summary": {"options": {}}}], at=1.0)


def test_isolas_at_nan_is_a_value_error():
    """Issue 39: at=nan ran and returned "completed" with nothing found; the CLI refuses --at nan."""
    case = hbtrack.load_case(DUFFING)
    for at in (float("nan"), float("inf")):
        with pytest.raises(ValueError, match="at: must be a finite number"):
            hbtrack.isolas(case, {}, at=at)


def test_keyboard_interrupt_in_sweep_ends_its_task_processes(tmp_path):
    """Issue 39: after a KeyboardInterrupt, hbtrack.sweep had killed the tool alone; its task
    processes went on computing."""
    folder = tmp_path / "sweep"
    script = textwrap.dedent(f"""
        import signal, hbtrack
        def stop(*_):
            raise KeyboardInterrupt
        signal.signal(signal.SIGALRM, stop)
        signal.setitimer(signal.ITIMER_REAL, 1.5)
        try:
            hbtrack.sweep({DUFFING!r}, {str(folder)!r}, grid={{"amplitude": [0.5, 1.0, 1.5, 2.0]}}, jobs=2,
                          set={{"continuation.step": 0.0002, "continuation.step_max": 0.0002, "continuation.max_points": 100000}})
            print("finished")
        except KeyboardInterrupt:
            print("interrupted")
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                          env={**os.environ, "PYTHONPATH": os.pathsep.join(sys.path)})
    assert done.stdout.strip() == "interrupted", done.stderr
    time.sleep(0.5)
    left = subprocess.run(["pgrep", "-f", str(folder)], capture_output=True, text=True).stdout.split()
    for pid in left:
        os.kill(int(pid), signal.SIGKILL)
    assert not left, "task processes still running after the KeyboardInterrupt"
