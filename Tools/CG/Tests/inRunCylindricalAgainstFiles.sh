#!/bin/sh
# In-run coarse graining in cylindrical coordinates against talus-cg on the same frames:
#   inRunCylindricalAgainstFiles.sh IN_RUN_DRUM TALUS_CG CHECK_SCRIPT [LAUNCHER...]
# runs the test driver InRunDrum (a small drum of spheres, filled, then turning; under the
# launcher, e.g. mpirun -np 2) with its RZ field sampled at the output steps, where it also writes
# its files, then talus-cg on the files with the same axis, kernel, points and --fixed boundary,
# and checkInRunAgainstFiles.py compares the fields number by number.
set -e
driver=$1 cg=$2 check=$3
shift 3
rm -f InRunDrum.* files.*.csv
"$@" "$driver" --radius 4 --length 3 --aspect 1 > run.log 2>&1 || { cat run.log; exit 1; }
grep "in-run coarse graining" run.log
"$cg" InRunDrum --coordinates RZ --axis y --axis-point 0 0 0 -w 1 -n 8 2 -r 0 4 -y 0 3 --fixed boundary \
  -o files.cylinder.csv > cg.log 2>&1 || { cat cg.log; exit 1; }
/usr/bin/python3 "$check" InRunDrum.cylinder.cg.csv files.cylinder.csv
