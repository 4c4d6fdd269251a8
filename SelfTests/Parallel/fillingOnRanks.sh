#!/bin/bash
# Self-test: a filling during the run on 2 ranks places the particles of the run on 1 rank, to the
# bit (FillingOnRanks.cc: a sphere filling of an annulus at the start, a filling of spheres and
# ellipsoids in turn while the scene is split; nothing moves). The particles are compared without
# their ids, sorted: a particle added during a run on ranks gets its id when the ranks next
# exchange particles (Parallel/RankContext.h), in another order than on one rank.
# Usage: fillingOnRanks.sh MPIRUN FILLINGONRANKS
set -euo pipefail
mpirun=("$1" --oversubscribe)
fill=$2
for ranks in 1 2; do
  "${mpirun[@]}" -np $ranks "$fill" --files off --progress-interval 1000 > ranks$ranks.log
  grep "filled during the run on $ranks ranks: inserted 80 of 80" ranks$ranks.log
  grep "^particle " ranks$ranks.log | cut -d' ' -f3- | sort > particles$ranks.txt
done
count=$(wc -l < particles1.txt)
[ "$count" -eq 140 ] || { echo "the run on 1 rank holds $count particles, not 60 + 80"; exit 1; }
diff particles1.txt particles2.txt > /dev/null || { echo "the particles on 2 ranks differ from those on 1:"; diff particles1.txt particles2.txt | head; exit 1; }
echo "filling on 2 ranks: the same $count particles as on 1 rank"
