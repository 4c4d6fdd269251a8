#!/usr/bin/python3
"""The mixing and segregation indices of a drum sweep's runs from time-averaged fields
(Documentation/Drums/RotatingDrum.md, "The sweep"): for every finished run of the sweep's folder,
talus-cg averages the fields (x, z) over the frames of NAME.data inside the run's windows and
computes M and S of that average (--mixing 0, the spheres species 0). Each sample of a run's
.series is M of one instant, which a few particles per kernel make noisy: a random mixture
there reads M below 1, and S = 1 - M away from 0 (with the sign of where the spheres' centre of
mass lies), so weak segregation and none look alike. The average over frames removes that noise.

    drumFieldIndices.py SWEEP --cg build/Tools/CG/talus-cg [--turns 10 --windows 3 --window-turns 0.5]

writes SWEEP/fields.csv: point, aspect, seed, frames, t_from, t_to, M_fields, S_fields (and each
run's fields beside it, points/NAME/NAME.fields.csv). The windows are those of runDrumSweep.py:
from the first sample at or after --turns turns to the last before --turns + --windows x
--window-turns.
"""
import argparse
import csv
import os
import re
import subprocess
import sys


def fail(message):
    sys.exit(f"drumFieldIndices: {message}")


def window_span(series_path, first_turn, last_turn):
    """(t_from, t_to): the first and last sample times with first_turn <= rotations < last_turn."""
    times = []
    try:
        with open(series_path) as f:
            for number, line in enumerate(f, start=1):
                if not line.strip() or line.startswith("#"):
                    continue
                words = line.split()
                if len(words) != 6:
                    fail(f"{series_path} line {number}: 6 columns expected, found {len(words)}")
                if first_turn <= float(words[1]) < last_turn:
                    times.append(float(words[0]))
    except OSError as e:
        fail(f"{series_path}: {e.strerror}")
    if not times:
        fail(f"{series_path}: no sample between {first_turn:g} and {last_turn:g} turns")
    return times[0], times[-1]


def field_indices(cg, folder, name, t_from, t_to):
    """(frames, M, S) of the fields averaged over the frames of NAME.data in [t_from, t_to]."""
    base = os.path.join(folder, name)
    fields = base + ".fields.csv"
    command = [cg, base, "--coordinates", "XZ", "--time-average", "--time-min", repr(t_from), "--time-max",
               repr(t_to), "--fixed", "exclude", "-w", "1", "--stress", "off", "--mixing", "0", "-o", fields]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{name}: talus-cg failed:\n{done.stderr}{done.stdout}")
    found = re.search(r"(\d+) frames? \(t = ", done.stdout + done.stderr)
    if not found:
        fail(f"{name}: talus-cg did not say how many frames it averaged:\n{done.stdout}{done.stderr}")
    with open(base + ".fields.mixing.csv", newline="") as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    if len(rows) != 1:
        fail(f"{base}.fields.mixing.csv: one line of M and S expected, found {len(rows)}")
    return int(found.group(1)), float(rows[0]["MixingIndex"]), float(rows[0]["SegregationIndex"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sweep", help="the sweep's folder (points/, results.csv)")
    parser.add_argument("--cg", required=True, help="the talus-cg program")
    parser.add_argument("--turns", type=float, default=10, help="turns before the first window (default 10)")
    parser.add_argument("--windows", type=int, default=3, help="windows (default 3)")
    parser.add_argument("--window-turns", type=float, default=0.5, help="turns per window (default 0.5)")
    args = parser.parse_args()
    if not (args.turns >= 0 and args.windows >= 1 and args.window_turns > 0):
        fail("--turns must not be negative, --windows at least 1, --window-turns positive")
    results = os.path.join(args.sweep, "results.csv")
    try:
        with open(results, newline="") as f:
            points = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{results}: {e.strerror}")
    if not points or "point" not in points[0]:
        fail(f"{results}: no finished points (a runDrumSweep.py results.csv)")
    last_turn = args.turns + args.windows * args.window_turns
    rows = []
    for point in points:
        name = point["point"]
        folder = os.path.join(args.sweep, "points", name)
        t_from, t_to = window_span(os.path.join(folder, name + ".series"), args.turns, last_turn)
        frames, m, s = field_indices(args.cg, folder, name, t_from, t_to)
        if frames < 2:
            print(f"{name}: only {frames} frame in the windows (t = {t_from:g} to {t_to:g}): the noise is not averaged "
                  f"out; write frames more often (--output-interval)", file=sys.stderr)
        rows.append({"point": name, "aspect": point["aspect"], "seed": point["seed"], "frames": frames,
                     "t_from": f"{t_from:g}", "t_to": f"{t_to:g}", "M_fields": f"{m:.8g}", "S_fields": f"{s:.8g}"})
        print(f"{name}: {frames} frames, t = {t_from:g} to {t_to:g}: M = {m:.5f}, S = {s:+.5f} "
              f"(the samples' means: M = {float(point['M']):.5f}, S = {float(point['S']):+.5f})")
    out = os.path.join(args.sweep, "fields.csv")
    with open(out + ".part", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    os.replace(out + ".part", out)
    print(f"wrote {out} ({len(rows)} points)")


if __name__ == "__main__":
    main()
