"""python/lanczos_filter_table.py (docs/rotor67.md's filter table) on two synthetic NFRCs whose
differences are known: an S-shaped branch with two folds, the unfiltered one 2 % larger on its
middle stretch only and its lower fold 1 % higher."""
import csv
import importlib.util
import json
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[1] / "lanczos_filter_table.py"
spec = importlib.util.spec_from_file_location("lanczos_filter_table", SCRIPT)
table = importlib.util.module_from_spec(spec)
spec.loader.exec_module(table)


def s_branch(folder, lower_fold, middle_gain):
    """Three stretches: up to omega 3 (fold after row 2), back to lower_fold (fold after row 5),
    up again; the middle stretch's extremes scaled by middle_gain."""
    omegas = [1.0, 2.0, 3.0, 2.9, 2.0, lower_fold, lower_fold + 0.1, 3.0, 4.0]
    peaks = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 6.1, 5.0, 1.0]
    rows = []
    for i, (w, p) in enumerate(zip(omegas, peaks)):
        p = p * middle_gain if 3 <= i <= 5 else p
        rows.append({"omega": w, "stable": 1, "max_x": p, "min_x": -0.5 * p})
    folder.mkdir()
    with open(folder / "branch.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    specials = [{"type": "LP", "index": 2, "omega": 3.0}, {"type": "LP", "index": 5, "omega": lower_fold}]
    (folder / "summary.json").write_text(json.dumps({"outputs": [{"name": "x"}], "special_points": specials}))
    return table.load(folder)


def test_stretches_end_before_each_fold_and_start_after_it(tmp_path):
    summary, rows, _ = s_branch(tmp_path / "f", 1.5, 1.0)
    assert table.stretches(rows, summary) == [(0, 2), (3, 5), (6, 8)]


def test_the_middle_stretch_is_the_only_one_reported_and_the_fold_shift_is_measured(tmp_path):
    filtered = s_branch(tmp_path / "f", 1.5, 1.0)
    unfiltered = s_branch(tmp_path / "u", 1.5 * 1.01, 1.02)
    points = table.special_point_rows("s", filtered, unfiltered)
    # The folds in omega order: the lower one moved by +1 %, the upper one not at all.
    assert points == ["| s | LP | 1.50 | 1.52 | +1.00 % |", "| s | LP | 3.00 | 3.00 | +0.00 % |"]
    rows = table.stretch_rows("s", filtered, unfiltered)
    assert len(rows) == 3
    # Outer stretches identical (a check that compared the wrong stretches would see 30 % and more).
    assert "+0.00 % at" in rows[0] and rows[0].endswith("| none |")
    assert "+0.00 % at" in rows[2] and rows[2].endswith("| none |")
    # The middle stretch: +2 % wherever both cover the omega (2.0 and 2.9; 1.5 lies below the
    # unfiltered stretch's 1.515 and is skipped, not extrapolated).
    assert "+2.00 % at" in rows[1] and rows[1].endswith("| 2-3 |")


def test_branches_with_different_fold_counts_are_not_paired(tmp_path):
    filtered = s_branch(tmp_path / "f", 1.5, 1.0)
    summary, rows, names = s_branch(tmp_path / "u", 1.5, 1.0)
    summary["special_points"] = summary["special_points"][:1]
    assert "not paired" in table.stretch_rows("s", filtered, (summary, rows, names))[0]
