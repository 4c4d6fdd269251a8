#!/usr/bin/env bash
# Sets up a new machine, builds Talus and passes every test:
#   1. the Release build: unit tests and self-tests (ctest);
#   2. the hand-written lanes compiled for the instruction sets this machine lacks
#      (Scripts/checkLaneForms.sh: AVX-512, AVX2, none);
#   3. the same tests under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/).
# Usage: Scripts/test.sh [--no-sanitize]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}

"$top/Scripts/build.sh" "$top/build" Release
(cd "$top/build" && ctest --output-on-failure -j2)
"$top/Scripts/checkLaneForms.sh"

if [ "${1:-}" != "--no-sanitize" ]; then
  "$top/Scripts/build.sh" "$top/build-asan" Sanitize
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  (cd "$top/build-asan" && ctest --output-on-failure -j2)
fi
