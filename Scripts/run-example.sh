#!/usr/bin/env bash
# Sets up a new machine, builds Talus and runs the main example end to end: a small periodic
# bidisperse chute flow (Drivers/Chute/PeriodicBidisperseChute, 600 spheres on a rough base,
# 30 time units), then a plot of its kinetic energy, mass flux, velocity and height over time.
# Output lands in run/ of the source tree. (Coarse graining joins when Tools/CG exists.)
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
"$top/Scripts/build.sh" "$top/build" Release
mkdir -p "$top/run" && cd "$top/run"
rm -f PeriodicBidisperseChute.series
"$top/build/Drivers/Chute/PeriodicBidisperseChute" --large 200 --small 400 --length 10 --width 5 \
  --end-time 30 --output-interval 1 --sample-interval 0.2 --window 50
/usr/bin/python3 "$top/Tools/Plot/plotChuteSeries.py" PeriodicBidisperseChute.series PeriodicBidisperseChute-series.png
echo "run-example: wrote $top/run/PeriodicBidisperseChute.{data,fstat,ene,restart,pvd,series} and PeriodicBidisperseChute-series.png"
