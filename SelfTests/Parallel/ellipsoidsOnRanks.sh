#!/bin/bash
# Self-test: ellipsoids on ranks without --id-ordered-sums (Documentation/Parallel.md). A cloud of
# 125 colliding ellipsoids in open space (EllipsoidsOnRanks.cc: no gravity, walls or periodic face,
# so momentum and angular momentum are conserved) for 1000 steps on 1, 2 and 3 ranks: every run
# checks the conservation laws at every step, and the runs on 2 and 3 ranks must follow the
# serial one to round-off. Measured at the last frame: 3e-13 in position and 1e-10 in velocity
# from the serial run on 2 and on 3 ranks, exactly what a serial run with its particles in another
# order (--reorder off) differs by; tolerance 1e-8, a hundred times the velocities' difference
# (.data writes 10 digits).
# Usage: ellipsoidsOnRanks.sh MPIRUN ELLIPSOIDSONRANKS compareRuns.py
set -euo pipefail
mpirun=("$1" --oversubscribe)
cloud=$2
compare="/usr/bin/python3 $3"
for ranks in 1 2 3; do
  "${mpirun[@]}" -np $ranks "$cloud" --name ranks$ranks --progress-interval 1000 > ranks$ranks.log
  grep "count, ids and masses kept exactly" ranks$ranks.log
done
$compare 1e-8 ranks1.data ranks2.data ranks3.data
echo "ellipsoids on 2 and 3 ranks: conserved, and the serial trajectory to round-off"
