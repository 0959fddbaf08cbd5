"""A study side by side with a paper's published numbers (data/rotor67/paper_values.json for the
GT2023 paper on rotor 67): the tables as Markdown and the counterparts of the paper's Figs 3, 7
and 12 in STUDY_DIR/figures/paper_fig*.png|pdf.

    /usr/bin/python3 python/compare_with_paper.py STUDY_DIR --paper data/rotor67/paper_values.json \
        --model data/rotor67/summary.json [--reversed NFRC_DIR]

Frequencies are also given as omega / omega_1B of each model (ours and the paper's), because the
two blades' first bending frequencies differ (data/rotor67/README.md). The paper's ||r(t)||_inf
values are signed extremes of the radial displacement (inward, negative): they compare with
min_le and min_te.
"""
import argparse
import json
import os
import sys

from .results import read_result, tracking_curve
from .special_points import CurveExtremumType, numbered_limit_points


def _load(path):
    with open(path) as f:
        return json.load(f)


def _mm(v):
    return f"{1e3 * v:.3f}"


def _limit_points(summary):
    """[(label, point)]: LP1, LP2, ... in omega order, as `hbtrack plot` and the paper number them."""
    return numbered_limit_points(summary.get("special_points", []))


def _resonance(numbered):
    """The (label, point) of most negative leading-edge extreme: the nonlinear resonance."""
    return min(numbered, key=lambda lp: lp[1].get("min_le", 0.0)) if numbered else None


def frequency_tables(paper, full_model, reduced):
    rows = ["| mode | paper (Table 2) | this model, full FE | vs paper | reduced (39 dofs) |", "|---|---|---|---|---|"]
    for k, (mode, w_paper) in enumerate(paper["table2_rad_s"].items()):
        w = full_model["natural_frequencies"][k]
        rows.append(f"| {mode} | {w_paper:.2f} | {w:.2f} | {100 * (w / w_paper - 1):+.1f} % | {reduced['natural_frequencies'][k]:.2f} |")
    return rows


def nfrc_table(paper, nfrc, w1b, label):
    lps = _limit_points(nfrc)
    rows = [f"| {label} | LPs | omega (rad/s) | omega / omega_1B | min le (mm) | min te (mm) |", "|---|---|---|---|---|---|"]
    for label, p in lps:
        rows.append(f"| {label} | | {p['omega']:.2f} | {p['omega'] / w1b:.4f} | {_mm(p['min_le'])} | {_mm(p['min_te'])} |")
    if lps:
        label, peak = _resonance(lps)
        rows.append(f"| resonance ({label}) | {len(lps)} | {peak['omega']:.2f} | {peak['omega'] / w1b:.4f} | "
                    f"{_mm(peak['min_le'])} | {_mm(peak['min_te'])} |")
    f3 = paper["fig3"]
    rows.append(f"| paper, resonance ({f3['resonance']}) | {f3['limit_points']} | | | {_mm(f3['min_le_m'])} | {_mm(f3['min_te_m'])} |")
    return rows


def events_table(paper, entry, w1b, w1b_paper):
    """Births (minima of the amplitude along the tracking curves) and merges (maxima)."""
    rows = ["| event | source | omega (rad/s) | omega / omega_1B | A |", "|---|---|---|---|---|"]
    for kind, name in ((CurveExtremumType.PARAMETER_MIN, "birth"), (CurveExtremumType.PARAMETER_MAX, "merge")):
        for e in sorted((e for e in entry.get("extrema", []) if e["type"] == kind), key=lambda e: e["value"]):
            rows.append(f"| {name} | this model | {e['omega']:.2f} | {e['omega'] / w1b:.4f} | {e['value']:.2f} |")
        for e in paper["table3_births" if kind == CurveExtremumType.PARAMETER_MIN else "table4_merges"]:
            rows.append(f"| {name} {e['family']} | paper | {e['omega']:.2f} | {e['omega'] / w1b_paper:.4f} | {e['amplitude']:.2f} |")
    return rows


