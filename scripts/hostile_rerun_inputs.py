"""The hostile inputs of scripts/hostile_rerun.py: mutations (drawn from its seeded generator)
and the named inputs of issue 39's findings."""
import json
import os
from pathlib import Path

from hostile_rerun_support import whole_rows

HOSTILE_NUMBERS = ["nan", "inf", "-inf", "-1", "0", "1e308", "1e-310", "4294967297", "-4294967297", "9223372036854775808", "1e9",
                   "\"x\"", "[]", "{}", "true", "[[[[[[[[", "2.5"]
HOSTILE_STRINGS = ['""', '"a,b"', '"a\\nb"', '"a\\"b"', '"a\\tb"', '"a\\u0000b"', '"/dev/zero"', '"../../../../etc/passwd"',
                   '"' + "y" * 5000 + '"', "1", "[]"]
BOUNDARY_WORDS = [0, 1, 2, 3, 5, 6, 8, 14, 15, 16, 0x7F, 0xFFFF, 0x10000, 0x7FFFFFFF, 0x80000000, 0xFFFFFFFF]


def whole_rows_or_empty(path):
    return whole_rows(path)


def json_or_absent(path):
    if not Path(path).exists():
        return True
    try:
        json.loads(Path(path).read_text())
        return True
    except ValueError:
        return False


def mutate_toml(text, rng):
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        if not lines:
            break
        op = rng.randrange(9)
        k = rng.randrange(len(lines))
        line = lines[k]
        if op == 0:
            del lines[k]
        elif op == 1:
            lines.insert(k, line)
        elif op in (2, 3) and "=" in line:
            key = line.split("=", 1)[0]
            value = rng.choice(HOSTILE_NUMBERS if op == 2 else HOSTILE_STRINGS)
            lines[k] = f"{key}= {value}"
        elif op == 4:
            j = rng.randrange(len(lines))
            lines[k], lines[j] = lines[j], lines[k]
        elif op == 5 and line:
            at = rng.randrange(len(line))
            lines[k] = line[:at] + rng.choice(["[", "]", "{", "}", "\"", "'", "=", ",", "#", "\x00", "\xe9", "\\"]) + line[at + 1:]
        elif op == 6:
            lines[k] = line + " " + rng.choice(HOSTILE_NUMBERS)
        elif op == 7:
            lines.insert(k, rng.choice(["[model]", "[[elements]]", "[continuation]", "[[forcing]]", "[parameters]", "[[outputs]]"]))
        else:
            lines = lines[:k]
    text = "\n".join(lines)
    return ("\ufeff" + text) if rng.random() < 0.03 else text


def template_case(nodes):
    """Five per_node lists over `nodes` nodes (the finding's shape), the last value an unknown
    parameter, so the case is refused after the whole expansion."""
    dofs = min(nodes, 4000)
    names = ", ".join(f'"{i % dofs + 1}"' for i in range(nodes))
    text = f"[model]\ndofs = {dofs}\nM = {{ diagonal = [{', '.join(['1.0'] * dofs)}] }}\n"
    text += f"K = {{ diagonal = [{', '.join(['2.0'] * dofs)}] }}\n[[forcing]]\ndof = \"x1\"\ncos = 1.0\n[parameters]\nk = 1.0\n"
    for e in range(5):
        values = ["1.0"] * nodes
        if e == 4:
            values[-1] = '"nope"'
        text += f"[[elements]]\ntype = \"cubic_spring\"\nnodes = [{names}]\ndofs = \"x{{node}}\"\n"
        text += f"cubic_stiffness.per_node = [{', '.join(values)}]\n"
    return text + "[continuation]\nomega_start = 0.5\nomega_end = 1.5\nstep = 0.1\n"


TWO_BY_TWO_MTX = "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n1 1 2.0\n2 1 -1.0\n2 2 1.0\n"


def two_dof_case(k_spec):
    return f"""[model]
dofs = ["a", "b"]
M = [[1.0, 0.0], [0.0, 1.0]]
K = {k_spec}
[damping]
C = [[0.05, 0.0], [0.0, 0.05]]
[[forcing]]
dof = "a"
cos = 0.1
[[elements]]
type = "cubic_spring"
dofs = ["a"]
cubic_stiffness = 0.1
[harmonic_balance]
harmonics = 3
samples = 32
[continuation]
omega_start = 0.2
omega_end = 2.0
step = 0.02
[[outputs]]
name = "a"
dof = "a"
"""


