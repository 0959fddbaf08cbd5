#!/usr/bin/env python3
"""What the Lanczos filter of the contact forces changes on an NFRC (scripts/rotor67-lanczos.sh):
the same case's NFRC with and without the filter, side by side, as Markdown tables.

1. The special points of both, paired in order along the branch, with the filter's shift.
2. ||r(t)||_inf of each output (the largest |displacement| over a period) stretch by stretch:
   a stretch runs between two limit points, so omega is monotonic on it and each omega has one
   point; the unfiltered stretch is interpolated at the filtered one's omegas (linear in omega,
   within the omega range both cover). Reported: the largest relative difference, where it is,
   and the omega interval where the two differ by more than 1 %.
3. With --simulate FOLDER (a `simulate --near-lp` result): each run that held the orbit, the full
   model's ||r(t)||_inf after the transient next to both HBM solutions at its omega.

Usage: lanczos_filter_table.py LABEL FILTERED UNFILTERED [--simulate SIM] [LABEL FILTERED ...]"""
import csv
import json
import sys
from pathlib import Path

# Differences worth a row: the threshold; below it the filter is invisible in a figure.
REPORT_ABOVE = 0.01


def load(folder):
    folder = Path(folder)
    summary = json.loads((folder / "summary.json").read_text())
    with open(folder / "branch.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    names = [o["name"] for o in summary["outputs"]]
    return summary, rows, names


def peak(row, name):
    """||r(t)||_inf over a period: the larger of the outward (max) and inward (min) extremes."""
    return max(abs(float(row["max_" + name])), abs(float(row["min_" + name])))


def limit_points(summary):
    """Branch rows after which the limit points lie (each between its row and the next), in order."""
    return sorted(p["index"] for p in summary["special_points"] if p["type"] == "LP")


def stretches(rows, summary):
    """(first, last) branch rows of the stretches between consecutive limit points: each ends on
    the row before a fold and the next starts on the row after it, so omega is monotonic on each."""
    folds = limit_points(summary)
    starts, ends = [0] + [i + 1 for i in folds], folds + [len(rows) - 1]
    return [(a, b) for a, b in zip(starts, ends) if b > a]


def interpolate(rows, first, last, omega, name):
    """||r||_inf of the stretch rows[first..last] at omega, None outside it."""
    ws = [float(rows[i]["omega"]) for i in range(first, last + 1)]
    ys = [peak(rows[i], name) for i in range(first, last + 1)]
    if ws[0] > ws[-1]:
        ws, ys = ws[::-1], ys[::-1]
    if not ws[0] <= omega <= ws[-1]:
        return None
    for j in range(1, len(ws)):
        if omega <= ws[j]:
            t = (omega - ws[j - 1]) / (ws[j] - ws[j - 1]) if ws[j] > ws[j - 1] else 0.0
            return ys[j - 1] + t * (ys[j] - ys[j - 1])
    return ys[-1]


def special_point_rows(label, filtered, unfiltered):
    (fs, _, _), (us, _, _) = filtered, unfiltered
    lines = []
    for kind in ("LP", "NS", "PD", "BP"):
        fw = sorted(p["omega"] for p in fs["special_points"] if p["type"] == kind)
        uw = sorted(p["omega"] for p in us["special_points"] if p["type"] == kind)
        for i in range(max(len(fw), len(uw))):
            a = f"{fw[i]:.2f}" if i < len(fw) else "-"
            b = f"{uw[i]:.2f}" if i < len(uw) else "-"
            shift = f"{100 * (uw[i] - fw[i]) / fw[i]:+.2f} %" if i < len(fw) and i < len(uw) else "-"
            lines.append(f"| {label} | {kind} | {a} | {b} | {shift} |")
    return lines


def stretch_rows(label, filtered, unfiltered):
    (fs, frows, names), (us, urows, _) = filtered, unfiltered
    fparts, uparts = stretches(frows, fs), stretches(urows, us)
    if len(fparts) != len(uparts):
        return [f"| {label} | - | - | {len(fparts)} against {len(uparts)} stretches: not paired | - | - |"]
    lines = []
    for k, ((fa, fb), (ua, ub)) in enumerate(zip(fparts, uparts), start=1):
        span = f"{float(frows[fa]['omega']):.0f} -> {float(frows[fb]['omega']):.0f}"
        for name in names:
            worst, worst_at, above = 0.0, None, []
            for i in range(fa, fb + 1):
                w = float(frows[i]["omega"])
                other = interpolate(urows, ua, ub, w, name)
                if other is None:
                    continue
                diff = (other - peak(frows[i], name)) / peak(frows[i], name)
                if abs(diff) > abs(worst):
                    worst, worst_at = diff, w
                if abs(diff) > REPORT_ABOVE:
                    above.append(w)
            where = f"{min(above):.0f}-{max(above):.0f}" if above else "none"
            at = f"{worst_at:.0f}" if worst_at is not None else "-"
            lines.append(f"| {label} | {k}: {span} | {name} | {100 * worst:+.2f} % at {at} | {where} |")
    return lines


def stretch_from_lp(summary, rows, lp, after):
    """The stretch that starts (after=True) or ends at LP `lp` (numbered in omega order)."""
    by_omega = sorted((p for p in summary["special_points"] if p["type"] == "LP"), key=lambda p: p["omega"])
    if lp > len(by_omega):
        return None
    index = by_omega[lp - 1]["index"]
    return next(((a, b) for a, b in stretches(rows, summary) if (a - 1 if after else b) == index), None)


def simulation_rows(label, filtered, unfiltered, simulate):
    (fs, frows, names), (us, urows, _) = filtered, unfiltered
    search = json.loads((Path(simulate) / "summary.json").read_text()).get("fold_search", {})
    lp = search.get("lp", 0)
    lines = []
    for run in search.get("runs", []):
        if not run["held"]:
            continue
        sim = json.loads((Path(simulate) / run["folder"] / "summary.json").read_text())
        w, row = run["omega"], frows[run["point"]]
        fold = next(p["index"] for p in fs["special_points"]
                    if p["type"] == "LP" and abs(p["omega"] - search["lp_omega"]) < 1e-9 * p["omega"])
        stretch = stretch_from_lp(us, urows, lp, after=run["point"] > fold)
        for name in names:
            full = max(abs(sim["max_" + name]), abs(sim["min_" + name]))
            hbm = peak(row, name)
            other = interpolate(urows, *stretch, w, name) if stretch else None
            text = f"{1e3 * other:.4f} ({100 * (other - full) / full:+.2f} %)" if other else "-"
            lines.append(f"| {label} | {w:.2f} | {name} | {1e3 * full:.4f} | "
                         f"{1e3 * hbm:.4f} ({100 * (hbm - full) / full:+.2f} %) | {text} |")
    return lines


def main(argv):
    cases, i = [], 0
    while i < len(argv):
        label, filtered, unfiltered = argv[i:i + 3]
        i += 3
        simulate = None
        if i < len(argv) and argv[i] == "--simulate":
            simulate, i = argv[i + 1], i + 2
        cases.append((label, load(filtered), load(unfiltered), simulate))
    print("| sense | point | with the filter (rad/s) | without (rad/s) | shift |")
    print("|---|---|---|---|---|")
    for label, f, u, _ in cases:
        print("\n".join(special_point_rows(label, f, u)))
    print()
    print("| sense | stretch (rad/s) | output | largest change of ||r||_inf without the filter | omega where over 1 % |")
    print("|---|---|---|---|---|")
    for label, f, u, _ in cases:
        print("\n".join(stretch_rows(label, f, u)))
    if any(sim for *_, sim in cases):
        print()
        print("| sense | omega (rad/s) | output | time integration ||r||_inf (mm) | HBM with the filter (mm) | without (mm) |")
        print("|---|---|---|---|---|---|")
        for label, f, u, sim in cases:
            if sim:
                print("\n".join(simulation_rows(label, f, u, sim)))


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    main(sys.argv[1:])
