#!/usr/bin/env bash
# Sets up a new machine, builds Talus and runs the main example end to end: a small periodic
# bidisperse chute flow (Drivers/Chute/PeriodicBidisperseChute, 600 spheres on a rough base,
# 30 time units), a plot of its kinetic energy, mass flux, velocity and height over time, then
# coarse graining (Tools/CG, talus-cg) of its last 15 time units into depth profiles of density,
# velocity, small-particle concentration and stress, and their plot.
# Output lands in run/ of the source tree.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
"$top/Scripts/build.sh" "$top/build" Release
mkdir -p "$top/run" && cd "$top/run"
rm -f PeriodicBidisperseChute.series
"$top/build/Drivers/Chute/PeriodicBidisperseChute" --large 200 --small 400 --length 10 --width 5 \
  --end-time 30 --output-interval 1 --sample-interval 0.2 --window 50
/usr/bin/python3 "$top/Tools/Plot/plotChuteSeries.py" PeriodicBidisperseChute.series PeriodicBidisperseChute-series.png
# Depth profiles (Theory/CoarseGraining.md eq. (2)): Lucy kernel of width 0.5, averaged over x and y and over the frames
# of t = 15..30, the fixed base left out of the particle fields (its contacts still carry stress).
"$top/build/Tools/CG/talus-cg" PeriodicBidisperseChute --coordinates Z -n 150 -z -1 14 -w 0.5 --fixed exclude \
  --time-min 15 --time-average -o PeriodicBidisperseChute-profile.csv
/usr/bin/python3 "$top/Tools/Plot/plotCGProfile.py" PeriodicBidisperseChute-profile.csv -o PeriodicBidisperseChute-profile.png
echo "run-example: wrote $top/run/PeriodicBidisperseChute.{data,fstat,ene,restart,pvd,series},"
echo "  PeriodicBidisperseChute-series.png, PeriodicBidisperseChute-profile.csv and PeriodicBidisperseChute-profile.png"
