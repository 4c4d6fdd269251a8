#!/bin/bash
# Self-test: the open-source comparison's drum on its published triangles, turning (a moving mesh),
# under mpirun. 2000 beads of the published start file fall onto the mesh in the drum's lower half
# for 0.05 s; with the sums in id order (--id-ordered-sums on) the 2-rank run must end with the
# 1-rank run's particle states to the bit (every rank moves the whole mesh alike and lists its own
# beads' triangles). The beads must have met the mesh: wall contacts in the 1-rank run's .fstat.
# And the turning triangles listed anew as the mesh travels (PairList::relistWalls), the particles'
# pairs kept, give the states of a run that builds the whole list instead (--relist off), to the
# bit (the sums in id order take the pairs' order out; the wall candidates keep a build's order).
# Usage: drumMeshOnRanks.sh MPIRUN COMPARISONDRUM START-FILE WALLS COMPARERUNS
set -euo pipefail
mpirun=("$1" --oversubscribe)
driver=$2 start=$3 walls=$4 compare=$5
head -n 2001 "$start" > beads.txt
for ranks in 1 2; do
  "${mpirun[@]}" -np $ranks "$driver" --start-file beads.txt --walls "$walls" --end-time 0.05 --output-interval 0.05 \
    --vtu off --id-ordered-sums on --progress-interval 1000 --name ranks$ranks > ranks$ranks.log
done
contacts=$(awk 'NF > 5 && $3 < 0 { n++ } END { print n + 0 }' ranks1.fstat)
[ "$contacts" -gt 100 ] || { echo "the beads hardly met the mesh ($contacts wall contacts)"; exit 1; }
/usr/bin/python3 "$compare" 0 ranks1.restart ranks2.restart
"$driver" --start-file beads.txt --walls "$walls" --end-time 0.05 --output-interval 0.05 --vtu off --fstat off \
  --id-ordered-sums on --relist off --progress-interval 1000 --name builds > builds.log
relistings=$(grep -o "triangles listed anew [0-9]*" ranks1.log | grep -o "[0-9]*$" || true)
[ "${relistings:-0}" -gt 2 ] || { echo "the mesh's triangles were hardly listed anew (${relistings:-0} times)"; exit 1; }
/usr/bin/python3 "$compare" 0 ranks1.restart builds.restart
echo "drum on its triangles on 2 ranks: the 1-rank particle states to the bit ($contacts wall contacts written);" \
  "its triangles listed anew $relistings times: the states of whole builds to the bit"
