#!/usr/bin/env python3
"""The comparison's silo driver, reduced: a few hundred soft spheres dropped into the silo with
the large orifice, settled on the lid, then drained. Checked against what must hold whatever the
flow: the filled mass is the spheres' count times pi/6 d^3 rho (M1: 2500 kg/m^3, d = 4 mm);
nothing leaves before the lid opens; at every sample the discharged mass and the mass left in
the silo add up to the filled mass (to round-off) and the discharged mass never falls; something
drains once the lid is open; and at every saved frame each sphere is held by the walls: within
the cylinder (distance from the axis at most R - r, less a quarter of r of overlap) and above
the cone and the lid (the surface of revolution's distance, Documentation/Theory/ContactLaws.md
eq. (6a)), unless it has fallen through the orifice (then within the 45-degree cone that widens
below it: a sphere may graze the orifice's rim on its way out). The same checks hold for the
published triangles (--walls FILE), whose inner face is that surface.

    checkComparisonSilo.py DRIVER [driver flags...]
"""
import math
import subprocess
import sys

driver, flags = sys.argv[1], sys.argv[2:]
count, open_time, end = 300, 0.2, 0.4
subprocess.run([driver, "--orifice", "large", "--particles", str(count), "--soft", "1", "--dt", "1e-5",
                "--open-time", str(open_time), "--end-time", str(end), "--output-interval", "0.05",
                "--vtu", "off", "--fstat", "off", "--name", "silo"] + flags, check=True)

diameter, density = 0.004, 2500.0
filled = count * math.pi / 6 * diameter**3 * density
rows = [list(map(float, line.split())) for line in open("silo.discharge") if not line.startswith("#")]
failures = []
if abs(rows[0][2] - filled) > 1e-12 * filled:
    failures.append(f"filled {rows[0][2]!r} kg, expected {filled!r}")
worst = max(abs(d + left - filled) for _, d, left in rows)
if worst > 1e-12 * filled:
    failures.append(f"discharged + left differs from the filled mass by {worst:.3e} kg")
if any(d != 0 for t, d, _ in rows if t < open_time):
    failures.append("mass left before the lid opened")
if any(b[1] < a[1] for a, b in zip(rows, rows[1:])):
    failures.append("the discharged mass fell")
drained = rows[-1][1]
if not drained > 0:
    failures.append("nothing drained after the lid opened")

# The large orifice: radius 0.03 m at z = -0.0554222 m, the cone at 45 degrees up to the cylinder
# of radius 0.1 m.
r0, z0, R, r = 0.03, -0.0554222, 0.1, diameter / 2
tolerance = 0.25 * r


def distance_to_segment(rho, z, a, b):
    s = (b[0] - a[0], b[1] - a[1])
    t = min(1.0, max(0.0, ((rho - a[0]) * s[0] + (z - a[1]) * s[1]) / (s[0] ** 2 + s[1] ** 2)))
    return math.hypot(rho - a[0] - t * s[0], z - a[1] - t * s[1])


frames, escaped = 0, 0
with open("silo.data") as data:
    while True:
        header = data.readline().split()
        if not header:
            break
        n, t = int(header[0]), float(header[1])
        frames += 1
        for _ in range(n):
            x, y, z = map(float, data.readline().split()[:3])
            rho = math.hypot(x, y)
            if z < z0 - r:  # through the orifice (a lost one is outside the cone below it)
                escaped += rho > r0 + (z0 - z)
                continue
            cone = distance_to_segment(rho, z, (r0, z0), (R, z0 + R - r0))
            above_cone = z - z0 >= rho - r0  # on the axis's side of the cone's generator
            if rho > R - r + tolerance or not above_cone or cone < r - tolerance or (t < open_time and z < z0 + r - tolerance):
                escaped += 1
if escaped:
    failures.append(f"{escaped} sphere positions outside the silo's walls")
print(f"silo: {count} spheres, {filled:.6e} kg filled, {drained:.6e} kg drained by t = {end}; "
      f"{frames} frames of positions inside the walls; mass kept to {worst:.1e} kg")
for f in failures:
    print("FAILED:", f)
if not failures:
    print("silo drained, its mass kept and its spheres held")
sys.exit(1 if failures else 0)
