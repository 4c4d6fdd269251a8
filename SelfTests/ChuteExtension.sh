#!/usr/bin/env bash
# Self-test: a maser-fed chute restarted after activation with a larger --chute-length is
# extended (Documentation/Chutes/MaserFedChute.md). Checks that
#  - the base laid at activation plus the base added at the restart is the base a chute of the
#    new length gets at activation (counted by a third run),
#  - the flow then passes the old outlet (the .series front),
#  - mass is conserved across the restart (the driver's own balance, deletions before it included),
#  - a shorter --chute-length at a restart is refused with an error naming the flag.
#   ChuteExtension.sh <MaserFedChute> <work-dir> [driver flags of a small maser...]
set -euo pipefail
driver=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work/long" "$work/extended"
quiet=(--progress-interval 1000 --vtu off)
baseOf() { sed -n 's/.*chute base of \([0-9]*\) spheres.*/\1/p' "$1"; }

(cd "$work/long" && "$driver" "$@" --chute-length 30 --end-time 2.1 --files off "${quiet[@]}" > run.log)
cd "$work/extended"
"$driver" "$@" --chute-length 10 --end-time 5 --output-interval 1 "${quiet[@]}" > first.log
"$driver" --restart MaserFedChute.restart --chute-length 30 --end-time 15 --output-interval 1 "${quiet[@]}" > second.log
if "$driver" --restart MaserFedChute.restart --chute-length 5 --end-time 16 --files off > shorter.log 2>&1; then
  echo "a shorter chute at a restart was accepted"; exit 1
fi

long=$(baseOf "$work/long/run.log") first=$(baseOf first.log)
added=$(sed -n 's/.*chute extended from x = 20 to 40 at t = 5 (\([0-9]*\) base spheres added).*/\1/p' second.log)
deletedBefore=$(sed -n 's/.*in the chute [0-9]* + deleted \([0-9]*\);.*/\1/p' first.log)
front=$(awk '!/^#/ && $1 > 5 && $15 > f { f = $15 } END { print f + 0 }' MaserFedChute.series)
echo "base: at activation $first (chute 10) + added $added (to 30) against $long (chute 30 from the start)"
echo "deleted before the extension: $deletedBefore; front after it reached x = $front (old outlet 20)"
status=0
[ -n "$added" ] && [ -n "$long" ] && [ $((first + added)) -eq "$long" ] || { echo "the extended base differs"; status=1; }
[ "${deletedBefore:-0}" -gt 0 ] || { echo "nothing left the short chute: the test does not test carrying deletions"; status=1; }
awk -v f="$front" 'BEGIN { exit !(f > 20) }' || { echo "the flow did not pass the old outlet"; status=1; }
grep -q "mass conserved: yes" second.log || { echo "mass not conserved after the extension"; status=1; }
grep -q "error: --chute-length 5 is shorter than the chute of the restart file (30)" shorter.log ||
  { echo "no clear error for a shorter chute"; cat shorter.log; status=1; }
[ $status -eq 0 ] && echo "chute extended on restart: base, front, mass and the error check out"
exit $status
