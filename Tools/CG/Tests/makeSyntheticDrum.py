#!/usr/bin/python3
"""Writes NAME.data and NAME.restart of a synthetic rotating drum for talus-cg's cylindrical
coordinates (Documentation/CoarseGraining.md "Cylindrical coordinates"; Theory/RotatingDrum.md "The drum and its wall" sizes):
a drum of radius 15 along y through the origin, periodic along y (length 3), its lower half
filled with spheres on a jittered lattice of spacing 1, species 1 (d = 0.7) within r < 8 of the
axis (the core), species 0 (d = 1) outside; solid-body rotation v = omega e_y x x with omega = 0.1
in two frames (t = 0 and 1, the second rotated by omega). The restart file gives the densities,
the periodic axis and the cylinder wall (axis and radius), as a Talus drum run would.

usage: makeSyntheticDrum.py NAME
"""
import math
import random
import sys

RADIUS, LENGTH, OMEGA, CORE = 15.0, 3.0, 0.1, 8.0
DENSITY = (1.909859317102744, 1.909859317102744)


def particles(turn):
    random.seed(5)
    result = []
    for i in range(-15, 16):
        for k in range(-15, 1):
            for j in range(3):
                x = i + 0.15 * (random.random() - 0.5)
                z = k - 0.5 + 0.15 * (random.random() - 0.5)
                y = j + 0.5 + 0.15 * (random.random() - 0.5)
                r = math.hypot(x, z)
                if r > RADIUS - 0.6:
                    continue
                species = 1 if r < CORE else 0
                # Rotate the bed by `turn` about +y: (x, z) -> (x cos + z sin, -x sin + z cos).
                c, s = math.cos(turn), math.sin(turn)
                x, z = x * c + z * s, -x * s + z * c
                # v = omega e_y x (x, y, z) = omega (z, 0, -x)
                result.append((x, y, z, OMEGA * z, 0.0, -OMEGA * x, 0.35 if species else 0.5, species))
    return result


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    name = sys.argv[1]
    with open(name + '.data', 'w') as f:
        for t in (0.0, 1.0):
            ps = particles(OMEGA * t)
            f.write(f"{len(ps)} {t} {-RADIUS} 0 {-RADIUS} {RADIUS} {LENGTH} {RADIUS}\n")
            for x, y, z, vx, vy, vz, r, s in ps:
                f.write(f"{x!r} {y!r} {z!r} {vx!r} {vy!r} {vz!r} {r} 0 0 0 0 0 0 {s}\n")
    with open(name + '.restart', 'w') as f:
        f.write("Talus restart 5\n")
        f.write(f"domain {-RADIUS} 0 {-RADIUS} {RADIUS} {LENGTH} {RADIUS} 0 1 0\n")
        f.write("species 2\n")
        for k, d in enumerate(DENSITY):
            f.write(f"   s{k} {d!r} LinearSpringDashpot 1 1 1 1 0 1\n")
        f.write("walls 1\n")
        f.write(f"   0 1 0 0 0 0 0 0 {RADIUS}\n")
        f.write("shapes 0 0\nparticles 0 0\n")
    print(f"wrote {name}.data and {name}.restart ({len(particles(0))} particles)")


main()
