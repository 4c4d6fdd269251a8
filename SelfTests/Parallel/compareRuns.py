#!/usr/bin/python3
"""Compares the last frames of .data files (Documentation/FileFormats/data.md) particle by
particle: prints the largest position and velocity differences from the first file and checks
them against a tolerance. Usage: compareRuns.py TOLERANCE REFERENCE.data OTHER.data...
(TOLERANCE 0: the frames must be equal to the last digit.)
compareRuns.py --parting TOLERANCE REFERENCE.data OTHER.data: every frame, for two runs of a
chaotic flow that may part by round-off: the first frame where they differ at all must differ by
at most TOLERANCE (a missed or extra contact would show at once, far above round-off).
With .restart files (tolerance 0 only): the particles' whole states, 17 digits, by id, must be
the same (Documentation/FileFormats/restart.md)."""
import sys


def restartParticles(path):
    with open(path) as f:
        lines = f.read().split("\n")
    k = next(i for i, line in enumerate(lines) if line.startswith("particles "))
    n = int(lines[k].split()[1])
    return sorted(lines[k + 1:k + 1 + n], key=lambda line: int(line.split()[0]))


if sys.argv[2].endswith(".restart"):
    reference = restartParticles(sys.argv[2])
    for path in sys.argv[3:]:
        if restartParticles(path) != reference:
            sys.exit(f"{path}: particle states differ from {sys.argv[2]}")
        print(f"{path}: the same particle states as {sys.argv[2]}, to the bit ({len(reference)} particles)")
    sys.exit(0)


def frames(path):
    with open(path) as f:
        lines = f.read().split("\n")
    k, result = 0, []
    while k < len(lines) and lines[k].strip():
        n = int(lines[k].split()[0])
        result.append([[float(x) for x in line.split()] for line in lines[k + 1:k + 1 + n]])
        k += n + 1
    if not result:
        sys.exit(f"{path}: no frames")
    return result


def largest_difference(a, b):
    """Of positions and velocities, the largest over the particles of two frames."""
    return max(abs(x - y) for p, q in zip(a, b) for x, y in zip(p[0:6], q[0:6]))


if sys.argv[1] == "--parting":
    tolerance, reference, other = float(sys.argv[2]), frames(sys.argv[3]), frames(sys.argv[4])
    if [len(f) for f in other] != [len(f) for f in reference]:
        sys.exit(f"{sys.argv[4]}: frames of other sizes than {sys.argv[3]}'s")
    first = None
    for k, (a, b) in enumerate(zip(reference, other)):
        worst = largest_difference(a, b)
        print(f"frame {k}: largest difference of positions and velocities {worst:.3g}")
        if worst > 0 and first is None:
            first = (k, worst)
    if first is not None and first[1] > tolerance:
        sys.exit(f"the runs part at frame {first[0]} by {first[1]:.3g}, more than round-off ({tolerance:.3g})")
    print("parted by round-off" if first else "equal in every frame")
    sys.exit(0)

tolerance = float(sys.argv[1])
reference = frames(sys.argv[2])
worst = 0.0
for path in sys.argv[3:]:
    other = frames(path)
    if len(other) != len(reference) or len(other[-1]) != len(reference[-1]):
        sys.exit(f"{path}: {len(other)} frames of {len(other[-1])} particles, "
                 f"{sys.argv[2]} has {len(reference)} of {len(reference[-1])}")
    dx = max(abs(a - b) for p, q in zip(reference[-1], other[-1]) for a, b in zip(p[0:3], q[0:3]))
    dv = max(abs(a - b) for p, q in zip(reference[-1], other[-1]) for a, b in zip(p[3:6], q[3:6]))
    print(f"{path}: largest difference from {sys.argv[2]}: position {dx:.3g}, velocity {dv:.3g}")
    worst = max(worst, dx, dv)
    if tolerance == 0 and other != reference:
        sys.exit(f"{path}: differs from {sys.argv[2]}")
if worst > tolerance:
    sys.exit(f"largest difference {worst:.3g} is above the tolerance {tolerance:.3g}")
