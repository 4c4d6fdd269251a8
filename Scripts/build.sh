#!/usr/bin/env bash
# Configures and builds Talus with ccache and two jobs.
#   Scripts/build.sh [build-dir] [Release|Debug|Sanitize] [march]
# With a third argument the build is for that instruction set (-march=x86-64-v3: the AVX2 lanes;
# x86-64: the scalar loops) instead of this machine's own (TALUS_NATIVE).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
dir=${1:-$top/build}
type=${2:-Release}
march=${3:-}
options=()
if command -v ccache >/dev/null; then options+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
if [ -n "$march" ]; then
  options+=(-DTALUS_NATIVE=OFF "-DCMAKE_CXX_FLAGS=-march=$march")
else
  options+=(-DTALUS_NATIVE=ON "-DCMAKE_CXX_FLAGS=")
fi
cmake -S "$top" -B "$dir" -DCMAKE_BUILD_TYPE="$type" "${options[@]}" >/dev/null
cmake --build "$dir" -j2
