#!/usr/bin/python3
"""Plots the stress and the boundary force near the base of a chute flow from a talus-cg depth
profile made with --fixed boundary (Documentation/CoarseGraining.md "Boundaries").

usage: plotBoundaryBalance.py PROFILE.csv [--exclude EXCLUDE.csv] [--angle DEG] [-o FIGURE.png]

Left: the normal stress sigma_zz (and, with --exclude, that of --fixed exclude on the same grid).
Middle: the boundary's force density InteractionForce (z and -x components) and the weight
density rho g (components along -z and x). Right: the residual of the momentum balance of the
time average, -d(T_az)/dz + rho g_a + InteractionForce_a with T = Stress + p p / rho, for a = x, z
(gravity of unit magnitude at --angle degrees, default 24).
"""
import argparse
import math
import sys

import matplotlib
import numpy as np

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
from cgFiles import read_cg_csv  # noqa: E402


def read_profile(path):
    p, _ = read_cg_csv(path, 'plotBoundaryBalance.py')
    if 'z' not in p or 'InteractionForceZ' not in p or 't' in p:
        sys.exit(f"{path}: expected a time-averaged depth profile with the contact stress "
                 "(talus-cg --coordinates Z --time-average with a .fstat file)")
    return p


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('profile')
    parser.add_argument('--exclude', help='the same profile made with --fixed exclude')
    parser.add_argument('--angle', type=float, default=24)
    parser.add_argument('-o', '--output', default='boundaryBalance.png')
    args = parser.parse_args()

    p = read_profile(args.profile)
    z, rho = p['z'], p['Density']
    angle = math.radians(args.angle)
    g = {'X': math.sin(angle), 'Z': -math.cos(angle)}
    fig, axes = plt.subplots(1, 3, figsize=(10, 4), sharey=True)
    axes[0].plot(p['StressZZ'], z, label='--fixed boundary')
    if args.exclude:
        e = read_profile(args.exclude)
        axes[0].plot(e['StressZZ'], e['z'], '--', label='--fixed exclude')
    axes[0].set_xlabel(r'$\sigma_{zz}$')
    axes[0].legend(fontsize=8)
    axes[1].plot(p['InteractionForceZ'], z, label=r'$f_z$ (boundary force)')
    axes[1].plot(-p['InteractionForceX'], z, label=r'$-f_x$')
    axes[1].plot(-rho * g['Z'], z, ':', label=r'$-\rho g_z$')
    axes[1].plot(rho * g['X'], z, ':', label=r'$\rho g_x$')
    axes[1].set_xlabel('force density')
    axes[1].legend(fontsize=8)
    safe = np.where(rho > 0, rho, 1)
    for a in 'XZ':
        flux = p['Stress' + a + 'Z'] + np.where(rho > 0, p['Momentum' + a] * p['MomentumZ'] / safe, 0)
        residual = -np.gradient(flux, z) + rho * g[a] + p['InteractionForce' + a]
        axes[2].plot(residual / rho.max(), z, label=a.lower())
    axes[2].set_xlim(-0.5, 0.5)
    axes[2].set_xlabel(r'residual / $\rho_{max} g$')
    axes[2].legend(fontsize=8)
    axes[0].set_ylabel('z')
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(args.output, dpi=80)
    print(f"wrote {args.output}")


main()
