#!/usr/bin/python3
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
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Plot"))
from dataFrames import read_frame  # noqa: E402

SPHERE_DENSITY = 6 / math.pi  # the driver's: a sphere of diameter 1 has mass 1
WALL_SPECIES = 2              # the driver's species: spheres 0, ellipsoids 1, wall 2
PROGRAM = "liggghtsDrum.py"


def fail(message):
    sys.exit(f"{PROGRAM}: {message}")


def frame_at(path, time):
    """The box and the particles (x, y, z, vx, vy, vz, r, wx, wy, wz, species) of the frame at `time`."""
    found, rows, header = read_frame(path, time, PROGRAM)
    if abs(found - time) > 1e-9 * max(1.0, abs(time)):
        fail(f"{path}: no frame at t = {time:g} (the nearest is at t = {found:g})")
    particles = [tuple(float(v) for v in r[:7]) + tuple(float(v) for v in r[10:13]) + (int(r[13]),) for r in rows]
    return header[2:], particles


def write_liggghts_data(box, particles, out):
    if any(p[10] not in (0, WALL_SPECIES) for p in particles):
        fail("the frame holds ellipsoids (species 1): LIGGGHTS takes spheres only (RotatingDrum --sphere-fraction 1)")
    with open(out, "w") as f:
        f.write("LIGGGHTS data file: the frame of a RotatingDrum run (liggghtsDrum.py)\n\n")
        f.write(f"{len(particles)} atoms\n2 atom types\n\n")
        for axis, (lo, hi) in enumerate(zip(box[:3], box[3:])):
            name = "xyz"[axis]
            f.write(f"{lo:.17g} {hi:.17g} {name}lo {name}hi\n")
        f.write("\nAtoms\n\n")
        for i, p in enumerate(particles, 1):
            kind = 2 if p[10] == WALL_SPECIES else 1
            f.write(f"{i} {kind} {2 * p[6]:.17g} {SPHERE_DENSITY:.17g} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}\n")
        f.write("\nVelocities\n\n")
        for i, p in enumerate(particles, 1):
            f.write(f"{i} {p[3]:.17g} {p[4]:.17g} {p[5]:.17g} {p[7]:.17g} {p[8]:.17g} {p[9]:.17g}\n")


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
            o.write(f"{count} {t0 + step * dt:.17g} {' '.join(lo)} {' '.join(hi)}\n")
            for r in rows:
                species = WALL_SPECIES if r[1] == "2" else 0
                o.write(f"{r[3]} {r[4]} {r[5]} {r[6]} {r[7]} {r[8]} {r[2]} 0 0 0 0 0 0 {species}\n")
            frames += 1
            k += 9 + count
    print(f"liggghtsDrum.py: {frames} frames to {out}", file=sys.stderr)


def main(argv):
    if len(argv) == 5 and argv[1] == "data":
        box, particles = frame_at(argv[2], float(argv[3]))
        write_liggghts_data(box, particles, argv[4])
    elif len(argv) == 6 and argv[1] == "dump":
        convert_dump(argv[2], float(argv[3]), float(argv[4]), argv[5])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv)
