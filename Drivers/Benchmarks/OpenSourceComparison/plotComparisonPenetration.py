#!/usr/bin/env python3
"""The comparison's penetration test: the steel sphere's height above the floor against time
(ComparisonPenetration's NAME.penetration, or LIGGGHTS's penetration.heights: t, height, vz), one
curve per run given, as the 2024 comparison of open-source DEM codes plots it; and a table on
standard output of each run's numbers: when the sphere stopped falling freely (its height more than
0.1 mm above free flight from the first row), its lowest height and when, and its height and
vertical velocity at the last row.

    plotComparisonPenetration.py LABEL=RUN.penetration [LABEL=OTHER.heights ...] -o penetration.png
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from comparisonTables import read_rows  # noqa: E402

GRAVITY = 9.8


def read_heights(path):
    return read_rows(path, 3, "t, height, vz")


def summary(h):
    t, height, vz = h[:, 0], h[:, 1], h[:, 2]
    t0, z0, v0 = t[0], height[0], vz[0]
    free = z0 + v0 * (t - t0) - GRAVITY * (t - t0) ** 2 / 2
    left = np.nonzero(height - free > 1e-4)[0]
    lowest = int(np.argmin(height))
    return {"impact": t[left[0]] if len(left) else float("nan"), "lowest": height[lowest], "lowestAt": t[lowest],
            "end": t[-1], "endHeight": height[-1], "endVz": vz[-1]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="LABEL=PATH of NAME.penetration or penetration.heights files")
    parser.add_argument("-o", "--output", default="comparisonPenetration.png")
    args = parser.parse_args()
    fig, ax = plt.subplots(figsize=(6, 4))
    print("| run | leaves free flight (s) | lowest height (m) | at t (s) | height at the end (m) | vz at the end (m/s) | end (s) |")
    print("|---|---|---|---|---|---|---|")
    for run in args.runs:
        label, _, path = run.rpartition("=")
        label = label or path
        h = read_heights(path)
        ax.plot(h[:, 0], h[:, 1], label=label)
        s = summary(h)
        print(f"| {label} | {s['impact']:.4f} | {s['lowest']:.5f} | {s['lowestAt']:.4f} | {s['endHeight']:.5f} |"
              f" {s['endVz']:.4f} | {s['end']:.4f} |")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("height of the sphere's centre above the floor (m)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
