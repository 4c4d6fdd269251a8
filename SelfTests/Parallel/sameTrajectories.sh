#!/bin/bash
# Self-test of the MPI domain split (Documentation/Parallel.md), on the periodic bidisperse
# chute of the benchmark (3000 flowing spheres on a rough base, 2000 steps):
#  1. the same trajectories on 1, 2, 3 and 4 ranks, and in a serial run with the particles in
#     another order, to round-off (the tolerance below);
#  2. bitwise the same files run to run on the same number of ranks;
#  3. a restart on the same number of ranks continues bitwise, on another to round-off: saved on
#     2 ranks and restarted on 1, 2 and 3; saved on 4 and restarted on 2; saved on 1 and
#     restarted on 4;
#  4. the same to round-off with the ranks in a grid (--rank-grid 1x2x1, 2x2x1, 1x2x2: cells cut
#     across the chute and along its height, which is not periodic);
#  5. with --id-ordered-sums on: the same particle states to the bit on 1, 2, 3 and 4 ranks and
#     in a serial run in another particle order, and a run saved on 2 ranks and restarted on 3
#     writes bitwise the files of the uninterrupted run;
#  6. the near list (Documentation/UserGuide/NeighbourSearch.md) changes nothing on ranks: 3 ranks
#     from the bed stirred by random velocities (it is remade tens of times between list builds)
#     write bitwise the files of the same run with it off (--near-skin-fraction 0).
# "To round-off": ranks sum a particle's contact forces in another order than a serial run, as
# a serial run with its particles in another order does, so the states first differ by an ulp
# (1e-16 of a force) and the dense flow amplifies that. Measured, the largest differences in
# position or velocity from the serial run of those four other orders grew alike: 1e-12 to
# 1e-11 at t = 0.05, 2e-11 to 8e-11 at 0.1, 1.1e-9 to 1.9e-9 at 0.2 (the end here), 1e-3 at 0.4; an
# e-folding every 0.015 to 0.03 time units (150 to 300 steps). The tolerance 1e-7 is 50 times the
# round-off at the end, what another rounding pattern (compiler, contraction into fused
# multiply-adds) could add in ln 50 = 4 e-foldings, a run some 0.1 time units longer. A real
# error stands out by far: ghosts whose spin is not updated each step differ by 0.01 in velocity
# at t = 0.05 and 0.09 at 0.2.
# Usage: sameTrajectories.sh MPIRUN BENCHMARK compareRuns.py
set -euo pipefail
roundOff=1e-7
mpirun=("$1" --oversubscribe)
benchmark=$2
compare="/usr/bin/python3 $3"
run() {  # ranks name flags...
  local ranks=$1 name=$2
  shift 2
  "${mpirun[@]}" -np "$ranks" "$benchmark" --files on --vtu off --name "$name" "$@" > "$name.log"
}

run 1 serial --end-time 0.2
"$benchmark" --files on --vtu off --name reordered --reorder off --end-time 0.2 > reordered.log
for ranks in 2 3 4; do run $ranks ranks$ranks --end-time 0.2; done
echo "a serial run with the particles in another order, and 1 to 4 ranks:"
$compare $roundOff serial.data reordered.data ranks2.data ranks3.data ranks4.data
run 2 grid1x2x1 --end-time 0.2 --rank-grid 1x2x1
run 4 grid2x2x1 --end-time 0.2 --rank-grid 2x2x1
run 4 grid1x2x2 --end-time 0.2 --rank-grid 1x2x2
echo "ranks in grids 1x2x1, 2x2x1, 1x2x2:"
$compare $roundOff serial.data grid1x2x1.data grid2x2x1.data grid1x2x2.data

run 2 again2 --end-time 0.2
for f in data fstat ene; do cmp ranks2.$f again2.$f; done
echo "2 ranks twice: bitwise the same .data, .fstat and .ene"

run 2 whole --end-time 0.2 --output-interval 0.05
run 2 part --end-time 0.1 --output-interval 0.05
for ranks in 1 2 3; do
  mkdir -p restart$ranks
  cp part.data part.fstat part.ene part.restart restart$ranks/
  (cd restart$ranks && "${mpirun[@]}" -np $ranks "$benchmark" --restart part.restart --end-time 0.2 > run.log)
done
for f in data fstat ene; do cmp whole.$f restart2/part.$f; done
echo "saved on 2 ranks, restarted on 2: bitwise the same files as the uninterrupted run"
$compare $roundOff whole.data restart1/part.data restart3/part.data
for saved in 4 1; do
  restarted=$((saved == 4 ? 2 : 4))
  mkdir -p from$saved && cd from$saved
  "${mpirun[@]}" -np $saved "$benchmark" --files on --vtu off --name part --end-time 0.1 --output-interval 0.05 > run.log
  "${mpirun[@]}" -np $restarted "$benchmark" --restart part.restart --end-time 0.2 > run.log
  cd ..
  echo "saved on $saved ranks, restarted on $restarted:"
  $compare $roundOff whole.data from$saved/part.data
done

for ranks in 1 2 3 4; do run $ranks ordered$ranks --end-time 0.2 --id-ordered-sums on; done
run 4 orderedGrid --end-time 0.2 --id-ordered-sums on --rank-grid 2x2x1
"$benchmark" --files on --vtu off --name orderedReordered --reorder off --id-ordered-sums on --end-time 0.2 > orderedReordered.log
echo "--id-ordered-sums on, 1 to 4 ranks, a 2x2x1 grid and another particle order:"
$compare 0 ordered1.data ordered2.data ordered3.data ordered4.data orderedGrid.data orderedReordered.data
$compare 0 ordered1.restart ordered2.restart ordered3.restart ordered4.restart orderedGrid.restart orderedReordered.restart
run 2 orderedWhole --end-time 0.2 --output-interval 0.05 --id-ordered-sums on
run 2 orderedPart --end-time 0.1 --output-interval 0.05 --id-ordered-sums on
mkdir -p orderedRestart3 && cp orderedPart.* orderedRestart3/
(cd orderedRestart3 && "${mpirun[@]}" -np 3 "$benchmark" --restart orderedPart.restart --end-time 0.2 --id-ordered-sums on > run.log)
for f in data ene; do cmp orderedWhole.$f orderedRestart3/orderedPart.$f; done
echo "--id-ordered-sums on, saved on 2 ranks, restarted on 3: bitwise the same .data and .ene"
run 3 nearOn --end-time 0.2 --perturbation 2
run 3 nearOff --end-time 0.2 --perturbation 2 --near-skin-fraction 0
grep -q "near list .* made [1-9][0-9]* times" nearOn.log || { echo "the near list was not used"; exit 1; }
grep -q "near list" nearOff.log && { echo "the near list was not switched off"; exit 1; }
for f in data fstat ene; do cmp nearOn.$f nearOff.$f; done
cmp <(sed 2d nearOn.restart) <(sed 2d nearOff.restart)  # (line 2 is the run's name)
echo "near list on 3 ranks: $(grep -o "made [0-9]* times" nearOn.log) on rank 0, bitwise the same files as without it"
echo "parallel trajectories ok"