def mutate_lines(text, rng, separator, values, own_edit):
    """One to three edits of a text format: a cell replaced by one of `values`, a line deleted,
    duplicated, swapped or the text cut there, or the format's `own_edit(lines, k, rng)`."""
    lines = text.split("\n")
    for _ in range(rng.randint(1, 3)):
        if not lines:
            break
        op, k = rng.randrange(6), rng.randrange(len(lines))
        if op == 0:
            cells = lines[k].split(separator)
            cells[rng.randrange(len(cells))] = rng.choice(values)
            lines[k] = separator.join(cells)
        elif op == 1:
            del lines[k]
        elif op == 2:
            lines.insert(k, lines[k])
        elif op == 3:
            j = rng.randrange(len(lines))
            lines[k], lines[j] = lines[j], lines[k]
        elif op == 4:
            lines = lines[:k]
        else:
            lines = own_edit(lines, k, rng)
    return "\n".join(lines)


def matrix_market_edit(lines, k, rng):
    if rng.random() < 0.4:
        lines[0] = lines[0].replace(rng.choice(["symmetric", "real", "coordinate", "matrix"]),
                                    rng.choice(["general", "skew-symmetric", "hermitian", "pattern", "complex", "array", "integer", ""]))
    elif rng.random() < 0.5 and len(lines) > 1:
        lines[1] = rng.choice(["4294967297 4294967297 1", "2 2 4000000", "5000000 5000000 3", "2 2 -3", "2 2", "0 0 0"])
    else:
        lines.insert(k, rng.choice(["%", "% comment", "", "1 1 1", "3 3 3", "2 2 1e308"]))
    return lines


def mutate_text_matrix(text, rng):
    values = HOSTILE_NUMBERS + ["", "0x10", "1 2", "-0", "5000000", "99999999999"]
    return mutate_lines(text, rng, " ", values, matrix_market_edit)


