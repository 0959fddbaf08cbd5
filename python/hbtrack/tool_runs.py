"""`hbtrack sweep` and `hbtrack study` from Python. Both are many runs written to a folder (each
task a child process writing its own result folder, resumable by running the same command
again, spread over local workers or MPI ranks), so Python runs the command-line tool itself, with
the same recipe, and returns the folder read back (:func:`hbtrack.read_result`).

The tool is found as: the ``HBTRACK_CLI`` environment variable; the build tree's ``hbtrack``
beside ``build/python``; the installed ``bin/hbtrack`` of the prefix holding this package; or
``hbtrack`` on the PATH.
"""
import os
import shutil
import signal
import subprocess

import numpy as np

from .results import read_result
from .settings import settings_overrides


def tool_path():
    """Where the ``hbtrack`` command-line tool is (see the module's docstring for the order).

    Parameters
    ----------
    None

    Returns
    -------
    str
        The executable's path.

    Raises
    ------
    RuntimeError
        When none of the places holds it.

    Examples
    --------
    >>> tool_path()
    '/work/hbtrack/build/hbtrack'
    """
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [os.environ.get("HBTRACK_CLI", ""),
                  os.path.join(here, "..", "..", "hbtrack"),                    # build/python/hbtrack -> build/hbtrack
                  os.path.join(here, "..", "..", "..", "..", "bin", "hbtrack")]  # P/lib/pythonX.Y/site-packages/hbtrack -> P/bin
    for path in candidates:
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.normpath(path)
    found = shutil.which("hbtrack")
    if found:
        return found
    raise RuntimeError("the hbtrack command-line tool was not found (set HBTRACK_CLI to its path, or put it on the PATH; "
                       "docs/install.md)")


def _case_file(case, caller):
    """The case file a folder run reads: a path, not a Case (the tool reads the file itself)."""
    if isinstance(case, (str, os.PathLike)):
        path = os.fspath(case)
        if not os.path.isfile(path):
            raise ValueError(f"case: {path}: no such file")
        return path
    raise TypeError(f"case: {caller} runs the command-line tool on a case file: give its path (settings for this run as "
                    f"keywords, e.g. set={{...}}), not a {type(case).__name__}")


def _run_as_group(args, quiet):
    """Runs ARGS in a process group of its own. On KeyboardInterrupt (or any exception) the whole
    group, the tool and its task processes, gets SIGTERM (they stop at their next point and write
    their summaries), then SIGKILL if still there after 10 s: subprocess.run killed the tool
    alone, and its tasks went on computing."""
    with subprocess.Popen(args, stderr=subprocess.PIPE if quiet else None, text=True, start_new_session=True) as process:
        try:
            _, err = process.communicate()
        except BaseException:
            _end_group(process)
            raise
        return subprocess.CompletedProcess(args, process.returncode, None, err)


