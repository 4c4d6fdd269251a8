#!/usr/bin/env python3
"""Speed against error of the time step on one collision (Documentation/SpeedVsError.md, "One
collision"): the head-on collision of two spheres (Drivers/Demos/TwoParticleCollision) with the
linear spring-dashpot law, at dt = tc/N for N from 10 to 200, with the contact's ends treated
(Talus's default) and integrated as plain velocity Verlet (as LAMMPS and LIGGGHTS do), against
the analytic restitution and collision time (Theory/ContactLaws.md eq. (10)-(11)). The cost is
N, the steps per collision time: most of a run's cost is per step (Documentation/SpeedVsError.md
says what is not). Writes OUT.csv (one line per run) and OUT.png (error against N, the Pareto front
of each collision marked), and prints the order of convergence of each error: about 2 with the
ends treated, 1 without (the contact starts and ends between steps). --expect-orders
TREATED,PLAIN fails the run when an order is more than 0.3 from the one expected.
  collisionTimeStep.py DRIVER [--out PREFIX] [--steps 10,15,...] [--restitution 0.5,0.88]
                      [--expect-orders 2,1]
"""
import argparse
import csv
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from speedVsError import number_after, order, plot, run_driver  # noqa: E402

tool = "collisionTimeStep.py"
quantities = {"restitution_error": "restitution", "collision_time_error": "collision time"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("driver")
    parser.add_argument("--out", default="collision-time-step")
    parser.add_argument("--steps", default="10,12,15,20,25,30,40,50,75,100,150,200")
    parser.add_argument("--restitution", default="0.5,0.88")
    parser.add_argument("--expect-orders", help="TREATED,PLAIN: the orders of convergence expected")
    a = parser.parse_args()
    steps = [float(s) for s in a.steps.split(",")]
    restitutions = [float(e) for e in a.restitution.split(",")]
    tc = 0.005
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for e in restitutions:
            for method in ("treated", "plain"):
                for n in steps:
                    said = run_driver(tool, os.path.abspath(a.driver),
                                      ["--dt", repr(tc / n), "--collision-time", repr(tc), "--restitution", repr(e),
                                       "--plain-verlet", "1" if method == "plain" else "0", "--end-time", "0.2",
                                       "--files", "off"], folder)
                    row = {"restitution": e, "integration": method, "steps_per_collision": n}
                    for column, name in quantities.items():
                        row[column] = number_after(tool, name + r": measured .* relative error ([0-9.e+-]+)", said)
                    rows.append(row)
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"{tool}: {len(rows)} runs in {a.out}.csv")

    def line(e, method):
        return [r for r in rows if r["restitution"] == e and r["integration"] == method]

    panels = []
    for column, name in quantities.items():
        lines = {f"e = {e:g}, {m}": [(r["steps_per_collision"], r[column]) for r in line(e, m)]
                 for e in restitutions for m in ("treated", "plain")}
        groups = [[f"e = {e:g}, treated", f"e = {e:g}, plain"] for e in restitutions]
        panels.append((f"relative error of the {name}", lines, groups))
    plot(a.out + ".png", panels, "steps per collision tc/dt (cost)")

    expected = dict(zip(("treated", "plain"), map(float, a.expect_orders.split(",")))) if a.expect_orders else {}
    wrong = 0
    for e in restitutions:
        for method in ("treated", "plain"):
            points = line(e, method)
            print(f"  e = {e}, {method}: " + ", ".join(
                f"N {r['steps_per_collision']:g}: {r['restitution_error']:.1e}/{r['collision_time_error']:.1e}"
                for r in points if r["steps_per_collision"] in (10, 50, 200)) + " (errors of e / tc)")
            orders = [order([r["steps_per_collision"] for r in points], [r[c] for r in points]) for c in quantities]
            print(f"    order of convergence {orders[0]:.2f} (restitution), {orders[1]:.2f} (collision time)")
            if method in expected and any(abs(o - expected[method]) > 0.3 for o in orders):
                print(f"    ^ expected {expected[method]:g} +- 0.3")
                wrong += 1
    if expected:
        print("orders of convergence as expected" if wrong == 0 else "orders of convergence NOT as expected")
    sys.exit(1 if wrong else 0)


if __name__ == "__main__":
    main()
