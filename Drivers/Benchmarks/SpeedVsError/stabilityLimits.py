#!/usr/bin/env python3
"""Stability limits on hard cases (Documentation/SpeedVsError.md, "Where the integration fails"):
for each case, the largest time step at which its run still ends without a blow-up, and the
failure beyond it as the run reported it. The runs take --dt auto --steps-per-collision N, with
--largest-step-fraction 1 so that steps above a tenth of the collision are accepted. Near the
limit a run's fate depends on chance encounters (a step of 0.53 tc may run where 0.5 tc fails), so
N is scanned on a grid from 1 to 50, the limit placed above the largest N of the grid that failed,
and that gap then narrowed by bisection. Writes OUT.csv (one line per case: the smallest N that
ran above every failure, the largest N that failed, its failure) and prints the same.
  stabilityLimits.py BUILD [--out PREFIX] [--cases a,b] [--precision 0.05]
"""
import argparse
import csv
import os
import subprocess
import tempfile

# name: (driver under BUILD/Drivers, its flags, simulated time)
cases = {
    "spheres settling": ("Demos/SettlingPacking", ["--particles", "300", "--width", "6"], "15"),
    "ellipsoids of aspect 5": ("Demos/SettlingEllipsoids", ["--particles", "100", "--width", "4", "--aspect", "5"], "8"),
    "blocky superquadrics e = 0.2": ("Demos/SettlingEllipsoids",
                                     ["--particles", "100", "--width", "4", "--aspect", "1.5", "--blockiness", "0.2"],
                                     "8"),
    "size ratio 20 (mass ratio 8000)": ("Benchmarks/HardCases", ["--case", "size-ratio"], "4"),
    "Hertz impacts at speed 10 (step for speed 1)": ("Benchmarks/HardCases", ["--case", "fast-impact"], "2"),
    "Hertz impacts at speed 10 (--impact-speed 10)": ("Benchmarks/HardCases",
                                                     ["--case", "fast-impact", "--impact-speed", "10"], "2"),
    "rattlers in a jammed lattice": ("Benchmarks/HardCases", ["--case", "rattlers"], "4"),
}
grid = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 3.5, 4, 5, 6, 8, 10, 15, 20, 30, 50]


def attempt(build, case, n, folder):
    """Runs the case at N steps per collision; returns (ran to its end, the error's first line)."""
    driver, flags, end = cases[case]
    out = subprocess.run([os.path.join(build, "Drivers", driver)] + flags +
                         ["--dt", "auto", "--steps-per-collision", repr(n), "--largest-step-fraction", "1",
                          "--end-time", end, "--files", "off", "--progress-interval", "1e9"],
                         capture_output=True, text=True, cwd=folder)
    error = next((line.split("error: ", 1)[1] for line in out.stderr.splitlines() if "error: " in line), "")
    return out.returncode == 0, error


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("build")
    parser.add_argument("--out", default="stability-limits")
    parser.add_argument("--cases", default=",".join(cases), help="comma-separated names of the cases")
    parser.add_argument("--precision", type=float, default=0.05, help="relative width of the final bracket")
    a = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for case in a.cases.split(","):
            outcomes = [(n, *attempt(a.build, case, n, folder)) for n in grid]
            if not outcomes[-1][1]:
                raise SystemExit(f"stabilityLimits.py: {case} fails even at N = {grid[-1]}: {outcomes[-1][2]}")
            failed = [k for k, (_, ran, _) in enumerate(outcomes) if not ran]
            if not failed:
                low, high, failure = 0, 1.0, "(runs at N = 1)"
            else:
                low, _, failure = outcomes[failed[-1]]
                high = grid[failed[-1] + 1]
            while low > 0 and high / low > 1 + a.precision:
                middle = (low * high) ** 0.5
                ran, error = attempt(a.build, case, middle, folder)
                if ran:
                    high = middle
                else:
                    low, failure = middle, error
            print(f"  grid: " + ", ".join(f"{n:g} {'ran' if ran else 'failed'}" for n, ran, _ in outcomes), flush=True)
            rows.append({"case": case, "smallest_N_that_ran": round(high, 3), "largest_N_that_failed": round(low, 3),
                         "largest_stable_dt_over_tc": round(1 / high, 4), "failure": failure})
            print(f"{case}: runs at N = {high:.3g} (dt = {1 / high:.3g} tc), fails at N = {low:.3g}: {failure[:160]}",
                  flush=True)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    main()
