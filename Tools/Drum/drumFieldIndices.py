#!/usr/bin/python3
"""The mixing and segregation indices of a drum sweep's runs from time-averaged fields, the
thesis's way (Documentation/Drums/RotatingDrum.md, "The sweep"): for every finished run of the
sweep's folder and each of its windows, talus-cg averages the fields (x, z) over the frames of
NAME.data inside the window and computes M and S of that average (--mixing 0, the spheres
species 0); the point's M and S are the means over the windows, their spread the standard
deviation of the window values. Each sample of a run's .series is M of one instant, which a few
particles per kernel make noisy: a random mixture there reads M below 1, and S = 1 - M away from
0 (with the sign of where the spheres' centre of mass lies), so weak segregation and none look
alike. The average over frames removes that noise.

    drumFieldIndices.py SWEEP --cg build/Tools/CG/talus-cg [--turns 10 --windows 3 --window-turns 0.5]

writes SWEEP/fields.csv: point, aspect, seed, windows, frames, M_fields, M_fields_sd, S_fields,
S_fields_sd, S_all (S of the fields averaged over the frames of all windows at once), and
SWEEP/fields-windows.csv: point, window, t_from, t_to, frames, M, S (and each run's fields
beside it, points/NAME/NAME.fields.csv, of all windows). The windows are those of
runDrumSweep.py: window w holds the samples with turns + w x window-turns <= rotations <
turns + (w + 1) x window-turns, and a frame belongs to it when its time lies between the first
and the last of those samples' times.
"""
import argparse
import csv
import os
import re
import subprocess
import sys

from runDrumSweep import mean_and_sd, series_samples, window_of  # (beside this file)


def fail(message):
    sys.exit(f"drumFieldIndices: {message}")


def window_spans(series_path, turns, windows, window_turns):
    """Per window, (t_from, t_to): the first and last sample times inside it."""
    spans = [[None, None] for _ in range(windows)]
    for t, rotations, _, _, _ in series_samples(series_path, "drumFieldIndices"):
        w = window_of(rotations, turns, window_turns)
        if 0 <= w < windows:
            spans[w][0] = t if spans[w][0] is None else spans[w][0]
            spans[w][1] = t
    for w, (first, _) in enumerate(spans):
        if first is None:
            fail(f"{series_path}: no sample in window {w + 1} (turns {turns + w * window_turns:g} to "
                 f"{turns + (w + 1) * window_turns:g})")
    return [tuple(span) for span in spans]


def field_indices(cg, folder, name, t_from, t_to, fields):
    """(frames, M, S) of the fields averaged over the frames of NAME.data in [t_from, t_to], the
    fields written to `fields` (and M and S beside it, .mixing.csv)."""
    base = os.path.join(folder, name)
    command = [cg, base, "--coordinates", "XZ", "--time-average", "--time-min", repr(t_from), "--time-max",
               repr(t_to), "--fixed", "exclude", "-w", "1", "--stress", "off", "--mixing", "0", "-o", fields]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:
        fail(f"{name}: talus-cg failed:\n{done.stderr}{done.stdout}")
    found = re.search(r"(\d+) frames? \(t = ", done.stdout + done.stderr)
    if not found:
        fail(f"{name}: talus-cg did not say how many frames it averaged:\n{done.stdout}{done.stderr}")
    mixing = fields[:-len(".csv")] + ".mixing.csv"
    with open(mixing, newline="") as f:
        rows = list(csv.DictReader(row for row in f if not row.startswith("#")))
    if len(rows) != 1:
        fail(f"{mixing}: one line of M and S expected, found {len(rows)}")
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
    rows, window_rows = [], []
    for point in points:
        name = point["point"]
        folder = os.path.join(args.sweep, "points", name)
        spans = window_spans(os.path.join(folder, name + ".series"), args.turns, args.windows, args.window_turns)
        scratch = os.path.join(folder, name + ".window.csv")
        per_window = []
        for w, (t_from, t_to) in enumerate(spans, start=1):
            frames, m, s = field_indices(args.cg, folder, name, t_from, t_to, scratch)
            if frames < 2:
                print(f"{name}: only {frames} frame in window {w} (t = {t_from:g} to {t_to:g}): its noise is not "
                      f"averaged out; write frames more often (the sweep's --restart-interval)", file=sys.stderr)
            per_window.append((frames, m, s))
            window_rows.append({"point": name, "window": w, "t_from": f"{t_from:g}", "t_to": f"{t_to:g}",
                                "frames": frames, "M": f"{m:.8g}", "S": f"{s:.8g}"})
        for leftover in (scratch, scratch[:-len(".csv")] + ".mixing.csv"):
            os.remove(leftover)
        _, _, s_all = field_indices(args.cg, folder, name, spans[0][0], spans[-1][1],
                                    os.path.join(folder, name + ".fields.csv"))
        m_mean, m_sd = mean_and_sd([w[1] for w in per_window])
        s_mean, s_sd = mean_and_sd([w[2] for w in per_window])
        frames = sum(w[0] for w in per_window)
        rows.append({"point": name, "aspect": point["aspect"], "seed": point["seed"], "windows": len(spans), "frames": frames,
                     "M_fields": f"{m_mean:.8g}", "M_fields_sd": f"{m_sd:.3g}", "S_fields": f"{s_mean:.8g}",
                     "S_fields_sd": f"{s_sd:.3g}", "S_all": f"{s_all:.8g}"})
        print(f"{name}: {frames} frames in {len(spans)} windows: S = {s_mean:+.5f} +- {s_sd:.5f} (windows "
              f"{', '.join(f'{w[2]:+.4f}' for w in per_window)}; all frames at once {s_all:+.5f}); "
              f"the samples' means: S = {float(point['S']):+.5f}")
    for path, table in ((os.path.join(args.sweep, "fields.csv"), rows),
                        (os.path.join(args.sweep, "fields-windows.csv"), window_rows)):
        with open(path + ".part", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(table[0]))
            writer.writeheader()
            writer.writerows(table)
        os.replace(path + ".part", path)
    print(f"wrote {os.path.join(args.sweep, 'fields.csv')} ({len(rows)} points) and fields-windows.csv")


if __name__ == "__main__":
    main()
