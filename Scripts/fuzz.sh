#!/usr/bin/env bash
# Fuzzes the readers with libFuzzer (SelfTests/Fuzz): builds the targets with clang under
# AddressSanitizer and UndefinedBehaviorSanitizer in their own build folder, seeds each with the
# repository's files (SelfTests/Fuzz/Seeds, Regressions) and with cuts of the MercuryDPM and
# peer files in $FUZZ_SHARED when present, runs each for the given minutes, and writes a summary:
# executions, corpus size and new findings per target.
#   Scripts/fuzz.sh [minutes per target, default 2] [target ...]
#   targets: lammps-data talus-restart cg-data cg-fstat cg-restart command-line (default: all)
# Environment: FUZZ_BUILD (default <repo>/build-fuzz), FUZZ_SHARED (default: the folder
# 'shared' next to the repository, which holds the peers' start files), FUZZ_JOBS (targets
# fuzzed at once, default 1; each uses one core), FUZZ_PROGRESS (seconds between progress lines,
# default 60).
# Each finding (a crash, a hang, running out of memory, or a reader that accepted garbage) is a
# file in $FUZZ_BUILD/findings/TARGET/: reproduce it with $FUZZ_BUILD/SelfTests/Fuzz/fuzz-TARGET
# FILE, fix the reader, and commit the file to SelfTests/Fuzz/Regressions/TARGET/ under a name
# that says what it is; ctest then replays it with the normal build (Fuzz.Replay.TARGET).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
minutes=${1:-2}
shift || true
seconds=$(awk -v m="$minutes" 'BEGIN { print int(m * 60 + 0.5) }')
[ "$seconds" -ge 1 ] || { echo "fuzz: minutes per target must be positive (fractions allowed), got '$minutes'"; exit 2; }
all=(lammps-data talus-restart cg-data cg-fstat cg-restart command-line)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all[@]}")
build=${FUZZ_BUILD:-$top/build-fuzz}
shared=${FUZZ_SHARED:-$top/../shared}

# clang and its libFuzzer runtime (Debian: clang, libclang-rt-dev); only this script needs them.
if ! command -v clang++ >/dev/null || ! echo 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }' |
    clang++ -x c++ -fsanitize=fuzzer - -o /dev/null 2>/dev/null; then
  echo "fuzz: installing clang and libclang-rt-dev (the libFuzzer runtime)"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends clang libclang-rt-dev >/dev/null
fi

mkdir -p "$build"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S "$top" -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DTALUS_FUZZ=ON -DTALUS_WITH_MPI=OFF -DTALUS_WITH_HDF5=OFF -DTALUS_NATIVE=OFF "${launcher[@]}" >"$build/configure.log"
cmake --build "$build" -j2 --target "${targets[@]/#/fuzz-}" >"$build/build.log" ||
  { tail -30 "$build/build.log"; exit 1; }

# Seeds cut from the reference files: a reader must see whole records to get past them, and
# libFuzzer works best on inputs of a few kilobytes.
seeds=$build/seeds
rm -rf "$seeds"
mkdir -p "$seeds"/{lammps-data,talus-restart,cg-data,cg-fstat,cg-restart,command-line}
mercury=$shared/reference/mercury/chute/Bidi_on
if [ -f "$mercury.data" ]; then
  # The first frame with its particle count cut to 6.
  awk 'NR == 1 { $1 = 6; print; next } NR <= 7' "$mercury.data" >"$seeds/cg-data/mercury-first-frame.data"
  awk '/^#/ { h++ } h <= 3 && n < 12 { print; if (!/^#/) n++ }' "$mercury.fstat" >"$seeds/cg-fstat/mercury-first-frame.fstat"
  # The restart up to its particle list, then 4 particles.
  awk '/^Particles / { print "Particles 4"; p = 1; next } p { if (n++ < 4) print; next } { print }' "$mercury.restart" |
    cut -c1-2000 >"$seeds/cg-restart/mercury-four-particles.restart"
