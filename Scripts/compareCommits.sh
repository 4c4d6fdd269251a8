#!/usr/bin/env bash
# Proves that a change of the code changed no bits: builds two commits, runs the same fixed scenes
# with each, and compares every file the scenes write byte for byte (Documentation/ComparingCommits.md).
#
#   Scripts/compareCommits.sh [options] BEFORE AFTER [scene ...]
#
#   BEFORE, AFTER   commits (ids, branches, tags: anything `git rev-parse` takes)
#   scene ...       the scenes to run (default: all; --list names them)
#   --list          print the scenes and their flags, and exit
#   --keep          keep the scenes' output files (SCRATCH/runs/SCENE/COMMIT/...; removed otherwise)
#   --jobs 1|2      2 (the default on two cores or more): a scene's runs of the two commits side by
#                   side; the scenes under mpirun always one at a time
#   --ignore GLOB   a differing file whose name matches is shown but not counted as different
#                   (e.g. '*.restart' when a commit changed the restart format on purpose); repeatable
#   --scratch DIR   where the two worktrees, their builds and the runs go (default <repo>/build-compare)
#   --remove        remove the scratch folder's worktrees, builds and runs, and exit
#
# The worktrees (SCRATCH/before, SCRATCH/after) and their builds stay for the next run, which
# checks out its commits there and rebuilds only what changed; ccache makes a new tree cheap.
# Both commits are built the same way: Release, this machine's instruction set (TALUS_NATIVE=ON,
# as Scripts/build.sh), and only the drivers the chosen scenes run.
#
# Exit status: 0 every scene ran with both commits and wrote the same files; 1 a file differs or
# a scene could not run (a flag one commit lacks, a failed run, no MPI); 2 bad arguments or a
# failed build.
set -euo pipefail
# The whole script is one block, read before it runs: a checkout in this tree during a run (the
# script lives in the tree it compares) cannot change what runs.
{
here=$(cd "$(dirname "$0")" && pwd)
top=$(git -C "$here" rev-parse --show-toplevel 2>/dev/null) || top=$(cd "$here/.." && pwd)
shared=$(realpath -m "${TALUS_SHARED_DIR:-$top/../shared}")
startBed=$shared/peers/data/chute_B_flowing.data

# ---------------------------------------------------------------------------------------------
# The scenes. A scene is a driver, its flags, the ranks it runs on and, for a restart scene, the
# time of the split: the scene then runs whole to END and, in a second folder, to SPLIT and
# from its .restart file on to END; both runs of both commits must write the same files.
scenes=()
declare -A driverOf flagsOf ranksOf endOf splitOf aboutOf
scene() {  # name driver ranks end split about flags...
    scenes+=("$1")
    driverOf[$1]=$2 ranksOf[$1]=$3 endOf[$1]=$4 splitOf[$1]=$5 aboutOf[$1]=$6
    shift 6
    flagsOf[${scenes[-1]}]="$*"
}
# The benchmark at 108000 flowing spheres (6 x 6 copies of the 3000 of the developed flow): 600
# steps, two list builds, frames every 200 steps; waves of 8 and single steps, set explicitly.
benchmark="--data $startBed --nx 6 --ny 6 --output-interval 0.02 --files on --vtu off"
scene benchmark-waves PeriodicChuteBenchmark 1 0.06 0.04 \
    "108000 spheres, 600 steps in waves of 8, restarted after 400" $benchmark --wave-steps 8
scene benchmark-steps PeriodicChuteBenchmark 1 0.06 "" \
    "108000 spheres, 600 single steps" $benchmark --wave-steps 1
scene bidisperse-chute PeriodicBidisperseChute 1 6 "" \
    "3000 spheres landing and flowing, steady (any trend) at t = 3" \
    --output-interval 1.5 --sample-interval 0.5 --window 6 --tolerance 10
scene maser-chute MaserFedChute 1 12 "" \
    "maser activated at t = 2, inflow and deletion" \
    --inflow-height 3 --maser-length 10 --width 3 --chute-length 10 --earliest-activation 1 \
    --latest-activation 2 --sample-interval 0.5 --output-interval 1
scene drum RotatingDrum 1 40 "" \
    "40 spheres and ellipsoids filled in rounds, turning from t = 21" \
    --radius 4 --length 4 --particles 40 --output-interval 5 --sample-interval 2
scene ellipsoids SettlingEllipsoids 1 3 "" \
    "500 ellipsoids settling in a box" --output-interval 0.5
small="--large 200 --small 400 --length 10 --width 5 --sample-interval 0.1 --window 5 --tolerance 10 --output-interval 0.25"
scene restart-1rank PeriodicBidisperseChute 1 2 1 \
    "600 spheres, restarted at t = 1 after steady at 0.5" $small
scene restart-maser MaserFedChute 1 4 1.5 \
    "maser saved before its activation, which follows the restart" \
    --inflow-height 3 --maser-length 10 --width 3 --chute-length 10 --earliest-activation 1 \
    --latest-activation 100 --window 4 --tolerance 10 --sample-interval 0.5 --output-interval 0.5
scene restart-2ranks PeriodicBidisperseChute 2 2 1 \
    "restart-1rank on 2 ranks, forces summed in id order" $small --id-ordered-sums on

# ---------------------------------------------------------------------------------------------
usage() { sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 2; }
fail() { echo "compareCommits.sh: $*" >&2; exit 2; }

listScenes() {
    for s in "${scenes[@]}"; do
        local how="${ranksOf[$s]} rank$([ "${ranksOf[$s]}" = 1 ] || echo s), to t = ${endOf[$s]}"
        [ -n "${splitOf[$s]}" ] && how+=", restarted at ${splitOf[$s]}"
        printf '%-17s %s: %s\n%18s(%s)\n%18s%s\n' "$s" "${driverOf[$s]}" "${aboutOf[$s]}" "" "$how" "" \
            "${flagsOf[$s]}"
    done
}

keep=0 scratch=$top/build-compare remove=0 ignored=() positional=()
jobs=$([ "$(nproc)" -ge 2 ] && echo 2 || echo 1)
while [ $# -gt 0 ]; do
    case $1 in
        --list) listScenes; exit 0 ;;
        --keep) keep=1 ;;
        --jobs) [ $# -ge 2 ] && [[ $2 =~ ^[12]$ ]] || fail "--jobs takes 1 or 2, got '${2:-}'"; jobs=$2; shift ;;
        --ignore) [ $# -ge 2 ] || fail "--ignore takes a file name pattern"; ignored+=("$2"); shift ;;
        --scratch) [ $# -ge 2 ] || fail "--scratch takes a folder"; scratch=$(realpath -m "$2"); shift ;;
        --remove) remove=1 ;;
        -h|--help) usage ;;
        -*) fail "unknown option $1 (--help lists them)" ;;
        *) positional+=("$1") ;;
    esac
    shift
