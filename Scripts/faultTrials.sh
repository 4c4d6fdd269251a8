#!/usr/bin/env bash
# Fault trials: a driver run killed with SIGKILL at random moments (in the time steps, while a
# frame is appended, while a .vtu, the .pvd or the restart file is written) and continued from
# what it left (its .restart file, or from the start when it left none) must end with files
# bitwise identical to those of a run that was never killed.
#
#   faultTrials.sh [trials] [driver] [driver flags...]
#
# trials: default 20. driver: default build/Drivers/Demos/SettlingPacking next to this script,
# with small, frequent output (the flags below) so that many kills land while files are written.
# Each trial kills 1 to 3 times (until a run finishes first), each at a random moment of the
# run's length (taken from the unkilled run), and restarts after each kill with `--restart NAME.restart` (the restart file
# holds every setting) or, when no restart file was left, from the start with the flags again.
# Works in ./faultTrials (made anew). Prints one line a trial saying where each kill landed and
# ends with "fault trials: P of T bitwise identical"; exit status 1 if any trial differs.
set -euo pipefail
trials=${1:-20}
here=$(cd "$(dirname "$0")" && pwd)
driver=${2:-$here/../build/Drivers/Demos/SettlingPacking}
shift $(($# < 2 ? $# : 2))
flags=("$@")
[ ${#flags[@]} -gt 0 ] || flags=(--particles 100 --width 4 --end-time 1 --output-interval 0.02)
driver=$(cd "$(dirname "$driver")" && pwd)/$(basename "$driver")
name=$(basename "$driver")
work=$PWD/faultTrials
rm -rf "$work" && mkdir -p "$work/whole"

milliseconds() { echo $(($(date +%s%N) / 1000000)); }
start=$(milliseconds)
(cd "$work/whole" && "$driver" "${flags[@]}" --progress-interval 1000 > run.log)
length=$(($(milliseconds) - start + 1))
rm "$work/whole/run.log"
echo "unkilled run: $length ms, $(ls "$work/whole" | wc -l) files"

# Where the kill landed, read from what it left: a FILE.tmp is a file being replaced; appended
# files longer than the restart file records are a frame written after its restart point.
landed() {
  local tmp
  tmp=$(cd "$1" && ls -- *.tmp 2> /dev/null | head -1 || true)
  if [ -n "$tmp" ]; then echo "writing ${tmp%.tmp}"; return; fi
  if [ ! -f "$1/$name.restart" ]; then echo "before the first restart file"; return; fi
  local recorded actual=0 f
  recorded=$(awk '$1 == "output" { print $3 + $4 + $5 }' "$1/$name.restart")
  if [ -z "$recorded" ]; then echo "leaving a restart file without its output line"; return; fi
  for f in data fstat ene; do
    [ -f "$1/$name.$f" ] && actual=$((actual + $(stat -c %s "$1/$name.$f")))
  done
  if [ "$actual" -gt "$recorded" ]; then echo "in a frame after its restart point"; else echo "in the time steps"; fi
}

arguments() {  # continues from the restart file if there is one
  if [ -f "$1/$name.restart" ]; then
    args=(--restart "$name.restart" --progress-interval 1000)
  else
    args=("${flags[@]}" --progress-interval 1000)
  fi
}

passed=0
for trial in $(seq 1 "$trials"); do
  dir=$work/trial$trial
  mkdir -p "$dir"
  report=()
  for kill in $(seq 1 $((1 + RANDOM % 3))); do
    delay=$(((RANDOM * 32768 + RANDOM) % length))
    arguments "$dir"
    (cd "$dir" && exec "$driver" "${args[@]}" > run.log 2>&1) &
    pid=$!  # (the driver's own: the subshell execs it)
    sleep "$(printf '%d.%03d' $((delay / 1000)) $((delay % 1000)))"
    if kill -KILL "$pid" 2> /dev/null; then
      wait "$pid" 2> /dev/null || true
      report+=("killed at $delay ms $(landed "$dir")")
    elif wait "$pid"; then
      report+=("finished before the kill at $delay ms")
      break
    else
      report+=("the run failed: $(tail -1 "$dir/run.log")")
      break
    fi
  done
  arguments "$dir"
  differs=""
  if (cd "$dir" && "$driver" "${args[@]}" > run.log 2>&1); then
    rm "$dir/run.log"
    diff <(cd "$work/whole" && ls) <(cd "$dir" && ls) > /dev/null || differs="other files"
    for f in "$work/whole"/*; do
      cmp -s "$f" "$dir/$(basename "$f")" || differs="$differs $(basename "$f")"
    done
  else
    differs="the continued run failed: $(tail -1 "$dir/run.log")"
  fi
  joined=$(printf '%s; ' "${report[@]}")
  if [ -z "$differs" ]; then
    passed=$((passed + 1))
    echo "trial $trial: ${joined%; }: identical"
    rm -rf "$dir"
  else
    echo "trial $trial: ${joined%; }: DIFFERS ($differs) (kept in $dir)"
  fi
done
echo "fault trials: $passed of $trials bitwise identical"
[ "$passed" -eq "$trials" ]
