#!/usr/bin/python3
"""Runs a periodic-chute calibration study (Documentation/Calibration.md): one CalibrationChute
run per point of a grid of species, angles and depths, as independent jobs (--jobs at once).

Each point runs in its own folder OUT/points/NAME. A point whose NAME.result.csv exists is
skipped; a point with a NAME.restart (a killed run) continues from it (--restart). So a study that
was killed resumes where it stopped when the same command runs again. Every finished point's line
goes into OUT/results.csv (rewritten at every point, with the column `point`). With --done FILE
the points that have a line in FILE (an earlier results.csv, say of a study begun on another
machine) count as finished: their lines go into their folders and they are not run again.

    Tools/Calibration/runStudy.py --driver build/Drivers/Calibration/CalibrationChute --out /work/studies/calibration

Without grid flags the reduced default study runs: large spheres on a base of small spheres in a
10 x 10 box, angles 23 to 27 degrees by 1, depths 1, 2, 3, 4 and 6 (25 points; estimated at 15
to 30 minutes on two free cores).
"""
import argparse
import csv
import ctypes
import itertools
import os
import signal
import subprocess
import sys
import time

# The reduced default study: large spheres only (the fewest per unit depth) in a 10 x 10 box
# (in 6 x 6 the flows near h_stop fluctuate too much for any plateau) on a base of small spheres
# (the thesis's section 3.2.4; on a base of large spheres h_stop comes out 1.5 to 2 times Table
# 3.1's: Documentation/Calibration.md "Accounts"), five angles and five depths around the large
# spheres' h_stop curve: Table 3.1 (d1 = 18.6, d2 = 30.06 deg, A = 3.07) gives h_stop = 5.4, 3.8,
# 2.7, 1.9, 1.2 at 23 ... 27 deg, which the driver's h puts 0.74 higher, and a depth D gives h of
# about D + 0.7. A plateau of 100 samples within 5%, 30 time units of averaging, at most 500 a point.
REDUCED = {
    "species": ["large"],
    "angles": [23, 24, 25, 26, 27],
    "depths": [1, 2, 3, 4, 6],
    "driver_flags": ["--base-diameter", "0.7937005259840998", "--length", "10", "--width", "10", "--window", "100",
                     "--tolerance", "0.05", "--average-time", "30", "--end-time", "500"],
}


def parse_list(text, kind, flag):
    try:
        return [kind(x) for x in text.split(",") if x.strip() != ""]
    except ValueError:
        sys.exit(f"runStudy: {flag} {text!r}: a comma-separated list of numbers is expected")


def point_name(species, angle, depth):
    return f"{species}-a{angle:g}-d{depth:g}"


def die_with_parent():
    """The child gets SIGTERM when the runner dies (also by SIGKILL), so that no run of a killed
    study goes on writing into its folder while a resumed study runs the same point."""
    libc = ctypes.CDLL("libc.so.6", use_errno=True)
    libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG


def collect(out, names):
    """All result lines of the finished points, in grid order, into OUT/results.csv."""
    rows, header = [], None
    for name in names:
        path = os.path.join(out, "points", name, name + ".result.csv")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            reader = csv.DictReader(f)
            for row in reader:
                header = ["point"] + reader.fieldnames
                rows.append({"point": name, **row})
    if header is None:
        return 0
    temporary = os.path.join(out, "results.csv.part")
    with open(temporary, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=header)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(temporary, os.path.join(out, "results.csv"))
    return len(rows)


