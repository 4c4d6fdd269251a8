#!/usr/bin/env python3
"""The comparison's penetration driver on a bed of two beads far from the steel sphere's path, so
that the sphere falls onto the steel floor and bounces: its heights before the impact against free
flight, z = z0 - v0 t - g t^2 / 2 and vz = -v0 - g t (to round-off), and its rebound speed against
the restitution of Hertz's law with the Tsuji-Antypov damping for steel on steel (e = 0.6;
Documentation/Theory/ContactLaws.md eq. (16)-(20a)), found here by integrating that law's one-body
equation of motion with fine Runge-Kutta steps (the law's restitution is not e itself).

    checkComparisonPenetration.py DRIVER [plotComparisonPenetration.py] [-- DRIVER FLAGS]

With the plot script given, its table's row of the run is checked too: the sphere leaves free
flight at the first sample after the impact, and its lowest height is the run's.
"""
import math
import subprocess
import sys

driver = sys.argv[1]
driverFlags = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
scriptArguments = sys.argv[:sys.argv.index("--")] if "--" in sys.argv else sys.argv
floor, z0, v0, g, radius = -0.0902431, 0.06, 5.0, 9.8, 0.01
with open("bed.txt", "w") as bed:
    bed.write("Radius[m] PosX[m] PosY[m] PosZ[m]\n")
    bed.write(f"0.001 -0.045 -0.025 {floor + 0.001}\n0.001 -0.045 -0.022 {floor + 0.001}\n")
    bed.write("5 0.01 0.01 0 0 0.06\n")  # (the published beds' last line, which describes the sphere)
end = 0.03
subprocess.run([driver, "--start-file", "bed.txt", "--end-time", str(end), "--vtu", "off", "--fstat", "off",
                "--name", "bounce"] + driverFlags, check=True)
rows = [list(map(float, line.split())) for line in open("bounce.penetration") if not line.startswith("#")]

# Free flight until the sphere's bottom reaches the floor.
h0 = z0 - floor
hit = (-v0 + math.sqrt(v0 * v0 + 2 * g * (h0 - radius))) / g
worst = 0.0
for t, height, vz in rows:
    if t < hit - 1e-4:
        worst = max(worst, abs(height - (h0 - v0 * t - g * t * t / 2)), abs(vz - (-v0 - g * t)))
flights = sum(1 for r in rows if r[0] < hit - 1e-4)
print(f"free flight: {flights} samples before the impact at t = {hit:.6f} s, worst error {worst:.2e}")

# The law's restitution for a sphere on a plane of the same steel: R* = r, m* = m, E* from eq. (20a).
E, nu, density, e = 210e9, 0.2, 7200.0, 0.6
Estar = 1 / (2 * (1 - nu * nu) / E)
mass = density * 4 / 3 * math.pi * radius**3
beta = math.log(e) / math.sqrt(math.log(e) ** 2 + math.pi**2)


def acceleration(x, u):
    a = math.sqrt(radius * max(x, 0.0))
    damping = -2 * math.sqrt(5 / 6) * beta * math.sqrt(2 * Estar * a * mass)
    return (-4 / 3 * Estar * a * x - damping * u) / mass


speed = v0 + g * hit
x, u, dt = 0.0, speed, 1e-9
while True:
    k1 = (u, acceleration(x, u))
    k2 = (u + dt / 2 * k1[1], acceleration(x + dt / 2 * k1[0], u + dt / 2 * k1[1]))
    k3 = (u + dt / 2 * k2[1], acceleration(x + dt / 2 * k2[0], u + dt / 2 * k2[1]))
    k4 = (u + dt * k3[1], acceleration(x + dt * k3[0], u + dt * k3[1]))
    xn = x + dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
    un = u + dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    if xn < 0:
        u = u + (un - u) * x / (x - xn)  # (the speed where the overlap returns to zero)
        break
    x, u = xn, un
restitution = -u / speed

# The run's rebound: the last sample's upward speed plus what gravity took since the impact (the
# contact lasts about 5e-5 s, so the impact's moment is known to that: 5e-4 m/s of 3 m/s).
t, height, vz = rows[-1]
rebound = vz + g * (t - hit)
ratio = rebound / speed
print(f"rebound: {rebound:.5f} m/s from {speed:.5f} m/s, restitution {ratio:.5f}; the law's {restitution:.5f}")
# The plot script's table: the sphere leaves free flight at the first sample after the impact.
if len(scriptArguments) > 2:
    table = subprocess.run([sys.executable, scriptArguments[2], "bounce=bounce.penetration", "-o", "bounce.png"],
                           check=True, capture_output=True, text=True).stdout
    row = [line for line in table.splitlines() if line.startswith("| bounce |")][0].split("|")
    leaves, lowest = float(row[2]), float(row[3])
    print(f"plot script: leaves free flight at {leaves} s, lowest height {lowest} m")
    ok_plot = hit < leaves <= hit + 5e-4 + 1e-12 and abs(lowest - min(r[1] for r in rows)) < 1e-5
else:
    ok_plot = True
ok = flights >= 50 and worst < 1e-9 and vz > 0 and abs(ratio - restitution) < 2e-3 and ok_plot
print("penetration driver: free flight and rebound agree" if ok else "penetration driver: MISMATCH")
sys.exit(0 if ok else 1)
