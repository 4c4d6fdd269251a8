#!/usr/bin/python3
"""Plots the time per particle-step against the number of flowing particles from the CSV that
Drivers/Benchmarks/scaling.sh writes.

usage: plotScaling.py scaling.csv out.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"{sys.argv[1]}: no rows")
    n = [float(r["flowing"]) for r in rows]
    t = [float(r["ns_per_particle_step"]) for r in rows]
    # (Older files have no marginal column: the band is then around the whole runs' time.)
    marginal = [float(r["marginal_ns_per_particle_step"]) for r in rows] if "marginal_ns_per_particle_step" in rows[0] else None
    reference = marginal if marginal else t
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogx(n, t, "o-", label="Talus, whole run")
    if marginal:
        ax.semilogx(n, marginal, "s-", label="Talus, a step alone (difference of two run lengths)")
    ax.axhspan(reference[0] * 0.7, reference[0] * 1.3, color="0.9", label=f"within 30% of N = {n[0]:.0f}")
    ax.set_xlabel("flowing particles N")
    ax.set_ylabel("wall time per particle-step [ns]")
    ax.set_ylim(0, max(t + (marginal or [])) * 1.3)
    ax.set_title("Periodic bidisperse chute, one core")
    ax.legend()
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=120)
    print(f"wrote {sys.argv[2]}")


if __name__ == "__main__":
    main()
