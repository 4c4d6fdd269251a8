#!/usr/bin/python3
"""Checks the vertical momentum balance of a static packing (issue 5: "the vertical stress
balances the weight above: d(sigma_zz)/dz = rho g_z within 2% in the bulk").

usage: checkStressBalance.py PROFILE.csv RUN.data RUN.restart G_Z WIDTH

PROFILE.csv is a talus-cg depth profile (--coordinates Z --fixed exclude --time-average, contact
stress on) of a packing at rest on a base of fixed particles, periodic in x and y (no side walls:
with frictional side walls part of the weight goes to the walls, Janssen's effect, and the
cross-section average of d(sigma_zz)/dz falls short of rho g_z by the wall shear per volume).

Why the balance holds, and where. In a 1-D profile the divergence of the contact stress is
exactly sum_i F_i,z W(z - z_i) / area over the ends of the contact segments (the particle
centres and the base particles' centres), and rho g_z is sum_i m_i g_z W(z - z_i) / area over
the flowing particles; a particle at rest has F_i + m_i g = 0. The two sides differ by
(a) the residual accelerations m_i a_i of a packing that is nearly at rest (its kinetic stress
is in StressZZ), and (b) the fixed base particles, which are not in rho and whose forces do not
balance. So the window is z >= (highest base centre) + w, where no base centre reaches the
kernel, and z <= (highest flowing centre) - w, below the free surface, where rho is the full
bulk density and the relative error is not a ratio of small numbers.

d(sigma_zz)/dz is a central difference on the grid; its error is h^2/6 |sigma'''|, with
|sigma'''| <= rho g |W''| <= rho g 12 c/w^3 (Lucy, c = 5/4): at h = 0.015, w = 1 a relative
error below 6e-4, well inside the 2%.
"""
import sys

import numpy as np

from checkDepthProfile import last_frame, read_csv, restart_info


def main():
    profile_path, data_path, restart_path = sys.argv[1:4]
    g_z, width = float(sys.argv[4]), float(sys.argv[5])
    profile = read_csv(profile_path)
    header, particles = last_frame(data_path)
    densities, fixed = restart_info(restart_path)
    z_base = max(float(p[2]) for p, f in zip(particles, fixed) if f)
    z_top = max(float(p[2]) for p, f in zip(particles, fixed) if not f)
    lo, hi = z_base + width, z_top - width
    z, rho, sigma = profile['z'], profile['Density'], profile['StressZZ']
    dsigma = np.gradient(sigma, z)
    inside = (z >= lo) & (z <= hi)
    inside[0] = inside[-1] = False
    error = np.abs(dsigma[inside] / (rho[inside] * g_z) - 1)
    worst = error.max()
    print(f"stress balance: window {lo:.3f} <= z <= {hi:.3f} (base top {z_base:.3f}, highest centre {z_top:.3f}, "
          f"w = {width}), {inside.sum()} points, largest |d(sigma_zz)/dz / (rho g_z) - 1| = {worst:.2e}, "
          f"mean {error.mean():.2e}")
    if inside.sum() >= 10 and worst < 0.02:
        print("stress balance ok")
    else:
        print("stress balance WRONG")
        sys.exit(1)


main()
