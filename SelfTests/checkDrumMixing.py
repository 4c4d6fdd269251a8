#!/usr/bin/python3
"""Self-test RotatingDrum.MixingIndexMatchesTalusCG: the mixing and segregation indices the
RotatingDrum driver computes while it runs (Drivers/Drum/DrumAnalysis.h, its last line
"M = ..., S = ...") equal those of talus-cg --mixing (Tools/CG/Fields/MixingIndex.h, an
independent implementation) on the run's last frame, to the 8 decimals the driver prints.

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
if worst > 1e-7:
    sys.exit("mixing index differs from talus-cg")
print("mixing index agrees with talus-cg: yes")
