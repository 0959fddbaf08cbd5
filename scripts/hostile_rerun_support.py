"""Running the CLI on hostile inputs and judging each outcome (scripts/hostile-rerun.sh).

Outcomes: ok, crash (a signal, an abort, a sanitizer report), hang (past its timeout), silent
(bad input accepted, or a wrong result), loss (an output half-written or replaced), alloc (a peak
RSS over 1 GB: a reader sizing memory from a header), other (refused, but not in one line with
exit 2 and no folder; or an unexpected exit code).
"""
import json
import os
import resource
import signal
import subprocess
import time
from collections import Counter, defaultdict
from pathlib import Path

OUTCOMES = ("ok", "crash", "hang", "silent", "loss", "alloc", "other")
BIG_RSS_MB = 1024


class Run:
    def __init__(self, code, signal_number, err, seconds, rss_mb, hung):
        self.code, self.signal, self.err, self.seconds, self.rss_mb, self.hung = code, signal_number, err, seconds, rss_mb, hung

    def first_line(self):
        return (self.err.strip().splitlines() or [""])[0][:200]


def start(args, work, file_size_limit=None, cwd=None, env=None):
    """Starts a command in its own session (so a kill reaches its children); stderr to a file."""
    err_path = Path(work) / f".err.{time.monotonic_ns()}"

    def limits():
        if file_size_limit is not None:
            resource.setrlimit(resource.RLIMIT_FSIZE, (file_size_limit, file_size_limit))

    err_file = open(err_path, "wb")
    process = subprocess.Popen([str(a) for a in args], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err_file,
                               preexec_fn=limits, start_new_session=True, cwd=cwd, env=env)
    err_file.close()
    return process, err_path


def finish(process, err_path, timeout, started=None):
    """Waits (with os.wait4, for the child's own peak RSS) up to `timeout` seconds, then kills it."""
    started = started or time.monotonic()
    hung = False
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() - started > timeout:
            os.killpg(process.pid, signal.SIGKILL)
            pid, status, usage = os.wait4(process.pid, 0)
            hung = True
            break
        time.sleep(0.005)
    process.returncode = 0  # reaped here; keeps Popen from waiting again
    err = Path(err_path).read_text(errors="replace")
    Path(err_path).unlink()
    code = os.WEXITSTATUS(status) if os.WIFEXITED(status) else None
    signal_number = os.WTERMSIG(status) if os.WIFSIGNALED(status) else None
    return Run(code, signal_number, err, time.monotonic() - started, usage.ru_maxrss / 1024.0, hung)


def run(args, work, timeout=60, file_size_limit=None, cwd=None, env=None):
    started = time.monotonic()
    process, err_path = start(args, work, file_size_limit, cwd, env)
    return finish(process, err_path, timeout, started)


def crashed(r):
    markers = ("AddressSanitizer", "runtime error:", "terminate called", "double free", "Segmentation fault")
    return r.signal is not None or r.code in (134, 136, 139) or any(m in r.err for m in markers)


def failure(r):
    """The outcome that overrides any expectation: a hang, a crash, a big allocation."""
    if r.hung:
        return "hang"
    if crashed(r):
        return "crash"
    if r.rss_mb > BIG_RSS_MB:
        return "alloc"
    return None


def one_line_refusal(r, out=None, words=None):
    return (r.code == 2 and r.err.count("\n") == 1 and (words is None or words in r.err)
            and (out is None or not Path(out).exists()))


def judge_refused(r, out=None, words=None):
    """Bad input: one line, exit 2, no folder, naming `words`."""
    bad = failure(r)
    if bad:
        return bad
    if r.code == 0:
        return "silent"
    return "ok" if one_line_refusal(r, out, words) else "other"


def whole_result(folder):
    """A result folder a finished (or cleanly stopped) run left: a parsable summary that is not
    `running`, and CSV files of whole rows."""
    folder = Path(folder)
    try:
        summary = json.loads((folder / "summary.json").read_text())
    except (OSError, ValueError):
        return False
    if summary.get("stop_reason") in (None, "running"):
        return False
    return all(whole_rows(csv) for csv in folder.glob("*.csv"))


def whole_rows(csv):
    data = Path(csv).read_bytes()
    if not data:
        return True
    if not data.endswith(b"\n"):
        return False
    lines = data.split(b"\n")[:-1]
    columns = lines[0].count(b",")
    return all(line.count(b",") == columns for line in lines)


def judge_valid_or_refused(r, out):
    """Mutated input that may still be valid: a one-line exit 2 and no folder, or a run that
    ends (0, or 1 for a continuation that stopped) with a whole result."""
    bad = failure(r)
    if bad:
        return bad
    if r.code == 2:
        return "ok" if one_line_refusal(r, out) else "other"
    if r.code in (0, 1):
        return "ok" if whole_result(out) else "loss"
    return "other"


class Tally:
    """Per class: how many inputs, each outcome, and the findings to look at."""

    def __init__(self):
        self.counts = defaultdict(Counter)
        self.findings = []

    def add(self, kind, name, outcome, r=None):
        self.counts[kind][outcome] += 1
        if outcome == "ok" and r is not None and r.code == 2:
            self.counts[kind]["refused"] += 1
        if outcome != "ok":
            detail = ""
            if r is not None:
                detail = f"exit {r.code} signal {r.signal} {r.seconds:.1f} s {r.rss_mb:.0f} MB: {r.first_line()}"
            self.findings.append(f"{kind} / {name}: {outcome} ({detail})")
            print(f"  FINDING {kind} / {name}: {outcome} {detail}", flush=True)

    def table(self):
        # "ok (refused)": of the ok outcomes, the one-line exit 2 refusals.
        columns = ("ok", "refused") + OUTCOMES[1:]
        lines = ["| class | runs | ok | ok (refused) | " + " | ".join(OUTCOMES[1:]) + " |", "|---|" + "---|" * (len(columns) + 1)]
        total = Counter()
        for kind, counts in list(self.counts.items()) + [("all", None)]:
            counts = counts if counts is not None else total
            runs = sum(counts[o] for o in OUTCOMES)
            lines.append(f"| {kind} | {runs} | " + " | ".join(str(counts[c]) for c in columns) + " |")
            if kind != "all":
                total.update(counts)
        return "\n".join(lines)
