#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Runs each argument as one test program (an argument may hold a command with its own
# arguments), shows its output, and adds up the counts the programs print: CMocka's
# "[  PASSED  ] N test(s)." / "[  FAILED  ] N test(s)" / "[  SKIPPED ] N test(s)" lines,
# or our own "name: N passed, M failed" lines. Ends with one line for the whole run, after
# one that says how many tests skipped for want of the paper's models (their
# "skipped: needs FILE, ..." lines; a fresh clone has not got them).
set -u
passed=0 failed=0 skipped=0 broken=""
log=$(mktemp)
needs=$(mktemp)
trap 'rm -f "$log" "$needs"' EXIT

count() { # $1 = regexp before the number
  sed -n "s/^$1 *\([0-9][0-9]*\).*/\1/p" "$log" | awk '{s += $1} END {print s + 0}'
}

for program in "$@"; do
  echo "=== $program"
  sh -c "$program" >"$log" 2>&1
  status=$?
  cat "$log"
  p=$(count '\[  PASSED  \]')
  f=$(count '\[  FAILED  \]')
  k=$(count '\[  SKIPPED \]')
  # Our own programs: "name: N passed, M failed"
  p=$((p + $(sed -n 's/^[a-z-]*: \([0-9][0-9]*\) passed, [0-9][0-9]* failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')))
  f=$((f + $(sed -n 's/^[a-z-]*: [0-9][0-9]* passed, \([0-9][0-9]*\) failed.*/\1/p' "$log" | awk '{s+=$1} END {print s+0}')))
  if [ "$status" -ne 0 ] && [ "$f" -eq 0 ]; then
    f=1 # it crashed or failed without saying so
  fi
  passed=$((passed + p)) failed=$((failed + f)) skipped=$((skipped + k))
  sed -n 's/^skipped: needs \([^,]*\),.*/\1/p' "$log" >>"$needs"
  [ "$status" -ne 0 ] && broken="$broken
  $program (exit $status)"
done

if [ -n "$broken" ]; then
  echo "failing programs:$broken"
fi
if [ -s "$needs" ]; then
  echo "$(wc -l <"$needs") of the skipped tests need the paper's models, which are not part of the project:" \
    "$(sort -u "$needs" | paste -sd ' ' -)"
fi
echo "check: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ] && [ -z "$broken" ]
