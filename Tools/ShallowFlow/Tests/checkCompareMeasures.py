#!/usr/bin/python3
"""The measures of compareLongChute.py (Documentation/ShallowFlow.md, "Against the particles") on a
profile whose answers follow by hand: h = 10 - x/10 (the front, h = 0.5, at x = 95), phi = 1 up to
x = 30 falling linearly to 0 at x = 31 (phi = 0.25 at x = 30.75), and a few grains beyond the
front at x = 120 (h = 0.3, phi = 1), which must be neither the front nor the shock; then a grain
bouncing far ahead (h = 0.8 around x = 160, beyond a 25-long stretch below 0.5) must not be the
front either, while a dip below 0.5 shorter than that inside the flow does not end it. And the
model's start (write_start): the inflow state in the cells whose centres lie within the seeded
length, nothing beyond, one line per cell at its centre. And the basal slip from a velocity
profile (slip_from_profile): a column of uniform density with the model's linear profile
u = a_s U + 2 (1 - a_s) U z / h gives back a_s (alpha = 1 + (1 - a_s)^2 / 3 by hand), a plug
flow a_s = 1, and empty points above the flow change nothing. Prints "compare measures ok"."""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import compareLongChute as c  # noqa: E402

x = np.linspace(0, 200, 2001)
h = np.maximum(0.0, 10 - x / 10)
phi = np.clip(31 - x, 0.0, 1.0)
grains = np.abs(x - 120) < 0.5
h[grains], phi[grains] = 0.3, 1.0
m = c.measures(x, h, phi)
expected = {"front": 95.0, "shock": 30.75, "head_height": 10.0, "head_length": 95.0 - 30.75}
bad = [f"{k} {m[k]} != {v}" for k, v in expected.items() if not math.isclose(m[k], v, abs_tol=1e-9)]
ahead = h.copy()
ahead[np.abs(x - 160) < 0.5] = 0.8  # a grain far ahead: the front stays at 95
dip = h.copy()
dip[np.abs(x - 80) < 2] = 0.2  # a short dip inside the flow (h = 2 there): the front stays at 95
for label, profile in (("a grain far ahead", ahead), ("a short dip", dip)):
    front = c.measures(x, profile, phi)["front"]
    if not math.isclose(front, 95.0, abs_tol=1e-9):
        bad.append(f"{label}: front {front} != 95")
if not math.isclose(c.connected_front(x, ahead, 0.5, 100.0), 160.4 + 0.3 / 0.8 * 0.1, abs_tol=1e-9):
    bad.append("with a gap longer than the distance to the grain, the grain is the front")
nowhere = c.last_crossing(x, h, 20.0)
if not math.isnan(nowhere):
    bad.append(f"a level reached nowhere gave {nowhere}")
with tempfile.TemporaryDirectory() as folder:
    start = os.path.join(folder, "start.csv")
    c.write_start(start, 100.0, 40, 20.0, (15.5, 4.1, 0.5))  # cells 2.5 long: 8 centres below 20
    with open(start) as f:
        lines = f.read().split()
    rows = [[float(v) for v in line.split(",")] for line in lines[1:]]
    if lines[0] != "x,h,u,phi" or len(rows) != 40:
        bad.append(f"start file: header {lines[0]!r}, {len(rows)} rows (40 expected)")
    elif [r[0] for r in rows[:2]] != [1.25, 3.75] or [r[1] for r in rows[7:9]] != [15.5, 0.0] or \
            rows[7][1:] != [15.5, 4.1, 0.5] or any(r[1:] != [0.0, 0.0, 0.0] for r in rows[8:]):
        bad.append(f"start file: rows 0-1 {rows[:2]}, 7-8 {rows[7:9]}")
dz = 0.01
z = np.arange(0.5 * dz, 12.0, dz)  # points up to 12, the flow up to h = 10
inside = z < 10.0
for slip in (0.17, 0.5, 1.0):
    rho = np.where(inside, 2.0, 0.0)
    u = slip * 3.0 + 2 * (1 - slip) * 3.0 * z / 10.0
    alpha, measured = c.slip_from_profile(dz, rho, rho * u)
    if not (math.isclose(alpha, 1 + (1 - slip) ** 2 / 3, rel_tol=1e-5) and abs(measured - slip) < 1e-3):
        bad.append(f"slip {slip}: alpha {alpha}, a_s {measured}")
if bad:
    sys.exit("compare measures: " + "; ".join(bad))
print("compare measures ok")
