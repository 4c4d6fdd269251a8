#!/usr/bin/env python3
"""The comparison drum's zone counts against time (ComparisonDrum's NAME.zones): the particles of
each size in zone 1 (x > 0, z > 0) and zone 2 (x < 0, z < 0), one curve per run given, as the
2024 comparison of open-source DEM codes plots them; and a table of the counts' means over the
last half of each run (the steady rotation) on standard output.

    plotComparisonDrum.py RUN.zones [LABEL=OTHER.zones ...] -o drum.png
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from comparisonTables import read_rows  # noqa: E402


def read_zones(path):
    return read_rows(path, 5, "t and four counts")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="NAME.zones files, optionally LABEL=PATH")
    parser.add_argument("-o", "--output", default="comparisonDrum.png")
    args = parser.parse_args()
    fig, axes = plt.subplots(1, 2, figsize=(10, 4), sharey=True)
    print("| run | zone 1, d = 2 mm | zone 1, d = 4 mm | zone 2, d = 2 mm | zone 2, d = 4 mm | from t |")
    print("|---|---|---|---|---|---|")
    for run in args.runs:
        label, _, path = run.rpartition("=")
        label = label or path
        z = read_zones(path)
        t = z[:, 0]
        for ax, (small, large), zone in zip(axes, [(1, 2), (3, 4)], ["zone 1 (x > 0, z > 0)", "zone 2 (x < 0, z < 0)"]):
            line, = ax.plot(t, z[:, small], label=f"{label}: d = 2 mm")
            ax.plot(t, z[:, large], "--", color=line.get_color(), label=f"{label}: d = 4 mm")
            ax.set_title(zone)
            ax.set_xlabel("t (s)")
        late = t >= 0.5 * t[-1]
        means = z[late, 1:].mean(axis=0)
        print(f"| {label} | " + " | ".join(f"{m:.0f}" for m in means) + f" | {t[late][0]:g} |")
    axes[0].set_ylabel("particles")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
