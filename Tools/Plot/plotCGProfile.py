#!/usr/bin/python3
"""Plots depth profiles written by talus-cg (--coordinates Z): density, downslope velocity,
concentration of one species, and the stress components sigma_zz and -sigma_xz against z
(Documentation/CoarseGraining.md).

usage: plotCGProfile.py PROFILE.csv [PROFILE2.csv ...] [-o FIGURE.png] [--species S] [--title T]

Several files are drawn on the same axes (e.g. two kernel widths). The '#' lines of the CSV
file say how it was made; the first other line names the columns.
"""
import argparse
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
from cgFiles import read_cg_csv  # noqa: E402


def read_profile(path):
    p, comments = read_cg_csv(path, 'plotCGProfile.py')
    if 'z' not in p:
        sys.exit(f"{path}: no z column (make the profile with talus-cg --coordinates Z)")
    if 't' in p:
        # Frames not averaged: plot the last one.
        last = p['t'] == p['t'].max()
        p = {name: values[last] for name, values in p.items()}
    return p, comments


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('profiles', nargs='+')
    parser.add_argument('-o', '--output', default='cgProfile.png')
    parser.add_argument('--species', type=int, default=1, help='species of the concentration panel (default 1)')
    parser.add_argument('--title', default='')
    args = parser.parse_args()

    panels = [('Density', r'density $\rho$'),
              ('VelocityX', r'velocity $u_x$'),
              (f'Concentration_s{args.species}', rf'concentration $\phi_{args.species}$'),
              ('Stress', r'stress')]
    fig, axes = plt.subplots(1, len(panels), figsize=(13, 4.6), sharey=True)
    for path in args.profiles:
        p, _ = read_profile(path)
        label = path.rsplit('/', 1)[-1]
        for ax, (name, title) in zip(axes, panels):
            if name == 'Stress':
                if 'StressZZ' in p:
                    ax.plot(p['StressZZ'], p['z'], label=r'$\sigma_{zz}$ ' + label)
                    ax.plot(-p['StressXZ'], p['z'], '--', label=r'$-\sigma_{xz}$ ' + label)
                else:
                    ax.plot(p['KineticStressZZ'], p['z'], label=r'kinetic $\sigma_{zz}$ ' + label)
            elif name in p:
                ax.plot(p[name], p['z'], label=label)
            ax.set_xlabel(title)
    axes[0].set_ylabel('z')
    axes[-1].legend(fontsize=7)
    if len(args.profiles) > 1:
        axes[0].legend(fontsize=7)
    for ax in axes:
        ax.grid(alpha=0.3)
    if args.title:
        fig.suptitle(args.title)
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


main()
