#!/usr/bin/python3
"""Runs the drum sweep (Documentation/Drums/RotatingDrum.md "The sweep"): one RotatingDrum run per
aspect ratio R and seed, as independent restartable jobs (Tools/Studies/studyRunner.py: a killed
sweep resumes when the same command runs again; --done takes the points of an earlier
results.csv as finished).

    Tools/Drum/runDrumSweep.py --driver build/Drivers/Drum/RotatingDrum --out DIR \\
        --aspects 1,1.5,2,2.5,3,3.5,4 --seeds 1,2 -- --radius 15 --length 10

Each run fills its drum, turns it --turns times and then --windows windows of --window-turns
turns each (the thesis's protocol: ten turns, then three windows of half a turn), and stops
(RotatingDrum --rotations). From the run's NAME.series (a sample every time unit: the mixing and
segregation indices M and S of the sphere fraction, from the coarse-graining library, and the
angle of repose) each window's means of M, S and the angle; the point's result line holds their
mean over the windows and the standard deviation of the window means:

    aspect, seed, turns, windows, samples, M, M_sd, S, S_sd, angle, angle_sd, particles

S > 0: spheres at the periphery, ellipsoids at the core. `plotDrumSweep.py` draws S against R.
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Studies"))
from studyRunner import Point, run_study  # noqa: E402 (Tools/Studies, beside this folder)

THESIS_ASPECTS = [1, 1.5, 2, 2.5, 3, 3.5, 4]


def parse_list(text, kind, flag):
    try:
        values = [kind(x) for x in text.split(",") if x.strip() != ""]
    except ValueError:
        sys.exit(f"runDrumSweep: {flag} {text!r}: a comma-separated list of numbers is expected")
    if not values:
        sys.exit(f"runDrumSweep: the sweep is empty: {flag} gave no values")
    return values


def point_name(aspect, seed):
    return f"R{aspect:g}-s{seed}"


def series_samples(series_path, program="runDrumSweep"):
    """The samples of a run's .series: (t, rotations, M, S, angle) per line."""
    try:
        with open(series_path) as f:
            lines = [(number, line.split()) for number, line in enumerate(f, start=1)
                     if line.strip() and not line.startswith("#")]
    except OSError as e:
        sys.exit(f"{program}: {series_path}: {e.strerror}")
    samples = []
    for number, words in lines:
        if len(words) != 6:
            sys.exit(f"{program}: {series_path} line {number}: 6 columns expected (t rotations kineticEnergy "
                     f"mixingIndex segregationIndex reposeAngleDegrees), found {len(words)}")
        samples.append((float(words[0]), float(words[1]), float(words[3]), float(words[4]), float(words[5])))
    return samples


def window_of(rotations, turns, window_turns):
    """The window (0, 1, ...) a sample at `rotations` turns belongs to; negative before the first."""
    return math.floor((rotations - turns) / window_turns)


def window_means(series_path, turns, windows, window_turns):
    """Per window, the means of M, S and the angle over the samples with turns + w * window_turns
    <= rotations < turns + (w + 1) * window_turns, and the number of samples."""
    sums = [[0.0, 0.0, 0.0, 0] for _ in range(windows)]
    for _, rotations, m, s, angle in series_samples(series_path):
        w = window_of(rotations, turns, window_turns)
        if 0 <= w < windows:
            sums[w][0] += m
            sums[w][1] += s
            sums[w][2] += angle
            sums[w][3] += 1
    for w, (_, _, _, count) in enumerate(sums):
        if count == 0:
            sys.exit(f"{series_path}: no sample in window {w + 1} (turns {turns + w * window_turns:g} to "
                     f"{turns + (w + 1) * window_turns:g}): the run ended early or samples too rarely")
    return [(m / n, s / n, a / n, n) for m, s, a, n in sums]


def mean_and_sd(values):
    mean = sum(values) / len(values)
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1)) if len(values) > 1 else float("nan")
    return mean, sd


