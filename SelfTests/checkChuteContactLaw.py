#!/usr/bin/env python3
"""Checks the pair laws that MaserFedChute prints against Theory/ContactLaws.md "Bidisperse mixtures" and the thesis's Table 3.C.1.

usage: checkChuteContactLaw.py LOG SIZE_RATIO BASE_DIAMETER

For every pair type the collision time and restitution are recovered from the printed kn,
gamma_n and reduced mass (tc = pi / sqrt(kn/m - (gn/2m)^2), e = exp(-tc gn / 2m)), and compared
with what the law named in the log must give: chapter-4, tc = 0.005 and e = 0.88 for all;
table-3C1, two large spheres with kn = 2e5 mL/dL and gamma_n = 25 mL/sqrt(dL) (the thesis's
values in its units dL = mL = g = 1, converted to the driver's unit of the mean diameter), and
every pair type the same e and tc/sqrt(d/g). Prints one line per pair and a verdict."""
import math
import sys

log, ratio, base_diameter = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
dL, dS = 2 * ratio / (1 + ratio), 2 / (1 + ratio)
mL = dL ** 3  # density 6/pi
diameters = {"large-large": dL, "small-small": dS, "large-small": (dL + dS) / 2,
             "base-large": (base_diameter + dL) / 2, "base-small": (base_diameter + dS) / 2}
law, pairs = None, {}
for line in open(log):
    if "contact law" in line:
        law = line.split()[-1]
    words = line.split()
    if words and words[0] in diameters and "kn" in words:
        value = {words[k]: float(words[k + 1]) for k in range(1, len(words) - 1) if words[k] in ("mass", "kn", "gamma_n", "kt", "mu")}
        pairs[words[0]] = value
ok = law in ("chapter-4", "table-3C1") and len(pairs) == 5
friction = {"large-large": 0.5, "small-small": 0.25, "large-small": 0.375, "base-large": 0.5,
            "base-small": 0.375 if law == "table-3C1" else 0.25}
for name, p in pairs.items():
    m, kn, gn = p["mass"], p["kn"], p["gamma_n"]
    tc = math.pi / math.sqrt(kn / m - (gn / (2 * m)) ** 2)
    e = math.exp(-tc * gn / (2 * m))
    if law == "chapter-4":
        want_tc, want_e = 0.005, 0.88
    else:
        tcLL = math.pi / math.sqrt(2e5 / 0.5 - (25 / 1.0) ** 2)  # Table 3.C.1, units of dL, mL, g
        want_tc, want_e = tcLL * math.sqrt(diameters[name]), math.exp(-tcLL * 25 / 1.0)
    good = abs(tc / want_tc - 1) < 1e-9 and abs(e / want_e - 1) < 1e-9 and abs(p["kt"] / kn - 2 / 7) < 1e-9 \
        and p["mu"] == friction[name]
    print(f"{name}: tc {tc:.10g} (want {want_tc:.10g}), e {e:.10g} (want {want_e:.10g}), mu {p['mu']}: {'ok' if good else 'WRONG'}")
    ok = ok and good
if law == "table-3C1" and "large-large" in pairs:
    p = pairs["large-large"]
    good = abs(p["kn"] / (2e5 * mL / dL) - 1) < 1e-9 and abs(p["gamma_n"] / (25 * mL / math.sqrt(dL)) - 1) < 1e-9
    print(f"large-large kn {p['kn']:.10g} (Table 3.C.1: {2e5 * mL / dL:.10g}), gamma_n {p['gamma_n']:.10g} "
          f"(Table 3.C.1: {25 * mL / math.sqrt(dL):.10g}): {'ok' if good else 'WRONG'}")
    ok = ok and good
print(f"contact law {law} as specified: {'yes' if ok else 'no'}")
sys.exit(0 if ok else 1)
