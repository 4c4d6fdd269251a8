#!/usr/bin/python3
"""Draws a width scan of talus-cg (--width-scan) as heat maps, one panel per point, in the
manner of the thesis's figure 4.5 (Denissen 2019, sec. 4.2.2; Documentation/CoarseGraining.md "Choosing
the widths"): log w_a against log w_b, colour = the field, white where no particle contributes
(zero density), the point's
insensitive width pairs outlined in black, the plateau common to all points as a red
rectangle and the chosen widths as a red star. Width pairs that are evaluated but not trusted
(fewer particle centres than --scan-min-particles, or narrower than --scan-min-width) are
drawn faded.

usage: plotWidthScan.py SCAN.csv [-o FIGURE.png] [--title T]
"""
import argparse
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402


def read_scan(path):
    """Returns the columns, the points (list of x, y, z), the chosen widths (or None) and the
    field name, from the CSV file and its '#' lines."""
    comments, lines = [], []
    with open(path) as f:
        for line in f:
            (comments if line.startswith('#') else lines).append(line)
    if not lines or not lines[0].startswith('point,'):
        sys.exit(f"{path}: not a talus-cg width scan (no 'point,...' column line)")
    names = lines[0].strip().split(',')
    data = np.genfromtxt(lines[1:], delimiter=',', ndmin=2)
    columns = {name: data[:, k] for k, name in enumerate(names)}
    points, chosen, field = [], None, '?'
    for c in comments:
        words = c[1:].split()
        if len(words) >= 5 and words[0] == 'point' and words[1].endswith(':'):
            points.append([float(w) for w in words[2:5]])
        elif len(words) == 5 and words[0] == 'chosen':
            chosen = (float(words[2]), float(words[4]))
        elif words and words[0] == 'field':
            field = words[1].rstrip(';')
    return names, columns, points, chosen, field


def cell_edges(widths):
    """Edges in log10 w halfway between the scan widths (pcolormesh cells centred on them)."""
    u = np.log10(widths)
    mid = 0.5 * (u[1:] + u[:-1])
    return np.concatenate(([u[0] - (mid[0] - u[0])], mid, [u[-1] + (u[-1] - mid[-1])]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('scan')
    parser.add_argument('-o', '--output', default='widthScan.png')
    parser.add_argument('--title', default='')
    args = parser.parse_args()

    names, col, points, chosen, field = read_scan(args.scan)
    wa_name, wb_name = names[1], names[2]
    wa, wb = np.unique(col[wa_name]), np.unique(col[wb_name])
    na, nb = len(wa), len(wb)
    n_points = int(col['point'].max()) + 1
    values = col['value'].reshape(n_points, na, nb)
    trusted = ~np.isnan(col['sensitivity'].reshape(n_points, na, nb))
    insensitive = col['insensitive'].reshape(n_points, na, nb) > 0
    plateau = col['plateau'].reshape(n_points, na, nb)[0] > 0
    # Colours over the 2nd to 98th percentile of the values: a few noisy extremes at small widths
    # would otherwise flatten the plateau's shades.
    lo, hi = np.nanpercentile(values, 2), np.nanpercentile(values, 98)

    ea, eb = cell_edges(wa), cell_edges(wb)
    fig, axes = plt.subplots(1, n_points, figsize=(4.6 * n_points + 1, 4.2), squeeze=False, sharey=True)
    for p, ax in enumerate(axes[0]):
        image = ax.pcolormesh(ea, eb, values[p].T, cmap='viridis', vmin=lo, vmax=hi, shading='flat')
        faded = np.where(trusted[p] | np.isnan(values[p]), np.nan, 0.0)  # white veil
        ax.pcolormesh(ea, eb, faded.T, cmap='Greys', vmin=0, vmax=1, alpha=0.55, shading='flat')
        # The point's insensitive pairs, outlined (contour of the 0/1 mask at 1/2).
        ua, ub = np.log10(wa), np.log10(wb)
        if insensitive[p].any() and not insensitive[p].all():
            ax.contour(ua, ub, insensitive[p].T.astype(float), levels=[0.5], colors='k', linewidths=0.8)
        if plateau.any():
            ia, ib = np.nonzero(plateau)
            ax.add_patch(Rectangle((ea[ia.min()], eb[ib.min()]), ea[ia.max() + 1] - ea[ia.min()], eb[ib.max() + 1] - eb[ib.min()],
                                   fill=False, edgecolor='red', linewidth=2))
        if chosen:
            ax.plot(np.log10(chosen[0]), np.log10(chosen[1]), '*', color='red', markersize=13, markeredgecolor='white')
        where = points[p] if p < len(points) else ['?'] * 3
        ax.set_title(f"point {p}: ({', '.join(f'{v:g}' if not isinstance(v, str) else v for v in where)})")
        ax.set_xlabel(rf'$\log_{{10}} {wa_name[0]}_{wa_name[1:]}$')
        if p == 0:
            ax.set_ylabel(rf'$\log_{{10}} {wb_name[0]}_{wb_name[1:]}$')
    fig.colorbar(image, ax=axes[0].tolist(), label=field)
    title = args.title or f'width scan of {field}' + (f': chosen {wa_name} = {chosen[0]:.3g}, {wb_name} = {chosen[1]:.3g}' if chosen else ': no common plateau')
    fig.suptitle(title)
    fig.savefig(args.output, dpi=110, bbox_inches='tight')
    print(f"wrote {args.output}")


if __name__ == '__main__':
    main()
