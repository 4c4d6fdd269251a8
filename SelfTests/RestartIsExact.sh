#!/usr/bin/env bash
# Self-test: a run restarted from its .restart file writes bitwise the same files as the
# uninterrupted run (Documentation/Architecture.md "Determinism").
#   RestartIsExact.sh <driver> <work-dir> <end-time> <restart-time> [driver flags...]
# With TALUS_LAUNCH set (for example "mpirun -np 2") every run is started by it.
set -euo pipefail
driver=$1 work=$2 end=$3 middle=$4
shift 4
read -r -a launch <<< "${TALUS_LAUNCH:-}"
run() { "${launch[@]}" "$driver" "$@"; }
rm -rf "$work" && mkdir -p "$work/whole" "$work/split"
name=$(basename "$driver")
(cd "$work/whole" && run "$@" --end-time "$end" --progress-interval 1000 >/dev/null)
(cd "$work/split" && run "$@" --end-time "$middle" --progress-interval 1000 >/dev/null)
(cd "$work/split" && run --restart "$name.restart" --end-time "$end" --progress-interval 1000 >/dev/null)
status=0
for f in "$work/whole"/*; do
  base=$(basename "$f")
  if ! cmp -s "$f" "$work/split/$base"; then
    echo "differs after restart: $base"; status=1
  fi
done
count=$(ls "$work/whole" | wc -l)
[ "$count" -ge 5 ] || { echo "expected at least 5 output files, found $count"; status=1; }
[ $status -eq 0 ] && echo "restart exact: $count files bitwise identical"
exit $status
