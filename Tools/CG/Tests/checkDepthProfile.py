#!/usr/bin/python3
"""Checks a depth profile written by talus-cg (--coordinates Z --fixed exclude --time-average):
its density integrates over z to the flowing mass per unit area.

usage: checkDepthProfile.py PROFILE.csv RUN.data RUN.restart

The flowing mass per unit area is computed here from the last frame of the .data file (radius,
species) and the restart file (densities, fixed flags), independently of talus-cg; the flowing
mass does not change between frames in a periodic chute, so it is the same for the averaged
frames. The integral is the midpoint rule on talus-cg's grid (points at the cell centres). The
Lucy kernel is twice continuously differentiable and the profile is a sum of such kernels, so the
midpoint rule's error is at most h^2/24 * int |rho''| dz; with h = 0.05 and w = 0.5,
|rho''| <= 12 c/w^3 per unit of mass per area (c = 5/4), which bounds the relative error by
h^2/24 * 2 * 12 * 1.25 / w^2 = 0.0050 in the worst case and by far less in practice: the test
asks for 1e-3, so a wrong normalisation, a lost particle or a wrong area (all of order one or
of a particle in 1500 = 7e-4 at least) would fail.
"""
import sys

import numpy as np


def read_csv(path):
    with open(path) as f:
        lines = [line for line in f if not line.startswith('#')]
    names = lines[0].strip().split(',')
    data = np.loadtxt(lines[1:], delimiter=',', ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def last_frame(path):
    with open(path) as f:
        lines = f.read().split('\n')
    start, frame = 0, None
    while start < len(lines) and lines[start].strip():
        header = lines[start].split()
        n = int(header[0])
        frame = (header, [line.split() for line in lines[start + 1:start + 1 + n]])
        start += 1 + n
    return frame


def restart_info(path):
    with open(path) as f:
        lines = f.read().split('\n')
    densities, fixed = [], []
    if lines[0].startswith('Talus restart'):
        for k, line in enumerate(lines):
            w = line.split()
            if w and w[0] == 'species':
                densities = [float(lines[k + 1 + s].split()[1]) for s in range(int(w[1]))]
            if w and w[0] == 'particles':
                rows = [lines[k + 1 + p].split() for p in range(int(w[1]))]
                rows.sort(key=lambda r: int(r[0]))
                fixed = [r[21] == '1' for r in rows]
    else:
        for line in lines:
            w = line.split()
            if w and w[0].endswith('Species') and 'density' in w and 'id' in w:
                densities.append(float(w[w.index('density') + 1]))
            if w and w[0] == 'BaseParticle':
                fixed.append(float(w[w.index('invMass') + 1]) == 0)
    return densities, fixed


def main():
    profile_path, data_path, restart_path = sys.argv[1:4]
    profile = read_csv(profile_path)
    header, particles = last_frame(data_path)
    densities, fixed = restart_info(restart_path)
    area = (float(header[5]) - float(header[2])) * (float(header[6]) - float(header[3]))
    mass = sum(densities[int(float(p[13]))] * 4 / 3 * np.pi * float(p[6]) ** 3
               for p, f in zip(particles, fixed) if not f)
    z = profile['z']
    h = z[1] - z[0]
    integral = profile['Density'].sum() * h
    expected = mass / area
    error = integral / expected - 1
    print(f"depth profile: int rho dz = {integral:.8g}, flowing mass per area = {expected:.8g}, "
          f"relative difference {error:.2e}")
    phi = [profile[k] for k in profile if k.startswith('Concentration_s')]
    if abs(error) < 1e-3 and all(((c >= 0) & (c <= 1)).all() for c in phi):
        print("depth profile ok")
    else:
        print("depth profile WRONG")
        sys.exit(1)


if __name__ == '__main__':
    main()
