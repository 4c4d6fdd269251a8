#!/usr/bin/env bash
# Self-test of Scripts/compareCommits.sh without building two commits (that takes minutes): its
# file comparison (compareOutputFiles.py) on files made here with known differences, and its
# arguments (scene list, refusals with exit status 2).
#   compareCommitsCheck.sh <Scripts folder>
set -uo pipefail
scripts=$1
compare() { python3 "$scripts/compareOutputFiles.py" "$@"; }
status=0
expect() {  # what, text, pattern
    if grep -q -- "$3" <<< "$2"; then echo "ok: $1"; else echo "FAILED: $1: no '$3' in:"; echo "$2"; status=1; fi
}

# Equal files: exit 0, nothing printed.
printf '1 2.5 3\n4 5 6\n' > a.txt
cp a.txt same.txt
out=$(compare a.txt same.txt before after); code=$?
[ $code = 0 ] && [ -z "$out" ] && echo "ok: equal files" || { echo "FAILED: equal files gave $code: $out"; status=1; }

# One number 1 + 1e-12 instead of 1: relative difference |a - b| / max(|a|, |b|) = 1e-12 / (1 + 1e-12),
# printed to 3 digits as 1e-12; a second line differs by 2.5 against 2.5000000005: 2e-10, the
# largest, in line 3, field 2. A word differs in line 4 (a field that is no number).
printf 'x 1 2.5\ny 1 2\nz 2.5 3\nname ball\n' > a.txt
printf 'x 1.000000000001 2.5\ny 1 2\nz 2.5000000005 3\nname drum\n' > b.txt
out=$(compare a.txt b.txt before after); code=$?
expect "exit status 1 for differing files" "status $code" "status 1"
expect "first differing line of both" "$out" "first difference at line 1:"
expect "the line of before" "$out" "before: x 1 2.5"
expect "the line of after" "$out" "after:  x 1.000000000001 2.5"
expect "differing lines counted" "$out" "3 of 4 lines differ"
expect "largest relative difference" "$out" "largest relative difference of their numbers 2e-10 (line 3, field 2: 2.5 against 2.5000000005), largest absolute 5e-10"
expect "text fields counted" "$out" "1 differing fields not numbers"

# A file with a line more, and opposite signs (relative difference 2: |1 - (-1)| / 1).
printf '0 1\n' > a.txt
printf '0 -1\nextra\n' > b.txt
out=$(compare a.txt b.txt before after)
expect "lines beyond the other file" "$out" "1 more lines in after"
expect "opposite signs" "$out" "largest relative difference of their numbers 2 "
out=$(compare a.txt missing.txt 2>&1); code=$?
expect "a missing file refused with status 2" "status $code: $out" "status 2: .*missing.txt"

# The script's arguments: the scene list, and refusals before any build.
out=$("$scripts/compareCommits.sh" --list); code=$?
expect "--list exits 0" "status $code" "status 0"
for scene in benchmark-waves benchmark-steps bidisperse-chute maser-chute drum ellipsoids restart-1rank restart-maser restart-2ranks; do
    expect "--list names $scene" "$out" "^$scene "
done
out=$("$scripts/compareCommits.sh" --jobs 3 HEAD HEAD 2>&1); code=$?
expect "--jobs 3 refused" "status $code: $out" "status 2: .*--jobs takes 1 or 2, got '3'"
out=$("$scripts/compareCommits.sh" HEAD no-such-commit-anywhere 2>&1); code=$?
expect "an unknown commit refused" "status $code: $out" "status 2: .*no-such-commit-anywhere is not a commit"
out=$("$scripts/compareCommits.sh" HEAD HEAD no-such-scene 2>&1); code=$?
expect "an unknown scene refused" "status $code: $out" "status 2: .*no scene 'no-such-scene'"

[ $status = 0 ] && echo "compareCommits checks passed"
exit $status
