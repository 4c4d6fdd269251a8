#!/bin/sh
# Runs a test's program and checks its exit status (Scripts/ProgramTest.cmake).
# Usage: expectExit.sh STATUS PROGRAM [ARG...]
# The program's output passes through unchanged. When its exit status differs from STATUS, a line
# "TALUS-TEST: exit status S, expected STATUS" follows it (the tests' FAIL_REGULAR_EXPRESSION),
# and this script exits 1; otherwise 0. A program killed by a signal has the status 128 + the
# signal's number (134 for abort()).
expected=$1
shift
"$@"
status=$?
if [ "$status" -ne "$expected" ]; then
  printf '\nTALUS-TEST: exit status %s, expected %s\n' "$status" "$expected"
  exit 1
fi
exit 0
