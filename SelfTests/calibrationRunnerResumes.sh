#!/bin/sh
# The calibration study runner (Tools/Calibration/runStudy.py) resumes a killed study: a grid of
# three very short points runs one at a time; the runner is killed (SIGKILL) once the first point
# has its result and the second a restart file; the second point's run must die with it; run
# again, the runner must skip the first point (its result file untouched), continue the second
# from its restart file, run the third, and collect three result lines.
#   calibrationRunnerResumes.sh CalibrationChute runStudy.py
set -eu
driver=$1
runner=$2
rm -rf study
mkdir study
grid="--species large --angles 25 --depths 1,1.5,2 --jobs 1 --restart-interval 0.05"
flags="--length 6 --width 6 --end-time 1.5 --window 4 --progress-interval 1e9"
/usr/bin/python3 "$runner" --driver "$driver" --out study $grid -- $flags > first.log 2>&1 &
runner_pid=$!
first=study/points/large-a25-d1/large-a25-d1.result.csv
second=study/points/large-a25-d1.5/large-a25-d1.5.restart
waited=0
while [ ! -s "$first" ] || [ ! -s "$second" ]; do
  sleep 0.05
  waited=$((waited + 1))
  if [ $waited -gt 2400 ]; then echo "FAIL: no result of the first point and restart of the second in 120 s"; cat first.log; exit 1; fi
done
if [ -e study/points/large-a25-d1.5/large-a25-d1.5.result.csv ]; then
  echo "FAIL: the second point finished before the kill (make the points longer)"; exit 1
fi
kill -KILL $runner_pid
wait $runner_pid 2>/dev/null || true
sleep 1
# No driver of the killed study may still run (they die with the runner: PR_SET_PDEATHSIG).
if pgrep -f "$driver --name large-a25-d" > /dev/null; then echo "FAIL: a point's run outlived its runner"; exit 1; fi
stamp=$(stat -c %Y.%s "$first")
cp "$first" first-result.csv
/usr/bin/python3 "$runner" --driver "$driver" --out study $grid -- $flags > second.log 2>&1
cat second.log
grep -q "skip large-a25-d1: its result exists" second.log || { echo "FAIL: the finished point was not skipped"; exit 1; }
if grep -q "large-a25-d1 starts\|large-a25-d1 continues" second.log; then echo "FAIL: the finished point ran again"; exit 1; fi
[ "$(stat -c %Y.%s "$first")" = "$stamp" ] && cmp -s "$first" first-result.csv || { echo "FAIL: the first result changed"; exit 1; }
grep -q "large-a25-d1.5 continues from its restart file" second.log || { echo "FAIL: the killed point started afresh"; exit 1; }
grep -q "large-a25-d1.5 finished" second.log || { echo "FAIL: the continued point did not finish"; exit 1; }
lines=$(wc -l < study/results.csv)
[ "$lines" -eq 4 ] || { echo "FAIL: results.csv has $lines lines, not a header and 3 points"; cat study/results.csv; exit 1; }
echo "runner: the finished point was skipped, the killed one continued from its restart file, 3 results collected"
# A study moved to another folder (another machine) continues from its collected results: with
# --done the three points count as finished and none runs.
rm -rf moved
/usr/bin/python3 "$runner" --driver "$driver" --out moved $grid --done study/results.csv -- $flags > third.log 2>&1
cat third.log
grep -q "study: 3 finished points taken from study/results.csv" third.log || { echo "FAIL: --done took not 3 points"; exit 1; }
grep -q "0 to run" third.log || { echo "FAIL: a point of --done ran again"; exit 1; }
cmp -s study/results.csv moved/results.csv || { echo "FAIL: the moved study's results.csv differs"; diff study/results.csv moved/results.csv; exit 1; }
echo "moved study: its collected results count as finished"
