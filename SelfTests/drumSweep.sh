#!/bin/sh
# The drum sweep (Tools/Drum/runDrumSweep.py) end to end on a tiny drum: two aspect ratios run as
# two jobs; each run must stop at its first sample after turns + windows x window-turns
# (RotatingDrum --rotations), and each result line's M and S must be the means over the windows
# of the samples in them, recomputed here with awk from the run's .series; then the plot of S and
# the angle of repose against R (plotDrumSweep.py) with its table; and the indices of the
# time-averaged fields of each window (drumFieldIndices.py): each window averages the frames of the
# run's .data whose times lie in it (counted here with awk) and gives talus-cg's M and S of that
# average; the point's S is the mean of its windows'.
#   drumSweep.sh RotatingDrum runDrumSweep.py talus-cg
set -eu
driver=$1
sweep=$2
cg=$3
rm -rf sweep
/usr/bin/python3 "$sweep" --driver "$driver" --out sweep --aspects 1,2 --seeds 3 --turns 0.02 --windows 2 \
  --window-turns 0.005 --restart-interval 0.1 -- --radius 4 --length 4 --particles 40 --sample-interval 0.1 > sweep.log 2>&1 \
  || { cat sweep.log; echo "FAIL: the sweep failed"; exit 1; }
cat sweep.log
lines=$(wc -l < sweep/results.csv)
[ "$lines" -eq 3 ] || { echo "FAIL: results.csv has $lines lines, not a header and 2 points"; exit 1; }
for name in R1-s3 R2-s3; do
  series=sweep/points/$name/$name.series
  # The last sample is the first at or after 0.03 turns.
  awk '!/^#/ { if (last != "") before = last; last = $2 } END {
         if (!(last >= 0.03 && before < 0.03)) { print "FAIL: '"$name"' stopped at " last " turns (before: " before ")"; exit 1 } }' "$series"
  # M and S: the mean over the two windows [0.02, 0.025) and [0.025, 0.03) of each window's mean.
  expected=$(awk '!/^#/ { w = int(($2 - 0.02) / 0.005 + 1e-9); if ($2 >= 0.02 && w < 2) { m[w] += $4; s[w] += $5; n[w]++ } }
                  END { if (n[0] == 0 || n[1] == 0) { print "empty"; exit }
                        printf "%.10g %.10g\n", (m[0] / n[0] + m[1] / n[1]) / 2, (s[0] / n[0] + s[1] / n[1]) / 2 }' "$series")
  found=$(awk -F, -v p="$name" '$1 == p { print $7, $9 }' sweep/results.csv)
  awk -v e="$expected" -v f="$found" -v p="$name" 'BEGIN { split(e, a, " "); split(f, b, " ");
      if (a[1] == "empty" || (a[1] - b[1]) ^ 2 > 1e-14 || (a[2] - b[2]) ^ 2 > 1e-14) {
        print "FAIL: " p ": M, S = " f " in results.csv, the windows of the series give " e; exit 1 }
      print p ": M, S = " f " (the series: " e ")" }'
done
# The plot and its table: one row per aspect ratio, S as in results.csv (one seed each).
/usr/bin/python3 "$(dirname "$sweep")/plotDrumSweep.py" sweep/results.csv -o sweep.png --csv table.csv > plot.log 2>&1 \
  || { cat plot.log; echo "FAIL: plotDrumSweep"; exit 1; }
cat table.csv
[ -s sweep.png ] && [ "$(wc -l < table.csv)" -eq 3 ] || { echo "FAIL: no plot, or not one table row per aspect ratio"; exit 1; }
# The time-averaged fields: frames every 0.1 (the restart interval) in each run's windows.
/usr/bin/python3 "$(dirname "$sweep")/drumFieldIndices.py" sweep --cg "$cg" --turns 0.02 --windows 2 \
  --window-turns 0.005 > fields.log 2>&1 || { cat fields.log; echo "FAIL: drumFieldIndices"; exit 1; }
cat fields.log
for name in R1-s3 R2-s3; do
  series=sweep/points/$name/$name.series
  sum=0
  for w in 1 2; do
    # The window's first and last sample times, its frames, and talus-cg's M and S over them.
    span=$(awk -v w=$w '!/^#/ { k = int(($2 - 0.02) / 0.005 + 1e-9) + 1; if ($2 >= 0.02 && k == w) { if (first == "") first = $1; last = $1 } }
                        END { print first, last }' "$series")
    frames=$(awk -v span="$span" 'BEGIN { split(span, s, " ") } NF == 8 && $2 + 0 >= s[1] - 1e-9 && $2 + 0 <= s[2] + 1e-9 { n++ }
                                  END { print n + 0 }' "sweep/points/$name/$name.data")
    "$cg" "sweep/points/$name/$name" --coordinates XZ --time-average --time-min ${span% *} --time-max ${span#* } \
      --fixed exclude -w 1 --stress off --mixing 0 -o direct.csv > direct.log 2>&1
    direct=$(awk -F, '!/^#/ && $1 != "t" { print $2, $3 }' direct.mixing.csv)
    found=$(awk -F, -v p="$name" -v w=$w '$1 == p && $2 == w { print $5, $6, $7 }' sweep/fields-windows.csv)
    awk -v f="$found" -v n="$frames" -v d="$direct" -v p="$name" -v w=$w 'BEGIN { split(f, a, " "); split(d, b, " ");
        if (a[1] != n || n < 4 || (a[2] - b[1]) ^ 2 > 1e-14 || (a[3] - b[2]) ^ 2 > 1e-14) {
          print "FAIL: " p " window " w ": frames, M, S = " f " in fields-windows.csv; the window holds " n " frames, talus-cg gives " d; exit 1 }
        print p " window " w ": " n " frames, M and S as talus-cg gives them (" d ")" }'
    sum=$(awk -v a="$sum" -v d="$direct" 'BEGIN { split(d, b, " "); printf "%.12g", a + b[2] }')
  done
  # The point's S: the mean of its windows'.
  found=$(awk -F, -v p="$name" '$1 == p { print $8 }' sweep/fields.csv)
  awk -v f="$found" -v s="$sum" -v p="$name" 'BEGIN { if ((f - s / 2) ^ 2 > 1e-14) { print "FAIL: " p ": S_fields " f ", the windows give " s / 2; exit 1 } }'
done
/usr/bin/python3 "$(dirname "$sweep")/plotDrumSweep.py" sweep/results.csv -o sweep.png --fields sweep/fields.csv > plot.log 2>&1 \
  || { cat plot.log; echo "FAIL: plotDrumSweep --fields"; exit 1; }
echo "drum sweep ok"
