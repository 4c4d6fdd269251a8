#!/usr/bin/env bash
# The comparison drum in Talus and in LIGGGHTS (Debian package `liggghts`) side by side: the same
# start file, materials, walls (Talus: smooth cylinder and planes; LIGGGHTS: the published
# triangles) and time step, each run for --time seconds from t = 0, in alternating rounds pinned to
# the first core, printing each round's particle-steps per second and their ratio.
#   drumRounds.sh [build-dir] [rounds] [time] [os-benchmark folder]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../../build}
rounds=${2:-3} time=${3:-0.05}
inputs=${4:-$here/../../../../shared/peers/os-benchmark}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/liggghts/comparisonInputs.py" data "$inputs/Drum/PartCoordinates.txt" "$work/drum.data" >/dev/null
python3 "$here/liggghts/comparisonInputs.py" stl "$inputs/Drum/walls.txt" "$work/drum.stl" >/dev/null
cp "$here/liggghts/in.drum.liggghts" "$work/"
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)
for r in $(seq "$rounds"); do
  talus=$(cd "$work" && "${pin[@]}" "$build/Drivers/Benchmarks/ComparisonDrum" --start-file "$inputs/Drum/PartCoordinates.txt" \
            --end-time "$time" --files off | grep -o "[0-9.e+]* particle-steps/s" | cut -d' ' -f1)
  liggghts=$(cd "$work" && "${pin[@]}" liggghts -in in.drum.liggghts -var time "$time" -log none |
             awk '/^Loop time of/ { print $9 * $12 / $4 }')
  python3 -c "print('round $r: Talus %.3g, LIGGGHTS %.3g particle-steps/s: Talus %.2fx' % ($talus, $liggghts, $talus / $liggghts))"
done
