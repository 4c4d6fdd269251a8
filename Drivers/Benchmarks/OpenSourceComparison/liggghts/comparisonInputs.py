#!/usr/bin/env python3
"""The open-source comparison's published inputs in LIGGGHTS's formats: a start file (a header,
then "radius x y z" per line, m) as a data file for read_data (atom style granular: id type
diameter density x y z; type 1 = M1, d = 2 mm, type 2 = M2, d = 4 mm), and a wall file (a header,
then nine numbers per line: three corners, m) as an ASCII STL file for fix mesh/surface. With
--penetration the start file is a penetration bed: its last line describes the steel sphere, not a
bead, and is replaced by the sphere as the last atom (type 3, steel, d = 20 mm at (0, 0, 0.06) m;
its velocity is the input script's to set), as Talus's ComparisonPenetration places it.

    comparisonInputs.py data START.txt OUT.data [--box xlo xhi ylo yhi zlo zhi] [--penetration]
    comparisonInputs.py stl WALLS.txt OUT.stl
"""
import argparse
import math
import sys


def numbers(path, count, skip_last=False):
    with open(path) as f:
        lines = f.readlines()
    last = max((k for k, line in enumerate(lines) if line.strip()), default=0)
    for k, line in enumerate(lines[1:], 1):  # (after the header)
        if not line.strip() or (skip_last and k == last):
            continue
        try:
            values = [float(v) for v in line.split()]
        except ValueError:
            sys.exit(f"{path}:{k + 1}: expected {count} numbers, got '{line.strip()}'")
        if len(values) != count or not all(math.isfinite(v) for v in values):
            sys.exit(f"{path}:{k + 1}: expected {count} finite numbers, got '{line.strip()}'")
        yield values


def write_data(start, out, box, penetration):
    particles = [(r, x, y, z, 1 if r < 1.5e-3 else 2) for r, x, y, z in numbers(start, 4, skip_last=penetration)]
    if penetration:
        particles.append((0.01, 0.0, 0.0, 0.06, 3))
    density = {1: 2500.0, 2: 2000.0, 3: 7200.0}
    with open(out, "w") as f:
        f.write(f"LIGGGHTS data file from {start}\n\n{len(particles)} atoms\n3 atom types\n\n")
        for axis, (lo, hi) in zip("xyz", zip(box[0::2], box[1::2])):
            f.write(f"{lo} {hi} {axis}lo {axis}hi\n")
        f.write("\nAtoms\n\n")
        for i, (r, x, y, z, kind) in enumerate(particles, 1):
            f.write(f"{i} {kind} {2 * r!r} {density[kind]!r} {x!r} {y!r} {z!r}\n")
    print(f"wrote {out}: {len(particles)} particles")


def write_stl(walls, out):
    count = 0
    with open(out, "w") as f:
        f.write("solid walls\n")
        for v in numbers(walls, 9):
            a, b, c = v[0:3], v[3:6], v[6:9]
            u = [b[k] - a[k] for k in range(3)]
            w = [c[k] - a[k] for k in range(3)]
            n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            length = math.sqrt(sum(x * x for x in n))
            if length == 0:
                sys.exit(f"{walls}: triangle {count + 1} has no area")
            f.write("facet normal " + " ".join(repr(x / length) for x in n) + "\nouter loop\n")
            for p in (a, b, c):
                f.write("vertex " + " ".join(repr(x) for x in p) + "\n")
            f.write("endloop\nendfacet\n")
            count += 1
        f.write("endsolid walls\n")
    print(f"wrote {out}: {count} triangles")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("kind", choices=["data", "stl"])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--box", type=float, nargs=6, default=[-0.11, 0.11, -0.035, 0.035, -0.11, 0.11])
    parser.add_argument("--penetration", action="store_true", help="a penetration bed: its last line is the steel sphere")
    args = parser.parse_args()
    if args.kind == "data":
        write_data(args.input, args.output, args.box, args.penetration)
    else:
        write_stl(args.input, args.output)


if __name__ == "__main__":
    main()
