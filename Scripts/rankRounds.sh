#!/usr/bin/env bash
# 2 ranks against 1 on the benchmark chute (Documentation/Parallel.md, "Speed"), in interleaved
# rounds: every configuration in turn, round after round, so that the host's slow spells fall on
# all of them alike. Configurations: this build on 1 rank on the first core and on the second
# (the cores of a virtual machine need not be equally fast; the speedup is taken against the
# faster of the two), on 2 ranks, on 2 ranks with Open MPI's
# single-copy transport (the MPI default that Talus turns off: Parallel/MpiCommunicator.cc), and
# (if given) another build on 2 ranks; the order turns by one each round. Prints a line per run (round, ranks, build, load average, wall seconds of the time loop,
# communication shares, as Documentation/Performance/ranks-3000-idle.txt has them), then per
# configuration the best and the median, the median speedup of the rounds, and the ratios of the medians.
# -n: the runs at this niceness (nice -n; below 0 needs root): on a host shared with other jobs,
# -10 keeps the ranks from waiting for the others' turns, most of what a loaded host measures.
#   Scripts/rankRounds.sh [-r rounds] [-t end-time] [-d data] [-n niceness] BUILD [OTHER-BUILD]
# e.g. Scripts/rankRounds.sh -r 8 build ../before/build   (scene B, flowing start, 10000 steps)
set -euo pipefail
rounds=8 endTime=1 niceness=0 data=${TALUS_SHARED_DIR:-$(cd "$(dirname "$0")/../.." && pwd)/shared}/peers/data/chute_B_flowing.data
while getopts "r:t:d:n:" option; do
  case $option in
    n) niceness=$OPTARG ;;
    r) rounds=$OPTARG ;;
    t) endTime=$OPTARG ;;
    d) data=$OPTARG ;;
    *) sed -n 2,12p "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || { sed -n 2,12p "$0" >&2; exit 2; }
[ -f "$data" ] || { echo "rankRounds.sh: no start file $data (-d)" >&2; exit 2; }
program() { echo "$1/Drivers/Benchmarks/PeriodicChuteBenchmark"; }
for build in "$@"; do
  [ -x "$(program "$build")" ] || { echo "rankRounds.sh: no benchmark in $build (build it first)" >&2; exit 2; }
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
# label ranks build extra-flags
configs=("1rank 1 $1" "1rank-second-core 1 $1" "2ranks 2 $1" "2ranks-single-copy 2 $1")
[ $# -ge 2 ] && configs+=("2ranks-other-build 2 $2")
field() { awk -v key="$2" '{for (i = 1; i < NF; ++i) if ($i == key) print $(i + 1)}' <<< "$1" | tr -d '%,)'; }
results=$(mktemp)
trap 'rm -f "$results"' EXIT
for round in $(seq "$rounds"); do
  n=${#configs[@]}
  for k in $(seq 0 $((n - 1))); do
    set -- ${configs[$(((k + round - 1) % n))]}
    label=$1 ranks=$2 build=$3
    shift 3
    load=$(cut -d' ' -f1 /proc/loadavg)
    copy=none
    [ "$label" = 2ranks-single-copy ] && copy=cma
    binding=(--bind-to core)
    [ "$label" = 1rank-second-core ] && binding=(--cpu-list 1 --bind-to cpu-list:ordered)
    line=$(OMPI_MCA_btl_vader_single_copy_mechanism=$copy nice -n "$niceness" mpirun "${binding[@]}" -np "$ranks" "$(program "$build")" --data "$data" --end-time "$endTime" \
             --progress-interval 1e9 "$@" | grep '^benchmark:')
    echo "round $round ranks $ranks build $label load $load wall $(field "$line" wall) comm $(field "$line" communication)%" \
         "exch $(field "$line" exchange)% agree $(field "$line" agreement)%" | tee -a "$results"
  done
done
# Best and median of each configuration (walls sorted), then the ratios of the medians.
declare -A median
for config in "${configs[@]}"; do
  set -- $config
  read -r best middle count < <(awk -v c="$1" '$6 == c {print $10}' "$results" | sort -g |
    awk '{t[NR] = $1} END {print t[1], (NR % 2 ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2), NR}')
  median[$1]=$middle
  printf "%-20s best %.3f s  median %.3f s  (%d runs)\n" "$1" "$best" "$middle" "$count"
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN {printf "%.2f", a / b}'; }
serial=$(awk -v a="${median[1rank]}" -v b="${median[1rank-second-core]}" 'BEGIN {print (a < b ? a : b)}')
# The speedup in each round (the faster single-core run of the round against its 2-rank run): a
# slow spell of the host then falls on both sides of a ratio.
pairs=$(awk '{wall[$2 " " $6] = $10} END {for (key in wall) {split(key, k, " "); if (k[2] != "2ranks") continue
          r = k[1]; one = wall[r " 1rank"]; other = wall[r " 1rank-second-core"]
          if (other != "" && other < one) one = other; if (one != "") print one / wall[key]}}' "$results" | sort -g |
        awk '{s[NR] = $1} END {printf "%.2f (%.2f-%.2f over %d rounds)", (NR % 2 ? s[(NR + 1) / 2] : (s[NR / 2] + s[NR / 2 + 1]) / 2), s[1], s[NR], NR}')
echo "speedup per round: median $pairs"
echo -n "ratios of the medians: 1 rank (the faster core) / 2 ranks $(ratio "$serial" "${median[2ranks]}") (the speedup);" \
        "buffered / single-copy transport $(ratio "${median[2ranks]}" "${median[2ranks-single-copy]}")"
[ -n "${median[2ranks-other-build]:-}" ] &&
  echo -n "; other build / this build on 2 ranks $(ratio "${median[2ranks-other-build]}" "${median[2ranks]}")"
echo
