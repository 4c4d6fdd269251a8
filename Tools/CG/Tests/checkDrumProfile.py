#!/usr/bin/python3
"""Checks talus-cg's RZ fields of the synthetic drum (makeSyntheticDrum.py; the run in
Tools/CG/Tests/CMakeLists.txt: -n 160 24 -r 0 16, Lucy w = 1, axis y, periodic along y), last frame:

- mass: int rho 2 pi r dr dy by the midpoint rule of the grid equals the mass of the frame from
  the .data text (density 6/pi times 4/3 pi r^3 = d^3). The midpoint rule's error is of order
  (dr/w)^2/24 times the field's curvature scale, at most about 4e-4 for dr = 0.1, w = 1
  (measured 1.9e-6): tolerance 1e-3. Along y (periodic) the grid must resolve the lattice layers
  (spacing 1): 24 points; 3 points at the layers' centres would overcount by 30%.
- radial velocity: solid-body rotation has none: |V_R| <= 1e-12 omega R (round-off).
- azimuthal velocity: omega r where the density is uniform (3 <= r <= 6.5 and 9.5 <= r <= 13.5:
  a kernel width away from the axis, the core/outer interface at r = 8 where the particle size
  and so the density jumps, and the wall), to 1%: V = omega e_y x (kernel-weighted mean position),
  and the mean position differs from the point by O(w^2 grad(rho)/rho), which is zero for a
  uniform continuum and small for the jittered lattice (measured 0.4%; 2% at the interface).
- angular velocity (angular momentum / moment of inertia about the axis): omega exactly for
  solid-body rotation, to 1e-12 relative wherever there is mass.
- concentration of species 1 (the core, r < 8): above 0.99 for r <= 6.5 and below 0.01 for
  r >= 9.5 (the kernel reaches w = 1 across the interface, and the particles' own radii 0.5).

usage: checkDrumProfile.py PROFILE.csv NAME.data
"""
import math
import sys

sys.path.insert(0, __file__.rsplit('/', 3)[0] + '/Plot')
from cgFiles import read_cg_csv  # noqa: E402

OMEGA, RADIUS = 0.1, 15.0


def main():
    p, _ = read_cg_csv(sys.argv[1], 'checkDrumProfile.py')
    last = p['t'] == p['t'].max()
    p = {k: v[last] for k, v in p.items()}
    with open(sys.argv[2]) as f:
        lines = f.read().split('\n')
    n = int(lines[0].split()[0])
    header = lines[n + 1].split()
    count = int(header[0])
    mass = sum(float(line.split()[6]) ** 3 * 8 for line in lines[n + 2:n + 2 + count])  # (6/pi)(4/3 pi r^3) = 8 r^3
    r = sorted(set(p['r']))
    y = sorted(set(p['y']))
    dr, dy = 16.0 / len(r), 3.0 / len(y)  # y: enough points to resolve the lattice layers (spacing 1)
    integral = sum(rho * 2 * math.pi * ri * dr * dy for rho, ri in zip(p['Density'], p['r']))
    failures = []
    error = integral / mass - 1
    print(f"mass {mass:.6f}, integral of rho 2 pi r dr dy {integral:.6f} (relative error {error:.2e})")
    if abs(error) > 1e-3:
        failures.append("mass")
    vr = max(abs(v) for v in p['VelocityR'])
    print(f"largest |VelocityR| {vr:.2e}")
    if vr > 1e-12 * OMEGA * RADIUS:
        failures.append("radial velocity")
    uniform = [(vt, ri) for vt, ri in zip(p['VelocityTheta'], p['r']) if 3 <= ri <= 6.5 or 9.5 <= ri <= 13.5]
    worst = max(abs(vt / (OMEGA * ri) - 1) for vt, ri in uniform)
    print(f"largest |VelocityTheta / (omega r) - 1| for 3 <= r <= 6.5 and 9.5 <= r <= 13.5: {worst:.2e}")
    if worst > 0.02:
        failures.append("azimuthal velocity")
    spin = max(abs(w / OMEGA - 1) for w, rho in zip(p['AngularVelocity'], p['Density']) if rho > 1e-9)
    print(f"largest |AngularVelocity / omega - 1| {spin:.2e}")
    if spin > 1e-12:
        failures.append("angular velocity")
    core = min(c for c, ri in zip(p['Concentration_s1'], p['r']) if ri <= 6.5)
    outside = max(c for c, ri in zip(p['Concentration_s1'], p['r']) if 9.5 <= ri <= 14)
    print(f"core concentration >= {core:.4f}, outer <= {outside:.4f}")
    if core < 0.99 or outside > 0.01:
        failures.append("concentration")
    if failures:
        sys.exit("drum profile failed: " + ", ".join(failures))
    print("drum profile ok")


main()
