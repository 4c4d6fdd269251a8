#!/bin/bash
# Self-test of the drift pass on ranks (Documentation/Parallel.md, "Speed"): the first half of a
# step in one pass over the owned particles (kick, drift, wrap, the list's check, their sweep
# points, the forces started), the ghosts' states and last forces arriving afterwards. It sums
# nothing in another order than the separate passes, so the files must be the same to the bit as
# with --drift-pass off. The flowing chute of the benchmark (3000 spheres, 1500 steps) builds its
# list several times, on steps where the pass has already started the forces: the build must put
# the last forces back before particles migrate, or the migrated particles' first kick after it
# differs. On 2 ranks (the agreement rides on the ghost messages) and on 4 (an allreduce).
# Usage: driftPassChangesNoBit.sh MPIRUN BENCHMARK DATA
set -euo pipefail
mpirun=("$1" --oversubscribe)
benchmark=$2
data=$3
. "$(dirname "$0")/onAndOff.sh"
for ranks in 2 4; do
  runOnAndOff $ranks drift-pass pass
  grep -q "stepper drift pass" passon$ranks.log || { echo "$ranks ranks: the drift pass was not used:"; grep stepper passon$ranks.log; exit 1; }
  grep -q "stepper plain velocity Verlet" passoff$ranks.log || { echo "--drift-pass off did not turn it off"; exit 1; }
  builds=$(grep -o "neighbour list built [0-9]* times" passon$ranks.log | grep -o "[0-9]*")
  [ "$builds" -ge 3 ] || { echo "$ranks ranks: the list was built $builds times; the test needs builds during the run"; exit 1; }
  sameFilesOnAndOff $ranks pass
  echo "$ranks ranks: list built $builds times, bitwise the same files as without the drift pass"
done
echo "drift pass on ranks changes no bit"
