#!/usr/bin/python3
"""Issue 39's hostile rerun: the kinds of hostile input its test found crashes, hangs, silent
results and losses with, run again against the built CLI, and a table of the outcomes.

    scripts/hostile-rerun.sh [--cli build/hbtrack] [--work DIR] [--seed 39] [--scale 1]

Mutated inputs are drawn from a seeded generator, so a run is reproducible. Each class's
expectations are those docs/reliability.md promises; outcomes: scripts/hostile_rerun_support.py.
"""
import argparse
import json
import os
import random
import shutil
import signal
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from hostile_rerun_support import Tally, failure, finish, judge_refused, judge_valid_or_refused, run, start, whole_result  # noqa: E402
import hostile_rerun_inputs as inputs  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
DUFFING = ROOT / "examples" / "duffing.toml"
FINE = ["--set", "continuation.step=0.003", "--set", "continuation.step_max=0.003"]  # about 1 s of frc


class Rerun:
    def __init__(self, cli, work, seed, scale):
        self.cli, self.work, self.random, self.scale = str(cli), Path(work), random.Random(seed), scale
        self.tally = Tally()
        self.serial = 0
        self.notes = []
        self.finished_first = 0
        self.before_folder = 0

    def fresh(self, name):
        self.serial += 1
        path = self.work / f"{self.serial:05d}-{name}"
        shutil.rmtree(path, ignore_errors=True)
        return path

    def write(self, name, data):
        path = self.fresh(name)
        path.write_bytes(data if isinstance(data, bytes) else data.encode())
        return path

    def hb(self, *args, **kw):
        return run([self.cli, *args], self.work, **kw)

    def n(self, count):
        return max(1, int(count * self.scale))

    # -- readers -------------------------------------------------------------------------------
    def case_files(self):
        sources = [p for p in sorted((ROOT / "examples").glob("*.toml")) if p.name != "two_dof_contact.toml"]
        sources += sorted((ROOT / "fuzz" / "seeds" / "case_file").glob("templates*.toml"))
        for k in range(self.n(240)):
            source = self.random.choice(sources)
            text = inputs.mutate_toml(source.read_text(), self.random)
            kind = "template cases, mutated" if source.name.startswith("templates") else "case files, mutated"
            case = self.write(f"case{k}.toml", text)
            out = self.fresh(f"case{k}.out")
            r = self.hb("frc", case, "-q", "--set", "continuation.max_points=3", "-o", out, timeout=60)
            self.tally.add(kind, f"{source.name} -> {case.name}", judge_valid_or_refused(r, out), r)
        # Template expansion was quadratic (20 000 nodes, 5 per_node lists: > 400 s).
        for nodes in (4000, 20000):
            case = self.write(f"template{nodes}.toml", inputs.template_case(nodes))
            out = self.fresh(f"template{nodes}.out")
            r = self.hb("frc", case, "-q", "-o", out, timeout=30)
            outcome = judge_refused(r, out)
            if outcome == "ok" and r.seconds > 10:
                outcome = "hang"
            self.tally.add("template cases, large", f"{nodes} nodes ({r.seconds:.2f} s)", outcome, r)

    def matrix_files(self):
        mtx = inputs.TWO_BY_TWO_MTX
        for k in range(self.n(120)):
            self._matrix_case("matrix market, mutated", f"k{k}.mtx", inputs.mutate_text_matrix(mtx, self.random), "")
        seeds = sorted((ROOT / "fuzz" / "seeds" / "mat_file").glob("*.mat"))
        for seed in seeds:
            self._matrix_case("mat files, mutated", seed.name, seed.read_bytes(), ', variable = "K"')
        for k in range(self.n(400)):
            seed = self.random.choice(seeds)
            data = inputs.mutate_binary(seed.read_bytes(), self.random)
            self._matrix_case("mat files, mutated", f"{seed.name} -> k{k}.mat", data, ', variable = "K"')

    def _matrix_case(self, kind, name, data, variable):
        folder = self.fresh("matrix")
        folder.mkdir()
        matrix = folder / ("k.mat" if variable else "k.mtx")
        matrix.write_bytes(data if isinstance(data, bytes) else data.encode())
        (folder / "case.toml").write_text(inputs.two_dof_case(f'{{ file = "{matrix.name}"{variable} }}'))
        out = folder / "out"
        r = self.hb("frc", folder / "case.toml", "-q", "--set", "continuation.max_points=3", "-o", out, timeout=60)
        self.tally.add(kind, name, judge_valid_or_refused(r, out), r)

    def section_tables(self):
        surfaces = inputs.two_surfaces(ROOT / "data" / "rotor67" / "sections.csv")
        named = inputs.hostile_tables(surfaces)
        for k in range(self.n(60)):
            named.append((f"mutated{k}", inputs.mutate_table(inputs.sections_table("# blade_count = 22\n", surfaces), self.random), ""))
        for name, table, flags in named:
            path = self.write(f"{name}.csv", table)
            out = self.fresh(f"{name}.blade")
            r = self.hb("make-blade", "-q", "--geometry", path, *flags.split(), "-o", out, timeout=60)
            if name.startswith("valid"):
                outcome = "ok" if r.code == 0 and out.exists() else (judge_refused(r) if r.code != 2 else "other")
            elif name.startswith("mutated"):
                outcome = judge_valid_or_refused(r, out) if r.code != 0 else ("ok" if out.exists() else "loss")
            else:
                outcome = judge_refused(r, out)
            self.tally.add("section tables", name, outcome, r)
        # SIGTERM during the meshing of a refined 20-surface table ended it only after minutes.
        path = self.write("refined.csv", inputs.sections_table("# blade_count = 22\n", surfaces, between=20))
        process, err = start([self.cli, "make-blade", "-q", "--geometry", path, "--refine", "3", "-o", self.fresh("term")], self.work)
        time.sleep(0.5)
        os.kill(process.pid, signal.SIGTERM)
        r = finish(process, err, timeout=5)
        ended = r.signal == signal.SIGTERM or r.code in (1, 143)
        self.tally.add("interrupts and locks", "SIGTERM to make-blade", "ok" if ended and r.seconds < 2.5 else "hang", r)

    # -- JSON read back ------------------------------------------------------------------------
    def json_read_back(self):
        frc = self.fresh("json.frc")
        self.hb("frc", DUFFING, "-q", "--set", "continuation.max_points=5", "-o", frc)
        summary, checkpoint = (frc / "summary.json").read_bytes(), (frc / "checkpoint.json").read_bytes()
        track = self.fresh("json.track")
        whole = self.fresh("json.whole")
        self.hb("frc", DUFFING, "-q", "-o", whole)
        track_args = ["track", DUFFING, "-q", "--set", "continuation.max_points=5", "--from", whole, "--lp", "1", "--param",
                      "amplitude", "--range", "0.1:2"]
        self.hb(*track_args, "-o", track)
        track_checkpoint = (track / "checkpoint.json").read_bytes()
        for name, data in inputs.hostile_json(summary, self.random, self.n(12)):
            folder = self.fresh("export")
            shutil.copytree(frc, folder)  # the tables of a whole result, its summary replaced
            (folder / "summary.json").write_bytes(data)
            for fmt in ("mat", "h5"):
                r = self.hb("export", folder, "-q", "--format", fmt, timeout=60)
                self.tally.add("JSON read back", f"export --format {fmt} of summary {name}", judge_refused(r, folder / f"results.{fmt}"), r)
        for verb, folder, saved, args in (("frc", frc, checkpoint, ["frc", DUFFING, "-q"]), ("track", track, track_checkpoint, track_args)):
            summary_before = (folder / "summary.json").read_bytes()
            for name, data in inputs.hostile_checkpoints(saved, self.random, self.n(8)):
                (folder / "checkpoint.json").write_bytes(data)
                r = self.hb(*args, "--resume", folder, timeout=60)
                outcome = judge_refused(r)
                if outcome == "ok" and (folder / "summary.json").read_bytes() != summary_before:
                    outcome = "loss"
                self.tally.add("JSON read back", f"{verb} --resume, checkpoint {name}", outcome, r)
            (folder / "checkpoint.json").write_bytes(saved)

    # -- killed runs and resumes ---------------------------------------------------------------
    def killed_runs(self):
        reference = self.fresh("kill.reference")
        self.hb("frc", DUFFING, "-q", *FINE, "-o", reference)
        frc = ["frc", DUFFING, "-q", *FINE]
        lp_source = self.fresh("kill.lp")
        self.hb("frc", DUFFING, "-q", "-o", lp_source)
        track = ["track", DUFFING, "-q", "--set", "continuation.step=0.0005", "--set", "continuation.step_max=0.0005", "--from", lp_source,
                 "--lp", "1", "--param", "amplitude", "--range", "0.1:2"]
        track_reference = self.fresh("kill.track.reference")
        started = time.monotonic()
        self.hb(*track, "-o", track_reference)
        track_seconds = time.monotonic() - started
        plans = [(frc, reference, 1.0, s) for s in ["SIGKILL"] * self.n(14) + ["SIGINT"] * self.n(4) + ["SIGTERM"] * self.n(4)]
        plans += [(track, track_reference, track_seconds, s) for s in ["SIGKILL"] * self.n(8) + ["SIGTERM"] * self.n(2)]
        plans += [(frc, reference, 1.0, "SIGKILL twice")] * self.n(4)
        for args, ref, seconds, how in plans:
            self._kill_and_resume(args, ref, seconds, how)
        self.notes.append(f"killed runs: {len(plans)} signalled, {self.finished_first} of them finished before their signal and "
                          f"{self.before_folder} stopped before they made their folder (not counted); frc takes about 1 s, "
                          f"track {track_seconds:.1f} s")
        self._study_kills()
        # Stopped at its first point, before its first checkpoint: the resume starts over.
        out = self.fresh("kill.first-point")
        self.hb(*frc, "--time-limit", "1e-9", "-o", out)
        r = self.hb(*frc, "--resume", out, timeout=60)
        self.tally.add("killed runs, resumed", "frc --time-limit 1e-9, resume", self._same_result(r, out, reference), r)

    def _study_kills(self):
        """A study of a few seconds (its steps in subfolders) killed with its steps, resumed: every
        table and the summary (times aside) as the uninterrupted study's."""
        case = self.write("study.toml", inputs.small_study(DUFFING.read_text()))
        full = self.fresh("study.full")
        started = time.monotonic()
        whole = self.hb("study", case, "-q", "--jobs", "1", "-o", full, timeout=300)
        seconds = time.monotonic() - started
        signals, finished_first = ["SIGKILL"] * self.n(6) + ["SIGINT"] * self.n(2), 0
        for how in signals:
            out = self.fresh("study.part")
            process, err = start([self.cli, "study", case, "-q", "--jobs", "1", "-o", out], self.work)
            time.sleep(self.random.uniform(0.1, 0.9 * seconds))
            os.killpg(process.pid, getattr(signal, how))
            r = finish(process, err, timeout=30)
            if r.signal is None and r.code == whole.code and inputs.study_stop(out) not in ("running", "interrupted"):
                finished_first += 1
                continue
            r = self.hb("study", case, "-q", "--jobs", "1", "--resume", out, timeout=300)
            same = r.code == whole.code and inputs.same_study(out, full)
            bad = judge_refused(r) if r.code != whole.code else None
            self.tally.add("killed runs, resumed", f"study {how}", bad if bad in ("crash", "hang", "alloc") else
                           ("ok" if same else "silent"), r)
        self.notes.append(f"study: {len(signals)} signalled, {finished_first} of them finished before their signal (not counted); "
                          f"{seconds:.1f} s uninterrupted")

    def python_interrupts(self):
        """Ctrl-C in Python's hbtrack.sweep: the KeyboardInterrupt arrives and no task process is left."""
        env = dict(os.environ, PYTHONPATH=str(Path(self.cli).resolve().parent / "python"))
        for k in range(self.n(3)):
            folder = self.fresh("py.sweep")
            script = self.write("py_sweep.py", inputs.python_sweep(DUFFING, folder))
            process, err = start(["/usr/bin/python3", script], self.work, env=env)
            time.sleep(self.random.uniform(0.8, 2.0))
            os.kill(process.pid, signal.SIGINT)
            r = finish(process, err, timeout=60)
            time.sleep(0.5)
            left = inputs.processes_naming(folder)
            for pid in left:
                os.kill(pid, signal.SIGKILL)
            outcome = failure(r) or ("loss" if left else ("ok" if r.code == 3 else "other"))
            self.tally.add("interrupts and locks", f"python sweep, Ctrl-C {k + 1}", outcome, r)

    def _kill_and_resume(self, args, reference, seconds, how):
        out = self.fresh("kill")
        kills = 2 if how == "SIGKILL twice" else 1
        for attempt in range(kills):
            command = [self.cli, *args, *(["-o", out] if attempt == 0 else ["--resume", out])]
            process, err = start(command, self.work)
            time.sleep(self.random.uniform(0.05, 0.9 * seconds))
            os.killpg(process.pid, getattr(signal, how.split()[0]))
            r = finish(process, err, timeout=30)
            if r.hung or (r.signal is None and r.code == 0):
                self.finished_first += attempt == 0
                break  # finished before the signal: nothing to resume
            if not out.exists():  # stopped before it made its folder (a slow start): nothing to resume
                self.before_folder += 1
                return
            if how in ("SIGINT", "SIGTERM") and not (r.code == 1 and whole_result(out)):
                self.tally.add("killed runs, resumed", f"{args[0]} {how}: stop", "loss" if r.code == 1 else "other", r)
                return
        summary = json.loads((out / "summary.json").read_text()) if (out / "summary.json").exists() else {}
        if summary.get("stop_reason") not in (None, "running", "interrupted", "time_limit"):
            self.finished_first += kills == 1
            return  # the run ended before the signal
        r = self.hb(*args, "--resume", out, timeout=120)
        self.tally.add("killed runs, resumed", f"{args[0]} {how}", self._same_result(r, out, reference), r)

    def _same_result(self, r, out, reference):
        bad = judge_refused(r) if r.code != 0 else None
        if bad in ("crash", "hang", "alloc"):
            return bad
        if r.code != 0:
            return "other"
        same = all((out / f).read_bytes() == (reference / f).read_bytes() for f in ("branch.csv", "states.csv"))
        return "ok" if same else "silent"

    def edited_models(self):
        original = DUFFING.read_text()
        for key, edit in inputs.MODEL_EDITS:
            folder = self.fresh("edit")
            folder.mkdir()
            case = folder / "case.toml"
            case.write_text(original)
            out = folder / "out"
            self.hb("frc", case, "-q", "--set", "continuation.max_points=5", "-o", out)
            case.write_text(edit(original))
            r = self.hb("frc", case, "-q", "--resume", out)
            self.tally.add("resumes of an edited model", f"frc, {key}", judge_refused(r, words="another model"), r)
            case.write_text(original)
            frc = folder / "lp"
            self.hb("frc", case, "-q", "-o", frc)
            track = ["track", case, "-q", "--set", "continuation.max_points=5", "--from", frc, "--lp", "1", "--param", "amplitude",
                     "--range", "0.1:2"]
            self.hb(*track, "-o", folder / "track")
            case.write_text(edit(original))
            r = self.hb(*track, "--resume", folder / "track")
            self.tally.add("resumes of an edited model", f"track, {key}", judge_refused(r, words="another model"), r)

    # -- outputs -------------------------------------------------------------------------------
    def outputs(self):
        folder = self.fresh("outputs")
        self.hb("frc", DUFFING, "-q", "-o", folder)
        for fmt in ("mat", "h5"):
            whole = self.fresh(f"whole.{fmt}")
            self.hb("export", folder, "-q", "--format", fmt, "-o", whole)
            for kb in (1, 2, 4, 8, 16, 32, 64):
                target = folder / f"limited{kb}.{fmt}"
                r = self.hb("export", folder, "-q", "--format", fmt, "-o", target, file_size_limit=kb * 1024)
                scratch = [p for p in folder.iterdir() if p.name.startswith(target.name + ".")]
                if r.code == 0:  # the limit was not reached: the file must be the whole one
                    # (a .mat file's 128-byte header holds its time of creation)
                    same = fmt == "h5" or target.read_bytes()[128:] == whole.read_bytes()[128:]
                    outcome = "ok" if same and target.stat().st_size == whole.stat().st_size and not scratch else "loss"
                else:
                    outcome = "ok" if r.code == 3 and not target.exists() and not scratch and r.err.count("\n") == 1 else "loss"
                self.tally.add("outputs under a file-size limit", f"export {fmt} at {kb} KB", self._unless_failed(r, outcome), r)
        for own in ("branch.csv", "summary.json", "states.csv", ""):
            target = folder / own
            before = target.read_bytes() if target.is_file() else None
            r = self.hb("export", folder, "-q", "-o", target)
            changed = before is not None and target.read_bytes() != before
            outcome = "loss" if changed else judge_refused(r)
            self.tally.add("outputs under a file-size limit", f"export -o DIR/{own}", outcome, r)
        for kb in (1, 1.5, 2, 2.5, 3, 3.5, 4, 4.5):
            out = self.fresh("continue")
            r = self.hb("continue", DUFFING, "--param", "amplitude", "--omega", "1.2", "--range", "0.05:3", "-q", "-o", out,
                        file_size_limit=int(kb * 1024))
            rows_whole = all(inputs.whole_rows_or_empty(p) for p in out.glob("*.csv"))
            outcome = "ok" if r.code == 3 and rows_whole else "loss"
            self.tally.add("outputs under a file-size limit", f"continue at {kb} KB", self._unless_failed(r, outcome), r)
        for kb in (2, 8, 32, 64):
            out = self.fresh("frc.full")
            r = self.hb("frc", DUFFING, "-q", *FINE, "-o", out, file_size_limit=kb * 1024)
            rows_whole = all(inputs.whole_rows_or_empty(p) for p in out.glob("*.csv"))
            summary_ok = inputs.json_or_absent(out / "summary.json")
            outcome = "ok" if r.code == 3 and rows_whole and summary_ok else "loss"
            self.tally.add("outputs under a file-size limit", f"frc at {kb} KB", self._unless_failed(r, outcome), r)

    @staticmethod
    def _unless_failed(r, outcome):
        return "crash" if r.signal is not None or r.code in (134, 139) else ("hang" if r.hung else outcome)

    # -- names, flags, refusals before any folder ----------------------------------------------
    def names_and_flags(self):
        for name, text, words in inputs.hostile_cases(DUFFING.read_text(), ROOT):
            case = self.write(f"{name}.toml", text)
            out = self.fresh(f"{name}.out")
            r = self.hb("frc", case, "-q", "--set", "continuation.max_points=3", "-o", out)
            outcome = judge_refused(r, out, words) if words is not None else judge_valid_or_refused(r, out)
            self.tally.add("names and numbers", name, outcome, r)
        names = self.write("names.txt", "\ufeffx\n")
        case = self.write("bom.toml", DUFFING.read_text().replace('dofs = ["x"]', f'dofs = {{ file = "{names}" }}', 1))
        out = self.fresh("bom.out")
        r = self.hb("frc", case, "-q", "--set", "continuation.max_points=3", "-o", out)
        self.tally.add("names and numbers", "names file with a BOM", "ok" if r.code == 0 else "other", r)
        for name, args, words in inputs.hostile_flags(DUFFING, ROOT, self.work):
            out = self.fresh(name)
            r = self.hb(*args, "-o", out)
            self.tally.add("names and numbers", name, judge_refused(r, out, words), r)
        python = ("import math, hbtrack\ncase = hbtrack.load_case(%r)\n"
                  "try:\n    hbtrack.isolas(case, {}, at=math.nan)\nexcept ValueError as e:\n    raise SystemExit(2)\n" % str(DUFFING))
        script = self.write("isolas_nan.py", python)
        env = dict(os.environ, PYTHONPATH=str(Path(self.cli).resolve().parent / "python"))
        r = run(["/usr/bin/python3", script], self.work, env=env)
        self.tally.add("names and numbers", "python isolas(at=nan)", "ok" if r.code == 2 else ("silent" if r.code == 0 else "other"), r)

    def locks(self):
        out = self.fresh("lock")
        first, err = start([self.cli, "frc", DUFFING, "-q", *FINE, "-o", out], self.work)
        deadline = time.monotonic() + 10
        while not (out / ".hbtrack.lock").exists() and time.monotonic() < deadline:
            time.sleep(0.01)
        time.sleep(0.1)
        second = self.hb("frc", DUFFING, "-q", "-o", out)
        r = finish(first, err, timeout=60)
        outcome = judge_refused(second, words="is being written by another hbtrack run")
        if outcome == "ok" and not (r.code == 0 and whole_result(out)):
            outcome = "loss"
        self.tally.add("interrupts and locks", "second writer into a live folder", outcome, second)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", default=str(ROOT / "build" / "hbtrack"))
    parser.add_argument("--work", default="/tmp/hbtrack-hostile-rerun")
    parser.add_argument("--seed", type=int, default=39)
    parser.add_argument("--scale", type=float, default=1.0, help="multiplies the number of mutated inputs")
    parser.add_argument("--only", default="", help="comma-separated classes (method names) to run")
    args = parser.parse_args()
    shutil.rmtree(args.work, ignore_errors=True)
    Path(args.work).mkdir(parents=True)
    rerun = Rerun(args.cli, args.work, args.seed, args.scale)
    steps = ["case_files", "matrix_files", "section_tables", "json_read_back", "killed_runs", "edited_models", "outputs",
             "names_and_flags", "locks", "python_interrupts"]
    started = time.monotonic()
    for step in steps:
        if args.only and step not in args.only.split(","):
            continue
        t0 = time.monotonic()
        getattr(rerun, step)()
        print(f"{step}: {time.monotonic() - t0:.0f} s", flush=True)
    print(f"\nseed {args.seed}, scale {args.scale}, {time.monotonic() - started:.0f} s, {args.cli}\n")
    print("\n".join(rerun.notes + [""]))
    print(rerun.tally.table())
    if rerun.tally.findings:
        print("\nfindings:\n" + "\n".join(rerun.tally.findings))
    return 1 if rerun.tally.findings else 0


if __name__ == "__main__":
    sys.exit(main())