def particles_of(log_path):
    """The particle count the run's log names ('N of N particles in the drum'), or nan."""
    try:
        with open(log_path) as f:
            for line in reversed(f.readlines()):
                if "particles in the drum" in line:
                    return line.rsplit(";", 1)[-1].split()[0]
    except OSError:
        pass
    return "nan"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--driver", required=True, help="the RotatingDrum program")
    parser.add_argument("--out", required=True, help="the sweep's folder (points/ and results.csv)")
    parser.add_argument("--aspects", default=",".join(f"{a:g}" for a in THESIS_ASPECTS),
                        help="comma-separated aspect ratios (default the thesis's 1 ... 4)")
    parser.add_argument("--seeds", default="1", help="comma-separated seeds (default 1)")
    parser.add_argument("--turns", type=float, default=10, help="turns before the first window (default 10)")
    parser.add_argument("--windows", type=int, default=3, help="windows averaged (default 3)")
    parser.add_argument("--window-turns", type=float, default=0.5, help="turns per window (default 0.5)")
    parser.add_argument("--jobs", type=int, default=2, help="runs at once (default 2)")
    parser.add_argument("--restart-interval", type=float, default=50,
                        help="simulated time between restart files of a run (default 50)")
    parser.add_argument("--done", help="an earlier results.csv: its points of this sweep count as finished")
    parser.add_argument("driver_flags", nargs="*", help="after --: flags for every run (e.g. --radius 15 --length 10)")
    args = parser.parse_args()

    aspects = parse_list(args.aspects, float, "--aspects")
    seeds = parse_list(args.seeds, int, "--seeds")
    if not (args.turns >= 0 and args.windows >= 1 and args.window_turns > 0):
        sys.exit("runDrumSweep: --turns must not be negative, --windows at least 1, --window-turns positive")
    bad = [a for a in aspects if not a >= 1]
    if bad:
        sys.exit(f"runDrumSweep: --aspects {args.aspects}: aspect ratios must be at least 1 (found {bad[0]:g})")
    last_turn = args.turns + args.windows * args.window_turns
    grid = {point_name(a, s): (a, s) for a in aspects for s in seeds}
    # Longer ellipsoids cost more (more neighbours in the list and Newton iterations): about R.
    points = [Point(name, ["--aspect", f"{a:g}", "--seed", str(s)], cost=a) for name, (a, s) in grid.items()]

    def finish(folder, name):
        aspect, seed = grid[name]
        means = window_means(os.path.join(folder, name + ".series"), args.turns, args.windows, args.window_turns)
        m, m_sd = mean_and_sd([w[0] for w in means])
        s, s_sd = mean_and_sd([w[1] for w in means])
        angle, angle_sd = mean_and_sd([w[2] for w in means])
        row = {"aspect": f"{aspect:g}", "seed": seed, "turns": f"{args.turns:g}", "windows": args.windows,
               "samples": sum(w[3] for w in means), "M": f"{m:.8g}", "M_sd": f"{m_sd:.3g}", "S": f"{s:.8g}",
               "S_sd": f"{s_sd:.3g}", "angle": f"{angle:.5g}", "angle_sd": f"{angle_sd:.3g}",
               "particles": particles_of(os.path.join(folder, "run.log"))}
        path = os.path.join(folder, name + ".result.csv")
        with open(path + ".part", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(row))
            writer.writeheader()
            writer.writerow(row)
        os.replace(path + ".part", path)

    run_study("runDrumSweep", args.driver, args.out, points, args.jobs,
              ["--rotations", f"{last_turn:g}", "--end-time", "1e9", "--vtu", "off", "--fstat", "off"] + args.driver_flags,
              args.restart_interval, done=args.done, finish=finish,
              describe=lambda row: f"S = {row['S']} +- {row['S_sd']}, M = {row['M']}, angle {row['angle']} degrees")


if __name__ == "__main__":
    main()
