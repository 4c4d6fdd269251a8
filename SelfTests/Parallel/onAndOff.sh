# Sourced by the self-tests that run the benchmark chute with a flag on and off and compare its
# files to the bit (overlapChangesNoForce.sh, driftPassChangesNoBit.sh). Needs mpirun (an array),
# benchmark and data set.
# runOnAndOff RANKS FLAG PREFIX: the flow (1500 steps, files on) with --FLAG on and off, as
# PREFIX{on,off}RANKS.{data,fstat,ene,restart,log}.
runOnAndOff() {
  for value in on off; do
    "${mpirun[@]}" -np "$1" "$benchmark" --data "$data" --end-time 0.15 --files on --vtu off \
      --name "$3$value$1" "--$2" $value > "$3$value$1.log"
  done
}
# sameFilesOnAndOff RANKS PREFIX: cmp fails the test at the first differing byte.
sameFilesOnAndOff() {
  for f in data fstat ene; do cmp "$2on$1.$f" "$2off$1.$f"; done
  cmp <(sed 2d "$2on$1.restart") <(sed 2d "$2off$1.restart")  # (line 2 is the run's name)
}
