#!/usr/bin/python3
"""The rotating parametric blade against CalculiX at several speeds: hbtrack's linear prestress,
K + W^2 (Kg1 - Mspin), of the full model (reduce --check-speed) and of its reduced model (the
Campbell diagram of modes --speeds), against ccx's *STATIC + *FREQUENCY PERTURBATION with and
without NLGEOM on the same mesh (make-blade --calculix). Prints the table of docs/analyses.md
and draws docs/figures/rotating_blade_calculix.png. The test RotatingCalculix checks the same
model against ccx given hbtrack's stress (which makes ccx's step the linear prestress itself).

    /usr/bin/python3 scripts/rotating-blade-vs-calculix.py [build/hbtrack] [FIGURE_STEM]
"""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
from hbtrack.figure_style import plt, save_figure  # noqa: E402
from hbtrack.results import read_result  # noqa: E402

HBTRACK = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else "build/hbtrack")
FIGURE = sys.argv[2] if len(sys.argv) > 2 else "docs/figures/rotating_blade_calculix"
SPEEDS = [0.0, 420.0, 840.0, 1260.0, 1680.0]
MODES = 3


def ccx_frequencies(work, job, deck):
    with open(os.path.join(work, job + ".inp"), "w") as f:
        f.write(deck)
    subprocess.run(["ccx", job], cwd=work, check=True, capture_output=True)
    text = open(os.path.join(work, job + ".dat")).read().split("E I G E N V A L U E   O U T P U T")[-1]
    return [float(m.group(1)) for m in re.finditer(r"^\s+\d+\s+\S+\s+(\S+)", text, re.MULTILINE)][:MODES]


def main():
    work = tempfile.mkdtemp()
    run = lambda *args: subprocess.run([HBTRACK, *args, "-q"], cwd=work, check=True)  # noqa: E731
    run("make-blade", "--rotating", "--calculix", "-o", "fe")
    base = open(os.path.join(work, "fe", "blade.inp")).read().split("*STEP")[0]
    rows = []
    for speed in SPEEDS:
        run("reduce", "--mass", "fe/M.mtx", "--stiffness", "fe/K.mtx", "--nodes", "fe/nodes.csv", "--boundary-file", "fe/boundary.txt",
            "--modes", "12", "--rotating", "--check-speed", str(speed), "--compare", str(MODES), "-o", "rom")
        at = json.load(open(os.path.join(work, "rom", "summary.json")))["rotation"]["check_at_speed"]
        load = f"*DLOAD\nEALL, CENTRIF, {speed * speed}, 0., 0., 0., 1., 0., 0.\n"
        steps = "*STATIC\n{}*END STEP\n*STEP, PERTURBATION\n*FREQUENCY\n6\n*END STEP\n"
        linear = ccx_frequencies(work, "linear", base + "*STEP\n" + steps.format(load))
        nlgeom = ccx_frequencies(work, "nlgeom", base + "*STEP, NLGEOM\n" + steps.replace("*STATIC\n", "*STATIC\n0.1, 1.0\n").format(load))
        rows.append((speed, at["full_model_frequencies"][:MODES], at["reduced_frequencies"][:MODES], linear, nlgeom))
    case = os.path.join(work, "rotating.toml")
    with open(case, "w") as f:
        f.write('[model]\ndofs = { file = "rom/summary.json" }\nM = { file = "rom/M.mtx" }\nK = { file = "rom/K.mtx" }\n'
                'Kg1 = { file = "rom/Kg1.mtx" }\nMspin = { file = "rom/Mspin.mtx" }\n[rotation]\nspeed = 0.0\n'
                '[continuation]\nomega_start = 1.0\nomega_end = 2.0\n')
    run("modes", case, "--speeds", f"0:{SPEEDS[-1]}:43", "--count", str(MODES), "-o", "campbell")
    campbell = read_result(os.path.join(work, "campbell"))

    names = ["1B", "2B", "1T"]
    print("| speed (rad/s) | mode | hbtrack full | reduced (39 dofs) | ccx linear static + perturbation | ccx NLGEOM | hbtrack vs NLGEOM |")
    print("|---|---|---|---|---|---|---|")
    for speed, full, reduced, linear, nlgeom in rows:
        for k in range(MODES):
            print(f"| {speed:.0f} | {names[k]} | {full[k]:.2f} | {reduced[k]:.2f} | {linear[k]:.2f} | {nlgeom[k]:.2f} | "
                  f"{100 * (full[k] / nlgeom[k] - 1):+.2f} % |")
    fig, axes = plt.subplots(1, MODES, figsize=(11, 3.8))
    for k, ax in enumerate(axes):
        table = campbell["campbell"]
        column = [c for c in table if c != "speed"][k]
        ax.plot(table["speed"], table[column], color="C0", label="hbtrack, reduced (linear prestress)")
        ax.plot([r[0] for r in rows], [r[1][k] for r in rows], "x", color="C0", label="hbtrack, full model")
        ax.plot([r[0] for r in rows], [r[3][k] for r in rows], "^", mfc="none", color="C1", label="ccx, linear static + perturbation")
        ax.plot([r[0] for r in rows], [r[4][k] for r in rows], "s", mfc="none", color="C2", label="ccx, NLGEOM + perturbation")
        ax.set_title(names[k])
        ax.set_xlabel(r"rotation speed $\Omega$ [rad/s]")
        ax.grid(True, linewidth=0.3)
    axes[0].set_ylabel(r"natural frequency $\omega$ [rad/s]")
    axes[0].legend(fontsize=7, loc="upper left")
    fig.suptitle("Parametric blade (1872 dofs) rotating about X: hbtrack against CalculiX")
    fig.tight_layout()
    save_figure(fig, FIGURE)
    print(FIGURE + ".png")


if __name__ == "__main__":
    main()
