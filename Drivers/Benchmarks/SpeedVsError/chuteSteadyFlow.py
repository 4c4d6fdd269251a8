#!/usr/bin/env python3
"""Speed against error of the time step and of the contact stiffness on a dense flow
(Documentation/SpeedVsError.md, "A steady chute flow"): the periodic chute of
Drivers/Chute/PeriodicBidisperseChute (the thesis's mixture at 24 degrees), run to its steady
state and averaged there, once per setting:

- the time step dt = tc/N (--dt auto, N steps per shortest collision) for N in --steps, against
  the reference N = --reference;
- softer particles: every stiffness divided by F and every damping by sqrt(F) (--softer F: the
  same restitution, collisions sqrt(F) times longer), at N = 50, F in --softer; the reference is
  the stiff one at N = 50 from the first study when it is among --steps, else a run of its own;
- the contact law: Hertz-Mindlin with the same restitution, friction and collision at speed 1
  (--law hertz) at N in --hertz-steps, against the linear law at N = 50; Hertz's collisions
  are timed at speed 1 by --dt auto as well.
--studies picks the studies to run (all three by default).

Each run gives the steady mean velocity, flow height and mass flux with their standard errors
(batch means: the scatter of one trajectory). The error of a setting is its relative difference
from the reference with the combined standard error of both; its cost the number of steps per
time unit (the wall time is printed too, but a shared host makes it noisy). Every run has its own
folder under --work and is skipped when its result exists, so a killed study resumes where it
stopped (a run killed midway starts again; each run's progress is in its folder's run.log).
--jobs runs that many at once. Writes OUT.csv and
OUT.png (|error| against cost with error bars, the Pareto front of each study marked).
  chuteSteadyFlow.py DRIVER [--out PREFIX] [--work DIR] [--jobs 2] [--steps 10,15,...]
                     [--reference 500] [--softer 1,3,10,...] [--hertz-steps 50,200]
                     [--studies "time step,stiffness,contact law"] [-- DRIVER FLAGS]
The default is the reduced form (a 10 x 5 base, 750 spheres, 400 time units): under an hour on two
cores. The driver's own size (20 x 10, 3000 spheres) needs about four times as long.
"""
import argparse
import concurrent.futures
import csv
import math
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speedVsError import pareto  # noqa: E402

tool = "chuteSteadyFlow.py"
STUDIES = ("time step", "stiffness", "contact law")
QUANTITIES = ("velocity", "height", "flux")
STEADY = re.compile(r"over (\d+) samples: mean velocity ([-0-9.e+]+) \+- ([0-9.e+-]+), height ([0-9.e+-]+) \+- "
                    r"([0-9.e+-]+), mass flux ([-0-9.e+]+) \+- ([0-9.e+-]+)")
FINISHED = re.compile(r"finished at t = [0-9.e+-]+: (\d+) steps in ([0-9.e+-]+) s wall")
STEP = re.compile(r"time step ([0-9.e+-]+) \(--dt auto\)")


