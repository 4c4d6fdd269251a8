#!/bin/bash
# Self-test of the overlap of the ghost exchange with the interior pairs (Documentation/Parallel.md,
# "Speed"): on ranks, the pairs of two owned particles are computed while the ghosts' states
# travel (--overlap-ghosts on; off is the default), and the rest once they have arrived; with it off all
# pairs are computed after. The force loop sums every particle's forces in the same order either
# way, so the two runs must write the same files to the bit. The flowing chute of the benchmark
# (3000 spheres, 1500 steps) rebuilds its list every few hundred steps, at a step where one
# rank's particle has moved far and the other's have not: the other rank has then computed its
# interior pairs already and must undo them (their contact histories put back) before the build.
# The run must report such undone steps, or this test would not test that path. On 2 ranks
# (the agreement rides on the ghost messages) and on 4 (an allreduce while the messages travel).
# And a settling packing in a box without periodic faces on 2 ranks, where the list has no
# interior pairs apart from those with ghosts, so nothing may be computed early: the same files
# with the flag on and off (computed early, the pairs with ghosts used the ghosts' last states and
# the files differed at t = 1.5 and 2).
# Usage: overlapChangesNoForce.sh MPIRUN BENCHMARK DATA SETTLING-PACKING
set -euo pipefail
mpirun=("$1" --oversubscribe)
benchmark=$2
data=$3
packing=$4
. "$(dirname "$0")/onAndOff.sh"
for ranks in 2 4; do
  runOnAndOff $ranks overlap-ghosts overlap
  grep -q "overlapped [1-9][0-9]*  undone [1-9]" overlapon$ranks.log ||
    { echo "$ranks ranks: no step computed interior pairs early and undid them:"; grep benchmark: overlapon$ranks.log; exit 1; }
  grep -q "overlapped 0  undone 0" overlapoff$ranks.log || { echo "--overlap-ghosts off did not turn it off"; exit 1; }
  sameFilesOnAndOff $ranks overlap
  echo "$ranks ranks: $(grep -o "overlapped [0-9]*  undone [0-9]*" overlapon$ranks.log) (steps of all ranks), bitwise the same files as without the overlap"
done
for overlap in on off; do
  "${mpirun[@]}" -np 2 "$packing" --particles 300 --width 6 --dt 2e-4 --end-time 2 --vtu off \
    --progress-interval 1000 --name packing$overlap --overlap-ghosts $overlap > packing$overlap.log
done
for f in data fstat ene; do cmp packingon.$f packingoff.$f; done
echo "a packing without periodic faces on 2 ranks: bitwise the same files"
echo "overlap changes no force"
