#!/usr/bin/python3
"""Plots the time per particle-step against the number of flowing particles from the CSV files
that Drivers/Benchmarks/scaling.sh writes (one per start: scaling-settled.csv, scaling-flowing.csv),
each with the band within 30% of its smallest scene.

usage: plotScaling.py scaling-A.csv [scaling-B.csv ...] out.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{path}: no rows")
    n = [float(r["flowing"]) for r in rows]
    t = [float(r["ns_per_particle_step"]) for r in rows]
    # (Older files have no marginal column: the band is then around the whole runs' time.)
    marginal = [float(r["marginal_ns_per_particle_step"]) for r in rows] if "marginal_ns_per_particle_step" in rows[0] else None
    return n, t, marginal


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    highest = 0
    for index, path in enumerate(sys.argv[1:-1]):
        n, t, marginal = read(path)
        stem = os.path.splitext(os.path.basename(path))[0]
        name = {"scaling-settled": "settled bed", "scaling-flowing": "developed flow"}.get(stem, stem)
        colour = f"C{index}"
        ax.semilogx(n, t, "o-", color=colour, label=f"{name}: whole run")
        if marginal:
            ax.semilogx(n, marginal, "s--", color=colour, label=f"{name}: a step alone")
        reference = marginal if marginal else t
        ax.axhspan(reference[0] * 0.7, reference[0] * 1.3, color=colour, alpha=0.12,
                   label=f"{name}: within 30% of N = {n[0]:.0f}")
        highest = max(highest, max(t + (marginal or [])))
    ax.set_xlabel("flowing particles N")
    ax.set_ylabel("wall time per particle-step [ns]")
    ax.set_ylim(0, highest * 1.3)
    ax.set_title("Periodic bidisperse chute, one core")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(sys.argv[-1], dpi=120)
    print(f"wrote {sys.argv[-1]}")


if __name__ == "__main__":
    main()
