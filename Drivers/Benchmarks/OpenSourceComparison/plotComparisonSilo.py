#!/usr/bin/env python3
"""The silo's discharge (ComparisonSilo's NAME.discharge files): the discharged mass against the
time since the lid opened, the mass flow rate as the slope of a straight line fitted over the
steady part of the discharge, and Beverloo's estimate for the orifice

    W = C rho_b sqrt(g) (D - k d)^(5/2)

(Beverloo, Leniger and van de Velde 1961; C = 0.58 and k = 1.5 as in Nedderman's review, rho_b
the bulk density, the solid fraction times the material's density; Documentation/Benchmarks/
OpenSourceComparison.md "The silo"). Prints a table row per file and writes a plot.

    plotComparisonSilo.py [--open-time 0.5] [--window 0.2,0.8] [--solid-fraction 0.6]
                          [--output silo.png] LABEL=FILE.discharge ...

The steady part: from the time the discharged mass passes the window's first fraction of what
left by the end to the time it passes its second.
"""
import argparse
import math

parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
parser.add_argument("runs", nargs="+", help="LABEL=FILE.discharge; the label names the orifice (small, large) and "
                                            "material (M1, M2), e.g. large-M1=ComparisonSilo.discharge")
parser.add_argument("--open-time", type=float, default=0.5, help="when the lid opened (s)")
parser.add_argument("--window", default="0.2,0.8", help="the fractions of the final discharged mass that bound the fit")
parser.add_argument("--solid-fraction", type=float, default=0.6, help="of the settled packing, for Beverloo's bulk density")
parser.add_argument("--output", default="ComparisonSilo.png")
args = parser.parse_args()
low, high = map(float, args.window.split(","))

ORIFICE_DIAMETER = {"small": 0.04, "large": 0.06}
DENSITY = {"M1": 2500.0, "M2": 2000.0}
C, K, G, PARTICLE_DIAMETER = 0.58, 1.5, 9.8, 0.004


def beverloo(label):
    orifice = next((d for name, d in ORIFICE_DIAMETER.items() if name in label), None)
    density = next((r for name, r in DENSITY.items() if name in label), DENSITY["M1"])
    if orifice is None:
        return math.nan
    return C * args.solid_fraction * density * math.sqrt(G) * (orifice - K * PARTICLE_DIAMETER) ** 2.5


def fit(ts, ms):
    n = len(ts)
    mt, mm = sum(ts) / n, sum(ms) / n
    return sum((t - mt) * (m - mm) for t, m in zip(ts, ms)) / sum((t - mt) ** 2 for t in ts)


curves = []
print("| run | discharged (kg) | by t - t_open (s) | fitted over (s) | rate (kg/s) | Beverloo (kg/s) | ratio |")
print("|---|---|---|---|---|---|---|")
for run in args.runs:
    label, path = run.split("=", 1)
    rows = [list(map(float, line.split())) for line in open(path) if not line.startswith("#")]
    t = [r[0] - args.open_time for r in rows if r[0] >= args.open_time]
    m = [r[1] for r in rows if r[0] >= args.open_time]
    final = m[-1] if m else 0.0
    inside = [(a, b) for a, b in zip(t, m) if low * final <= b <= high * final]
    rate = fit([a for a, _ in inside], [b for _, b in inside]) if len(inside) >= 3 else math.nan
    estimate = beverloo(label)
    span = f"{inside[0][0]:.2f}-{inside[-1][0]:.2f}" if inside else "-"
    print(f"| {label} | {final:.4f} | {t[-1] if t else 0:.2f} | {span} | {rate:.4f} | {estimate:.4f} | "
          f"{rate / estimate if estimate == estimate and estimate > 0 else math.nan:.3f} |")
    curves.append((label, t, m))

try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("(matplotlib not found: no plot)")
else:
    fig, ax = plt.subplots(figsize=(6, 4))
    for label, t, m in curves:
        ax.plot(t, m, label=label)
    ax.set_xlabel("time since the lid opened (s)")
    ax.set_ylabel("discharged mass (kg)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output}")
