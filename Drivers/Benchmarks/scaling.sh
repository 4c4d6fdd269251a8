#!/usr/bin/env bash
# Time per particle-step of the periodic chute benchmark from 3000 to about 10^6 flowing spheres
# (the start bed replicated nx x ny times), one core, from the settled bed and from the developed
# flow. Writes scaling-settled.csv, scaling-flowing.csv and scaling.png in the current folder.
#     Drivers/Benchmarks/scaling.sh [build-dir] [repeats] [steps]
# Flags for every run of the benchmark in TALUS_BENCHMARK_FLAGS, e.g. "--wave-steps 8 --wave-strip
# 32" for several steps per pass (Documentation/TimeSkewing.md).
#
# Every size runs the same number of steps, n and 2n (default n = 200), from the same start, so
# that every size does the same physics: the bed starts to flow and dilates, and a run of 5000
# steps of the small scene ends with a quarter fewer contacts per
# particle than a run of 200 steps of the large one (Documentation/Performance.md "Scaling and
# memory"). Each run is repeated `repeats` times (default 3) and the fastest kept (the host's
# speed changes by a third from minute to minute). ns_per_particle_step is the whole loop of the
# longer run over its particle-steps; marginal_ns_per_particle_step is the difference of the two
# over the n extra steps: the cost of a step alone, without what the loop pays once (choosing the
# sweep's form by timing it, the first near list). contacts_per_flowing is the number of contacts
# at the end of the longer run over the flowing particles: the work a step does per particle.
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$top/build}
repeats=${2:-3}
steps=${3:-200}
talus="$build/Drivers/Benchmarks/PeriodicChuteBenchmark"
data=${TALUS_SHARED_DIR:-$top/../shared}/peers/data
[[ -d $data ]] || { echo "scaling.sh: no $data (set TALUS_SHARED_DIR)" >&2; exit 1; }
field() { awk -v key="$1" '{for (i = 1; i < NF; ++i) if ($i == key) print $(i + 1)}'; }
run() {  # copies steps start: the closing line of the fastest of `repeats` runs
    local k line best="" fastest=""
    for ((k = 0; k < repeats; ++k)); do
        # shellcheck disable=SC2086 # (the flags are words)
        line=$("$talus" --nx "$1" --ny "$1" --data "$data/chute_B_$3.data" ${TALUS_BENCHMARK_FLAGS:-} \
            --end-time "$(awk -v n="$2" 'BEGIN {print n * 1e-4}')" --progress-interval 1e9 | grep '^benchmark:')
        local wall=$(echo "$line" | field wall)
        if [[ -z $fastest ]] || awk -v a="$wall" -v b="$fastest" 'BEGIN {exit !(a < b)}'; then
            fastest=$wall best=$line
        fi
    done
    echo "$best"
}
for start in settled flowing; do
    csv=scaling-$start.csv
    echo "flowing,steps,wall_s,particle_steps_per_s,ns_per_particle_step,bytes_per_particle,marginal_ns_per_particle_step,contacts_per_flowing" > "$csv"
    for copies in 1 2 6 18; do  # 3000, 12000, 108000 and 972000 flowing spheres
        short=$(run "$copies" "$steps" "$start")
        long=$(run "$copies" $((2 * steps)) "$start")
        echo "$start: $long"
        awk -v n="$steps" -v flowing="$(echo "$long" | field flowing)" -v steps="$(echo "$long" | field steps)" \
            -v wall="$(echo "$long" | field wall)" -v memory="$(echo "$long" | field memory)" \
            -v contacts="$(echo "$long" | field contacts)" -v shortWall="$(echo "$short" | field wall)" 'BEGIN {
            rate = steps * flowing / wall
            printf "%s,%s,%s,%.4g,%.2f,%s,%.2f,%.3f\n", flowing, steps, wall, rate, 1e9 / rate, memory,
                   1e9 * (wall - shortWall) / (n * flowing), contacts / flowing
        }' >> "$csv"
        tail -1 "$csv"
    done
done
/usr/bin/python3 "$top/Tools/Plot/plotScaling.py" scaling-settled.csv scaling-flowing.csv scaling.png