def extrema_and_isolas(entry):
    param = entry["parameter"]
    rows = [f"| {param} extremum | value | omega (rad/s) | curve |", "|---|---|---|---|"]
    for e in sorted(entry.get("extrema", []), key=lambda e: e["value"]):
        rows.append(f"| {e['type']} | {e['value']:.6g} | {e['omega']:.2f} | {e['curve']} |")
    isolas = [(v["value"], b) for v in entry.get("validations", []) for b in v.get("isola_branches", [])]
    rows += ["", f"Isolated branches computed ({len(isolas)}):", ""]
    if isolas:
        rows += [f"| {param} | omega range (rad/s) | points | unstable points |", "|---|---|---|---|"]
        rows += [f"| {value:.6g} | {b['omega_range'][0]:.2f} - {b['omega_range'][1]:.2f} | {b['points']} | {b['unstable_points']} |"
                 for value, b in isolas]
    failed = [v for v in entry.get("validations", []) if v.get("stop_reason") != "reached_end"]
    if failed:
        rows += ["", "Validation NFRCs that did not reach the end of the range: " +
                 ", ".join(f"{v['value']:.6g} ({v['stop_reason']})" for v in failed) + "."]
    return rows


def convergence_rows(summary):
    conv = summary.get("convergence")
    if not conv:
        return ["No convergence check in this study."]
    rows = [f"H = 10, N = 1024 against H = {conv['harmonics']}, N = {conv['samples']}:", "",
            "| event | omega | refined omega | difference | value | refined value | difference |", "|---|---|---|---|---|---|---|"]
    for lp in conv.get("limit_points", []):
        if "refined_omega" in lp:
            rows.append(f"| NFRC LP | {lp['omega']:.2f} | {lp['refined_omega']:.2f} | {100 * lp['relative_difference_omega']:+.3f} % | "
                        f"max le {_mm(lp['max_le'])} mm | {_mm(lp['refined_max_le'])} mm | {100 * lp['relative_difference_max_le']:+.2f} % |")
    for t in conv.get("tracking", []):
        for e in t.get("extrema", []):
            if "refined_value" in e:
                rows.append(f"| {t['parameter']} {e['type']} | {e['omega']:.2f} | {e['refined_omega']:.2f} | "
                            f"{100 * e['relative_difference_omega']:+.3f} % | {e['value']:.6g} | {e['refined_value']:.6g} | "
                            f"{100 * e['relative_difference_value']:+.2f} % |")
            else:
                rows.append(f"| {t['parameter']} {e['type']} | {e['omega']:.2f} | none found | | {e['value']:.6g} | | |")
    return rows


def simulation_rows(summary):
    rows = []
    for key, title in (("simulation", "nominal NFRC, stable point next to the resonance"), ("isola_simulation", "isolated branch, stable point")):
        s = summary.get(key)
        if not s:
            rows.append(f"- {title}: none")
            continue
        diffs = ", ".join(f"{o['name']} {100 * o['relative_difference']:+.2f} %" for o in s["outputs"] if o["name"].startswith(("max_", "min_")))
        rows.append(f"- {title} (omega = {s['omega']:.2f}, {s['periods']} periods, periodic: {s['converged']}): {diffs}")
    return rows


