#!/bin/sh
# talus-drum-angle and the LIGGGHTS converters (Tools/Drum/liggghtsDrum.py) on a tiny drum of
# spheres (Documentation/Drums/RotatingDrum.md, "The angle of repose against LIGGGHTS"):
# - the tool's angle of every frame of the run's .data file equals the angle the driver wrote to
#   its .series in the run at the same time (the bed in memory, the wall by its fixed flag; the
#   tool reads the frame and leaves out the wall's species);
# - a LIGGGHTS dump made from the last frame (shuffled ids, as a dump's own order) converts back
#   to a frame with the same angle, at the time T0 + step dt;
# - the start file for LIGGGHTS holds every particle of the frame, the bed's as type 1 and the
#   wall's as type 2.
#   drumAngle.sh RotatingDrum talus-drum-angle liggghtsDrum.py
set -eu
driver=$1
tool=$2
convert=$3
"$driver" --radius 4 --length 4 --particles 40 --sphere-fraction 1 --end-time 30 --output-interval 1 --vtu off --fstat off \
  > run.log 2>&1 || { cat run.log; echo "FAIL: the run failed"; exit 1; }
"$tool" --data RotatingDrum.data --from 25 > angles.txt
awk 'NR == FNR { if ($1 !~ /^#/) a[$1 + 0] = $2; next }
     !/^#/ && $6 != "nan" { t = $1 + 0; if (!(t in a)) { print "FAIL: no frame at t = " t; bad = 1; exit 1 }
                            d = $6 - a[t]; if (d < 0) d = -d; if (d > m) m = d; n++ }
     END { if (bad) exit 1; print n " samples, largest difference " m + 0
           if (n < 5 || m > 1e-6) { print "FAIL: the tool does not give the driver'"'"'s angles"; exit 1 } }' \
  angles.txt RotatingDrum.series
# The last frame (its header: the last line of 8 numbers) as a LIGGGHTS dump, timestep 1000 of dt
# 0.001 after T0 = 29.
frame=$(awk 'NF == 8 { start = NR } END { print start }' RotatingDrum.data)
tail -n +"$frame" RotatingDrum.data > last.data
awk 'NR == 1 { n = $1; print "ITEM: TIMESTEP\n1000\nITEM: NUMBER OF ATOMS\n" n
               print "ITEM: BOX BOUNDS ff pp ff\n" $3 " " $6 "\n" $4 " " $7 "\n" $5 " " $8
               print "ITEM: ATOMS id type radius x y z vx vy vz"; next }
     { print (NR - 1), ($14 == 2 ? 2 : 1), $7, $1, $2, $3, $4, $5, $6 }' last.data > ordered.dump
# (A dump's lines in its own order: the atoms reversed.)
head -n 9 ordered.dump > drum.dump
tail -n +10 ordered.dump | sort -k1,1nr >> drum.dump
/usr/bin/python3 "$convert" dump drum.dump 29 0.001 converted.data 2> convert.log || { cat convert.log; exit 1; }
expected=$("$tool" --data last.data | awk '!/^#/ { print $2 }')
found=$("$tool" --data converted.data | awk '!/^#/ { print $1, $2 }')
echo "last frame $expected, from the dump: $found"
awk -v e="$expected" -v f="$found" 'BEGIN { split(f, b, " ");
    if (b[1] != 30 || b[2] != e) { print "FAIL: the converted dump gives t, angle = " f ", the frame t = 30, " e; exit 1 } }'
/usr/bin/python3 "$convert" data RotatingDrum.data 30 start.data
atoms=$(awk '$2 == "atoms" { print $1 }' start.data)
bed=$(awk '/^Atoms/ { inside = 1; next } /^Velocities/ { inside = 0 } inside && NF == 7 && $2 == 1 { n++ } END { print n + 0 }' start.data)
wall=$(awk '/^Atoms/ { inside = 1; next } /^Velocities/ { inside = 0 } inside && NF == 7 && $2 == 2 { n++ } END { print n + 0 }' start.data)
total=$(head -n 1 last.data | awk '{ print $1 }')
walls=$(awk 'NR > 1 && $14 == 2 { n++ } END { print n + 0 }' last.data)
echo "start file: $atoms atoms, $bed of the bed, $wall of the wall (the frame: $total, $walls of the wall)"
[ "$atoms" -eq "$total" ] && [ "$wall" -eq "$walls" ] && [ "$bed" -eq 40 ] || { echo "FAIL: the start file's atoms"; exit 1; }
echo "drum angle ok"
