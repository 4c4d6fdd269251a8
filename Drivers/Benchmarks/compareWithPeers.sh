#!/usr/bin/env bash
# Talus against LAMMPS and LIGGGHTS on the periodic bidisperse chute (shared/peers, scene B), on
# one core: first that the physics agrees, then the speed as ratios of interleaved runs.
#
#   Drivers/Benchmarks/compareWithPeers.sh [--steps N] [--rounds R] [--build DIR] [--start settled|flowing]
#
# Needs the Debian packages lammps and liggghts (installed here with apt-get when missing, as
# root). Prints Markdown tables (Documentation/Performance.md quotes them).
set -euo pipefail
top=$(cd "$(dirname "$0")/../.." && pwd)
steps=50000 rounds=3 build="$top/build" start=settled
while [ $# -gt 0 ]; do
  case $1 in
    --steps) steps=$2; shift 2;;
    --rounds) rounds=$2; shift 2;;
    --build) build=$2; shift 2;;
    --start) start=$2; shift 2;;
    *) echo "compareWithPeers.sh: unknown argument '$1' (see the header of this script)" >&2; exit 2;;
  esac
done
shared=${TALUS_SHARED_DIR:-$top/../shared}
[ -d "$shared/peers" ] || { echo "compareWithPeers.sh: no $shared/peers" >&2; exit 1; }
if ! command -v lmp >/dev/null || ! command -v liggghts >/dev/null; then
  echo "installing lammps and liggghts (Debian packages)"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends lammps liggghts openmpi-bin >/dev/null
fi
talus="$build/Drivers/Benchmarks/PeriodicChuteBenchmark"
collision="$build/Drivers/Demos/TwoParticleCollision"
[ -x "$talus" ] || { echo "compareWithPeers.sh: build Talus first (Scripts/build.sh)" >&2; exit 1; }
work=$(mktemp -d /tmp/talus-peers.XXXXXX)
cp -r "$shared/peers/." "$work/"
mkdir -p "$work/runs"
data="$work/data/chute_B_$start.data"
echo "work folder: $work; start file: $data; $steps steps of dt = 1e-4; $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"

# ---- physics 1: two-particle collision (scene A, d = 1, kn = 2e5, gn = 25, m* = 1/2)
(cd "$work/A_collision" && lmp -in in.collision.lammps -var out ../runs/A_lammps.txt -log none >/dev/null &&
  liggghts -in in.collision.liggghts -var abs 0 -var out ../runs/A_liggghts.txt -log none >/dev/null)
echo
echo "## Two-particle collision (analytic tc = 4.971179e-3, e = 0.883133)"
echo
python3 "$work/tools/analyze_collision.py" "$work/runs/A_lammps.txt" "$work/runs/A_liggghts.txt" | tail -2
for mode in 0 1; do
  "$collision" --restitution 0.883133 --collision-time 4.971179e-3 --dt 1e-4 --plain-verlet $mode --files off |
    awk -v m=$mode '/^restitution/ {e=$3} /^collision time/ {t=$4} END {printf "Talus%s  tc %s  e %s\n", (m ? " --plain-verlet 1" : ""), t, e}' | tr -d ','
done

# ---- physics 2: mean downslope velocity after the same time, against the scatter of trajectories
echo
echo "## Mean downslope velocity of the flowing spheres after $steps steps"
echo
meanvx_lammps() { awk '/^Loop time/ {print prev} {prev=$4}' "$1" | tail -1; }
(cd "$work/B_chute" &&
  lmp -in in.chute.lammps -var data "$data" -var out ../runs/P_lammps -var dumpevery 0 -var nsteps $steps -var nfirst $steps -log ../runs/P_lammps.log >/dev/null &&
  liggghts -in in.chute.liggghts -var data "$data" -var out ../runs/P_liggghts -var dumpevery 0 -var nsteps $steps -var nfirst $steps -log ../runs/P_liggghts.log >/dev/null)
echo "| code | mean vx |"
echo "|---|---|"
echo "| LAMMPS | $(meanvx_lammps "$work/runs/P_lammps.log") |"
echo "| LIGGGHTS | $(meanvx_lammps "$work/runs/P_liggghts.log") |"
endtime=$(awk -v n=$steps 'BEGIN {printf "%.10g", n * 1e-4}')
for mode in 0 1; do
  values=""
  for seed in 1 2 3 4; do
    v=$("$talus" --data "$data" --end-time "$endtime" --perturbation 1e-6 --seed $seed --plain-verlet $mode --progress-interval 1e9 |
        sed -n 's/.*mean vx \([^ ]*\).*/\1/p')
    values="$values $v"
  done
  echo "$values" | awk -v m=$mode '{n=NF; for(i=1;i<=n;i++){s+=$i; q+=$i*$i} mean=s/n; sd=sqrt((q-n*mean*mean)/(n-1));
    printf "| Talus%s, 4 trajectories (start velocities +-1e-6) | %.6g +- %.2g (%s) |\n", (m ? " --plain-verlet 1" : ""), mean, sd, $0}'
done

# ---- speed: interleaved rounds, ratios per round
echo
echo "## Speed: mobile particle-steps per second, $steps steps, one core, interleaved rounds"
echo
echo "| round | LAMMPS | LIGGGHTS | Talus | Talus/LAMMPS | Talus/LIGGGHTS |"
echo "|---|---|---|---|---|---|"
# The peers' logs give the loop time; the number of mobile particles is Talus's count of the same file.
rate_peer() { awk -v n=$steps -v m="$2" '/^Loop time of/ {t+=$4} END {printf "%.4g", m * n / t}' "$1"; }
for r in $(seq 1 "$rounds"); do
  (cd "$work/B_chute" && lmp -in in.chute.lammps -var data "$data" -var out ../runs/S_lammps_$r -var dumpevery 0 -var nsteps $steps -var nfirst $steps -log ../runs/S_lammps_$r.log >/dev/null)
  (cd "$work/B_chute" && liggghts -in in.chute.liggghts -var data "$data" -var out ../runs/S_liggghts_$r -var dumpevery 0 -var nsteps $steps -var nfirst $steps -log ../runs/S_liggghts_$r.log >/dev/null)
  line=$("$talus" --data "$data" --end-time "$endtime" --progress-interval 1e9 | grep '^benchmark:')
  tal=$(echo "$line" | sed -n 's/.*wall [^ ]* s  \([^ ]*\) particle-steps.*/\1/p')
  flowing=$(echo "$line" | sed -n 's/.*flowing \([0-9]*\).*/\1/p')
  lam=$(rate_peer "$work/runs/S_lammps_$r.log" "$flowing"); lig=$(rate_peer "$work/runs/S_liggghts_$r.log" "$flowing")
  awk -v r=$r -v a=$lam -v b=$lig -v c=$tal 'BEGIN {printf "| %d | %.4g | %.4g | %.4g | %.2f | %.2f |\n", r, a, b, c, c/a, c/b}'
done
echo
echo "(logs in $work/runs)"
