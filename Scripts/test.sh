#!/usr/bin/env bash
# Sets up a new machine, builds Talus and passes every test:
#   1. the Release build for this machine's processor: unit tests and self-tests (ctest);
#   2. the hand-written lanes compiled for every instruction set they have a form for
#      (Scripts/checkLaneForms.sh: AVX-512, AVX2, none);
#   3. the same tests under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/), built
#      for the next lane form this processor can run (AVX2 on an AVX-512 machine, the scalar loops
#      on an AVX2 one), so that two forms run every test (Scripts/laneForms.sh).
# Usage: Scripts/test.sh [--no-sanitize]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}

"$top/Scripts/build.sh" "$top/build" Release
echo "test: Release build, lanes of this machine: $("$top/Scripts/laneForms.sh" native)"
(cd "$top/build" && ctest --output-on-failure -j2)
"$top/Scripts/checkLaneForms.sh"

if [ "${1:-}" != "--no-sanitize" ]; then
  second=$("$top/Scripts/laneForms.sh" second-march)
  echo "test: sanitizer build for -march=$second, lanes: $("$top/Scripts/laneForms.sh" "$second")"
  "$top/Scripts/build.sh" "$top/build-asan" Sanitize "$second"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  (cd "$top/build-asan" && ctest --output-on-failure -j2)
fi
