#!/usr/bin/env python3
"""Plots a talus-shallow run (Documentation/ShallowFlow.md).

Usage: plotShallowFlow.py PREFIX [-o FILE.png] [--xmin X] [--xmax X]

Reads PREFIX.profiles.csv and PREFIX.fronts.csv and draws, like figure 3.3 of Denissen (2019),
one panel per output time with the height h (line) and the small-particle height h phi (shaded),
and a last panel with the front, head and shock positions against time.
"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("prefix")
    parser.add_argument("-o", "--output", help="image file (default PREFIX.png)")
    parser.add_argument("--xmin", type=float)
    parser.add_argument("--xmax", type=float)
    args = parser.parse_args()
    profiles = np.genfromtxt(args.prefix + ".profiles.csv", delimiter=",", names=True)
    fronts = np.atleast_1d(np.genfromtxt(args.prefix + ".fronts.csv", delimiter=",", names=True))
    times = np.unique(profiles["t"])
    figure, axes = plt.subplots(len(times) + 1, 1, figsize=(10, 2.2 * (len(times) + 1)), squeeze=False)
    axes = axes[:, 0]
    top = 1.1 * max(profiles["h"].max(), 1e-9)
    for axis, t in zip(axes, times):
        p = profiles[profiles["t"] == t]
        axis.fill_between(p["x"], 0, p["hphi"], color="0.75", label="h phi (small particles)")
        axis.plot(p["x"], p["h"], "k", label="h")
        axis.set_ylim(0, top)
        axis.set_xlim(args.xmin if args.xmin is not None else p["x"].min(), args.xmax if args.xmax is not None else p["x"].max())
        axis.set_ylabel("z / dL")
        axis.set_title(f"t = {t:g}", loc="left", fontsize=9)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[len(times) - 1].set_xlabel("x / dL")
    last = axes[-1]
    last.plot(fronts["t"], fronts["front"], "o-", label="front (h = front height)")
    last.plot(fronts["t"], fronts["shock"], "s-", label="small-particle shock")
    last.plot(fronts["t"], fronts["head_position"], "^-", label="highest point of the head")
    last.set_xlabel("t / sqrt(dL/g)")
    last.set_ylabel("x / dL")
    last.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(args.output or args.prefix + ".png", dpi=110)


if __name__ == "__main__":
    main()