def mutate_binary(data, rng):
    data = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        op = rng.randrange(6)
        if not data:
            break
        at = rng.randrange(len(data))
        if op == 0:
            data[at] = rng.choice([0, 0xFF, 0x7F, 0x80, rng.randrange(256)])
        elif op in (1, 2):
            at = (at // 4) * 4
            word = rng.choice(BOUNDARY_WORDS) if op == 1 else rng.randrange(1 << 32)
            data[at:at + 4] = word.to_bytes(4, rng.choice(["little", "big"]))
        elif op == 3:
            del data[at:]
        elif op == 4:
            data[at:at] = bytes(rng.randrange(256) for _ in range(rng.choice([1, 2, 4, 8])))
        else:
            span = rng.randrange(1, 64)
            data[at:at] = data[at:at + span]
    return bytes(data)


def two_surfaces(path):
    """Rotor 67's hub and casing sections, 8 points each (as tests/test_blade_input_cli.cpp)."""
    surfaces = [[], []]
    header = False
    for line in Path(path).read_text().splitlines():
        if not line or line.startswith("#"):
            continue
        if not header:
            header = True
            continue
        cells = line.split(",")
        surface, point = int(cells[0]), int(cells[1])
        if surface in (1, 14) and (point == 1 or point % 10 == 0):
            surfaces[0 if surface == 1 else 1].append(cells)
    return surfaces


def sections_table(preamble, surfaces, between=0):
    hub, tip = surfaces[0], surfaces[-1]
    all_surfaces = [hub]
    for k in range(1, between + 1):
        f = k / (between + 1)
        all_surfaces.append([row[:2] + ["%.12g" % ((1 - f) * float(h) + f * float(t)) for h, t in zip(row[2:], tip_row[2:])]
                             for row, tip_row in zip(hub, tip)])
    all_surfaces += surfaces[1:]
    text = preamble + "surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n"
    for s, surface in enumerate(all_surfaces):
        for p, row in enumerate(surface):
            text += ",".join([str(s + 1), str(p + 1)] + row[2:]) + "\n"
    return text


def hostile_tables(surfaces):
    count = "# blade_count = 22\n"
    reversed_points = [list(reversed(s)) for s in surfaces]
    flat = [[row[:5] + ["0"] for row in s] for s in surfaces]
    subnormal = [[s[0][:5] + ["1e-310"]] + s[1:] for s in surfaces]
    tables = [("valid", sections_table(count, surfaces), ""), ("valid-subnormal", sections_table(count, subnormal), ""),
              ("reversed", sections_table(count, reversed_points), ""), ("no-thickness", sections_table(count, flat), ""),
              ("count-million", sections_table("# blade_count = 1000000\n", surfaces), ""),
              ("count-twice", sections_table(count + "# blade_count = 30\n", surfaces), ""),
              ("surfaces-150", sections_table(count, surfaces, 148), ""), ("surfaces-3000", sections_table(count, surfaces, 2998), ""),
              ("refine-17", sections_table(count, surfaces), "--refine 17"),
              ("rim-depth-negative", sections_table(count, surfaces), "--rim-depth=-5"),
              ("rim-depth-nan", sections_table(count, surfaces), "--rim-depth nan"), ("empty", "", ""),
              ("header-only", count + "surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n", "")]
    for value in ("0", "-1", "4294967297", "nan", "22.5", ""):
        tables.append((f"count-{value or 'empty'}", sections_table(f"# blade_count = {value}\n", surfaces), ""))
    return tables


def section_table_edit(lines, k, rng):
    cells = lines[k].split(",")
    lines[k] = ",".join(cells[:-1] if rng.random() < 0.5 else cells + ["1"])
    return lines


def mutate_table(text, rng):
    return mutate_lines(text, rng, ",", HOSTILE_NUMBERS + ["", "x", "1e400", "-0.5", "99999"], section_table_edit)


def hostile_json(saved, rng, truncations):
    """Summaries export must refuse in one line."""
    out = [("nested 100000 deep", b'{"verb": "frc", "x": ' + b"[" * 100000 + b"]" * 100000 + b"}"),
           ("objects nested 100000 deep", b'{"a":' * 100000 + b"1" + b"}" * 100000),
           ("malformed", b'{"verb": "frc", "points": 3,, }'), ("empty", b""), ("an array", b"[]"), ("a number", b"1"),
           ("NUL bytes", saved[:20] + b"\x00" * 8 + saved[20:])]
    for _ in range(truncations):
        at = rng.randrange(1, len(saved) - 2)
        out.append((f"cut at byte {at}", saved[:at]))
    return out


def hostile_checkpoints(saved, rng, truncations):
    """Checkpoints a resume must refuse in one line (exit 2), the stopped run's summary unchanged."""
    j = json.loads(saved)
    out = [("settings nested 200000 deep", saved.replace(b'"settings":', b'"settings": ' + b"[" * 200000 + b"]" * 200000 + b', "s":', 1)),
           ("empty", b""), ("an array", b"[]"), ("malformed", saved[:-1] + b",,}")]
    for name, edit in (("state.x one value short", lambda x: x[:-1]), ("state.x one value more", lambda x: x + [0.5]),
                       ("state.x a string", lambda x: "x"), ("state.x with a null", lambda x: [None] + x[1:])):
        edited = json.loads(saved)
        edited["state"]["x"] = edit(edited["state"]["x"])
        out.append((name, json.dumps(edited).encode()))
    if "settings" in j:
        edited = json.loads(saved)
        edited.pop("state")
        out.append(("no state", json.dumps(edited).encode()))
    for _ in range(truncations):
        at = rng.randrange(1, len(saved) - 2)
        out.append((f"cut at byte {at}", saved[:at]))
    return out


MODEL_EDITS = [("stiffness", lambda t: t.replace("K = [[1.0]]", "K = [[1.1]]")),
               ("damping", lambda t: t.replace("C = [[0.05]]", "C = [[0.06]]")),
               ("forcing", lambda t: t.replace("cos = 0.18", "cos = 0.19")),
               ("element", lambda t: t.replace("cubic_stiffness = 0.1", "cubic_stiffness = 0.11"))]


def hostile_cases(duffing, root):
    """(name, case text, words the refusal must hold ("" any), or None for a valid case)."""
    cases = []
    for name, toml in (("comma", '"a,b"'), ("newline", '"a\\nb"'), ("quote", '"a\\"b"'), ("tab", '"a\\tb"'), ("NUL", '"a\\u0000b"'),
                       ("empty", '""')):
        cases.append((f"dof name with {name}", duffing.replace('"x"', toml), "model.dofs"))
    cases.append(("parameter name with a comma", duffing.replace("amplitude = 1.0", 'amplitude = 1.0\n"k,2" = 1.0'), "parameter name"))
    cases.append(("dofs = 5000", duffing.replace('dofs = ["x"]', "dofs = 5000"), "4000"))
    cases.append(("dofs = 4294967297", duffing.replace('dofs = ["x"]', "dofs = 4294967297"), ""))
    cases.append(("harmonics = 4294967297", duffing.replace("harmonics = 7", "harmonics = 4294967297"), "harmonics"))
    cases.append(("cubic_stiffness = 1e-310 (valid)", duffing.replace("cubic_stiffness = 0.1", "cubic_stiffness = 1e-310"), None))
    cases.append(("8 KB of [", duffing.replace("amplitude = 1.0", "amplitude = " + "[" * 8192), "nested deeper than 64"))
    return cases


def hostile_flags(duffing, root, work):
    rigid = Path(work) / "rigid.toml"
    rigid.write_text(two_dof_case("[[1.0, -1.0], [-1.0, 1.0]]"))
    dlft = root / "examples" / "frictional_contact_dlft.toml"
    return [("backbone --mode 4294967297", ["backbone", duffing, "--mode", "4294967297", "--range", "0.01:2", "-q"], "--mode"),
            ("backbone subharmonic = 2", ["backbone", duffing, "--set", "harmonic_balance.subharmonic=2", "--range", "0.01:2", "-q"],
             ""),
            ("backbone of a rigid-body mode", ["backbone", rigid, "--mode", "1", "--range", "0.01:2", "-q"], "rigid-body mode"),
            ("backbone with a dlft element", ["backbone", dlft, "--range", "0.01:2", "-q"], "dlft"),
            ("isolas --at nan", ["isolas", duffing, "--from", work, "--at", "nan", "-q"], ""),
            ("sweep of 1e8 tasks", ["sweep", duffing, "-q", "--param", "amplitude", "--values", "1:2:100000000"], ""),
            ("case path /dev/zero", ["frc", "/dev/zero", "-q"], "not a regular file"),
            ("--set with a comment", ["frc", duffing, "-q", "--set", "amplitude=1 #2"], ""),
            ("--set 20000 [", ["frc", duffing, "-q", "--set", "amplitude=" + "[" * 20000], "")]


def small_study(duffing):
    """The Duffing oscillator's limit points tracked in the amplitude (tests/test_study_resume_cli.cpp)."""
    return duffing + ('\n[study]\ntrack = [ { parameter = "amplitude", range = [0.5, 3.0], validate = [2.5] } ]\nmax_points = 40\n'
                      "simulate_periods = 0\n")


def study_stop(folder):
    try:
        return json.loads((Path(folder) / "summary.json").read_text()).get("stop_reason")
    except (OSError, ValueError):
        return "running"


def without_timings(j):
    if isinstance(j, dict):
        return {k: without_timings(v) for k, v in j.items() if k not in ("wall_s", "timings", "resumed_steps", "jobs", "runner")}
    if isinstance(j, list):
        return [without_timings(v) for v in j]
    return j


def same_study(folder, reference):
    """Every CSV table byte for byte, and the summary without its times, as the reference study's."""
    folder, reference = Path(folder), Path(reference)
    tables = sorted(p.relative_to(reference) for p in reference.rglob("*.csv"))
    if tables != sorted(p.relative_to(folder) for p in folder.rglob("*.csv")):
        return False
    if any((folder / t).read_bytes() != (reference / t).read_bytes() for t in tables):
        return False
    summaries = [without_timings(json.loads((f / "summary.json").read_text())) for f in (folder, reference)]
    return summaries[0] == summaries[1]


def python_sweep(duffing, folder):
    """A sweep of long tasks (tests/test_reliability.py's), exit 3 on the KeyboardInterrupt."""
    return f"""import hbtrack
try:
    hbtrack.sweep({str(duffing)!r}, {str(folder)!r}, grid={{"amplitude": [0.5, 1.0, 1.5, 2.0]}}, jobs=2,
                  set={{"continuation.step": 0.0002, "continuation.step_max": 0.0002, "continuation.max_points": 100000}})
except KeyboardInterrupt:
    raise SystemExit(3)
"""


def processes_naming(folder):
    """The processes whose command line names `folder`."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and int(entry.name) != os.getpid():
            try:
                if str(folder).encode() in (entry / "cmdline").read_bytes():
                    found.append(int(entry.name))
            except OSError:
                pass
    return found
