#!/bin/bash
# Self-test: the rotating drum (Drivers/Drum) under mpirun. A small drum (40 particles, half of
# them ellipsoids) is filled in two rounds, the second at t = 10 while the scene is split over
# the ranks, settles and starts turning; every sample the driver itself requires that the bed
# holds every inserted particle, with their mass, and none left the drum (RotatingDrum::checkBed,
# whole-scene sums of Kernel/Sampling). The run on 2 ranks must give the 1-rank run's series
# (time, rotations, kinetic energy, mixing and segregation indices, angle) to within round-off:
# the ranks sum the forces and the measurements in another order, which the collisions of the
# filling amplify (compareDrumSeries.py states the tolerance and why).
# Usage: drumOnRanks.sh MPIRUN ROTATINGDRUM COMPARE
set -euo pipefail
mpirun=("$1" --oversubscribe)
drum=$2
compare=$3
# (--shape-tolerance 1e-10: the contacts solved to convergence, so that the ranks' other order of
# work changes round-off alone; at the driver's 1e-6 a contact's answer is one Newton step from
# its warm start, and the series part by about 1e-5 within the 16 time units: RotatingDrum.md.)
scene=(--radius 4 --length 4 --particles 40 --end-time 16 --output-interval 16 --vtu off --progress-interval 1000
       --id-ordered-sums on --shape-tolerance 1e-10)
for ranks in 1 2; do
  "${mpirun[@]}" -np $ranks "$drum" "${scene[@]}" --name drum$ranks > drum$ranks.log
  grep -q "40 of 40 in" drum$ranks.log || { echo "drum on $ranks ranks: not all 40 particles inserted"; exit 1; }
done
grep -q "insertion round 2 at t = 10" drum2.log || { echo "no insertion round while split over the ranks"; exit 1; }
/usr/bin/python3 "$compare" drum1.series drum2.series