def run_setting(driver, folder, flags):
    """One steady chute flow in folder (skipped when its result exists): a dict of the numbers the
    driver printed."""
    os.makedirs(folder, exist_ok=True)
    log = os.path.join(folder, "run.log")
    if not (os.path.exists(log) and STEADY.search(open(log).read())):
        # (Into run.log as it runs: the driver's progress lines show how far a long run is.)
        with open(log, "w") as f:
            if subprocess.run([driver] + flags, stdout=f, stderr=subprocess.STDOUT, cwd=folder).returncode != 0:
                sys.exit(f"{tool}: {driver} {' '.join(flags)} failed: see {log}")
    said = open(log).read()
    steady, finished, step = STEADY.search(said), FINISHED.search(said), STEP.search(said)
    if not (steady and finished and step):
        sys.exit(f"{tool}: {log}: the flow did not become steady (or the run printed no step): run longer (--end-time)")
    values = [float(v) for v in steady.groups()]
    row = {"samples": int(values[0]), "dt": float(step.group(1)), "steps": int(finished.group(1)),
           "wall_seconds": float(finished.group(2))}
    for k, name in enumerate(QUANTITIES):
        row[name], row[name + "_error"] = values[1 + 2 * k], values[2 + 2 * k]
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("driver")
    parser.add_argument("--out", default="chute-steady-flow")
    parser.add_argument("--work", default="chute-steady-flow-runs", help="one folder per run (kept: a study resumes)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--steps", default="10,15,25,50,100,200")
    parser.add_argument("--reference", type=float, default=500)
    parser.add_argument("--softer", default="1,3,10,30,100")
    parser.add_argument("--hertz-steps", default="50,200")
    parser.add_argument("--studies", default=",".join(STUDIES), help="comma-separated: " + ", ".join(STUDIES))
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    a = parser.parse_args(argv[:split])
    a.flags = argv[split + 1:]  # (after --: flags for the driver; none: the reduced chute)
    driver = os.path.abspath(a.driver)
    flags = a.flags or ["--length", "10", "--width", "5", "--large", "250", "--small", "500", "--end-time", "400",
                        "--window", "100"]
    common = flags + ["--vtu", "off", "--output-interval", "1000", "--progress-interval", "600", "--dt", "auto"]
    studies = [name.strip() for name in a.studies.split(",")]
    for name in studies:
        if name not in STUDIES:
            sys.exit(f"{tool}: --studies: unknown study '{name}' (known: {', '.join(STUDIES)})")
    steps = sorted({float(n) for n in a.steps.split(",")} | {a.reference})
    softer = sorted({float(f) for f in a.softer.split(",")} | {1.0})
    # A setting: (study, N, F, law); each study's reference is among its settings.
    settings = set()
    if "time step" in studies:
        settings |= {("time step", n, 1.0, "linear") for n in steps}
    if "stiffness" in studies:
        settings |= {("stiffness", 50.0, f, "linear") for f in softer}
    if "contact law" in studies:
        settings |= {("contact law", float(n), 1.0, "hertz") for n in a.hertz_steps.split(",")}
        settings |= {("contact law", 50.0, 1.0, "linear")}
    work = os.path.abspath(a.work)

    def launch(setting):
        study, n, f, law = setting
        folder = os.path.join(work, f"N{n:g}-F{f:g}" if law == "linear" else f"N{n:g}-{law}")
        return run_setting(driver, folder, common + ["--steps-per-collision", repr(n), "--softer", repr(f), "--law", law])

    started = time.time()
    results = {}
    runs = sorted({s[1:] for s in settings}, key=lambda r: -r[0] / math.sqrt(r[1]))  # (one run serves two studies)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, a.jobs)) as pool:
        # (The costliest first, so that the last job to finish is a short one.)
        futures = {pool.submit(launch, ("",) + r): r for r in runs}
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            n, f, law = futures[future]
            results[(n, f, law)] = future.result()
            r = results[(n, f, law)]
            print(f"[{(time.time() - started) / 60:.1f} min] {done}/{len(runs)}: N = {n:g}, F = {f:g}, {law}: velocity "
                  f"{r['velocity']:.4f} +- {r['velocity_error']:.4f}, height {r['height']:.3f} +- {r['height_error']:.3f} "
                  f"({r['steps']} steps in {r['wall_seconds']:.0f} s)", flush=True)

    rows = []
    for study, n, f, law in sorted(settings, key=lambda s: (s[0], s[3], s[1], s[2])):
        reference = results[(a.reference, 1.0, "linear")] if study == "time step" else results[(50.0, 1.0, "linear")]
        r = results[(n, f, law)]
        row = {"study": study, "law": law, "steps_per_collision": n, "softer": f, "dt": r["dt"],
               "steps_per_time_unit": 1 / r["dt"], "wall_seconds": r["wall_seconds"],
               "microseconds_per_step": 1e6 * r["wall_seconds"] / r["steps"], "samples": r["samples"]}
        for q in QUANTITIES:
            row[q], row[q + "_error"] = r[q], r[q + "_error"]
            row[q + "_relative_difference"] = r[q] / reference[q] - 1
            row[q + "_relative_uncertainty"] = math.hypot(r[q + "_error"] / reference[q],
                                                          r[q] * reference[q + "_error"] / reference[q] ** 2)
        row["is_reference"] = int(r is reference)
        rows.append(row)
    with open(a.out + ".csv", "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})
    print(f"{'study':<11} {'law':<6} {'N':>5} {'F':>5} {'dt':>10} {'us/step':>7} " +
          " ".join(f"{q + ' difference':>24}" for q in QUANTITIES))
    for row in rows:
        print(f"{row['study']:<11} {row['law']:<6} {row['steps_per_collision']:5g} {row['softer']:5g} {row['dt']:10.4g} "
              f"{row['microseconds_per_step']:7.1f} " +
              " ".join(f"{100 * row[q + '_relative_difference']:+10.2f}% +- {100 * row[q + '_relative_uncertainty']:5.2f}%      "
                       for q in QUANTITIES))
    plot(a.out + ".png", rows)
    print(f"wrote {a.out}.csv and {a.out}.png")


def plot(path, rows):
    """Per study: |relative difference| of velocity and height against the steps per time unit,
    with the combined standard errors as bars; the Pareto front of the velocity's points."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    studies = [study for study in STUDIES if any(r["study"] == study for r in rows)]
    fig, axes = plt.subplots(1, len(studies), figsize=(5.5 * len(studies), 4.5), squeeze=False)
    for ax, study in zip(axes[0], studies):
        points = [r for r in rows if r["study"] == study and not r["is_reference"]]
        for k, q in enumerate(("velocity", "height")):
            cost = [r["steps_per_time_unit"] for r in points]
            difference = [abs(r[q + "_relative_difference"]) for r in points]
            bars = [r[q + "_relative_uncertainty"] for r in points]
            ax.errorbar(cost, difference, yerr=bars, fmt="o" if k == 0 else "s", mfc="none", capsize=3, color=f"C{k}",
                        label=f"{q}: |difference| (bar: standard error)")
            for r, c, d in zip(points, cost, difference):
                label = (f"N={r['steps_per_collision']:g}" if study == "time step" else f"F={r['softer']:g}"
                         if study == "stiffness" else f"Hertz, N={r['steps_per_collision']:g}")
                if k == 0:
                    ax.annotate(label, (c, d), textcoords="offset points", xytext=(4, 4), fontsize=7)
        front = pareto([(r["steps_per_time_unit"], abs(r["velocity_relative_difference"])) for r in points])
        ax.plot(*zip(*front), "k:", lw=2, label="Pareto front (velocity)")
        ax.set_xscale("log")
        ax.set_xlabel("steps per time unit (cost)")
        ax.set_ylabel("relative difference from the reference")
        ax.set_title({"time step": "time step dt = tc/N", "stiffness": "stiffness / F (N = 50)",
                      "contact law": "Hertz-Mindlin against linear (N = 50)"}[study])
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
