#!/usr/bin/python3
"""Draws a 2-D map of one coarse-grained field written by talus-cg on a grid, from its CSV or
HDF5 file (Documentation/CoarseGraining.md "Output formats"), e.g. the small-particle
concentration of a chute in x and z (--coordinates XZ).

usage: plotCGField.py FIELDS.csv|FIELDS.h5 [--field NAME] [--slice AXIS VALUE] [-o FIGURE.png]

The map's axes are the two resolved directions of the file; a 3-D file (XYZ) is cut at the
grid plane nearest to --slice (default: the middle of z). Several frames: the last one.
"""
import argparse
import sys

import matplotlib

matplotlib.use('Agg')
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from cgFiles import read_cg_fields  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('fields')
    parser.add_argument('--field', default=None, help='column name (default Concentration_s1, else Density)')
    parser.add_argument('--slice', nargs=2, metavar=('AXIS', 'VALUE'), default=None,
                        help='for a 3-D file: the plane AXIS = VALUE (default the middle of z)')
    parser.add_argument('-o', '--output', default='cgField.png')
    parser.add_argument('--title', default='')
    args = parser.parse_args()

    columns = read_cg_fields(args.fields, 'plotCGField.py')
    field = args.field or ('Concentration_s1' if 'Concentration_s1' in columns else 'Density')
    if field not in columns:
        sys.exit(f"plotCGField.py: {args.fields}: no field {field} (fields: "
                 f"{', '.join(c for c in columns if c not in ('t', 'x', 'y', 'z'))})")
    axes = [a for a in 'xyz' if a in columns]
    if len(axes) == 3:
        cut_axis, cut_value = (args.slice[0], float(args.slice[1])) if args.slice else ('z', None)
        if cut_axis not in 'xyz':
            sys.exit(f"plotCGField.py: --slice: AXIS must be x, y or z, found {cut_axis}")
        levels = np.unique(columns[cut_axis])
        level = levels[len(levels) // 2] if cut_value is None else levels[np.argmin(np.abs(levels - cut_value))]
        keep = columns[cut_axis] == level
        columns = {name: values[keep] for name, values in columns.items()}
        axes.remove(cut_axis)
        where = f', {cut_axis} = {level:.4g}'
    elif len(axes) == 2:
        where = ''
    else:
        sys.exit(f"plotCGField.py: {args.fields}: {len(axes)} resolved direction(s); a map needs a grid in 2 or 3 "
                 "directions (talus-cg --coordinates XZ, XY, YZ or XYZ)")
    h, v = axes
    hs, vs = np.unique(columns[h]), np.unique(columns[v])
    if len(hs) * len(vs) != len(columns[field]):
        sys.exit(f"plotCGField.py: {args.fields}: the points are not a grid in {h} and {v}")
    # Grid order: the first resolved direction slowest.
    values = columns[field].reshape(len(hs), len(vs))
    if field != 'Density' and 'Density' in columns:
        # Ratios (velocity, concentration) are written as 0 where there is no mass: leave blank.
        values = np.ma.masked_where(columns['Density'].reshape(len(hs), len(vs)) <= 0, values)
    wide = (hs[-1] - hs[0]) > 2 * (vs[-1] - vs[0])
    fig, ax = plt.subplots(figsize=(12 if wide else 7, 4.2))
    image = ax.pcolormesh(hs, vs, values.T, shading='nearest', cmap='viridis')
    fig.colorbar(image, ax=ax, label=field)
    ax.set_xlabel(h)
    ax.set_ylabel(v)
    t = columns['t'][0] if 't' in columns else None
    ax.set_title(args.title or f"{field}{where}" + (f', t = {t:g}' if t is not None else ''))
    fig.tight_layout()
    fig.savefig(args.output, dpi=110)
    print(f"wrote {args.output}")


if __name__ == '__main__':
    main()
