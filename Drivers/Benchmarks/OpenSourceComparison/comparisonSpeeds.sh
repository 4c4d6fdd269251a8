#!/usr/bin/env bash
# The speed of each case of the open-source comparison in Talus, on one core and on two ranks:
# the drum (smooth walls and the published turning triangles, 38000 beads, 500 steps at the
# published 1e-4 s), the penetration (25K bed, the published 5e-7 s, 4000 steps) and the reduced
# silo (5000 soft spheres, large orifice, smooth walls and the published triangles, the lid opened
# at 0.3 s, to 0.6 s). Prints a Markdown table of the wall time and particle-steps per second of
# each run (from the run's closing line), the speedup of two ranks, and the two ranks' share of
# wall time in communication (waits included) with their ghosts. Run it with the host's
# other jobs stopped: one core is pinned with taskset, the ranks with mpirun --bind-to core.
#   comparisonSpeeds.sh INPUTS [build-dir]
# INPUTS: the comparison's published input folder (Drum/, Penetration/, Silo/).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
[ $# -ge 1 ] || { echo "usage: comparisonSpeeds.sh INPUTS [build-dir]" >&2; exit 2; }
[ -d "$1" ] || { echo "comparisonSpeeds.sh: the inputs folder $1 does not exist" >&2; exit 2; }
inputs=$(cd "$1" && pwd)
build=${2:-$here/../../../build}
[ -d "$build" ] || { echo "comparisonSpeeds.sh: the build folder $build does not exist" >&2; exit 2; }
build=$(cd "$build" && pwd)
bin=$build/Drivers/Benchmarks
for f in Drum/PartCoordinates.txt Drum/walls.txt Penetration/25KParticles.txt Silo/walls-large-orifice.txt; do
  [ -f "$inputs/$f" ] || { echo "comparisonSpeeds.sh: $inputs/$f is missing (INPUTS: the comparison's published input folder)" >&2; exit 2; }
done
for program in ComparisonDrum ComparisonPenetration ComparisonSilo; do
  [ -x "$bin/$program" ] || { echo "comparisonSpeeds.sh: $bin/$program is not built" >&2; exit 2; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
pin=()
command -v taskset >/dev/null && pin=(taskset -c 0)

drum=("$bin/ComparisonDrum" --start-file "$inputs/Drum/PartCoordinates.txt" --dt 1e-4 --end-time 0.05 --files off)
silo=("$bin/ComparisonSilo" --orifice large --particles 5000 --soft 1 --dt 1e-5 --open-time 0.3 --end-time 0.6
      --vtu off --fstat off)
cases=("drum, smooth walls|${drum[*]}"
       "drum, the published triangles|${drum[*]} --walls $inputs/Drum/walls.txt"
       "penetration, 25K bed|$bin/ComparisonPenetration --start-file $inputs/Penetration/25KParticles.txt --end-time 0.002 --files off"
       "silo (reduced), smooth walls|${silo[*]}"
       "silo (reduced), the published triangles|${silo[*]} --walls $inputs/Silo/walls-large-orifice.txt")

# The closing line "finished at t = T: S steps in W s wall, R particle-steps/s" as "S W R".
finished() { grep -o "finished at t = .*" "$1" | head -1 | sed -E 's/.*: ([0-9]+) steps in ([0-9.e+-]+) s wall, ([0-9.e+-]+) particle-steps.*/\1 \2 \3/'; }

echo "| case | steps | one core: wall time, particle-steps/s | two ranks: wall time, particle-steps/s | speedup | two ranks: communication, ghosts |"
echo "|---|---|---|---|---|---|"
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a command <<< "${entry#*|}"
  (cd "$work" && "${pin[@]}" "${command[@]}" --name one > one.log 2>&1) || { echo "$name: the run on one core failed, see its log:" >&2; tail -5 "$work/one.log" >&2; exit 1; }
  (cd "$work" && mpirun --bind-to core -np 2 "${command[@]}" --name two > two.log 2>&1) || { echo "$name: the run on two ranks failed:" >&2; tail -5 "$work/two.log" >&2; exit 1; }
  read -r steps1 wall1 rate1 <<< "$(finished "$work/one.log")"
  read -r steps2 wall2 rate2 <<< "$(finished "$work/two.log")"
  # (The ranks' report: "ranks 2  communication C%  ghosts G ...", Sampling/RankReport.h.)
  shared=$(grep -o "communication [0-9.]*%  ghosts [0-9]*" "$work/two.log" | head -1 | sed 's/communication //; s/  ghosts /, /')
  awk -v name="$name" -v steps="$steps1" -v w1="$wall1" -v r1="$rate1" -v w2="$wall2" -v r2="$rate2" -v shared="$shared" \
    'BEGIN { printf "| %s | %s | %.2f s, %.3g | %.2f s, %.3g | %.2f | %s |\n", name, steps, w1, r1, w2, r2, w1 / w2, shared }'
done
