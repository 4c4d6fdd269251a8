#!/usr/bin/env bash
# The comparison drum in Talus and in LIGGGHTS (Debian package `liggghts`) side by side: the same
# start file, materials, walls (Talus: smooth cylinder and planes; LIGGGHTS: the published
# triangles) and time step (the published 1e-4 s), each run for --time seconds from t = 0, in
# alternating rounds pinned to the first core, printing each round's particle-steps per second and their ratio.
#   drumRounds.sh INPUTS [build-dir] [rounds] [time]
# INPUTS: the comparison's published input folder (its Drum/PartCoordinates.txt and Drum/walls.txt).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 1 ] || { echo "usage: drumRounds.sh INPUTS [build-dir] [rounds] [time]" >&2; exit 2; }
inputs=$1
build=${2:-$here/../../../build}
rounds=${3:-3} time=${4:-0.05}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/liggghts/comparisonInputs.py" data "$inputs/Drum/PartCoordinates.txt" "$work/drum.data" >/dev/null
python3 "$here/liggghts/comparisonInputs.py" stl "$inputs/Drum/walls.txt" "$work/drum.stl" >/dev/null
cp "$here/liggghts/in.drum.liggghts" "$work/"
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)
for r in $(seq "$rounds"); do
  talus=$(cd "$work" && "${pin[@]}" "$build/Drivers/Benchmarks/ComparisonDrum" --start-file "$inputs/Drum/PartCoordinates.txt" \
            --dt 1e-4 --end-time "$time" --files off | grep -o "[0-9.e+]* particle-steps/s" | cut -d' ' -f1)
  liggghts=$(cd "$work" && "${pin[@]}" liggghts -in in.drum.liggghts -var time "$time" -log none |
             awk '/^Loop time of/ { print $9 * $12 / $4 }')
  python3 -c "print('round $r: Talus %.3g, LIGGGHTS %.3g particle-steps/s: Talus %.2fx' % ($talus, $liggghts, $talus / $liggghts))"
done
