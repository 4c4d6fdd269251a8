#!/usr/bin/python3
"""Checks, on one frame of real files, that with --fixed boundary every contact force arrives at
the centre of the flowing particle it acts on (Documentation/CoarseGraining.md "Boundaries"):

    -d(ContactStress_az)/dz + InteractionForce_a = sum over flowing i of F_i,a W(z - z_i) / area

usage: checkBoundaryForces.py PROFILE.csv RUN.data RUN.fstat RUN.restart TIME WIDTH

PROFILE.csv is talus-cg's depth profile (--coordinates Z, Lucy kernel of width WIDTH,
--fixed boundary) of the frame at TIME, on a fine grid. The right-hand side is computed here,
independently of talus-cg, from the file text: F_i is the sum of the contact forces on the
flowing particle i of that frame's .fstat lines (Documentation/FileFormats/fstat.md: the force on
i is fn n + ft t, for a wall -(fn n + ft t)), a line written from a fixed particle's side giving
its partner the reaction, a pair written from both sides counted once from each side with half
weight; contacts among fixed particles and of fixed particles with walls drop out. W is the 1-D
Lucy kernel (5/4)/w (1 - 6q^2 + 8q^3 - 3q^4), q = |z - z_i|/w < 1.

The identity is exact for any frame, in equilibrium or not (the divergence of a contact's stress
segment is f [W(r - end) - W(r - start)]). What is left is the central difference of the
profile: its error is at most h^2/6 max|Q''| with Q the right-hand side, |Q''| <= sum_i |F_i|
|W''| / area and |W''| <= 15/w^3; the script asks the two sides to agree within twice this
bound plus the printed digits' share (12 digits of the stress, divided by 2h).
Prints "boundary forces ok" when they agree.
"""
import sys
from collections import defaultdict

import numpy as np

from checkDepthProfile import read_csv, restart_info


def data_frame(path, time):
    with open(path) as f:
        lines = f.read().split('\n')
    at = 0
    while at < len(lines) and lines[at].strip():
        header = lines[at].split()
        n = int(header[0])
        if abs(float(header[1]) - time) <= 1e-9 * max(1, abs(time)):
            return header, [[float(v) for v in line.split()] for line in lines[at + 1:at + 1 + n]]
        at += 1 + n
    sys.exit(f"checkBoundaryForces.py: no frame at t = {time} in {path}")


def fstat_frame(path, time):
    rows, inside = [], False
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                words = line.split()
                if len(words) == 3 and not rows:
                    inside = abs(float(words[1]) - time) <= 1e-9 * max(1, abs(time))
                elif len(words) == 3 and rows:
                    break
                continue
            if inside:
                rows.append(line.split())
    return rows


def main():
    profile_path, data_path, fstat_path, restart_path = sys.argv[1:5]
    time, width = float(sys.argv[5]), float(sys.argv[6])
    header, particles = data_frame(data_path, time)
    densities, fixed = restart_info(restart_path)
    area = (float(header[5]) - float(header[2])) * (float(header[6]) - float(header[3]))
    lines = fstat_frame(fstat_path, time)
    sides = defaultdict(int)
    for w in lines:
        i, j = int(w[1]), int(w[2])
        if j >= 0:
            sides[(min(i, j), max(i, j))] += 1
    force = np.zeros((len(particles), 3))
    boundary_lines = 0
    for w in lines:
        i, j = int(w[1]), int(w[2])
        fn, ft = float(w[8]), float(w[9])
        n = np.array([float(v) for v in w[10:13]])
        t = np.array([float(v) for v in w[13:16]])
        f = fn * n + ft * t
        if j < 0:
            f = -f
            if not fixed[i]:
                force[i] += f
                boundary_lines += 1
            continue
        weight = 1.0 / sides[(min(i, j), max(i, j))]
        if fixed[i] and fixed[j]:
            continue
        if not fixed[i]:
            force[i] += weight * f
        if not fixed[j]:
            force[j] -= weight * f  # the reaction (a line from j's side adds the other half)
        boundary_lines += fixed[i] or fixed[j]
    profile = read_csv(profile_path)
    z = profile['z']
    h = z[1] - z[0]
    zi = np.array([p[2] for p in particles])
    mobile = ~np.array(fixed)
    worst, scale = 0.0, 0.0
    for a, name in enumerate('XYZ'):
        q = np.abs(z[:, None] - zi[None, mobile]) / width
        W = np.where(q < 1, 1.25 / width * (1 - 6 * q ** 2 + 8 * q ** 3 - 3 * q ** 4), 0.0)
        expected = W @ force[mobile, a] / area
        measured = -np.gradient(profile['ContactStress' + name + 'Z'], z) + profile['InteractionForce' + name]
        inside = slice(1, -1)  # np.gradient is one-sided at the ends
        bound = h ** 2 / 6 * np.abs(force[mobile, a]).sum() / area * 15 / width ** 3
        digits = 1e-12 * np.abs(profile['ContactStress' + name + 'Z']).max() / (2 * h)
        error = np.abs(measured - expected)[inside].max()
        scale = max(scale, np.abs(expected).max())
        print(f"{name}: largest |-d(sigma_{name.lower()}z)/dz + f_b - sum F W| = {error:.3g} "
              f"(bound {2 * bound + 10 * digits:.3g}; largest sum F W {np.abs(expected).max():.4g})")
        if error > 2 * bound + 10 * digits:
            print("boundary forces WRONG")
            sys.exit(1)
        worst = max(worst, error)
    print(f"{len(lines)} contact lines at t = {time}, {boundary_lines} with the boundary (walls and fixed particles)")
    if boundary_lines == 0 or scale == 0:
        print("boundary forces WRONG: no boundary contacts in the frame")
        sys.exit(1)
    print("boundary forces ok")


main()
