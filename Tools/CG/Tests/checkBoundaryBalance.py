#!/usr/bin/python3
"""Checks the momentum balance of a steady chute flow near its base with the base as a boundary
(talus-cg --fixed boundary; Documentation/CoarseGraining.md "Boundaries"; Weinhart, Thornton,
Luding and Bokhove 2012, Granular Matter 14).

usage: checkBoundaryBalance.py FRAMES.csv AVERAGE.csv EXCLUDE.csv RUN.data RUN.restart ANGLE WIDTH

FRAMES.csv is a depth profile (--coordinates Z --fixed boundary, Lucy kernel of width WIDTH) of
every frame of a steady periodic chute flow at ANGLE degrees under unit gravity, on a coarse
grid; AVERAGE.csv the time average of the same frames on a fine grid (step h), EXCLUDE.csv that
average with --fixed exclude on the same fine grid.

The balance. At every instant and height the coarse-grained fields satisfy exactly
    d(p_a)/dt = -d(T_az)/dz + rho g_a + F_a,    T = Stress + p p / rho = K + sigma_contact,
with F the InteractionForce (the unit test BoundaryBalanceTest.cc shows it to round-off on a
packing in equilibrium). T, rho and F are linear in the sums, so the residual
    R_a(z) = -d(T_az)/dz + rho g_a + F_a
of the time average is the mean over the frames of d(p_a)/dt, whose expectation vanishes in a
steady flow. It is not zero in a finite sample: every frame catches the particles in the middle of
collisions, and the per-frame residual at a height fluctuates by about rho g itself. The frames
are nearly independent (their lag-one correlation is printed), so the mean has the standard error
s(z) = std / sqrt(N) (inflated for the measured lag-one correlation as for an AR(1) series).
(s comes from the frames on the coarse grid, interpolated to the fine one: it varies on the
scale of the kernel width.) The test asks, at every height of the profile, base included:
  - |R(z)| <= 4.5 s(z) + 2e-3 rho_max g: consistent with zero (4.5 standard errors: over about
    (height range) / (kernel width) = 7 independent heights a false alarm has odds below 1e-4);
  - s(z) <= 5% of rho_max g: the frames resolve the balance to a few percent of rho g (with 300
    frames of 600 particles and w = 2 the largest s is about 4%, in the bulk; |R| itself is
    printed, 4.5% at most in this run).
d/dz of the average is a central difference on the fine grid; its error scales as h^2 (the
profile is a sum of Lucy kernels, twice continuously differentiable). Measured on this chute
with w = 2: 1.2% of rho_max g at h = 0.1 next to the base, where the boundary force has its
sharpest features, hence h = 0.025 (0.08%) and the floor 2e-3 rho_max g.

Basal friction. The base's force per area is the traction t = int F dz (midpoint rule: the
kernel integrates to one). By the momentum balance of the whole layer, t = -(weight per area)
in a steady flow, so mu = -t_x / t_z = tan(angle); asked within 4 standard errors (delta method
over the frames' tractions; about 1.3% of tan(angle) here). The stress just above the boundary layer (the lowest
height the boundary force no longer reaches, base top + w) carries the weight above it, so there
-T_xz / T_zz = tan(angle) as well, asked within 4 standard errors.

Boundary and exclude: both leave the fixed particles out of rho; they differ only in the
contacts that touch the base, whose segments and forces lie below the top of the base (the
chute's bottom wall lies below the base). So more than the kernel's reach w above the base top
the two profiles must agree to the printed digits (1e-9 of each column's largest value), and
below it they must differ (the test sees the two treatments).
Prints "boundary balance ok" when all hold.
"""
import math
import sys

import numpy as np

from checkDepthProfile import last_frame, read_csv, restart_info


def fail(message):
    print("boundary balance WRONG: " + message)
    sys.exit(1)


def residual(fields, g):
    """R_a(z) for a = x, y, z, and the momentum flux T_az."""
    z, rho = fields['z'], fields['Density']
    safe = np.where(rho > 0, rho, 1)
    out, flux = [], []
    for a, name in enumerate('XYZ'):
        T = fields['Stress' + name + 'Z'] + np.where(rho > 0, fields['Momentum' + name] * fields['MomentumZ'] / safe, 0)
        flux.append(T)
        out.append(-np.gradient(T, z) + rho * g[a] + fields['InteractionForce' + name])
    return np.array(out), np.array(flux)


