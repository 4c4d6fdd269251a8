#!/usr/bin/env bash
# Sets up a new machine, builds Talus and runs the main example end to end:
# a settling packing (Drivers/Demos/SettlingPacking), then a plot of its energies.
# Output lands in run/ of the source tree.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
"$top/Scripts/build.sh" "$top/build" Release
mkdir -p "$top/run" && cd "$top/run"
"$top/build/Drivers/Demos/SettlingPacking" --end-time 20 --output-interval 0.5
/usr/bin/python3 "$top/Tools/Plot/plotEnergies.py" SettlingPacking.ene SettlingPacking-energies.png
echo "run-example: wrote $top/run/SettlingPacking.{data,fstat,ene,restart,pvd} and SettlingPacking-energies.png"
