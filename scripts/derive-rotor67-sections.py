#!/usr/bin/env python3
"""Derives hbtrack's rotor 67 section table from NASA's published geometry.

Source: NASA Lewis Research Center, "Rotor 67 geometry for export" (1991, re-run 1992), the
geometry of NASA TP-2879 (Strazisar, Wood, Hathaway & Suder, 1989). The file gives 14 stream
surfaces (1 = hub, 14 = casing), each of 110 points in feet, of which points 16..85 (1-based) are
the blade. This script keeps the blade's points, converts them to metres and writes one row per
point: surface, point (1..70 from the leading to the trailing edge), axial position, radius, r*theta
of the suction (upper) surface and the tangential thickness r*dtheta (pressure surface =
suction - thickness). Nothing is smoothed or moved: the mesh generator (hbtrack make-blade
--geometry) resamples these sections by arc length and floors the edge thickness itself.

Usage: derive-rotor67-sections.py NASA_FILE OUT_CSV
"""
import sys

FOOT = 0.3048  # m, exact
FIELD = 10     # the file's 8F10.6 columns


def numbers(lines, start, count):
    """`count` fixed-width numbers from lines[start:], and the index of the next line."""
    values, i = [], start
    while len(values) < count:
        line = lines[i].rstrip("\n")
        for k in range(0, len(line), FIELD):
            text = line[k:k + FIELD].strip()
            if text:
                values.append(float(text))
        i += 1
    if len(values) != count:
        raise ValueError(f"line {i}: expected {count} numbers, read {len(values)}")
    return values, i


def read_nasa_geometry(path):
    """Per surface: dict of 'axial', 'rtheta', 'thickness', 'radius' lists (feet), and JLE, JTE."""
    lines = open(path, encoding="ascii").readlines()
    header = next(i for i, l in enumerate(lines) if l.split()[:5] == ["JM", "NS", "NB", "JLE", "JTE"]
                  and i > 0 and "Formats" not in lines[i - 1])
    jm, ns, nb, jle, jte = (int(v) for v in lines[header + 1].split())
    surfaces, i = [], header + 2
    blocks = ("axial", "rtheta", "thickness", "radius")
    for s in range(ns):
        while "Surface number" not in lines[i]:
            i += 1
        if int(lines[i].split()[2]) != s + 1:
            raise ValueError(f"line {i + 1}: expected surface {s + 1}")
        i += 1
        surface = {}
        for block in blocks:
            i += 1                       # the block's title
            scale, i = numbers(lines, i, 1)
            data, i = numbers(lines, i, jm)
            surface[block] = [scale[0] * v for v in data]
        surfaces.append(surface)
    return surfaces, (jm, ns, nb, jle, jte)


def main(argv):
    if len(argv) != 3:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    surfaces, (jm, ns, nb, jle, jte) = read_nasa_geometry(argv[1])
    with open(argv[2], "w", encoding="ascii") as out:
        out.write("# NASA rotor 67 blade sections, derived by scripts/derive-rotor67-sections.py from NASA\n"
                  "# Lewis RC's 'Rotor 67 geometry for export' (1991/1992; NASA TP-2879): the blade's points\n"
                  f"# {jle}..{jte} of its {ns} stream surfaces (1 = hub, {ns} = casing), {nb} blades, feet -> metres.\n"
                  "# X is the rotation axis; theta is NASA's angle (pressure surface = suction - thickness).\n"
                  f"# blade_count = {nb}\n")
        out.write("surface,point,axial_m,radius_m,rtheta_suction_m,tangential_thickness_m\n")
        for s, surface in enumerate(surfaces, start=1):
            for p, j in enumerate(range(jle - 1, jte), start=1):
                row = [surface[k][j] * FOOT for k in ("axial", "radius", "rtheta", "thickness")]
                out.write(f"{s},{p}," + ",".join(f"{v:.9f}" for v in row) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
