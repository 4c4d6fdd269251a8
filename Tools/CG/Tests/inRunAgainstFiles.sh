#!/bin/sh
# In-run coarse graining against talus-cg on the same frames (InRun/InRunFields.h):
#   inRunAgainstFiles.sh DRIVER TALUS_CG CHECK_SCRIPT FIXED [LAUNCHER...]
# runs the test driver InRunChute (under the launcher, e.g. mpirun -np 2) with the in-run depth
# profile and XZ field sampled at its output steps and its .data/.fstat/.restart written at
# those same steps, then talus-cg on the files with the same coordinates, kernels, points and
# --fixed FIXED, and checkInRunAgainstFiles.py compares the fields number by number.
set -e
driver=$1 cg=$2 check=$3 fixed=$4
shift 4
rm -f InRunChute.* files.*.csv
"$@" "$driver" --fixed "$fixed" > run.log 2>&1 || { cat run.log; exit 1; }
grep "in-run coarse graining" run.log
"$cg" InRunChute --coordinates Z -n 96 -z -1 11 -w 0.5 --fixed "$fixed" -o files.profile.csv > cg.log 2>&1
"$cg" InRunChute --coordinates XZ --function Gauss -w 1 -n 8 6 -x 0 8 -z -1 11 --fixed "$fixed" -o files.field.csv >> cg.log 2>&1
/usr/bin/python3 "$check" InRunChute.profile.cg.csv files.profile.csv
/usr/bin/python3 "$check" InRunChute.field.cg.csv files.field.csv
# The same run with the depth profile averaged over the run (the sums averaged, then the fields
# derived) against talus-cg --time-average of its files.
"$@" "$driver" --fixed "$fixed" --averaging whole-run > run-average.log 2>&1 || { cat run-average.log; exit 1; }
profile="$cg InRunChute --coordinates Z -n 96 -z -1 11 -w 0.5 --fixed $fixed"
$profile --time-average -o files.average.csv >> cg.log 2>&1
$profile -o files.frames.csv >> cg.log 2>&1
/usr/bin/python3 "$check" InRunChute.profile.cg.csv files.average.csv --frames files.frames.csv
