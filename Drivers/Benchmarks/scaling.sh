#!/usr/bin/env bash
# Time per particle-step of the periodic chute benchmark from 3000 to about 10^6 flowing spheres
# (the start bed replicated nx x ny times), one core. Writes scaling.csv and scaling.png in the
# current folder.   Drivers/Benchmarks/scaling.sh [build-dir]
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build}
talus="$build/Drivers/Benchmarks/PeriodicChuteBenchmark"
echo "flowing,steps,wall_s,particle_steps_per_s,ns_per_particle_step,bytes_per_particle" > scaling.csv
# copies per side and steps, chosen for a few seconds each
for spec in "1 5000" "2 2000" "6 200" "18 50"; do
  set -- $spec
  line=$("$talus" --nx "$1" --ny "$1" --end-time "$(awk -v n="$2" 'BEGIN {print n * 1e-4}')" --progress-interval 1e9 | grep '^benchmark:')
  echo "$line"
  echo "$line" | awk '{for (i = 1; i <= NF; ++i) v[$i] = $(i + 1); print v["flowing"] "," v["steps"] "," v["wall"] "," $9 "," 1e9 / $9 "," v["memory"]}' >> scaling.csv
done
/usr/bin/python3 "$top/Tools/Plot/plotScaling.py" scaling.csv scaling.png
