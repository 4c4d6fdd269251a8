#!/usr/bin/env bash
# Sets up a new machine, builds Talus and passes every test:
#   1. the Release build (the portable library, which runs the lane form this processor runs
#      best, Kernel/Math/LaneForm.h): unit tests and self-tests (ctest); the unit tests of the
#      lane forms' own code run in every form this processor runs (UnitTests/LaneFormTest.h), and
#      every build compiles all the forms;
#   2. the same tests under AddressSanitizer and UndefinedBehaviorSanitizer (build-asan/).
# Usage: Scripts/test.sh [--no-sanitize]
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
"$top/Scripts/setup.sh"
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}

"$top/Scripts/build.sh" "$top/build" Release
(cd "$top/build" && ctest --output-on-failure -j2)

if [ "${1:-}" != "--no-sanitize" ]; then
  "$top/Scripts/build.sh" "$top/build-asan" Sanitize
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  (cd "$top/build-asan" && ctest --output-on-failure -j2)
fi
