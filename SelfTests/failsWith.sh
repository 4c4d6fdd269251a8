#!/usr/bin/env bash
# Self-test helper: passes when a command fails as a bad input or a failed write must: exit
# status 1 and a message holding the expected text on stderr (not a crash, not a silent loss).
#   failsWith.sh "EXPECTED TEXT" command [arguments...]
# Prints "fails as expected: <the message>" or what went wrong; exit status 0 or 1.
expected=$1
shift
"$@" > stdout.log 2> stderr.log
status=$?
if [ $status -ne 1 ]; then
  echo "exit status $status, expected 1; stderr:"; cat stderr.log; exit 1
fi
if ! grep -qF -- "$expected" stderr.log; then
  echo "the message lacks '$expected'; stderr:"; cat stderr.log; exit 1
fi
echo "fails as expected: $(grep -F -- "$expected" stderr.log | head -1)"
