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
# The map's cells are the file's: its filled cells and the place of its largest sphere fraction,
# found here with awk in the csv (first the largest, as numpy's argmax), are the map's.
expected=$(awk -F, '!/^#/ && $1 != "x" { if ($4 >= 0.1) { n++; if (!(best != "" && $20 <= best)) { best = $20; x = $1; z = $2 } } }
                    END { printf "%d %.6g %.6g\n", n, x, z }' mixed.cg.csv)
found=$(awk '/^R = 2:/ { gsub(",", "", $25); print $17, $25, $28 }' maps.log)
[ "$expected" = "$found" ] || { echo "FAIL: the mixed drum's map has cells, largest at: $found; the file: $expected"; exit 1; }
echo "the map's filled cells and largest sphere fraction where the file has them: $found"
if /usr/bin/python3 "$maps" --run mixed/RotatingDrum mixed.cg.csv 0.5 -o bad.png > bad.log 2>&1; then
  echo "FAIL: aspect 0.5 accepted"; exit 1
fi
grep -q "aspect ratio must be at least 1, got 0.5" bad.log || { cat bad.log; echo "FAIL: aspect 0.5 not named"; exit 1; }
echo "drum maps ok"
