#!/bin/bash
# Self-test: the open-source comparison's penetration driver under mpirun. The steel sphere falls
# onto the floor between four beads that it pushes aside as it lands (beads on either side of the
# cut between two ranks, the sphere on the cut), two more beads far away. With the sums in id
# order (--id-ordered-sums on) the 2-rank run must write the 1-rank run's heights to the bit: the
# driver's measurement (the sphere's height and velocity, a sum over the one steel particle on
# whichever rank holds it) knows no ranks.
# Usage: penetrationOnRanks.sh MPIRUN COMPARISONPENETRATION
set -euo pipefail
mpirun=("$1" --oversubscribe)
driver=$2
printf 'Radius PosX PosY PosZ\n0.001 0.006 0 -0.0892431\n0.001 -0.006 0 -0.0892431\n0.001 0 0.006 -0.0892431
0.001 0 -0.006 -0.0892431\n0.001 -0.045 -0.025 -0.0892431\n0.001 0.045 0.025 -0.0892431\n5 0.01 0.01 0 0 0.06\n' > bed.txt
for ranks in 1 2; do
  "${mpirun[@]}" -np $ranks "$driver" --start-file bed.txt --end-time 0.03 --vtu off --fstat off --id-ordered-sums on \
    --progress-interval 1000 --name ranks$ranks > ranks$ranks.log
done
# The beads took part: the rebound is slower than from the bare floor (3.16 m/s).
rebound=$(awk '!/^#/ { v = $3 } END { print v }' ranks1.penetration)
awk -v v="$rebound" 'BEGIN { exit !(v > 2 && v < 3.15) }' || { echo "the beads were not met (rebound $rebound m/s)"; exit 1; }
cmp ranks1.penetration ranks2.penetration && echo "penetration on 2 ranks: the 1-rank heights to the bit (rebound $rebound m/s)"