def main():
    frames_path, average_path, exclude_path, data_path, restart_path = sys.argv[1:6]
    angle, width = math.radians(float(sys.argv[6])), float(sys.argv[7])
    g = np.array([math.sin(angle), 0.0, -math.cos(angle)])
    average = read_csv(average_path)
    z = average['z']
    h = z[1] - z[0]
    R, T = residual(average, g)
    scale = average['Density'].max()  # rho_max |g|, |g| = 1

    frames = read_csv(frames_path)
    times = np.unique(frames['t'])
    per_frame, fluxes, tractions = [], [], []
    for t in times:
        one = {name: column[frames['t'] == t] for name, column in frames.items()}
        r, flux = residual(one, g)
        per_frame.append(r)
        fluxes.append(flux)
        tractions.append([one['InteractionForce' + a].sum() * (one['z'][1] - one['z'][0]) for a in 'XZ'])
    per_frame, fluxes, tractions = np.array(per_frame), np.array(fluxes), np.array(tractions)
    coarse = one['z']
    n = len(times)
    lag = np.mean([np.corrcoef(per_frame[:-1, a, k], per_frame[1:, a, k])[0, 1]
                   for a in (0, 2) for k in range(0, len(coarse), 5) if per_frame[:, a, k].std() > 0])
    inflation = math.sqrt((1 + max(lag, 0)) / (1 - max(lag, 0)))
    stderr = np.array([np.interp(z, coarse, per_frame[:, a].std(axis=0, ddof=1)) for a in range(3)])
    stderr *= inflation / math.sqrt(n)

    worst_sigma, worst = 0.0, 0.0
    for a in (0, 1, 2):
        excess = np.abs(R[a]) / (4.5 * stderr[a] + 2e-3 * scale)
        worst_sigma = max(worst_sigma, (np.abs(R[a]) / np.maximum(stderr[a], 1e-300))[stderr[a] > 0].max())
        worst = max(worst, np.abs(R[a]).max() / scale)
        if excess.max() > 1:
            k = excess.argmax()
            fail(f"R_{'xyz'[a]} = {R[a][k]:.4g} at z = {z[k]:.3f} is {abs(R[a][k]) / stderr[a][k]:.1f} standard errors "
                 f"({stderr[a][k]:.3g}) from zero")
    largest_stderr = stderr.max() / scale
    print(f"momentum balance: {n} frames (lag-one correlation {lag:.3f}), {len(z)} heights {z[0]:.2f} to {z[-1]:.2f}: "
          f"largest |R| = {worst:.4f} rho_max g, largest standard error {largest_stderr:.4f} rho_max g, "
          f"largest |R| / standard error {worst_sigma:.2f}")
    if largest_stderr > 0.05:
        fail("the standard error of the frame average exceeds 5% of rho g: too few frames to resolve the balance")

    # Basal friction from the traction.
    tx, tz = (average['InteractionForce' + a].sum() * h for a in 'XZ')
    mu = -tx / tz
    # delta method: mu = -tx/tz, var(mu) = var(tx + mu tz) / (N tz^2)
    sigma_mu = (tractions[:, 0] + mu * tractions[:, 1]).std(ddof=1) / math.sqrt(n) / abs(tz) * inflation
    header, particles = last_frame(data_path)
    densities, fixed = restart_info(restart_path)
    area = (float(header[5]) - float(header[2])) * (float(header[6]) - float(header[3]))
    weight = sum(densities[int(float(p[13]))] * 4 / 3 * math.pi * float(p[6]) ** 3
                 for p, f in zip(particles, fixed) if not f) / area
    tan = math.tan(angle)
    print(f"basal friction: traction ({tx:.5g}, {tz:.5g}) per area, weight per area {weight:.5g} "
          f"(normal part {weight * math.cos(angle):.5g}); -t_x/t_z = {mu:.4f} +- {sigma_mu:.4f}, tan(angle) = {tan:.4f}")
    if abs(mu - tan) > 4 * sigma_mu:
        fail("the basal friction of the traction is not tan(angle)")
    base_top = max(float(p[2]) + float(p[6]) for p, f in zip(particles, fixed) if f)
    k = np.searchsorted(z, base_top + width)
    ratio = -T[0][k] / T[2][k]
    c = np.searchsorted(coarse, z[k])
    sigma_ratio = (fluxes[:, 0, c] + ratio * fluxes[:, 2, c]).std(ddof=1) / math.sqrt(n) / abs(T[2][k]) * inflation
    print(f"stress above the boundary layer: z = {z[k]:.3f} (base top {base_top:.3f} + w), "
          f"-T_xz/T_zz = {ratio:.4f} +- {sigma_ratio:.4f}")
    if abs(ratio - tan) > 4 * sigma_ratio + 1e-3:
        fail("the stress ratio above the boundary layer is not tan(angle)")

    # --fixed exclude agrees more than w above the base top.
    exclude = read_csv(exclude_path)
    above = z > base_top + width
    differ = False
    for name, column in average.items():
        if name == 'z':
            continue
        size = max(np.abs(column).max(), 1e-300)
        if np.abs(column - exclude[name])[above].max() > 1e-9 * size:
            fail(f"{name} of --fixed boundary and exclude differ at z > {base_top + width:.3f}")
        differ = differ or np.abs(column - exclude[name])[~above].max() > 1e-3 * size
    if not differ:
        fail("--fixed boundary and exclude agree near the base as well: the test cannot see the boundary")
    print(f"--fixed boundary and exclude agree above z = {base_top + width:.3f} and differ below")
    print("boundary balance ok")


main()
