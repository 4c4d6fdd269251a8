#!/usr/bin/env bash
# Cost per particle-step of a settled packing of ellipsoids (aspect ratio 2) against spheres of
# the same volume in the same box (Drivers/Demos/SettlingEllipsoids), on one core: each packing
# settles for --settle time units, then both continue from their restart files for --time units,
# alternating, --rounds times, and the ratio of each round is printed. The timed runs are pinned
# to the first core (taskset): the cores of a virtual machine need not be equally fast, and a
# ratio of runs on different cores measures the host.
#   superquadricCost.sh [build-dir] [particles] [settle] [time] [rounds]
set -euo pipefail
build=${1:-$(cd "$(dirname "$0")/../.." && pwd)/build}
n=${2:-200} settle=${3:-8} time=${4:-0.2} rounds=${5:-3}
driver=$build/Drivers/Demos/SettlingEllipsoids
work=$(mktemp -d)
for kind in 0 1; do
  mkdir -p "$work/$kind" && cd "$work/$kind"
  "$driver" --particles "$n" --spheres $kind --end-time "$settle" --output-interval "$settle" --vtu off \
    --progress-interval 60 | tail -1
done
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)
rate() { grep -o "[0-9.e+]* particle-steps/s" | cut -d' ' -f1; }
end=$(python3 -c "print($settle + $time)")
for r in $(seq "$rounds"); do
  e=$(cd "$work/0" && "${pin[@]}" "$driver" --restart SettlingEllipsoids.restart --end-time "$end" --files off | rate)
  s=$(cd "$work/1" && "${pin[@]}" "$driver" --restart SettlingEllipsoids.restart --end-time "$end" --files off | rate)
  python3 -c "print('round $r: ellipsoids %.3g, spheres %.3g particle-steps/s: ellipsoid cost %.1fx the spheres' % ($e, $s, $s / $e))"
done
rm -rf "$work"
