#!/usr/bin/python3
"""Plots radial profiles of a rotating drum written by talus-cg in cylindrical coordinates
(--coordinates RZ or R; Documentation/CoarseGraining.md "Cylindrical coordinates"): density,
azimuthal and radial velocity, and the concentration of one species against the distance r
from the axis, averaged along the axis (the mean over the rows of equal r) for the last frame.

usage: plotCGRadialProfile.py PROFILE.csv [-o FIGURE.png] [--species S] [--omega W] [--title T]

--omega draws the solid-body rotation omega r beside the azimuthal velocity.
"""
import argparse
import sys

import matplotlib
import numpy as np

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
from cgFiles import read_cg_csv  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('profile')
    parser.add_argument('-o', '--output', default='cgRadialProfile.png')
    parser.add_argument('--species', type=int, default=1, help='species of the concentration panel (default 1)')
    parser.add_argument('--omega', type=float, help='drum angular velocity: draw omega r')
    parser.add_argument('--title', default='')
    args = parser.parse_args()

    p, _ = read_cg_csv(args.profile, 'plotCGRadialProfile.py')
    if 'r' not in p:
        sys.exit(f"{args.profile}: no r column (make the profile with talus-cg --coordinates RZ or R)")
    if 't' in p:
        last = p['t'] == p['t'].max()
        p = {name: values[last] for name, values in p.items()}
    r = np.unique(p['r'])
    mean = {name: np.array([values[p['r'] == ri].mean() for ri in r]) for name, values in p.items()}

    concentration = f'Concentration_s{args.species}'
    panels = [('Density', r'density $\rho$'), ('VelocityTheta', r'velocity'), (concentration, rf'concentration $\phi_{args.species}$')]
    fig, axes = plt.subplots(1, len(panels), figsize=(12, 4), sharex=True)
    for ax, (name, label) in zip(axes, panels):
        if name == 'VelocityTheta':
            ax.plot(r, mean['VelocityTheta'], label=r'azimuthal $u_\theta$')
            ax.plot(r, mean['VelocityR'], label=r'radial $u_r$')
            if args.omega is not None:
                ax.plot(r, args.omega * r, 'k:', label=rf'$\omega r$, $\omega$ = {args.omega:g}')
            ax.legend(fontsize=8)
        elif name in mean:
            ax.plot(r, mean[name])
        ax.set_ylabel(label)
        ax.set_xlabel('distance from the axis r')
        ax.grid(alpha=0.3)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


main()
