#!/usr/bin/env python3
"""The rotor 67 NFRC against the contact stiffness (scripts/rotor67-contact-stiffness.sh): one
Markdown table row per run folder <sense>-k<k>[-h15] of OUT, from its summary.json and
branch.csv; with --figure, the leading edge's radial ||r(t)||_inf against omega,
one panel per sense, one line per stiffness (H = 10), stable solid, unstable dashed, LP and NS
marked (hbtrack.figure_style; run from the repository, python/hbtrack needs no build to plot).
Usage: contact_stiffness_table.py OUT [--figure PNG]"""
import csv
import json
import sys
from pathlib import Path


def peak_le(r):
    """||le(t)||_inf over a period, m: the outward swing is capped by the casing, the inward one is not."""
    return max(abs(float(r["max_le"])), abs(float(r["min_le"])))


def row(folder):
    summary = json.loads((folder / "summary.json").read_text())
    with open(folder / "branch.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    params = summary["options"]["parameters"]
    peak = max(rows, key=peak_le)
    specials = sorted(summary["special_points"], key=lambda p: p["omega"])
    def omegas(kind):
        # Points within 1 % of the previous one as one cluster, "first-last (count)": a law
        # sharper than the time samples leaves dozens of micro folds 1e-3 apart.
        values = [p["omega"] for p in specials if p["type"] == kind]
        clusters = []
        for w in values:
            if clusters and w <= 1.01 * clusters[-1][-1]:
                clusters[-1].append(w)
            else:
                clusters.append([w])
        return ", ".join(f"{c[0]:.1f}" if len(c) == 1 else f"{c[0]:.1f}-{c[-1]:.1f} ({len(c)})" for c in clusters) or "-"
    gains = summary.get("friction_loop_gain", [])
    above = [g.get("node", str(g["element"])) for g in gains if g.get("self_energising")]
    return "| {sense} | {k:.0e} | {h} | {points} | {stop} | {lp} | {ns} | {peak:.3f} at {at:.1f} | {above} |".format(
        sense=folder.name.split("-k")[0], k=float(params["contact_stiffness"]),
        h=summary["options"]["harmonic_balance"]["harmonics"], points=summary["points"], stop=summary["stop_reason"],
        lp=omegas("LP"), ns=omegas("NS"), peak=1e3 * peak_le(peak), at=float(peak["omega"]),
        above=", ".join(above) or "none")


def figure(folders, path):
    """One panel per sense, one curve per stiffness (H = 10): ||le(t)||_inf in mm, with hbtrack's
    figure style (stable solid, unstable dashed, every LP and NS of every branch marked by type,
    a legend entry per type) and the output named by its description in the case."""
    from hbtrack.branch_figures import NORM_LABEL, norm_of
    from hbtrack.figure_style import (OMEGA_LABEL, SPECIAL_MARKERS, _plot_split, _stable_masks, length_label,
                                      marker_legend, plt, stability_legend)
    from hbtrack.output_descriptions import output_descriptions
    from hbtrack.results import read_result
    senses = [s for s in ("geometry", "reversed", "frictionless") if any(d.name.startswith(s + "-") for d in folders)]
    fig, axes = plt.subplots(1, len(senses), figsize=(5 * len(senses), 4.6), sharey=True, squeeze=False)
    colours = {"1e8": "C0", "1e9": "C1", "1e10": "C3", "1e11": "C4"}
    description = None
    for ax, sense in zip(axes[0], senses):
        branches, types = [], set()
        for k, colour in colours.items():
            folder = next((d for d in folders if d.name == f"{sense}-k{k}"), None)
            if folder is None:
                continue
            result = read_result(str(folder))
            description = description or output_descriptions(result)["le"]
            branch = result["branch"]
            branches.append(branch)
            stable, unstable = _stable_masks(branch)
            _plot_split(ax, branch["omega"], 1e3 * norm_of(branch, "le"), stable, unstable, colour,
                        f"k = {k} N/m", lw=1.2)
            for sp in result["special_points"]:
                if sp["type"] in SPECIAL_MARKERS and "max_le" in sp:
                    types.add(sp["type"])
                    ax.plot(sp["omega"], 1e3 * float(norm_of(sp, "le")), SPECIAL_MARKERS[sp["type"]][0], color=colour,
                            mec="k", mew=0.7, ms=5, ls="none", zorder=5)
        ax.set_title({"geometry": "friction sense of the geometry", "reversed": "friction sense reversed",
                      "frictionless": r"nearly frictionless (friction coefficient $\mu$ = 1e-4)"}[sense], fontsize=9)
        ax.set_xlabel(OMEGA_LABEL)
        ax.grid(alpha=0.3)
        handles, _ = ax.get_legend_handles_labels()
        ax.legend(handles=handles + stability_legend(branches) + marker_legend(types), fontsize=7)
    axes[0][0].set_ylabel(length_label(f"{NORM_LABEL}, {description}" if description else NORM_LABEL, "mm"))
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    out = Path(sys.argv[1])
    print("| sense | k (N/m) | H | points | stop | LP omega (rad/s) | NS omega (rad/s) | max abs le (mm) at omega | loop gain > 1 |")
    print("|---|---|---|---|---|---|---|---|---|")
    order = {"geometry": 0, "reversed": 1, "frictionless": 2}
    folders = [d for d in out.iterdir() if (d / "summary.json").is_file()]
    def key(d):
        sense, rest = d.name.split("-k", 1)
        return order.get(sense, 3), float(rest.split("-")[0]), rest
    for d in sorted(folders, key=key):
        print(row(d))
    if len(sys.argv) > 3 and sys.argv[2] == "--figure":
        figure(folders, sys.argv[3])


if __name__ == "__main__":
    main()
