#!/usr/bin/python3
"""Self-tests RotatingDrum.MixingIndexMatchesTalusCG and .EllipsoidMixingIndexMatchesTalusCG: the
mixing and segregation indices the RotatingDrum driver computes while it runs (Drivers/Drum/
DrumAnalysis.h, on the particles in memory with the kernel's masses; its last line
"M = ..., S = ...") equal those of talus-cg --mixing (Tools/CG/Fields/MixingIndex.h) on the run's
last frame read from its files (positions from the .data file, the fixed wall and the masses of
the ellipsoids from the restart file), to the 8 decimals the driver prints: talus-cg's value,
printed with 12 digits, must round to the driver's (|difference| <= 5e-9, plus 1e-12 for the
round-off of the .data positions' 15 digits).

    checkDrumMixing.py run.log cg.mixing.csv
"""
import re
import sys

log, csv = sys.argv[1], sys.argv[2]
found = re.findall(r"M = (-?[0-9.]+), S = (-?[0-9.]+)", open(log).read())
if not found:
    sys.exit(f"checkDrumMixing: {log}: no line with 'M = ..., S = ...'")
driver = [float(v) for v in found[-1]]
rows = [line for line in open(csv) if line.strip() and not line.startswith("#")]
header, last = rows[0].strip().split(","), rows[-1].strip().split(",")
cg = [float(last[header.index("MixingIndex")]), float(last[header.index("SegregationIndex")])]
worst = max(abs(a - b) for a, b in zip(driver, cg))
print(f"driver M = {driver[0]:.8f}, S = {driver[1]:.8f}; talus-cg M = {cg[0]:.10f}, S = {cg[1]:.10f}; "
      f"largest difference {worst:.2e}")
if worst > 5e-9 + 1e-12:
    sys.exit("mixing index differs from talus-cg")
print("mixing index agrees with talus-cg: yes")
