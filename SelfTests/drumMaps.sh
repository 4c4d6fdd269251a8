#!/bin/sh
# Tools/Drum/plotDrumMaps.py on two tiny drums (Documentation/Drums/RotatingDrum.md, "The sweep"):
# talus-cg's time-averaged fields in (x, z) of a mixed drum (R = 2) and of a drum of spheres; the
# map of the spheres' drum must read a sphere fraction of 1 in every filled cell, the mixed one's
# must lie in (0, 1) and span both kinds' excess; a bad aspect ratio is refused by name.
#   drumMaps.sh RotatingDrum talus-cg plotDrumMaps.py
set -eu
driver=$1
cg=$2
maps=$3
for kind in mixed spheres; do
  fraction=0.5
  [ $kind = spheres ] && fraction=1
  mkdir -p $kind
  (cd $kind && "$driver" --radius 4 --length 4 --particles 40 --sphere-fraction $fraction --end-time 30 \
     --output-interval 1 --vtu off --fstat off > run.log 2>&1) || { cat $kind/run.log; echo "FAIL: the $kind run"; exit 1; }
  "$cg" $kind/RotatingDrum --coordinates XZ --time-average --time-min 25 --fixed exclude -w 1 -n 16 16 \
    -x -4 4 -z -4 4 --stress off -o $kind.cg.csv > $kind.cg.log 2>&1 || { cat $kind.cg.log; exit 1; }
done
/usr/bin/python3 "$maps" --run mixed/RotatingDrum mixed.cg.csv 2 --run spheres/RotatingDrum spheres.cg.csv 1 \
  -o maps.png > maps.log 2>&1 || { cat maps.log; echo "FAIL: the maps"; exit 1; }
cat maps.log
[ -s maps.png ] || { echo "FAIL: no maps.png"; exit 1; }
awk '/^R = 1:/ { if ($13 != "1.0000" || $15 != "1.0000" || $17 < 10) { print "FAIL: the spheres drum maps " $0; exit 1 } ones = 1 }
     /^R = 2:/ { if (!($13 >= 0 && $13 < 0.5 && $15 > 0.5 && $15 <= 1 && $17 >= 10)) { print "FAIL: the mixed drum maps " $0; exit 1 } mixed = 1 }
     END { if (!(ones && mixed)) { print "FAIL: a run not mapped"; exit 1 } }' maps.log
if /usr/bin/python3 "$maps" --run mixed/RotatingDrum mixed.cg.csv 0.5 -o bad.png > bad.log 2>&1; then
  echo "FAIL: aspect 0.5 accepted"; exit 1
fi
grep -q "aspect ratio must be at least 1, got 0.5" bad.log || { cat bad.log; echo "FAIL: aspect 0.5 not named"; exit 1; }
echo "drum maps ok"
