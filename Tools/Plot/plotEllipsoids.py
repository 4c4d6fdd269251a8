#!/usr/bin/python3
"""Side view (x-z) of ellipsoids at one saved frame of NAME.data: each ellipsoid drawn as its
exact outline in the x-z plane, shaded by its depth y (front light, back dark). The .data file
gives the centre and the orientation (roll, pitch, yaw: Documentation/FileFormats/data.md); the
semi-axes of the one shape of the scene are given on the command line.

    /usr/bin/python3 Tools/Plot/plotEllipsoids.py NAME.data out.png --semi-axes A,B,C [--time T]

The outline of an ellipsoid {x : (x - c)^T Q (x - c) <= 1}, Q = R diag(1/a^2, 1/b^2, 1/c^2) R^T,
seen along y is the ellipse whose matrix is the inverse of the x-z block of Q^-1 =
R diag(a^2, b^2, c^2) R^T: its semi-axes are the square roots of that block's eigenvalues.
Spheres (rows with all three angles 0 and radius below the largest semi-axis) are drawn as circles.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Ellipse  # noqa: E402
import numpy as np  # noqa: E402

from dataFrames import read_frame  # noqa: E402



def semi_axes(text):
    """The semi-axes a,b,c of --semi-axes as an array; exits with a message naming the flag."""
    try:
        axes = np.array([float(v) for v in text.split(",")])
        assert len(axes) == 3 and np.all(axes > 0)
    except (ValueError, AssertionError):
        sys.exit(f"--semi-axes: expected three positive numbers a,b,c, got '{text}'")
    return axes

def rotation(roll, pitch, yaw):
    """Body-to-lab rotation of Tait-Bryan Z-Y-X angles: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    cr, sr, cp, sp, cy, sy = np.cos(roll), np.sin(roll), np.cos(pitch), np.sin(pitch), np.cos(yaw), np.sin(yaw)
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    return rz @ ry @ rx


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("data")
    parser.add_argument("out")
    parser.add_argument("--semi-axes", required=True, help="a,b,c of the scene's ellipsoids")
    parser.add_argument("--time", type=float, default=None)
    args = parser.parse_args()
    axes = semi_axes(args.semi_axes)
    t, rows, _ = read_frame(args.data, args.time, "plotEllipsoids")
    order = np.argsort(-rows[:, 1])  # back (large y) first, front last
    y = rows[:, 1]
    span = max(y.max() - y.min(), 1e-12)
    fig, ax = plt.subplots(figsize=(8, 5))
    for k in order:
        x, yk, z, r = rows[k, 0], rows[k, 1], rows[k, 2], rows[k, 6]
        shade = 0.25 + 0.6 * (yk - y.min()) / span
        colour = plt.cm.Blues(shade)
        if np.all(rows[k, 7:10] == 0) and r < axes.max() * (1 - 1e-9):
            ax.add_patch(plt.Circle((x, z), r, facecolor=colour, edgecolor="k", linewidth=0.3))
            continue
        R = rotation(*rows[k, 7:10])
        inverse_q = R @ np.diag(axes**2) @ R.T
        block = inverse_q[np.ix_([0, 2], [0, 2])]
        values, vectors = np.linalg.eigh(block)
        angle = np.degrees(np.arctan2(vectors[1, 1], vectors[0, 1]))
        ax.add_patch(Ellipse((x, z), 2 * np.sqrt(values[1]), 2 * np.sqrt(values[0]), angle=angle,
                             facecolor=colour, edgecolor="k", linewidth=0.3))
    ax.set_xlim(rows[:, 0].min() - axes.max(), rows[:, 0].max() + axes.max())
    ax.set_ylim(0, rows[:, 2].max() + axes.max())
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("z")
    ax.set_title(f"t = {t:g}: {len(rows)} particles seen along y (darker: further back)")
    fig.tight_layout()
    fig.savefig(args.out, dpi=150)
    print(f"wrote {args.out} (t = {t:g}, {len(rows)} particles)")


if __name__ == "__main__":
    main()
