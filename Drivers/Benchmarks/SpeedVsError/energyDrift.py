#!/usr/bin/env python3
"""Speed against error of the time step on many collisions (Documentation/SpeedVsError.md,
"Energy of an elastic packing"): the frictionless, perfectly elastic packing of
Drivers/Benchmarks/SpeedVsError/ElasticPacking, whose total energy (kinetic, rotational and
elastic, from NAME.ene) must not change, run with --dt auto at N steps per shortest collision for
N from 10 to 200, with the contact's ends treated and as plain velocity Verlet. The error of a run
is the largest |E(t) - E(0)| / E(0) over its frames; its cost N (steps per collision time) and
the wall time it took. Writes OUT.csv and OUT.png (error against N, the Pareto front marked) and
prints the order of convergence of each integration; --expect-treated-order X fails the run when
that of the treated ends is more than 0.3 from X (plain velocity Verlet scatters more: whether its
error at a touch adds or cancels depends on where between two steps the touches fall).
  energyDrift.py DRIVER [--out PREFIX] [--steps 10,15,...] [--end-time T] [--particles N]
                 [--expect-treated-order 2]
"""
import argparse
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speedVsError import number_after, order, plot, run_driver  # noqa: E402

tool = "energyDrift.py"


def energies(path):
    """The total energy of each frame of a .ene file (columns: time, gravitational, kinetic,
    rotational, elastic, ...; Documentation/FileFormats/ene.md)."""
    totals = []
    with open(path) as f:
        for line in f:
            fields = line.split()
            try:
                values = [float(x) for x in fields[:5]]
            except ValueError:
                continue  # the header
            totals.append(sum(values[1:5]))
    return totals


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("driver")
    parser.add_argument("--out", default="energy-drift")
    parser.add_argument("--steps", default="10,15,20,30,50,75,100,150,200")
    parser.add_argument("--end-time", default="2")
    parser.add_argument("--particles", default="500")
    parser.add_argument("--expect-treated-order", type=float)
    a = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for method in ("treated", "plain"):
            for n in [float(s) for s in a.steps.split(",")]:
                said = run_driver(tool, os.path.abspath(a.driver),
                                  ["--dt", "auto", "--steps-per-collision", repr(n), "--end-time", a.end_time,
                                   "--particles", a.particles, "--plain-verlet", "1" if method == "plain" else "0",
                                   "--output-interval", repr(float(a.end_time) / 40), "--vtu", "off", "--fstat", "off",
                                   "--name", "packing"], folder)
                e = energies(os.path.join(folder, "packing.ene"))
                rows.append({"integration": method, "steps_per_collision": n,
                             "largest_energy_error": max(abs(x - e[0]) for x in e) / e[0],
                             "final_energy_error": abs(e[-1] - e[0]) / e[0],
                             "wall_seconds": number_after(tool, r"steps in ([0-9.]+) s wall", said),
                             "frames": len(e)})
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"{tool}: {len(rows)} runs in {a.out}.csv")
    lines, wrong = {}, 0
    for method in ("treated", "plain"):
        points = [r for r in rows if r["integration"] == method]
        lines[method] = [(r["steps_per_collision"], r["largest_energy_error"]) for r in points]
        print(f"  {method}: " + ", ".join(f"N {r['steps_per_collision']:g}: {r['largest_energy_error']:.1e}"
                                        for r in points) +
              f"; order {order(*zip(*lines[method])):.2f}")
        wrong += (method == "treated" and a.expect_treated_order is not None
                  and abs(order(*zip(*lines[method])) - a.expect_treated_order) > 0.3)
    plot(a.out + ".png", [("largest relative error of the total energy", lines, [list(lines)])],
         "steps per shortest collision tc/dt (cost)")
    if a.expect_treated_order is not None:
        print("orders of convergence as expected" if wrong == 0 else "orders of convergence NOT as expected")
    sys.exit(1 if wrong else 0)


if __name__ == "__main__":
    main()
