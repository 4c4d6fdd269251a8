#!/usr/bin/env bash
# The lane forms of the passes written by hand (Math/EightParticleLanes.h: AVX-512;
# Math/FourParticleLanes.h: AVX2 with FMA; otherwise the scalar loops), as the compiler's own
# macros decide them for an instruction set.
#   Scripts/laneForms.sh MARCH         the form a build for -march=MARCH compiles (native: this machine's)
#   Scripts/laneForms.sh second-march  the -march of the best form this machine runs after its own
set -euo pipefail
form() {
  local macros
  macros=$(g++ -march="$1" -dM -E -x c++ /dev/null)
  if grep -q __AVX512F__ <<<"$macros" && grep -q __AVX512BW__ <<<"$macros" && grep -q __AVX512VL__ <<<"$macros" \
     && grep -q __BMI2__ <<<"$macros"; then
    echo "AVX-512 (eight particles)"
  elif grep -q __AVX2__ <<<"$macros" && grep -q __FMA__ <<<"$macros"; then
    echo "AVX2 (four particles)"
  else
    echo "none (scalar loops)"
  fi
}
case "${1:?usage: laneForms.sh MARCH|second-march}" in
  second-march)
    case "$(form native)" in
      AVX-512*) echo x86-64-v3 ;;
      *) echo x86-64 ;;
    esac ;;
  *) form "$1" ;;
esac