done

removeTree() {  # a worktree of ours: unregistered and deleted
    git -C "$top" worktree remove --force "$1" 2>/dev/null || rm -rf "$1"
    git -C "$top" worktree prune
}
if [ $remove = 1 ]; then
    for slot in before after; do removeTree "$scratch/$slot"; done
    rm -rf "$scratch/runs" "$scratch"/*.log
    rmdir "$scratch" 2>/dev/null || true
    echo "removed the worktrees, builds and runs under $scratch"
    exit 0
fi

[ ${#positional[@]} -ge 2 ] || usage
commitOf=()
for k in 0 1; do
    commitOf[k]=$(git -C "$top" rev-parse --verify --quiet "${positional[k]}^{commit}") ||
        fail "${positional[k]} is not a commit of $top"
done
chosen=("${positional[@]:2}")
[ ${#chosen[@]} -gt 0 ] || chosen=("${scenes[@]}")
for s in "${chosen[@]}"; do
    [ -n "${driverOf[$s]:-}" ] || fail "no scene '$s' (--list names them)"
done

milliseconds() { echo $(($(date +%s%N) / 1000000)); }
seconds() { awk -v ms="$1" 'BEGIN { printf "%.1f", ms / 1000 }'; }
started=$(milliseconds)
slots=(before after)
mkdir -p "$scratch"

# ---------------------------------------------------------------------------------------------
# The two builds.
targets=()
for s in "${chosen[@]}"; do
    [[ " ${targets[*]} " == *" ${driverOf[$s]} "* ]] || targets+=("${driverOf[$s]}")
done
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

prepareTree() {  # slot commit: SCRATCH/slot is a worktree at the commit (made or reused)
    local tree=$scratch/$1
    git -C "$top" worktree prune
    if [ -e "$tree/.git" ] && [ "$(git -C "$tree" rev-parse --show-toplevel 2>/dev/null)" = "$tree" ]; then
        git -C "$tree" checkout --quiet --force --detach "$2"
        git -C "$tree" clean -fdq  # untracked files; the ignored build folder stays
    else
        rm -rf "$tree"
        git -C "$top" worktree add --quiet --detach "$tree" "$2"
    fi
}

declare -A driverPath
buildCommit() {  # slot commit
    local slot=$1 tree=$scratch/$1 t0 log=$scratch/$1.build.log
    t0=$(milliseconds)
    echo "building $slot ($(git -C "$top" log -1 --format='%h %s' "$2" | cut -c1-80)) in $tree/build: ${targets[*]}"
    prepareTree "$slot" "$2"
    cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" -DTALUS_NATIVE=ON \
        "-DCMAKE_CXX_FLAGS=" > "$log" 2>&1 || { tail -20 "$log"; fail "configuring $slot failed ($log)"; }
    if grep -q "Manually-specified variables were not used" "$log"; then
        echo "  warning: $slot's CMakeLists do not know $(grep -A3 'Manually-specified' "$log" | grep -o 'TALUS_[A-Z_]*' | sort -u | tr '\n' ' ')- it is built with its own default instruction set"
    fi
    cmake --build "$tree/build" -j2 --target "${targets[@]}" >> "$log" 2>&1 ||
        { tail -20 "$log"; fail "building $slot failed ($log)"; }
    for name in "${targets[@]}"; do
        local path
        path=$(find "$tree/build" -name CMakeFiles -prune -o -type f -perm -u+x -name "$name" -print -quit)
        [ -n "$path" ] || fail "$slot built no program $name ($log)"
        driverPath[$slot.$name]=$path
    done
    echo "  built $slot in $(seconds $(($(milliseconds) - t0))) s"
}
buildCommit before "${commitOf[0]}"
buildCommit after "${commitOf[1]}"
buildSeconds=$(seconds $(($(milliseconds) - started)))

# ---------------------------------------------------------------------------------------------
# Running the scenes.
mpirun=(env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl=self,vader
        mpirun --oversubscribe -np 2)
runs=$scratch/runs
rm -rf "$runs"

# The flags of scene $1 that the driver of commit slot $2 does not list in its --help.
missingFlags() {
    local help flag missing=()
    help=$("${driverPath[$2.${driverOf[$1]}]}" --help 2>&1 || true)
    for flag in ${flagsOf[$1]} --end-time --progress-interval $([ -n "${splitOf[$1]}" ] && echo --restart); do
        [[ $flag == --* ]] || continue
        grep -q -- "^ *$flag " <<< "$help" || missing+=("$flag")
    done
    echo "${missing[*]}"
}

# Why scene $1 cannot run under mpirun with the drivers built, or nothing.
noMpi() {
    [ "${ranksOf[$1]}" = 1 ] && return
    command -v mpirun >/dev/null || { echo "no mpirun on this machine"; return; }
    for slot in "${slots[@]}"; do
        # (not `ldd | grep -q`: grep's early exit fails ldd on a closed pipe, and pipefail the test)
        [[ $(ldd "${driverPath[$slot.${driverOf[$1]}]}") == *libmpi* ]] || { echo "$slot is built without MPI"; return; }
    done
}

# Runs scene $1 with the build of slot $2 in RUNS/scene/slot: in files/, or whole/ and split/
# for a restart scene. The driver's messages go to run.log there; the status is the driver's.
runScene() {
    local scene=$1 slot=$2 out=$runs/$1/$2 t0 flags launch=() status=0
    local driver=${driverPath[$2.${driverOf[$1]}]} quiet=(--progress-interval 1000)
    read -r -a flags <<< "${flagsOf[$scene]}"
    [ "${ranksOf[$scene]}" = 1 ] || launch=("${mpirun[@]}")
    t0=$(milliseconds)
    if [ -z "${splitOf[$scene]}" ]; then
        mkdir -p "$out/files"
        (cd "$out/files" && "${launch[@]}" "$driver" "${flags[@]}" --end-time "${endOf[$scene]}" "${quiet[@]}") \
            > "$out/run.log" 2>&1 || status=$?
    else
        mkdir -p "$out/whole" "$out/split"
        {
            (cd "$out/whole" && "${launch[@]}" "$driver" "${flags[@]}" --end-time "${endOf[$scene]}" "${quiet[@]}") &&
            (cd "$out/split" && "${launch[@]}" "$driver" "${flags[@]}" --end-time "${splitOf[$scene]}" "${quiet[@]}") &&
            (cd "$out/split" && "${launch[@]}" "$driver" --restart "$(basename "$driver").restart" \
                --end-time "${endOf[$scene]}" "${quiet[@]}")
        } > "$out/run.log" 2>&1 || status=$?
    fi
    seconds $(($(milliseconds) - t0)) > "$out/seconds"
    return $status
}

# Compares the files of folder $1 (labelled $2) with those of $3 (labelled $4); adds to the
# scene's counts compared, equal, different.
compareFolders() {
    local name
    for name in $( (ls "$1"; ls "$3") | sort -u); do
        compared=$((compared + 1))
        local a=$1/$name b=$3/$name
        if [ -f "$a" ] && [ -f "$b" ] && cmp -s "$a" "$b"; then
            equal=$((equal + 1))
            continue
        fi
        local excused=""
        for pattern in "${ignored[@]}"; do
            # shellcheck disable=SC2053  # a glob on purpose
            [[ $name == $pattern ]] && excused=" (ignored: --ignore '$pattern')"
        done
        [ -n "$excused" ] && ignoredCount=$((ignoredCount + 1)) || different=$((different + 1))
        if [ ! -f "$a" ] || [ ! -f "$b" ]; then
            echo "  $name: only in $([ -f "$a" ] && echo "$2" || echo "$4")$excused"
        else
            echo "  $name differs, $2 against $4$excused:"
            python3 "$here/compareOutputFiles.py" "$a" "$b" "$2" "$4" || true
        fi
    done
}

rows=() status=0 k=0
for scene in "${chosen[@]}"; do
    k=$((k + 1))
    t0=$(milliseconds)
    compared=0 equal=0 different=0 ignoredCount=0 note=""
    echo "[$k/${#chosen[@]}] $scene: ${aboutOf[$scene]} (${driverOf[$scene]}, ${ranksOf[$scene]} rank$([ "${ranksOf[$scene]}" = 1 ] || echo s))"
    reason=""
    [[ ${driverOf[$scene]} != PeriodicChuteBenchmark || -f $startBed ]] ||
        reason="no start file $startBed (set TALUS_SHARED_DIR)"
    [ -n "$reason" ] || reason=$(noMpi "$scene")
    if [ -z "$reason" ]; then
        for slot in "${slots[@]}"; do
            missing=$(missingFlags "$scene" "$slot")
            [ -z "$missing" ] || reason+="${reason:+; }$slot's ${driverOf[$scene]} has no $missing"
        done
    fi
    if [ -z "$reason" ]; then
        failed=()
        if [ "$jobs" = 2 ] && [ "${ranksOf[$scene]}" = 1 ]; then
            runScene "$scene" before & first=$!
            runScene "$scene" after & second=$!
            wait $first || failed+=(before)
            wait $second || failed+=(after)
        else
            for slot in "${slots[@]}"; do runScene "$scene" "$slot" || failed+=("$slot"); done
        fi
        echo "  ran in $(cat "$runs/$scene/before/seconds") s (before) and $(cat "$runs/$scene/after/seconds") s (after)"
        for slot in "${failed[@]}"; do
            echo "  the run of $slot failed; the end of $runs/$scene/$slot/run.log:"
            tail -5 "$runs/$scene/$slot/run.log" | sed 's/^/    /'
            reason+="${reason:+; }$slot's run failed"
            keep=1
        done
    fi
    if [ -n "$reason" ]; then
        echo "  NOT RUN: $reason"
        note="not run: $reason"
        status=1
    elif [ -z "${splitOf[$scene]}" ]; then
        compareFolders "$runs/$scene/before/files" before "$runs/$scene/after/files" after
    else
        for other in after/whole after/split before/split; do
            compareFolders "$runs/$scene/before/whole" before/whole "$runs/$scene/$other" "$other"
        done
    fi
    [ -z "$note" ] && [ $different -gt 0 ] && note="DIFFERENT" && status=1
    [ -z "$note" ] && note="equal"
    [ $ignoredCount -gt 0 ] && note+=" ($ignoredCount differing, ignored)"
    sceneSeconds=$(seconds $(($(milliseconds) - t0)))
    echo "  $scene: $equal of $compared equal, $different different: $note ($sceneSeconds s)"
    rows+=("$(printf '%-17s %8s %6s %10s %8s  %s' "$scene" "$compared" "$equal" "$different" "$sceneSeconds" "$note")")
done

[ $keep = 1 ] || rm -rf "$runs"
echo
echo "before: ${commitOf[0]:0:12} $(git -C "$top" log -1 --format=%s "${commitOf[0]}" | cut -c1-70)"
echo "after:  ${commitOf[1]:0:12} $(git -C "$top" log -1 --format=%s "${commitOf[1]}" | cut -c1-70)"
printf '%-17s %8s %6s %10s %8s  %s\n' scene compared equal different seconds result
printf '%s\n' "${rows[@]}"
echo "builds $buildSeconds s; total $(seconds $(($(milliseconds) - started))) s$([ $keep = 1 ] && echo "; outputs kept in $runs")"
[ $status = 0 ] && echo "all files equal to the bit" || echo "NOT all files equal (exit status 1)"
exit $status
}
