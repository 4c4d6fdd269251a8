#!/bin/bash
# Self-test: with --id-ordered-sums on, superquadric scenes give the same result to the bit on any
# number of ranks (Documentation/Parallel.md). 100 ellipsoids of aspect ratio 2 settle in a box
# (Drivers/Demos/SettlingEllipsoids, dt = tc/12.5 to keep it short) for 7500 steps on 1, 2 and 3
# ranks: from t = 1.2 on they touch the floor, the walls and each other (about 20 contacts, the
# lasting ones in the ellipsoid batch), and the .data and .ene files must be the same bytes.
# Without the flag the runs on 2 and 3 ranks differ from the serial one by 5e-10 (2 ranks) and
# 1e-9 (3) in position at t = 2, and by 7e-3 and 9e-3 at t = 3 (round-off of the summation order,
# grown by the collisions). With the ellipsoids' pair forces added in list order (the sphere
# pairs alone kept for the sums in id order) the frames first differ at t = 2.8, when particles
# have two ellipsoid partners at once.
# Usage: ellipsoidsIdOrdered.sh MPIRUN SETTLINGELLIPSOIDS
set -euo pipefail
mpirun=("$1" --oversubscribe)
ellipsoids=$2
scene=(--particles 100 --width 5 --dt 4e-4 --end-time 3 --output-interval 0.2 --vtu off --progress-interval 1000)
for ranks in 1 2 3; do
  "${mpirun[@]}" -np $ranks "$ellipsoids" "${scene[@]}" --id-ordered-sums on --name ordered$ranks > ordered$ranks.log
done
contacts=$(tail -1 ordered1.ene | awk '{print $NF}')
[ "$contacts" -gt 5 ] || { echo "only $contacts contacts at the end: the test tests little"; exit 1; }
for ranks in 2 3; do for f in data ene; do cmp ordered1.$f ordered$ranks.$f; done; done
echo "ellipsoids with --id-ordered-sums on 1, 2 and 3 ranks: bitwise the same .data and .ene ($contacts contacts at the end)"
