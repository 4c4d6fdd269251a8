#!/usr/bin/python3
"""Plots a drum sweep (runDrumSweep.py's results.csv): the segregation index S and the angle of
repose against the aspect ratio R, and prints the table (Documentation/Drums/RotatingDrum.md
"The sweep").

    plotDrumSweep.py DIR/results.csv -o sweep.png [--csv sweep-table.csv] [--fields DIR/fields.csv]

Per R, over its seeds: S is the mean of the seeds' S; its error bar the standard error, from the
spread between seeds where there are several and the spread of the windows within each run:
sqrt(var_seeds / k + mean(S_sd^2) / (windows k)) for k seeds (the first term left out for one
seed). The window means of one run are correlated (half a turn apart), so the error bar of a
single seed is a lower bound. S > 0: spheres at the periphery, ellipsoids at the core.
With --fields (drumFieldIndices.py's fields.csv), S of the windows' time-averaged fields too, with
error bars from the windows and seeds alike, as open circles.
"""
import argparse
import csv
import math
import sys
from collections import defaultdict


def fail(message):
    sys.exit(f"plotDrumSweep: {message}")


def summarise(rows, key, spread=None):
    """Per aspect ratio: (R, seeds, mean, error) of column key, with column spread (default
    key_sd) the window spread."""
    spread = spread or key + "_sd"
    by_aspect = defaultdict(list)
    for row in rows:
        by_aspect[float(row["aspect"])].append(row)
    table = []
    for aspect in sorted(by_aspect):
        runs = by_aspect[aspect]
        values = [float(r[key]) for r in runs]
        k = len(values)
        mean = sum(values) / k
        within = sum(float(r[spread]) ** 2 / int(r["windows"]) for r in runs if r[spread] != "nan") / k
        between = sum((v - mean) ** 2 for v in values) / (k - 1) if k > 1 else 0.0
        table.append((aspect, k, mean, math.sqrt(between / k + within / k)))
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", help="the sweep's results.csv")
    parser.add_argument("-o", "--output", required=True, help="the plot (png)")
    parser.add_argument("--csv", help="also write the table per aspect ratio here")
    parser.add_argument("--fields", help="drumFieldIndices.py's fields.csv: S of the time-averaged fields too")
    args = parser.parse_args()
    try:
        with open(args.results, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{args.results}: {e.strerror}")
    needed = {"aspect", "windows", "S", "S_sd", "M", "M_sd", "angle", "angle_sd"}
    if not rows or not needed <= set(rows[0]):
        fail(f"{args.results}: no result lines with the columns {', '.join(sorted(needed))} (a runDrumSweep.py results.csv)")
    s_table, angle_table = summarise(rows, "S"), summarise(rows, "angle")
    print("R,seeds,S,S_error,angle,angle_error")
    lines = [f"{a:g},{k},{s:.5f},{e:.5f},{an:.3f},{ae:.3f}"
             for (a, k, s, e), (_, _, an, ae) in zip(s_table, angle_table)]
    print("\n".join(lines))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("R,seeds,S,S_error,angle,angle_error\n" + "\n".join(lines) + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(6, 6.5), sharex=True)
    top.axhline(0, color="0.6", linewidth=0.8)
    top.errorbar([t[0] for t in s_table], [t[2] for t in s_table], yerr=[t[3] for t in s_table], marker="o",
                 capsize=3, color="tab:blue")
    if args.fields:
        try:
            with open(args.fields, newline="") as f:
                field_rows = list(csv.DictReader(f))
        except OSError as e:
            fail(f"{args.fields}: {e.strerror}")
        if not field_rows or not {"aspect", "windows", "S_fields", "S_fields_sd"} <= set(field_rows[0]):
            fail(f"{args.fields}: no lines with the columns aspect, windows, S_fields, S_fields_sd "
                 "(a drumFieldIndices.py fields.csv)")
        fields_table = summarise(field_rows, "S_fields")
        top.errorbar([t[0] for t in fields_table], [t[2] for t in fields_table], yerr=[t[3] for t in fields_table],
                     marker="o", markerfacecolor="none", linestyle="--", capsize=3, color="tab:blue",
                     label="of the windows' time-averaged fields")
        top.plot([], [], marker="o", color="tab:blue", label="mean of the samples")
        top.legend(loc="upper right", fontsize=8)
    top.set_ylabel("segregation index S")
    top.text(0.02, 0.95, "S > 0: ellipsoids at the core", transform=top.transAxes, va="top", fontsize=8)
    top.text(0.02, 0.05, "S < 0: ellipsoids at the periphery", transform=top.transAxes, va="bottom", fontsize=8)
    bottom.errorbar([t[0] for t in angle_table], [t[2] for t in angle_table], yerr=[t[3] for t in angle_table],
                    marker="s", capsize=3, color="tab:red")
    bottom.set_ylabel("dynamic angle of repose (degrees)")
    bottom.set_xlabel("aspect ratio R of the ellipsoids")
    figure.tight_layout()
    figure.savefig(args.output, dpi=120)
    print(f"plotDrumSweep: wrote {args.output}")


if __name__ == "__main__":
    main()
