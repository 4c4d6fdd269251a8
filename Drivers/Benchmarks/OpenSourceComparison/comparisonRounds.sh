#!/usr/bin/env bash
# A case of the open-source comparison in Talus and in LIGGGHTS (Debian package `liggghts`) side by
# side: the same start file, materials, walls and time step, each run for TIME seconds from t = 0,
# in alternating rounds pinned to the first core, printing each round's particle-steps per second
# and their ratio.
#   drum: Talus's smooth cylinder and planes (or, with TALUS_WALLS=mesh, the published triangles
#         turning, as LIGGGHTS's) against LIGGGHTS's published triangles, at the published soft
#         step of 1e-4 s (default TIME 0.05);
#   penetration: the 25K bed in both codes' plane walls at the published 5e-7 s (default TIME 0.002,
#         the sphere still falling onto the bed at rest).
#   comparisonRounds.sh drum|penetration INPUTS [build-dir] [rounds] [time]
# INPUTS: the comparison's published input folder (Drum/PartCoordinates.txt and Drum/walls.txt;
# Penetration/25KParticles.txt).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
usage="usage: comparisonRounds.sh drum|penetration INPUTS [build-dir] [rounds] [time]"
[ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
case=$1 inputs=$2
build=${3:-$here/../../../build}
rounds=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
inputsTool="$here/liggghts/comparisonInputs.py"
case $case in
  drum)
    time=${5:-0.05}
    python3 "$inputsTool" data "$inputs/Drum/PartCoordinates.txt" "$work/drum.data" >/dev/null
    python3 "$inputsTool" stl "$inputs/Drum/walls.txt" "$work/drum.stl" >/dev/null
    talus=("$build/Drivers/Benchmarks/ComparisonDrum" --start-file "$inputs/Drum/PartCoordinates.txt" --dt 1e-4)
    [ "${TALUS_WALLS:-smooth}" = mesh ] && talus+=(--walls "$inputs/Drum/walls.txt")
    script=in.drum.liggghts ;;
  penetration)
    time=${5:-0.002}
    python3 "$inputsTool" data "$inputs/Penetration/25KParticles.txt" "$work/penetration.data" --penetration \
      --box -0.049 0.049 -0.03 0.03 -0.0902431 1.5 >/dev/null
    talus=("$build/Drivers/Benchmarks/ComparisonPenetration" --start-file "$inputs/Penetration/25KParticles.txt")
    script=in.penetration.liggghts ;;
  *) echo "$usage" >&2; exit 2 ;;
esac
cp "$here/liggghts/$script" "$work/"
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)
for r in $(seq "$rounds"); do
  talusRate=$(cd "$work" && "${pin[@]}" "${talus[@]}" --end-time "$time" --files off | grep -o "[0-9.e+]* particle-steps/s" | tail -1 | cut -d' ' -f1)
  liggghtsRate=$(cd "$work" && "${pin[@]}" liggghts -in "$script" -var time "$time" -log none |
                 awk '/^Loop time of/ { print $9 * $12 / $4 }')
  python3 -c "print('$case round $r: Talus %.3g, LIGGGHTS %.3g particle-steps/s: Talus %.2fx' % ($talusRate, $liggghtsRate, $talusRate / $liggghtsRate))"
done
