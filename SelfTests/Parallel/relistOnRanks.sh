#!/bin/bash
# Self-test of relisting on MPI ranks (Documentation/UserGuide/NeighbourSearch.md, "Relisting"):
# a small maser-fed chute (the self-tests' scene, with a chute of 60) runs on 2 ranks to t = 20,
# the rank boundaries following the flow (--rebalance-interval 1), so that the maser box lies
# far from the other rank; from its restart file it goes on to t = 21 twice, relisting the pairs
# of the maser's copies and moved spheres (--relist on) and building the list anew at every
# crossing (--relist off). Passes when the relisting run did relist, the two created the same
# spheres, and their frames (saved every 0.1) agree until they part by round-off: the first
# frame that differs at all differs by at most 1e-9 (a missed or extra contact would show at
# once, as a difference of the order of a step's contact impulse). The two lists sum forces in
# other orders, and the flow is chaotic: once the round-off shows it grows about 30-50 times per
# 0.1 time units, and by t = 21 it can reach 1e-2 (measured: first seen at t = 20.4 at 1e-13 in
# velocity, 2.7e-2 at t = 21; in a sanitizer build once first seen at t = 21.6). A save on ranks
# builds the list anew and rebalances, so both runs meet the same rebuilds.
# Usage: relistOnRanks.sh MPIRUN MASERFEDCHUTE compareRuns.py
set -euo pipefail
mpirun=("$1" --oversubscribe -np 2)
chute=$2
compare="/usr/bin/python3 $3"
scene=(--inflow-height 3 --maser-length 10 --width 3 --chute-length 60 --earliest-activation 1 --latest-activation 2
       --rebalance-interval 1 --vtu off)
"${mpirun[@]}" "$chute" "${scene[@]}" --end-time 20 --output-interval 20 --name base --relist off > base.log
for relist in on off; do
  rm -rf "$relist" && mkdir "$relist" && cp base.* "$relist"/
  (cd "$relist" && "${mpirun[@]}" "$chute" --restart base.restart --end-time 21 --output-interval 0.1 --relist "$relist" > run.log)
done
relisted=$(sed -n 's/.*the pairs of \([0-9]*\) added or moved particles relisted.*/\1/p' on/run.log)
[ "${relisted:-0}" -gt 0 ] || { echo "the run with --relist on relisted nothing"; cat on/run.log; exit 1; }
grep -q "relisted" off/run.log && { echo "the run with --relist off relisted"; exit 1; }
created() { grep -o "created [0-9]* (seeded [0-9]* + crossed [0-9]*)" "$1"; }
[ "$(created on/run.log)" = "$(created off/run.log)" ] || { echo "different crossings"; exit 1; }
$compare --parting 1e-9 off/base.data on/base.data
echo "relisted on ranks: $relisted particles, $(created on/run.log), same trajectories"
