"""Runs the points of a study as independent, restartable jobs (the calibration study,
Tools/Calibration/runStudy.py; the drum sweep, Tools/Drum/runDrumSweep.py).

Each point runs in its own folder OUT/points/NAME and is finished when its NAME.result.csv (one
header and one line) exists: such a point is skipped. A point with a NAME.restart (a killed run)
continues from it. So a study that was killed resumes where it stopped when the same command runs
again; the runs die with their runner (PR_SET_PDEATHSIG), so that no run of a killed study goes on
writing into a folder a resumed study uses. Every finished point's line goes into OUT/results.csv
(rewritten at every point, with the column `point`). With `done` (an earlier results.csv, say of
a study begun on another machine) the points that have a line there count as finished.
"""
import csv
import ctypes
import os
import signal
import subprocess
import sys
import time


class Point:
    """One run of a study: its name, the flags that start it and those that continue it from its
    restart file (the runner adds --name, --restart), and its cost relative to the other points
    (for the estimate of the time left)."""

    def __init__(self, name, start_flags, cost=1.0):
        self.name, self.start_flags, self.cost = name, list(start_flags), cost


def die_with_parent():
    """The child gets SIGTERM when the runner dies (also by SIGKILL)."""
    libc = ctypes.CDLL("libc.so.6", use_errno=True)
    libc.prctl(1, signal.SIGTERM)  # PR_SET_PDEATHSIG


def minutes(seconds):
    return f"{seconds / 60:.1f} min"


def result_path(out, name):
    return os.path.join(out, "points", name, name + ".result.csv")


def read_result(out, name):
    with open(result_path(out, name)) as f:
        return next(csv.DictReader(f))


def collect(out, names):
    """All result lines of the finished points, in grid order, into OUT/results.csv. The columns
    are those of every point's file, in the order they first appear (a point run by an older
    driver, or adopted from an older study, may lack a later column: it is left empty there)."""
    rows, header = [], ["point"]
    for name in names:
        if not os.path.exists(result_path(out, name)):
            continue
        with open(result_path(out, name)) as f:
            reader = csv.DictReader(f)
            for row in reader:
                header += [c for c in reader.fieldnames if c not in header]
                rows.append({"point": name, **row})
    if not rows:
        return 0
    temporary = os.path.join(out, "results.csv.part")
    with open(temporary, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=header)
        writer.writeheader()
        writer.writerows(rows)
    os.replace(temporary, os.path.join(out, "results.csv"))
    return len(rows)


def adopt_done(path, out, names, tool):
    """The lines of an earlier results.csv whose point is in this grid become those points' result
    files (where they have none yet), so that the points are skipped. Returns how many."""
    try:
        with open(path, newline="") as f:
            reader = csv.DictReader(f)
            rows = list(reader)
            fields = reader.fieldnames or []
    except OSError as e:
        sys.exit(f"{tool}: --done {path}: {e.strerror}")
    if "point" not in fields:
        sys.exit(f"{tool}: --done {path}: no column 'point' (a study's results.csv is expected)")
    columns = [c for c in fields if c != "point"]
    adopted = 0
    for line, row in enumerate(rows, start=2):
        name = row["point"]
        if name not in names:
            continue
        if any(row.get(c) is None for c in columns):
            sys.exit(f"{tool}: --done {path} line {line}: point {name} has fewer columns than the header")
        result = result_path(out, name)
        if os.path.exists(result):
            continue
        os.makedirs(os.path.dirname(result), exist_ok=True)
        with open(result + ".part", "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=columns)
            writer.writeheader()
            writer.writerow({c: row[c] for c in columns})
        os.replace(result + ".part", result)
        adopted += 1
    return adopted


def run_study(tool, driver, out, points, jobs, common_flags, restart_interval, done=None, finish=None,
              describe=None):
    """Runs the points (a list of Point) `jobs` at a time with `common_flags` each, a restart file
    every `restart_interval` of simulated time. `finish(folder, name)` runs after a point's run
    ended well, to write its NAME.result.csv if the driver does not (it may raise SystemExit with
    a message); `describe(row)` says what a finished point's result line holds. Exits non-zero
    naming the points that failed."""
    if jobs < 1:
        sys.exit(f"{tool}: --jobs {jobs}: at least one job")
    if not os.access(driver, os.X_OK):
        sys.exit(f"{tool}: --driver {driver}: not an executable program")
    driver = os.path.abspath(driver)
    names = [p.name for p in points]
    os.makedirs(os.path.join(out, "points"), exist_ok=True)
    if done is not None:
        print(f"study: {adopt_done(done, out, names, tool)} finished points taken from {done}", flush=True)
    todo = []
    for point in points:
        if os.path.exists(result_path(out, point.name)):
            print(f"skip {point.name}: its result exists", flush=True)
            continue
        todo.append(point)
    print(f"study: {len(points)} points, {len(points) - len(todo)} done before, {len(todo)} to run, "
          f"{jobs} at a time", flush=True)

    running, durations, failed = {}, [], []
    finished_cost = 0.0
    start = time.time()
    queue = list(todo)

    def report():
        # The time left from the wall time per unit cost of the points finished so far, for the
        # points waiting and running, over the jobs.
        finished = len(durations) + len(failed)
        waiting = sum(p.cost for p in queue) + sum(entry[0].cost for entry in running.values())
        estimate = ""
        if durations and finished_cost > 0:
            estimate = f", about {minutes(sum(durations) / finished_cost * waiting / jobs)} left"
        print(f"[{minutes(time.time() - start)}] {finished}/{len(todo)} points run, {len(running)} running{estimate}",
              flush=True)

    while queue or running:
        while queue and len(running) < jobs:
            point = queue.pop(0)
            folder = os.path.join(out, "points", point.name)
            os.makedirs(folder, exist_ok=True)
            command = [driver, "--name", point.name, "--output-interval", f"{restart_interval:g}"]
            if os.path.exists(os.path.join(folder, point.name + ".restart")):
                command += ["--restart", point.name + ".restart"]
                how = "continues from its restart file"
            else:
                command += point.start_flags
                how = "starts"
            command += common_flags
            log = open(os.path.join(folder, "run.log"), "a")
            print(f"{point.name} {how}", flush=True)
            process = subprocess.Popen(command, cwd=folder, stdout=log, stderr=subprocess.STDOUT,
                                       preexec_fn=die_with_parent)
            running[process] = (point, folder, time.time(), log)
        time.sleep(0.2)
        for process in [p for p in running if p.poll() is not None]:
            point, folder, began, log = running.pop(process)
            log.close()
            ok = process.returncode == 0
            if ok and finish is not None and not os.path.exists(result_path(out, point.name)):
                try:
                    finish(folder, point.name)
                except SystemExit as e:
                    print(f"{point.name}: {e}", flush=True)
                    ok = False
            if ok and os.path.exists(result_path(out, point.name)):
                durations.append(time.time() - began)
                finished_cost += point.cost
                said = describe(read_result(out, point.name)) if describe else ""
                print(f"{point.name} finished in {minutes(durations[-1])}{': ' + said if said else ''}", flush=True)
            else:
                failed.append(point.name)
                print(f"{point.name} FAILED (exit status {process.returncode}): see {folder}/run.log", flush=True)
            collect(out, names)
            report()
    count = collect(out, names)
    print(f"study: {count} of {len(points)} points have results in {os.path.join(out, 'results.csv')}", flush=True)
    if failed:
        sys.exit(f"{tool}: {len(failed)} points failed: {', '.join(failed)}")
