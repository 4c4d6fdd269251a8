#!/usr/bin/env python3
"""The drum of RotatingDrum in LIGGGHTS, for a side-by-side run (Drivers/Drum/liggghts/in.sphereDrum.liggghts;
Documentation/Drums/RotatingDrum.md, "The angle of repose against LIGGGHTS").

  liggghtsDrum.py data RUN.data T drum.data   the frame of a RotatingDrum run at time T (the bed at rest,
                                              the drum about to turn) as a LIGGGHTS data file: the bed's
                                              spheres type 1, the wall's particles type 2
  liggghtsDrum.py dump drum.dump T0 DT out.data
                                              a LIGGGHTS dump (id type radius x y z vx vy vz) as .data
                                              frames, at times T0 + step DT, the wall species 2 as the
                                              driver's (for talus-drum-angle)

Only spheres: an ellipsoid's frame line holds its bounding radius, which LIGGGHTS cannot take.
"""
import math
import sys

SPHERE_DENSITY = 6 / math.pi  # the driver's: a sphere of diameter 1 has mass 1
WALL_SPECIES = 2              # the driver's species: spheres 0, ellipsoids 1, wall 2


def fail(message):
    sys.exit(f"liggghtsDrum.py: {message}")


def read_frame(path, time):
    """The particles of the frame at `time` of a .data file: (box, [(x, y, z, vx, vy, vz, r, wx, wy, wz, species)])."""
    with open(path) as f:
        line_number = 0
        while True:
            header = f.readline()
            line_number += 1
            if not header:
                fail(f"{path}: no frame at t = {time}")
            fields = header.split()
            if len(fields) != 8:
                fail(f"{path}:{line_number}: a frame header has 8 numbers (N t xmin ymin zmin xmax ymax zmax), found {len(fields)}")
            count, t = int(fields[0]), float(fields[1])
            box = [float(v) for v in fields[2:]]
            lines = [f.readline() for _ in range(count)]
            if abs(t - time) > 1e-9 * max(1.0, abs(time)):
                line_number += count
                continue
            particles = []
            for k, line in enumerate(lines):
                v = line.split()
                if len(v) != 14:
                    fail(f"{path}:{line_number + k + 1}: a particle line has 14 columns, found {len(v)}")
                x, y, z, vx, vy, vz, r = (float(a) for a in v[:7])
                wx, wy, wz = (float(a) for a in v[10:13])
                particles.append((x, y, z, vx, vy, vz, r, wx, wy, wz, int(v[13])))
            return box, particles


def write_liggghts_data(box, particles, out):
    if any(p[10] not in (0, WALL_SPECIES) for p in particles):
        fail("the frame holds ellipsoids (species 1): LIGGGHTS takes spheres only (RotatingDrum --sphere-fraction 1)")
    with open(out, "w") as f:
        f.write("LIGGGHTS data file: the frame of a RotatingDrum run (liggghtsDrum.py)\n\n")
        f.write(f"{len(particles)} atoms\n2 atom types\n\n")
        for axis, (lo, hi) in enumerate(zip(box[:3], box[3:])):
            name = "xyz"[axis]
            f.write(f"{lo!r} {hi!r} {name}lo {name}hi\n")
        f.write("\nAtoms\n\n")
        for i, p in enumerate(particles, 1):
            kind = 2 if p[10] == WALL_SPECIES else 1
            f.write(f"{i} {kind} {2 * p[6]!r} {SPHERE_DENSITY!r} {p[0]!r} {p[1]!r} {p[2]!r}\n")
        f.write("\nVelocities\n\n")
        for i, p in enumerate(particles, 1):
            f.write(f"{i} {p[3]!r} {p[4]!r} {p[5]!r} {p[7]!r} {p[8]!r} {p[9]!r}\n")


def convert_dump(path, t0, dt, out):
    with open(path) as f:
        lines = f.read().split("\n")
    frames = 0
    k = 0
    with open(out, "w") as o:
        while k < len(lines) and lines[k].strip():
            if lines[k] != "ITEM: TIMESTEP":
                fail(f"{path}:{k + 1}: expected 'ITEM: TIMESTEP', found '{lines[k]}'")
            step = int(lines[k + 1])
            count = int(lines[k + 3])
            bounds = [lines[k + 5 + a].split()[:2] for a in range(3)]
            columns = lines[k + 8].split()[2:]
            need = ["id", "type", "radius", "x", "y", "z", "vx", "vy", "vz"]
            if columns[:len(need)] != need:
                fail(f"{path}:{k + 9}: the dump's columns must begin {' '.join(need)}, found {' '.join(columns)}")
            rows = sorted((lines[k + 9 + a].split() for a in range(count)), key=lambda r: int(r[0]))
            lo = [b[0] for b in bounds]
            hi = [b[1] for b in bounds]
            o.write(f"{count} {t0 + step * dt!r} {' '.join(lo)} {' '.join(hi)}\n")
            for r in rows:
                species = WALL_SPECIES if r[1] == "2" else 0
                o.write(f"{r[3]} {r[4]} {r[5]} {r[6]} {r[7]} {r[8]} {r[2]} 0 0 0 0 0 0 {species}\n")
            frames += 1
            k += 9 + count
    print(f"liggghtsDrum.py: {frames} frames to {out}", file=sys.stderr)


def main(argv):
    if len(argv) == 5 and argv[1] == "data":
        box, particles = read_frame(argv[2], float(argv[3]))
        write_liggghts_data(box, particles, argv[4])
    elif len(argv) == 6 and argv[1] == "dump":
        convert_dump(argv[2], float(argv[3]), float(argv[4]), argv[5])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
