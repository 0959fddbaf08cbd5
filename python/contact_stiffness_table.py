#!/usr/bin/env python3
"""The rotor 67 NFRC against the contact stiffness (scripts/rotor67-contact-stiffness.sh): one
Markdown table row per run folder <sense>-k<k>[-h15] of OUT, from its summary.json and
branch.csv. Usage: contact_stiffness_table.py OUT"""
import csv
import json
import sys
from pathlib import Path


def row(folder):
    summary = json.loads((folder / "summary.json").read_text())
    with open(folder / "branch.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    params = summary["options"]["parameters"]
    peak = max(rows, key=lambda r: float(r["max_le"]))
    specials = sorted(summary["special_points"], key=lambda p: p["omega"])
    def omegas(kind):
        return ", ".join(f"{p['omega']:.1f}" for p in specials if p["type"] == kind) or "-"
    gains = summary.get("friction_loop_gain", [])
    above = [g.get("node", str(g["element"])) for g in gains if g.get("self_energising")]
    return "| {sense} | {k:.0e} | {h} | {points} | {stop} | {lp} | {ns} | {peak:.3f} at {at:.1f} | {above} |".format(
        sense=folder.name.split("-k")[0], k=float(params["contact_stiffness"]),
        h=summary["options"]["harmonic_balance"]["harmonics"], points=summary["points"], stop=summary["stop_reason"],
        lp=omegas("LP"), ns=omegas("NS"), peak=1e3 * float(peak["max_le"]), at=float(peak["omega"]),
        above=", ".join(above) or "none")


def main():
    out = Path(sys.argv[1])
    print("| sense | k (N/m) | H | points | stop | LP omega (rad/s) | NS omega (rad/s) | peak le (mm) at omega | loop gain > 1 |")
    print("|---|---|---|---|---|---|---|---|---|")
    order = {"geometry": 0, "reversed": 1, "frictionless": 2}
    folders = [d for d in out.iterdir() if (d / "summary.json").is_file()]
    def key(d):
        sense, rest = d.name.split("-k", 1)
        return order.get(sense, 3), float(rest.split("-")[0]), rest
    for d in sorted(folders, key=key):
        print(row(d))


if __name__ == "__main__":
    main()
