#!/usr/bin/env bash
# Installs a Talus build tree into a prefix (cmake --install) and builds and runs the study in
# OutOfTreeDriver/ against the installed package alone, as a user who never saw the source tree
# would. Fails when the package is incomplete (a header, the CMake files), when its interface
# carries an instruction set (-march: the installed library must not tie the programs built
# against it to one processor), or when the driver does not build, run or find its result.
#   installAndBuild.sh BUILD_TREE WORK_DIR CXX "CXX_FLAGS" "LINK_FLAGS" [LAUNCHER]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
buildTree=$1 work=$2 cxx=$3 cxxFlags=$4 linkFlags=$5 launcher=${6:-}
prefix=$work/prefix
rm -rf "$prefix" "$work/driver"
cmake --install "$buildTree" --prefix "$prefix" > "$work/install.log"
test -f "$prefix/include/talus/Simulation.h" || { echo "installAndBuild: no include/talus/Simulation.h"; exit 1; }
config=$(find "$prefix" -name TalusConfig.cmake)
test -n "$config" || { echo "installAndBuild: no TalusConfig.cmake under $prefix"; exit 1; }
if grep -n -- '-march' "$(dirname "$config")"/Talus*.cmake; then
  echo "installAndBuild: the installed package passes an instruction set on"; exit 1
fi
options=(-DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release
         -DCMAKE_CXX_FLAGS="$cxxFlags" -DCMAKE_EXE_LINKER_FLAGS="$linkFlags")
if [ -n "$launcher" ]; then options+=(-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"); fi
cmake -S "$here/OutOfTreeDriver" -B "$work/driver" "${options[@]}" > "$work/configure.log"
cmake --build "$work/driver" > "$work/build.log"
cd "$work" && driver/RestingSphere --files off
