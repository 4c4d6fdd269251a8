#!/usr/bin/python3
"""Plots the energies of a .ene file (Documentation/FileFormats/ene.md) against time.

usage: plotEnergies.py NAME.ene OUT.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_ene(path):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            fields = line.split()
            if not fields or not fields[0][0] in "0123456789-+.":
                continue  # header line
            try:
                rows.append([float(x) for x in fields[:9]])
            except ValueError:
                sys.exit(f"{path} line {number}: not a row of numbers: {line.strip()}")
    if not rows:
        sys.exit(f"{path}: no data rows")
    return np.array(rows)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    data = read_ene(sys.argv[1])
    t = data[:, 0]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for column, label in [(2, "translational kinetic"), (3, "rotational kinetic"), (4, "elastic")]:
        ax.semilogy(t, np.maximum(data[:, column], 1e-12), label=label)
    ax.set_xlabel("time $t$ [$\\sqrt{d/g}$]")
    ax.set_ylabel("energy [$m g d$]")
    ax.set_title(sys.argv[1])
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    print(f"wrote {sys.argv[2]}")


if __name__ == "__main__":
    main()
