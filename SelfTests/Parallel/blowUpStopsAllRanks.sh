#!/usr/bin/env bash
# A blow-up found on one rank stops every rank, promptly and with the same diagnosis as the
# serial run: the periodic chute with an overlap limit of 0.2% of the radius (exceeded while the
# spheres land on the base, at t = 0.98 with seed 1) on 1, 2 and 3 ranks. Each run must fail
# within the time limit (no rank left waiting) and print the serial run's "blow-up at t = ..."
# line word for word (the overlap check of a step is agreed with the next step's, Simulation.h).
#   blowUpStopsAllRanks.sh MPIEXEC DRIVER
set -u
mpiexec=$1 driver=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
flags=(--end-time 2 --output-interval 1 --vtu off --max-overlap 0.002 --progress-interval 1e9)
diagnosis() { grep -o "blow-up at t = .*" "$1" | head -1; }
timeout 300 "$driver" "${flags[@]}" > serial.txt 2>&1
status=$?
serial=$(diagnosis serial.txt)
[ $status -ne 0 ] && [ $status -ne 124 ] && [ -n "$serial" ] || { echo "serial run: exit $status, no blow-up diagnosis"; cat serial.txt; exit 1; }
echo "serial: $serial"
for ranks in 2 3; do
  timeout 300 "$mpiexec" --oversubscribe -np $ranks "$driver" "${flags[@]}" > ranks$ranks.txt 2>&1
  status=$?
  [ $status -eq 124 ] && { echo "$ranks ranks: still running after 300 s (a rank left waiting)"; exit 1; }
  [ $status -ne 0 ] || { echo "$ranks ranks: exit 0, the blow-up was not found"; exit 1; }
  got=$(diagnosis ranks$ranks.txt)
  [ "$got" = "$serial" ] || { echo "$ranks ranks: diagnosis '$got' differs from the serial '$serial'"; cat ranks$ranks.txt; exit 1; }
  echo "$ranks ranks: the same diagnosis, exit $status"
done
echo "blow-up stops all ranks"