def adopt_done(path, out, names):
    """The lines of an earlier results.csv whose point is in this grid become those points' result
    files (where they have none yet), so that the points are skipped. Returns how many."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            fields = reader.fieldnames or []
    except OSError as e:
        sys.exit(f"runStudy: --done {path}: {e.strerror}")
    if "point" not in fields:
        sys.exit(f"runStudy: --done {path}: no column 'point' (a results.csv of runStudy.py is expected)")
    columns = [c for c in fields if c != "point"]
    adopted = 0
    for line, row in enumerate(rows, start=2):
        name = row["point"]
        if name not in names:
            continue
        if any(row.get(c) is None for c in columns):
            sys.exit(f"runStudy: --done {path} line {line}: point {name} has fewer columns than the header")
        folder = os.path.join(out, "points", name)
        result = os.path.join(folder, name + ".result.csv")
        if os.path.exists(result):
            continue
        os.makedirs(folder, exist_ok=True)
        with open(result + ".part", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=columns)
            writer.writeheader()
            writer.writerow({c: row[c] for c in columns})
        os.replace(result + ".part", result)
        adopted += 1
    return adopted


def minutes(seconds):
    return f"{seconds / 60:.1f} min"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--driver", required=True, help="the CalibrationChute program")
    parser.add_argument("--out", required=True, help="the study's folder (points/ and results.csv)")
    parser.add_argument("--species", help="comma-separated: large, small, mixture")
    parser.add_argument("--angles", help="comma-separated angles in degrees")
    parser.add_argument("--depths", help="comma-separated depths (CalibrationChute --depth)")
    parser.add_argument("--jobs", type=int, default=2, help="points run at once (default 2)")
    parser.add_argument("--restart-interval", type=float, default=20,
                        help="simulated time between restart files of a point (default 20)")
    parser.add_argument("--done", help="an earlier results.csv: its points of this grid count as finished")
    parser.add_argument("driver_flags", nargs="*", help="after --: flags for every point's run")
    args = parser.parse_args()

    grid_given = args.species is not None or args.angles is not None or args.depths is not None
    species = args.species.split(",") if args.species is not None else REDUCED["species"]
    angles = parse_list(args.angles, float, "--angles") if args.angles is not None else REDUCED["angles"]
    depths = parse_list(args.depths, float, "--depths") if args.depths is not None else REDUCED["depths"]
    flags = list(args.driver_flags) if grid_given or args.driver_flags else list(REDUCED["driver_flags"])
    species = [s for s in species if s.strip() != ""]
    if not species or not angles or not depths:
        missing = [f for f, v in (("--species", species), ("--angles", angles), ("--depths", depths)) if not v]
        sys.exit(f"runStudy: the study grid is empty: {', '.join(missing)} gave no values")
    if args.jobs < 1:
        sys.exit(f"runStudy: --jobs {args.jobs}: at least one job")
    if not os.access(args.driver, os.X_OK):
        sys.exit(f"runStudy: --driver {args.driver}: not an executable program")
    driver = os.path.abspath(args.driver)

    points = list(itertools.product(species, angles, depths))
    names = [point_name(*p) for p in points]
    os.makedirs(os.path.join(args.out, "points"), exist_ok=True)
    if args.done is not None:
        print(f"study: {adopt_done(args.done, args.out, names)} finished points taken from {args.done}", flush=True)
    todo = []
    for (s, a, d), name in zip(points, names):
        folder = os.path.join(args.out, "points", name)
        if os.path.exists(os.path.join(folder, name + ".result.csv")):
            print(f"skip {name}: its result exists", flush=True)
            continue
        todo.append((s, a, d, name, folder))
    print(f"study: {len(points)} points, {len(points) - len(todo)} done before, {len(todo)} to run, "
          f"{args.jobs} at a time", flush=True)

    running, durations, failed = {}, [], []
    finished_depth = 0.0
    start = time.time()

    def report():
        # A point costs about its number of spheres, so its depth, times its time: the time left is
        # estimated from the wall time per unit depth of the points finished so far, for the depths
        # waiting and running, over the jobs.
        done = len(durations) + len(failed)
        waiting = sum(p[2] for p in queue) + sum(d for (_, _, _, _, d) in running.values())
        if durations and finished_depth > 0:
            left = sum(durations) / finished_depth * waiting / args.jobs
            estimate = f", about {minutes(left)} left"
        else:
            estimate = ""
        print(f"[{minutes(time.time() - start)}] {done}/{len(todo)} points run, {len(running)} running{estimate}",
              flush=True)

    queue = list(todo)
    while queue or running:
        while queue and len(running) < args.jobs:
            s, a, d, name, folder = queue.pop(0)
            os.makedirs(folder, exist_ok=True)
            command = [driver, "--name", name, "--output-interval", f"{args.restart_interval:g}",
                       "--vtu", "off", "--fstat", "off"]
            restart = os.path.join(folder, name + ".restart")
            if os.path.exists(restart):
                command += ["--restart", name + ".restart"]
                how = "continues from its restart file"
            else:
                command += ["--species", s, "--angle", f"{a:g}", "--depth", f"{d:g}"]
                how = "starts"
            command += flags
            log = open(os.path.join(folder, "run.log"), "a")
            print(f"{name} {how}", flush=True)
            running[subprocess.Popen(command, cwd=folder, stdout=log, stderr=subprocess.STDOUT,
                                     preexec_fn=die_with_parent)] = (name, folder, time.time(), log, d)
        time.sleep(0.2)
        for process in [p for p in running if p.poll() is not None]:
            name, folder, began, log, depth = running.pop(process)
            log.close()
            if process.returncode == 0 and os.path.exists(os.path.join(folder, name + ".result.csv")):
                durations.append(time.time() - began)
                finished_depth += depth
                with open(os.path.join(folder, name + ".result.csv")) as f:
                    row = next(csv.DictReader(f))
                print(f"{name} finished in {minutes(durations[-1])}: {row['state']}, h = {row['h']}, F = {row['F']}",
                      flush=True)
            else:
                failed.append(name)
                print(f"{name} FAILED (exit status {process.returncode}): see {folder}/run.log", flush=True)
            collect(args.out, names)
            report()
    count = collect(args.out, names)
    print(f"study: {count} of {len(points)} points have results in {os.path.join(args.out, 'results.csv')}",
          flush=True)
    if failed:
        sys.exit(f"runStudy: {len(failed)} points failed: {', '.join(failed)}")


if __name__ == "__main__":
    main()
