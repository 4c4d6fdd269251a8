#!/usr/bin/python3
"""The rotating drum (Drivers/Drum, Documentation/Drums/RotatingDrum.md) in one picture: left the
time series NAME.series (mixing index M, segregation index S and the dynamic angle of repose
against the drum's turns), right the cross-section (x, z) of a saved frame of NAME.data seen
along the axis y: spheres as circles, ellipsoids as their exact outlines (as in
plotEllipsoids.py), the wall's fixed particles grey.

    /usr/bin/python3 Tools/Plot/plotDrum.py NAME out.png --semi-axes A,B,C [--time T]

The species of a particle is column 14 of .data: 0 spheres, 1 ellipsoids, 2 the wall.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Ellipse  # noqa: E402
import numpy as np  # noqa: E402

from dataFrames import read_frame  # noqa: E402
from plotEllipsoids import rotation, semi_axes  # noqa: E402


def read_series(path):
    try:
        values = np.loadtxt(path, comments="#", ndmin=2)
    except OSError:
        sys.exit(f"plotDrum: cannot read {path}")
    if values.shape[1] != 6:
        sys.exit(f"plotDrum: {path}: expected 6 columns (t rotations energy M S angle), found {values.shape[1]}")
    return values


def draw_cross_section(ax, rows, axes, t):
    colours = {0: "tab:orange", 1: "tab:blue", 2: "0.6"}
    for row in rows[np.argsort(rows[:, 1])]:
        x, z, r, species = row[0], row[2], row[6], int(row[13])
        colour = colours.get(species, "k")
        if species != 1:
            ax.add_patch(plt.Circle((x, z), r, facecolor=colour, edgecolor="k", linewidth=0.2))
            continue
        # The outline seen along y: the x-z block of R diag(a^2, b^2, c^2) R^T (plotEllipsoids.py).
        R = rotation(*row[7:10])
        block = (R @ np.diag(axes**2) @ R.T)[np.ix_([0, 2], [0, 2])]
        values, vectors = np.linalg.eigh(block)
        angle = np.degrees(np.arctan2(vectors[1, 1], vectors[0, 1]))
        ax.add_patch(Ellipse((x, z), 2 * np.sqrt(values[1]), 2 * np.sqrt(values[0]), angle=angle,
                             facecolor=colour, edgecolor="k", linewidth=0.2))
    extent = np.abs(rows[:, [0, 2]]).max() + 0.5
    ax.set_xlim(-extent, extent)
    ax.set_ylim(-extent, extent)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("z")
    ax.set_title(f"t = {t:g}: spheres orange, ellipsoids blue (all of y)")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("name", help="run name: reads NAME.series and NAME.data")
    parser.add_argument("out")
    parser.add_argument("--semi-axes", required=True, help="a,b,c of the ellipsoids")
    parser.add_argument("--time", type=float, default=None, help="frame to draw (default: the last)")
    args = parser.parse_args()
    axes = semi_axes(args.semi_axes)
    series = read_series(args.name + ".series")
    t, rows, _ = read_frame(args.name + ".data", args.time, "plotDrum")

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 5.2))
    turning = series[:, 1] > 0
    left.plot(series[turning, 1], series[turning, 3], label="mixing index M")
    left.plot(series[turning, 1], series[turning, 4], label="segregation index S")
    left.set_xlabel("rotations")
    left.set_ylabel("M, S")
    left.set_ylim(-0.3, 1.05)
    left.axhline(0, color="0.8", linewidth=0.5)
    angle_axis = left.twinx()
    angle_axis.plot(series[turning, 1], series[turning, 5], color="tab:green", linewidth=0.6,
                    label="angle of repose")
    angle_axis.set_ylabel("angle of repose (degrees)", color="tab:green")
    angle_axis.set_ylim(0, 60)
    lines = left.get_legend_handles_labels()[0] + angle_axis.get_legend_handles_labels()[0]
    left.legend(lines, [line.get_label() for line in lines], loc="lower left", fontsize=8)
    left.set_title("NAME.series while the drum turns")
    draw_cross_section(right, rows, axes, t)
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    print(f"wrote {args.out} ({turning.sum()} samples while turning, frame t = {t:g} of {len(rows)} particles)")


if __name__ == "__main__":
    main()
