#!/bin/bash
# Self-test: a restart keeps the summation mode of the run it continues
# (Documentation/FileFormats/restart.md, "What a restart keeps").
#  1. A settling packing (300 spheres) run with --id-ordered-sums on, saved at t = 1 and restarted
#     on 2 ranks WITHOUT the flag, writes bitwise the .data and .ene of the uninterrupted serial
#     run, and the same particle states (17 digits) in its last restart file. The mode makes the
#     result independent of the rank count (Documentation/Parallel.md), so the only way to get the
#     same bits is to keep it: a continuation with the sums in list order differs in the last
#     digits as soon as a sphere has three contacts, which the bed has from t = 0.9 on.
#  2. A contradicting --id-ordered-sums (off on the run above, on on a run saved without it) and a
#     contradicting --dt are refused before the first step, with exit status 1 and an error that
#     names the flag and the value in the restart file.
# Usage: restartKeepsSummation.sh MPIRUN SETTLINGPACKING compareRuns.py
set -euo pipefail
mpirun=("$1" --oversubscribe)
packing=$2
compare="/usr/bin/python3 $3"
scene=(--particles 300 --width 6 --dt 2e-4 --output-interval 0.25 --vtu off --progress-interval 1000)

"$packing" "${scene[@]}" --id-ordered-sums on --end-time 2 --name whole > whole.log
"$packing" "${scene[@]}" --id-ordered-sums on --end-time 1 --name part > part.log
grep -q "^summation 1 " part.restart || { echo "the restart file does not keep --id-ordered-sums on"; exit 1; }
rm -rf restarted && mkdir restarted && cp part.data part.fstat part.ene part.restart restarted/
(cd restarted && "${mpirun[@]}" -np 2 "$packing" --restart part.restart --end-time 2 --progress-interval 1000 > run.log)
for f in data ene; do cmp whole.$f restarted/part.$f; done
$compare 0 whole.restart restarted/part.restart
echo "saved with --id-ordered-sums on, restarted on 2 ranks without the flag: bitwise the uninterrupted run"

# refused RESTARTFILE 'EXPECTED MESSAGE' FLAGS...: exits 1 with the message before the first step.
refused() {
  local file=$1 message=$2
  shift 2
  rm -rf refused && mkdir refused && cp "${file%.restart}".* refused/
  local status=0
  (cd refused && "$packing" --restart "$(basename "$file")" --end-time 2 "$@" > run.log 2>&1) || status=$?
  [ $status -eq 1 ] || { echo "$*: exit status $status, expected 1"; cat refused/run.log; exit 1; }
  grep -qF "$message" refused/run.log || { echo "$*: no '$message' in:"; cat refused/run.log; exit 1; }
  grep -q "running from" refused/run.log && { echo "$*: the run started"; exit 1; }
  echo "refused: $*"
}
refused part.restart \
  "error: --id-ordered-sums off contradicts the restart file part.restart, whose run has --id-ordered-sums on" \
  --id-ordered-sums off
refused part.restart "error: --dt 0.0001 contradicts the restart file part.restart, whose run has --dt 0.0002" \
  --dt 1e-4
"$packing" "${scene[@]}" --end-time 0.25 --name listOrder > listOrder.log
refused listOrder.restart \
  "error: --id-ordered-sums on contradicts the restart file listOrder.restart, whose run has --id-ordered-sums off" \
  --id-ordered-sums on
echo "restart keeps the summation mode"
