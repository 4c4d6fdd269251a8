#!/usr/bin/python3
"""The same drum run by two codes, side by side (Documentation/Drums/RotatingDrum.md, "The angle of repose
against LIGGGHTS"): the angle of repose against time (talus-drum-angle's output for each run) and the
velocity profile through the drum's axis, the mean of vx over the bed's particles with |x| < half-width in
bins of z, over the frames from --from on (the rolling regime's flowing layer above the bed turning with
the drum).

  plotDrumComparison.py --names Talus,LIGGGHTS --angles a.txt,b.txt --data a.data,b.data --from T -o out.png
                        [--csv profile.csv] [--wall-species 2] [--half-width 1] [--bin 0.5]
"""
import argparse
import os
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Plot"))
from dataFrames import frames, rows_of  # noqa: E402

PROGRAM = "plotDrumComparison.py"


def read_angles(path):
    rows = [line.split() for line in open(path) if line.strip() and not line.startswith("#")]
    return np.array([[float(t), float(a)] for t, a in rows])


def velocity_profile(path, start, wall, half_width, edges):
    """Sum of vx and count per z bin over the mobile particles with |x| < half_width, frames t >= start."""
    sums = np.zeros(len(edges) - 1)
    counts = np.zeros(len(edges) - 1)
    frames_used = 0
    for time, lines, _ in frames(path, PROGRAM):
        if time < start:
            continue
        data = rows_of(path, time, lines, PROGRAM)
        keep = (data[:, 13] != wall) & (np.abs(data[:, 0]) < half_width)
        index = np.digitize(data[keep, 2], edges) - 1
        ok = (index >= 0) & (index < len(sums))
        np.add.at(sums, index[ok], data[keep, 3][ok])
        np.add.at(counts, index[ok], 1)
        frames_used += 1
    if frames_used == 0:
        sys.exit(f"{PROGRAM}: {path}: no frame at or after t = {start}")
    return sums, counts, frames_used


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--names", required=True)
    p.add_argument("--angles", required=True)
    p.add_argument("--data", required=True)
    p.add_argument("--from", dest="start", type=float, required=True)
    p.add_argument("-o", "--output", required=True)
    p.add_argument("--csv")
    p.add_argument("--wall-species", type=int, default=2)
    p.add_argument("--half-width", type=float, default=1.0)
    p.add_argument("--bin", type=float, default=0.5)
    a = p.parse_args()
    names, angles, data = a.names.split(","), a.angles.split(","), a.data.split(",")
    if not (len(names) == len(angles) == len(data)):
        sys.exit("plotDrumComparison.py: --names, --angles and --data need as many entries each")
    edges = np.arange(-16, 16 + a.bin / 2, a.bin)
    centres = 0.5 * (edges[1:] + edges[:-1])
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    table = [centres]
    for name, angle_file, data_file in zip(names, angles, data):
        series = read_angles(angle_file)
        late = series[series[:, 0] >= a.start, 1]
        left.plot(series[:, 0], series[:, 1], lw=0.8,
                  label=f"{name}: {np.nanmean(late):.2f} +- {np.nanstd(late, ddof=1):.2f} deg from t = {a.start:g}")
        sums, counts, used = velocity_profile(data_file, a.start, a.wall_species, a.half_width, edges)
        mean = np.where(counts > 0, sums / np.maximum(counts, 1), np.nan)
        right.plot(mean, centres, marker=".", lw=0.8, label=f"{name} ({used} frames)")
        table.append(mean)
        print(f"{name}: angle {np.nanmean(late):.3f} +- {np.nanstd(late, ddof=1):.3f} (s.d. of {len(late)} frames); "
              f"profile from {used} frames")
    left.axvline(a.start, color="grey", lw=0.5)
    left.set_xlabel("t")
    left.set_ylabel("angle of repose (degrees)")
    left.legend(fontsize=8)
    right.set_xlabel(f"mean vx of the bed's particles with |x| < {a.half_width:g}")
    right.set_ylabel("z")
    right.axvline(0, color="grey", lw=0.5)
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.output, dpi=110)
    if a.csv:
        with open(a.csv, "w") as f:
            f.write("z," + ",".join(f"vx_{n}" for n in names) + "\n")
            for row in zip(*table):
                if all(np.isnan(v) for v in row[1:]):
                    continue
                f.write(",".join(f"{v:.6g}" for v in row) + "\n")


if __name__ == "__main__":
    main()