def write_figures(study_dir, paper, w1b, reversed_dir=None):
    import matplotlib
    if "MPLBACKEND" not in os.environ:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from .figure_style import save_figure

    files = []
    nfrc = read_result(os.path.join(study_dir, "nfrc"))
    # Fig. 3: the signed inward extremes of leading and trailing edge, each sense of friction in
    # its own panel (two systems), stable solid, unstable dashed, every limit point marked on both
    # edges' curves and named once (LP1.. in omega order, as the tables), omega over our 1B (its
    # value in the label). The paper's curves are not digitised here: its resonance values are in
    # the table beside the figure, not drawn as lines across it.
    from .figure_style import SPECIAL_MARKERS, _plot_split, _stable_masks, marker_legend, stability_legend
    from .special_points import distinct_special_points, numbered_special_points
    types = set()
    from .label_layout import place_labels
    senses = [("sense of the geometry", nfrc)] + ([("friction sense reversed", read_result(reversed_dir))] if reversed_dir else [])
    fig, axes = plt.subplots(1, len(senses), figsize=(6.5 if len(senses) == 1 else 11, 4.3), squeeze=False, sharey=True)
    for ax, (title, result) in zip(axes[0], senses):
        branch = result["branch"]
        stable, unstable = _stable_masks(branch)
        for key, colour, what in (("min_le", "C0", "leading edge"), ("min_te", "C1", "trailing edge")):
            _plot_split(ax, branch["omega"] / w1b, 1e3 * branch[key], stable, unstable, colour, what)
        lp_labels = []
        # Every special point (LP and NS: the NS points bound the unstable bands), named once
        for label, p in numbered_special_points(distinct_special_points(result["summary"].get("special_points", []))):
            if p["type"] not in ("LP", "NS") or "min_le" not in p:
                continue
            types.add(p["type"])
            for key, colour in (("min_le", "C0"), ("min_te", "C1")):
                ax.plot(p["omega"] / w1b, 1e3 * p[key], SPECIAL_MARKERS[p["type"]][0], color=colour, mec="k", ms=5, ls="none", zorder=5)
            lp_labels.append((p["omega"] / w1b, 1e3 * min(p["min_le"], p["min_te"]), label))
        ax.set_title(title, fontsize=9, loc="left")
        ax.set_xlabel(rf"$\omega / \omega_{{1B}}$ ($\omega_{{1B}}$ = {w1b:.1f} rad/s)")
        ax.grid(alpha=0.3)
        ax._lp_labels = lp_labels
    axes[0, 0].set_ylabel(r"inward extreme of $r(t)$ [mm]")
    handles, labels = axes[0, 0].get_legend_handles_labels()
    extra = stability_legend([r["branch"] for _, r in senses]) + marker_legend(types or {"LP"})
    fig.legend(handles + extra, labels + [h.get_label() for h in extra], loc="lower center", ncol=len(handles + extra), fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.08, 1, 1))
    for ax in axes[0]:
        place_labels(ax, ax._lp_labels)
    files += save_figure(fig, os.path.join(study_dir, "figures", "paper_fig3"))
    # Fig. 7: the amplitude tracking curves in (omega / omega_1B, A), births and merges marked.
    summary = _load(os.path.join(study_dir, "summary.json"))
    entry = next((t for t in summary.get("tracking", []) if t["parameter"] == "amplitude"), None)
    if entry:
        from .plots import _curve_name, _nfrc_points_on
        nominal_marked = False
        from .study_figures import curve_label
        fig, ax = plt.subplots(figsize=(6.5, 4.6))
        for c in entry["curves"]:
            if "folder" in c:
                track = read_result(os.path.join(study_dir, c["folder"]))
                curve = tracking_curve(track)
                # As the study's own figure names it: every fold of the NFRC on the curve (one curve can hold two)
                label = curve_label(c, entry) or _curve_name(track, 0, nfrc["summary"].get("special_points", []))
                line, = ax.plot(curve["omega"] / w1b, curve["amplitude"], lw=1.2, label=label)
                if not c.get("from"):  # the nominal NFRC's folds on it, where it crosses the nominal A
                    value = track["summary"]["start"]["amplitude"]
                    for _, p in _nfrc_points_on(track, nfrc["summary"].get("special_points", [])):
                        ax.plot(p["omega"] / w1b, value, "o", color=line.get_color(), mec="k", ms=5, zorder=5)
                        nominal_marked = value
        if nominal_marked is not False:  # one legend entry, in no curve's colour
            ax.plot([], [], "o", color="0.7", mec="k", ms=5, ls="none", label=f"the nominal NFRC's LPs (A = {nominal_marked:g})")
        for kind, marker, text in ((CurveExtremumType.PARAMETER_MIN, "v", "this model, births (min of A)"),
                                   (CurveExtremumType.PARAMETER_MAX, "^", "this model, merges (max of A)")):
            points = [(e["omega"] / w1b, e["value"]) for e in entry.get("extrema", []) if e["type"] == kind]
            if points:
                ax.plot(*zip(*points), marker, color="k", ms=6, ls="none", label=text)
        w_paper = paper["table2_rad_s"]["1B"]
        for key, marker, label in (("table3_births", "v", "paper, births (Table 3)"), ("table4_merges", "^", "paper, merges (Table 4)")):
            pts = paper[key]
            ax.plot([p["omega"] / w_paper for p in pts], [p["amplitude"] for p in pts], marker, mfc="none", color="C3", ms=8, ls="none", label=label)
        ax.set_xlabel(rf"$\omega / \omega_{{1B}}$ (each model's own: {w1b:.1f}, paper {w_paper:.1f} rad/s)")
        ax.set_ylabel("forcing amplitude A [-]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.14), ncol=2, frameon=False)
        fig.tight_layout()
        files += save_figure(fig, os.path.join(study_dir, "figures", "paper_fig7"))
    # Fig. 12: the study's own (study_paper_figures): a panel per parameter value, the isola the
    # time integration started on beside the nominal NFRC rather than on its axes.
    from .study_paper_figures import nfrc_isolas_simulation_figure
    from .units import scale_lengths

    def read_mm(folder):
        return scale_lengths(read_result(folder), 1e3)

    files += save_figure(nfrc_isolas_simulation_figure(study_dir, length_unit="mm", read=read_mm),
                         os.path.join(study_dir, "figures", "paper_fig12"))
    return files


def comparison_page(study_dir, paper, model_summary, full_model_summary, reversed_dir=None, label=None):
    summary = _load(os.path.join(study_dir, "summary.json"))
    nfrc = _load(os.path.join(study_dir, "nfrc", "summary.json"))
    w1b = model_summary["natural_frequencies"][0]
    w1b_paper = paper["table2_rad_s"]["1B"]
    lines = ["# Against the paper" + (f": {label}" if label else ""), "", f"Source: {paper['source']}.", "",
             "## Table 2: first frequencies (rad/s)", ""] + frequency_tables(paper, full_model_summary, model_summary)
    lines += ["", "## Fig. 3: the NFRC at A = 140, mu = 0.15, c = 0.4 mm", ""] + nfrc_table(paper, nfrc, w1b, "this model")
    if reversed_dir:
        lines += ["", "The same with the friction sense reversed (the blade turning with its trailing edge ahead):", ""]
        lines += nfrc_table(paper, _load(os.path.join(reversed_dir, "summary.json")), w1b, "reversed sense")
    for t in summary.get("tracking", []):
        if t["parameter"] == "amplitude":
            lines += ["", "## Tables 3-4: births and merges of isolated branches in A", ""] + events_table(paper, t, w1b, w1b_paper)
    for t in summary.get("tracking", []):
        lines += ["", f"## Tracking in {t['parameter']}", ""] + extrema_and_isolas(t)
    lines += ["", "Paper, mu: " + paper["mu"] + ".", "", "Paper, clearance: " + paper["clearance"] + "."]
    lines += ["", "## Convergence of the events", ""] + convergence_rows(summary)
    lines += ["", "## Time integration", ""] + simulation_rows(summary)
    lines += ["", "![Fig. 3](figures/paper_fig3.png)", "", "![Fig. 7](figures/paper_fig7.png)", "", "![Fig. 12](figures/paper_fig12.png)", ""]
    return "\n".join(lines)


def _link_from_the_study_page(study_dir):
    """Puts a link to paper_comparison.md at the top of the study's index.md (once)."""
    index = os.path.join(study_dir, "index.md")
    if not os.path.exists(index):
        return
    with open(index) as f:
        text = f.read()
    link = "Side by side with the paper: [paper_comparison.md](paper_comparison.md)."
    if link in text:
        return
    first, _, rest = text.partition("\n")
    with open(index + ".tmp", "w") as f:
        f.write(f"{first}\n\n{link}\n{rest}")
    os.replace(index + ".tmp", index)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="compare_with_paper.py", description=__doc__.splitlines()[0])
    parser.add_argument("study", help="an hbtrack study folder")
    parser.add_argument("--paper", required=True, help="the paper's values (JSON, e.g. data/rotor67/paper_values.json)")
    parser.add_argument("--model", required=True, help="the reduced model's summary (e.g. data/rotor67/summary.json)")
    parser.add_argument("--full-model", help="the full model's summary (default: full_model_summary.json beside --model)")
    parser.add_argument("--reversed", help="an NFRC folder of the same case with the friction sense reversed")
    parser.add_argument("--label", help="what this study is, for the page's title (e.g. 'friction sense reversed')")
    args = parser.parse_args(argv)
    try:
        paper, model = _load(args.paper), _load(args.model)
        full = _load(args.full_model or os.path.join(os.path.dirname(args.model), "full_model_summary.json"))
        page = comparison_page(args.study, paper, model, full, args.reversed, args.label)
        files = write_figures(args.study, paper, model["natural_frequencies"][0], args.reversed)
    except (OSError, KeyError, ValueError) as error:
        print(f"compare_with_paper.py: {error}", file=sys.stderr)
        return 2
    out = os.path.join(args.study, "paper_comparison.md")
    with open(out + ".tmp", "w") as f:
        f.write(page)
    os.replace(out + ".tmp", out)
    _link_from_the_study_page(args.study)
    for name in [out, *files]:
        print(name)
    return 0
