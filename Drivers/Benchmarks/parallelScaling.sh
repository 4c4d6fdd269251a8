#!/usr/bin/env bash
# Speedup of the MPI domain split (Documentation/Parallel.md) on the periodic chute benchmark:
# the start bed replicated nx x ny times (3000, about 10^5 and about 10^6 flowing spheres), run
# on 1 and on 2 ranks in alternation, several rounds; prints each pair's speedup and writes
# parallelScaling.csv (ranks, flowing, steps, wall seconds, particle-steps per second,
# communication share, ghosts, and of the communication the ghost exchange and the agreement
# of all ranks each step, which includes waiting for the slowest) in the current folder.
#   Drivers/Benchmarks/parallelScaling.sh [build-dir] [rounds] [largest: 3|5|6]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build}
rounds=${2:-2}
largest=${3:-6}
talus="$build/Drivers/Benchmarks/PeriodicChuteBenchmark"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
echo "ranks,flowing,steps,wall_s,particle_steps_per_s,communication_percent,ghosts,ghost_exchange_percent,agreement_percent" > parallelScaling.csv
field() { echo "$1" | awk -v key="$2" '{for (i = 1; i < NF; ++i) if ($i == key) print $(i + 1)}'; }
run() {  # ranks nx ny steps
  local line
  line=$(mpirun --bind-to core -np "$1" "$talus" --nx "$2" --ny "$3" --end-time "$(awk -v n="$4" 'BEGIN {print n * 1e-4}')" \
         --progress-interval 1e9 | grep '^benchmark:')
  echo "$1,$(field "$line" flowing),$(field "$line" steps),$(field "$line" wall),$(echo "$line" | awk '{print $9}'),$(field "$line" communication | tr -d %),$(field "$line" ghosts),$(field "$line" exchange | tr -d %,),$(field "$line" agreement | tr -d %\))" >> parallelScaling.csv
  field "$line" wall
}
specs=("1 1 2000" "6 6 300")
[ "$largest" -ge 6 ] && specs+=("19 18 150")
for spec in "${specs[@]}"; do
  set -- $spec
  for round in $(seq "$rounds"); do
    one=$(run 1 "$1" "$2" "$3")
    two=$(run 2 "$1" "$2" "$3")
    echo "nx $1 ny $2 ($3 steps), round $round: 1 rank $one s, 2 ranks $two s, speedup $(awk -v a="$one" -v b="$two" 'BEGIN {printf "%.2f", a / b}')"
  done
done
