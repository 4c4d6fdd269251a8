#!/usr/bin/env python3
"""Speed against error of the time step on one collision (Documentation/SpeedVsError.md, "The
time step"): the head-on collision of two spheres (Drivers/Demos/TwoParticleCollision) with the
linear spring-dashpot law, at dt = tc/N for N from 10 to 200, with the contact's ends treated
(Talus's default) and integrated as plain velocity Verlet (as LAMMPS and LIGGGHTS do), against
the analytic restitution and collision time (Theory/ContactLaws.md eq. (10)-(11)). The cost of a
run is its number of steps, N per collision time, whatever the scene: the cost of a step does not
depend on dt. Writes OUT.csv (one line per run) and OUT.png (error against N, the Pareto front
of each quantity and collision marked), and prints the order of convergence of each error (the slope of a
least-squares line through log error against log N): about 2 with the ends treated, 1 without
(the contact starts and ends between steps). --expect-orders TREATED,PLAIN fails the run when an
order is more than 0.3 from the one expected.
  collisionTimeStep.py DRIVER [--out PREFIX] [--steps 10,15,...] [--restitution 0.5,0.88]
                      [--expect-orders 2,1]
"""
import math
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile


def run(driver, steps, restitution, plain, folder):
    tc = 0.005
    out = subprocess.run([driver, "--dt", repr(tc / steps), "--collision-time", repr(tc), "--restitution",
                          repr(restitution), "--plain-verlet", "1" if plain else "0", "--end-time", "0.2",
                          "--files", "off"], capture_output=True, text=True, cwd=folder)
    if out.returncode != 0:
        sys.exit(f"collisionTimeStep.py: {driver} failed at N = {steps}: {out.stderr.strip()}")
    errors = {}
    for quantity in ("restitution", "collision time"):
        found = re.search(quantity + r": measured .* relative error ([0-9.e+-]+)", out.stdout)
        if not found:
            sys.exit(f"collisionTimeStep.py: no '{quantity}' line in the output of N = {steps}:\n{out.stdout}")
        errors[quantity] = float(found.group(1))
    return errors


def pareto(points):
    """The points (cost, error) no other point beats in both."""
    front, best = [], float("inf")
    for cost, error in sorted(points):
        if error < best:
            front.append((cost, error))
            best = error
    return front


def order(line, quantity):
    xs = [math.log(r["steps_per_collision"]) for r in line]
    ys = [math.log(max(r[quantity], 1e-300)) for r in line]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return -sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


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
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for e in restitutions:
            for plain in (False, True):
                for n in steps:
                    errors = run(os.path.abspath(a.driver), n, e, plain, folder)
                    rows.append({"restitution": e, "integration": "plain" if plain else "treated",
                                 "steps_per_collision": n, "restitution_error": errors["restitution"],
                                 "collision_time_error": errors["collision time"]})
    with open(a.out + ".csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    print(f"collisionTimeStep.py: {len(rows)} runs in {a.out}.csv")
    for e in restitutions:
        for method in ("treated", "plain"):
            line = [r for r in rows if r["restitution"] == e and r["integration"] == method]
            print(f"  e = {e}, {method}: " + ", ".join(
                f"N {r['steps_per_collision']:g}: {r['restitution_error']:.1e}/{r['collision_time_error']:.1e}"
                for r in line if r["steps_per_collision"] in (10, 50, 200)) + " (errors of e / tc)")
    plot(rows, restitutions, a.out + ".png")
    expected = dict(zip(("treated", "plain"), map(float, a.expect_orders.split(",")))) if a.expect_orders else {}
    wrong = 0
    for e in restitutions:
        for method in ("treated", "plain"):
            line = [r for r in rows if r["restitution"] == e and r["integration"] == method]
            orders = [order(line, q) for q in ("restitution_error", "collision_time_error")]
            print(f"  e = {e}, {method}: order of convergence {orders[0]:.2f} (restitution), {orders[1]:.2f} "
                  "(collision time)")
            if method in expected and any(abs(o - expected[method]) > 0.3 for o in orders):
                print(f"  ^ expected {expected[method]:g} +- 0.3")
                wrong += 1
    if expected:
        print("orders of convergence as expected" if wrong == 0 else "orders of convergence NOT as expected")
    sys.exit(1 if wrong else 0)


def plot(rows, restitutions, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, quantity, title in zip(axes, ("restitution_error", "collision_time_error"),
                                   ("restitution", "collision time")):
        for e, colour in zip(restitutions, ("C0", "C1", "C2", "C3")):
            for method, marker in (("treated", "o-"), ("plain", "s--")):
                line = [r for r in rows if r["restitution"] == e and r["integration"] == method]
                ax.loglog([r["steps_per_collision"] for r in line], [max(r[quantity], 1e-17) for r in line], marker,
                          color=colour, mfc="none", label=f"e = {e:g}, {method}")
        for k, e in enumerate(restitutions):  # (of each collision: both integrations, every N)
            front = pareto([(r["steps_per_collision"], max(r[quantity], 1e-17)) for r in rows if r["restitution"] == e])
            ax.plot(*zip(*front), "k:", lw=2, label="Pareto front of each e" if k == 0 else None)
        ax.set_xlabel("steps per collision tc/dt (cost)")
        ax.set_title(f"relative error of the {title}")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("relative error")
    axes[1].legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()