fi
for lammps in "$shared"/peers/data/*.data "$shared"/reference/mercury/*.data; do
  [ -f "$lammps" ] || continue
  # The header and the first 6 atoms, the count set to match.
  awk '/ atoms$/ { print "6 atoms"; next } /^Atoms/ { a = 1; print; next } a && NF > 3 { if (n++ < 6) print; next } !a || NF <= 3 { print }' \
    "$lammps" | head -c 4000 >"$seeds/lammps-data/$(basename "$lammps")"
done

summary=$build/fuzz-summary.txt
jobs=${FUZZ_JOBS:-1}
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: FUZZ_JOBS must be a positive integer, got '$jobs'"; exit 2; }
{
  echo "Fuzzing $(date -u +%Y-%m-%dT%H:%MZ), $seconds s per target, $jobs at once, commit $(git -C "$top" rev-parse --short HEAD)"
  printf '%-14s %12s %10s %8s %9s\n' target executions "exec/s" corpus findings
} >"$summary"

# Fuzzes one target and writes its summary line to $build/TARGET.summary.
fuzz_target() {
  local t=$1
  local corpus=$build/corpus/$t findings=$build/findings/$t
  mkdir -p "$corpus" "$findings"
  local before
  before=$(ls "$findings" | wc -l)
  local inputs=("$corpus" "$top/SelfTests/Fuzz/Seeds/$t" "$seeds/$t")
  [ -d "$top/SelfTests/Fuzz/Regressions/$t" ] && inputs+=("$top/SelfTests/Fuzz/Regressions/$t")
  local dict=()
  [ -f "$top/SelfTests/Fuzz/$t.dict" ] && dict=(-dict="$top/SelfTests/Fuzz/$t.dict")
  echo "fuzz: $t for $minutes min"
  # -close_fd_mask=1: the targets' stdout (none of their messages) is not the report's.
  # Runs on after a finding (-fork with -ignore_crashes) so that one target's time is used fully.
  "$build/SelfTests/Fuzz/fuzz-$t" "${inputs[@]}" "${dict[@]}" -max_total_time="$seconds" \
    -artifact_prefix="$findings/" -max_len=16384 -timeout=10 -rss_limit_mb=2048 -close_fd_mask=1 \
    -print_final_stats=1 -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    >"$build/$t.log" 2>&1 || true
  # (fork mode reports its progress as "#N: cov: ..."; the last is the total)
  local executions
  executions=$( (grep -oE '^#[0-9]+' "$build/$t.log" || true) | tail -1 | tr -d '#')
  local after
  after=$(ls "$findings" | wc -l)
  printf '%-14s %12s %10s %8s %9s\n' "$t" "${executions:-0}" "$(( ${executions:-0} / seconds ))" \
    "$(ls "$corpus" | wc -l)" "$((after - before))" >"$build/$t.summary"
}

# Every FUZZ_PROGRESS seconds, the latest progress line of each target still running: its
# executions, coverage and corpus so far, and the seconds it has run.
progress=${FUZZ_PROGRESS:-60}
[[ "$progress" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: FUZZ_PROGRESS must be a positive integer, got '$progress'"; exit 2; }
report_progress() {
  while sleep "$progress"; do
    for t in "${targets[@]}"; do
      [ -f "$build/$t.log" ] && [ ! -f "$build/$t.summary" ] || continue
      line=$( (grep -E '^#[0-9]+' "$build/$t.log" || true) | tail -1)
      [ -n "$line" ] && echo "fuzz: $t ${line%% oom/*} (of ${seconds} s)"
    done
  done
}
for t in "${targets[@]}"; do rm -f "$build/$t.summary" "$build/$t.log"; done
report_progress &
reporter=$!
trap 'kill "$reporter" 2>/dev/null || true' EXIT

pids=()
for t in "${targets[@]}"; do
  if [ "${#pids[@]}" -ge "$jobs" ]; then
    wait -n "${pids[@]}" || true
    alive=()
    for p in "${pids[@]}"; do kill -0 "$p" 2>/dev/null && alive+=("$p"); done
    pids=("${alive[@]}")
  fi
  fuzz_target "$t" &
  pids+=($!)
done
wait "${pids[@]}" || true
kill "$reporter" 2>/dev/null || true
status=0
for t in "${targets[@]}"; do
  cat "$build/$t.summary" >>"$summary"
  [ "$(awk '{ print $5 }' "$build/$t.summary")" -gt 0 ] && status=1
done
cat "$summary"
echo "logs: $build/TARGET.log; findings: $build/findings/TARGET/"
exit $status