def _end_group(process):
    for sig, wait_s in ((signal.SIGTERM, 10.0), (signal.SIGKILL, None)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            break
        try:
            process.wait(timeout=wait_s)
        except subprocess.TimeoutExpired:
            continue
        # The tool ended: any task it left is still in the group.
        try:
            os.killpg(process.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        break
    process.wait()


def _run_tool(verb, case_path, output, options, settings, quiet):
    """Runs `hbtrack VERB CASE OPTIONS --set ...` (OPTIONS name the folder OUTPUT); returns the
    folder read back."""
    args = [tool_path(), verb, case_path, *options]
    for override in settings_overrides(**settings):
        args += ["--set", override]
    if quiet:
        args.append("-q")
    done = _run_as_group(args, quiet)
    if done.returncode == 2:  # bad input: nothing was computed
        raise ValueError((done.stderr or "").strip() or f"hbtrack {verb}: bad input")
    if done.returncode not in (0, 1):
        raise RuntimeError(f"hbtrack {verb} ended with exit code {done.returncode}: {(done.stderr or '').strip()}")
    # Exit 1: the run ended early (a task failed, a check did not pass); its folder says what.
    return read_result(os.fspath(output))


def sweep(case, output, *, grid=None, samples=None, track=None, jobs=0, quiet=True, **settings):
    """NFRCs (and optionally limit-point tracking) over a grid of parameter values (``hbtrack sweep``).

    Parameters
    ----------
    case : str or os.PathLike
        The case file.
    output : str or os.PathLike
        The sweep's folder (new, empty, or holding this same sweep: finished tasks are kept).
    grid : dict, optional
        {NAME: values}: a named parameter and its values (a list of numbers, or a string as
        ``--values`` takes it: "A,B,C" or "LO:HI:count=N"); the tasks are the cartesian
        product, the first name varying slowest.
    samples : str or os.PathLike, optional
        A CSV table instead of `grid`: a header of parameter names, one task per row.
    track : str, optional
        "PARAM" or "PARAM:LO:HI": every limit point of each NFRC followed in PARAM.
    jobs : int, optional
        Tasks side by side on this machine (0: one per core).
    quiet : bool, optional
        True (default): the tool's progress lines are not printed.
    **settings : dict, optional
        The case's settings for every task, as :func:`hbtrack.frc` takes them.

    Returns
    -------
    dict
        The folder read back: ``kind`` = "sweep", ``summary`` and the merged table under
        ``sweep`` ({column: array} of sweep.csv: task, the parameters, status, the peaks, the
        limit points).

    Raises
    ------
    ValueError
        Bad input, with the tool's one-line message.

    Examples
    --------
    >>> table = hbtrack.sweep("examples/duffing.toml", "out/sweep", grid={"amplitude": [0.5, 1.0, 2.0]}, jobs=2)
    >>> table["sweep"]["amplitude"], table["sweep"]["peak_max_x"]
    """
    options = ["-o", os.fspath(output)]
    for name, values in (grid or {}).items():
        text = values if isinstance(values, str) else ",".join(repr(float(v)) for v in values)
        options += ["--param", str(name), "--values", text]
    if samples is not None:
        options += ["--samples", os.fspath(samples)]
    if track is not None:
        options += ["--track", str(track)]
    options += ["--jobs", str(int(jobs))]
    result = _run_tool("sweep", _case_file(case, "sweep"), output, options, settings, quiet)
    if os.path.exists(os.path.join(os.fspath(output), "sweep.csv")):
        from .sweep_figures import read_sweep  # its reader keeps the text columns (status) as text

        result["sweep"] = {name: _numbers_or_text(values) for name, values in read_sweep(os.fspath(output))[1].items()}
    return result


def _numbers_or_text(values):
    """A sweep.csv column as a float array (blank cells: NaN), or as its texts (status)."""
    try:
        return np.array([float(v) if v != "" else np.nan for v in values])
    except ValueError:
        return list(values)


def study(case, output, *, jobs=0, only=None, resume=False, quiet=True, **settings):
    """The whole study of a case with a [study] section (``hbtrack study``): the NFRC, limit-point
    tracking, isolated branches, their checks, time integration and the figures.

    Parameters
    ----------
    case : str or os.PathLike
        The case file (with its [study] section: docs/study.md).
    output : str or os.PathLike
        The study's folder.
    jobs : int, optional
        Steps side by side on this machine (0: one per core).
    only : list of str, optional
        Track only these parameters of [study] (``--only``).
    resume : bool, optional
        Go on with the stopped study in `output`, keeping its finished steps (``--resume``; same
        case, settings and `only`).
    quiet : bool, optional
        True (default): the tool's progress lines are not printed.
    **settings : dict, optional
        The case's settings for every step, as :func:`hbtrack.frc` takes them.

    Returns
    -------
    dict
        The folder read back: ``kind`` = "study" and ``summary`` (the steps, their checks and
        the verdict, as summary.json).

    Raises
    ------
    ValueError
        Bad input, with the tool's one-line message.

    Examples
    --------
    >>> done = hbtrack.study("tests/data/blade_small_study.toml", "out/study", jobs=2)
    >>> done["summary"]["stop_reason"]
    """
    options = ["--resume" if resume else "-o", os.fspath(output), "--jobs", str(int(jobs))]
    for name in only or []:
        options += ["--only", str(name)]
    return _run_tool("study", _case_file(case, "study"), output, options, settings, quiet)
