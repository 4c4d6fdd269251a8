#!/usr/bin/python3
"""Plots the time series a chute driver writes (NAME.series: t, kinetic energy, mass flux, mean
velocity, height, small-species concentration) into one PNG of four panels, and marks the start
of the steady flow if NAME.steady exists.

    /usr/bin/python3 Tools/Plot/plotChuteSeries.py NAME.series out.png
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    path, out = sys.argv[1], sys.argv[2]
    try:
        data = np.loadtxt(path, comments="#", ndmin=2)
    except (OSError, ValueError) as error:
        sys.exit(f"plotChuteSeries: cannot read {path}: {error}")
    if data.shape[0] == 0 or data.shape[1] < 6:
        sys.exit(f"plotChuteSeries: {path} has no samples of 6 columns")
    steady = None
    steadyFile = os.path.splitext(path)[0] + ".steady"
    if os.path.exists(steadyFile):
        with open(steadyFile) as f:
            first = f.readline().split()
            if "t" in first:
                steady = float(first[first.index("t") + 2].rstrip(","))
    t = data[:, 0]
    figure, axes = plt.subplots(2, 2, figsize=(9, 6), sharex=True)
    panels = [(1, "kinetic energy per unit area"), (2, "mass flux per unit width"), (3, "mean velocity"),
              (4, "flow height")]
    for axis, (column, label) in zip(axes.flat, panels):
        axis.plot(t, data[:, column], lw=1)
        axis.set_ylabel(label)
        if steady is not None:
            axis.axvline(steady, color="grey", ls="--", lw=1)
    for axis in axes[1]:
        axis.set_xlabel("time")
    figure.suptitle(os.path.basename(path) + ("" if steady is None else f" (steady from t = {steady:g})"))
    figure.tight_layout()
    figure.savefig(out, dpi=100)
    print(f"plotChuteSeries: wrote {out} ({len(t)} samples)")


if __name__ == "__main__":
    main()
