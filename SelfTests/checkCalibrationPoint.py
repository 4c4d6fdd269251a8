#!/usr/bin/python3
"""Checks one steady point of CalibrationChute (Documentation/Calibration.md) by the momentum
balance of its flowing spheres. Over the averaging time T from t1 to t2 the base's force on the
flow, F_base, and gravity change the flow's momentum: M (u(t2) - u(t1)) = M g sin(theta) T +
integral of F_base,x dt. The driver writes mu = -F_base,x / F_base,z and weightCarried =
F_base,z / (M g cos(theta)) (time averages), so their product is -F_base,x / (M g cos theta) and
must equal tan(theta) - (u(t2) - u(t1)) / (g cos(theta) T), with u the mean velocity of the
.series at t1 and t2. Round-off of the written numbers (6 digits) and the force integrated as a
sum over steps (against the trapezoid of velocity Verlet: dt/2 of the force's change over T) are
below 1e-5; the test allows 1e-4. The normal part must carry the weight up to the change of the
layer's normal momentum (its dilation: mean normal velocities below 0.05 over T = 20 give
0.003): |weightCarried - 1| < 0.01. Prints "momentum balance ok" or the differences.
Usage: checkCalibrationPoint.py NAME"""
import csv
import math
import sys

name = sys.argv[1]
with open(name + ".result.csv") as f:
    r = next(csv.DictReader(f))
if r["state"] != "flowing":
    sys.exit(f"FAIL: the point is {r['state']}, not flowing")
theta = math.radians(float(r["angle"]))
t1, averaged = float(r["decidedAt"]), float(r["averagedFor"])
t2 = t1 + averaged
u = {}
with open(name + ".series") as f:
    for line in f:
        if not line.startswith("#"):
            t, _, _, velocity, _ = (float(x) for x in line.split())
            u[round(t, 6)] = velocity
u1, u2 = u[round(t1, 6)], u[round(t2, 6)]
mu, carried = float(r["mu"]), float(r["weightCarried"])
expected = math.tan(theta) - (u2 - u1) / (math.cos(theta) * averaged)
print(f"mu {mu:.6f} x weightCarried {carried:.6f} = {mu * carried:.6f}; momentum balance: tan(theta) - du/(g cos T) "
      f"= {math.tan(theta):.6f} - ({u2:.6g} - {u1:.6g}) / ({math.cos(theta):.4f} x {averaged:g}) = {expected:.6f}")
failed = False
if not abs(mu * carried - expected) < 1e-4:
    print(f"FAIL: the base's downslope force is off the momentum balance by {mu * carried - expected:.3g}")
    failed = True
if not abs(carried - 1) < 0.01:
    print(f"FAIL: the base carries {carried:.4f} of the flow's weight, not 1 within 0.01")
    failed = True
if failed:
    sys.exit(1)
print("momentum balance ok")
