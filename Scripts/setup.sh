#!/usr/bin/env bash
# Installs every Debian package Talus needs to build, test and plot (README.md, Documentation/Architecture.md).
# Safe to run again; needs root (or sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
packages=(
  g++ cmake make ccache
  libeigen3-dev             # Kernel/Math
  libhdf5-dev               # optional HDF5 output (TALUS_WITH_HDF5)
  libopenmpi-dev openmpi-bin # optional MPI domain split (TALUS_WITH_MPI)
  libgtest-dev libgmock-dev # UnitTests
  libbenchmark-dev          # Drivers/Benchmarks micro-benchmarks
  libfmt-dev
  python3 python3-numpy python3-matplotlib python3-h5py  # Tools/Plot
  python3-scipy             # Tools/Calibration (the fit)
  python3-vtk9              # VTK's readers: SelfTests/checkVtu.py (.vtu frames), Tools/CG/Tests/checkVtkOutput.py (.vti fields)
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
