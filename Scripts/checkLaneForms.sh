#!/usr/bin/env bash
# Compiles the passes written in lanes by hand for every instruction set they have a form for,
# whatever this machine has: -march=native builds only the form of the machine at hand (AVX-512:
# Math/EightParticleLanes.h; AVX2 without it: Math/FourParticleLanes.h; neither: the loops), so a
# mistake in another form would otherwise go unseen until someone builds on such a processor.
# Syntax and warnings only (-Werror); the tests run the form of the machine they run on.
#   Scripts/checkLaneForms.sh
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
# The sources with the lanes, and the unit tests that include their headers.
sources=(Kernel/Particles/DriftPass.cc UnitTests/PairSweepTest.cc UnitTests/VelocityVerletTest.cc UnitTests/DriftPassTest.cc)
for arch in x86-64 x86-64-v3 icelake-server; do  # none, AVX2, AVX-512
  for source in "${sources[@]}"; do
    g++ -std=c++20 -O2 -march="$arch" -Wall -Wextra -Wpedantic -Werror -fno-math-errno -fno-trapping-math \
      -DEIGEN_DONT_VECTORIZE -isystem /usr/include/eigen3 -I "$top/Kernel" -I "$top/UnitTests" \
      -fsyntax-only "$top/$source"
  done
  echo "checkLaneForms: -march=$arch compiles"
done
