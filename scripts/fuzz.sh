#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Runs each libFuzzer harness for a given time, from its committed corpus, and reports what
# it did. Usage: fuzz.sh SECONDS NAME...  (run by `make fuzz`; the harnesses are built in
# build/fuzz/bin). New inputs go to build/fuzz/corpus/NAME; a crash, hang or contract
# violation leaves its input in build/fuzz/crashes/NAME and makes this script fail.
set -u
seconds=$1
shift
status=0
for name in "$@"; do
  corpus=build/fuzz/corpus/$name
  crashes=build/fuzz/crashes/$name
  mkdir -p "$corpus" "$crashes"
  # Each input must finish in 10 s and 2 GiB: a longer one is a hang the harness reports.
  build/fuzz/bin/"$name" "$corpus" tests/fuzz/corpus/"$name" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -artifact_prefix="$crashes/" -print_final_stats=1 >build/fuzz/"$name".log 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' build/fuzz/"$name".log)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' build/fuzz/"$name".log)
  found=$(ls "$crashes" | wc -l)
  echo "{\"fuzz\":\"$name\",\"seconds\":$seconds,\"executions\":${runs:-0},\"per_second\":${speed:-0},\"corpus\":$(ls "$corpus" | wc -l),\"crashes\":$found,\"exit\":$rc}"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    echo "fuzz: $name found a problem: see build/fuzz/$name.log and $crashes" >&2
    status=1
  fi
done
exit $status
