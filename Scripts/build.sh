#!/usr/bin/env bash
# Configures and builds Talus with ccache and two jobs.
#   Scripts/build.sh [build-dir] [Release|Debug|Sanitize] [native]
# The library is built for the baseline x86-64 and picks its lane form when it starts
# (Kernel/Math/LaneForm.h); with "native" everything is compiled for this machine's processor
# (TALUS_NATIVE), and the programs built then run only on processors like it.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$top/build}
type=${2:-Release}
native=OFF
case "${3:-}" in
  "") ;;
  native) native=ON ;;
  *) echo "build.sh: third argument '$3': only 'native' (or nothing) is known" >&2; exit 2 ;;
esac
options=(-DTALUS_NATIVE=$native "-DCMAKE_CXX_FLAGS=")
if command -v ccache >/dev/null; then options+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$top" -B "$dir" -DCMAKE_BUILD_TYPE="$type" "${options[@]}" >/dev/null
cmake --build "$dir" -j2
