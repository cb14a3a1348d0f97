#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The paper's three flow experiments at full size through the command-line tool: one JSON
# line per run with the total time, the time per call (advection, sfa_smooth, sfa_adapt)
# and per phase inside them (analysis, smoothing, flipping, splitting and contraction),
# vertex counts, volume errors, the largest normal turn and crossings, and the ratio of
# smoothing + adaptation time to bare advection time in the same run. The shorter runs are
# repeated (RUNS, default 3) and a last line per experiment gives the median time. Enright
# runs also without the crossing guard, to show what the guard costs; Enright and vortex
# T = 2 also with collision-safe motion and with topology change (which makes motion
# collision-safe too), to show what those cost against the run above them; and those costs
# again as ratios measured in alternating rounds (cost_ratio, last). Each flow runs also
# isotropically (once for Enright and T = 6), for the shape errors of the two modes at
# about equal vertex counts. The shape error of
# each experiment comes from its checkpoints (bench/fidelity.cpp says how it is measured).
set -eu
cd "$(dirname "$0")/.."
tool=${SURFADAPT:-bin/surfadapt}
runs=${RUNS:-3}
fidelity=${FIDELITY:-build/bench/fidelity}
checkpoints=${CHECKPOINTS:-build/bench/checkpoints}

# median NUMBERS FORMAT: the median of the space-separated numbers, printed with FORMAT.
median() {
    echo "$1" | tr ' ' '\n' | grep . | sort -n | awk -v format="$2" '{ t[NR] = $1 } END {
        printf format, (NR % 2) ? t[(NR + 1) / 2] : (t[NR / 2] + t[NR / 2 + 1]) / 2 }'
}

# flow NAME RUNS ARGS...: the runs' JSON lines, then their median time; the first run saves
# its checkpoints (t = 0, T/4, T/2, 3T/4, T) and bench/fidelity measures the shape error at
# each by backtracing (one JSON line per checkpoint, tagged with the experiment's name).
flow() {
    name=$1 count=$2
    shift 2
    times=""
    i=0
    while [ "$i" -lt "$count" ]; do
        if [ "$i" -eq 0 ]; then
            rm -rf "$checkpoints/$name"
            line=$("$tool" "$@" --json --report-every 100000 --checkpoints "$checkpoints/$name" | grep '^{')
        else
            line=$("$tool" "$@" --json --report-every 100000 | grep '^{')
        fi
        echo "$line"
        times="$times $(echo "$line" | sed 's/.*"seconds":\([0-9.]*\).*/\1/')"
        i=$((i + 1))
    done
    printf '{"bench":"flow_median","experiment":"%s","runs":%d,"median_seconds":%s}\n' "$name" "$count" \
        "$(median "$times" %.2f)"
    for mesh in $(ls "$checkpoints/$name"/t*.obj | sed 's/.*\/t\(.*\)[.]obj$/\1/' | sort -g); do
        "$fidelity" "$checkpoints/$name/t$mesh.obj" --json | grep '^{' | sed "s/^{/{\"experiment\":\"$name\",/"
    done
}

flow enright "$runs" enright
flow enright_no_crossing_guard "$runs" enright --no-crossing-guard
flow enright_isotropic 1 enright --isotropic
flow enright_collision_safe "$runs" enright --collision-safe
flow enright_topology_change "$runs" enright --topology-change
flow vortex_t2 "$runs" vortex --period 2
flow vortex_t2_collision_safe "$runs" vortex --period 2 --collision-safe
flow vortex_t2_topology_change "$runs" vortex --period 2 --topology-change
flow vortex_t2_isotropic "$runs" vortex --period 2 --isotropic
flow vortex_t6 1 vortex --period 6
flow vortex_t6_topology_change 1 vortex --period 6 --topology-change
flow vortex_t6_isotropic 1 vortex --period 6 --isotropic

# ratios NAME ARGS...: what collision-safe motion and topology change cost, as ratios to
# the same run without them. The flows above run each configuration RUNS times in a row,
# minutes apart, and this machine's speed drifts by a quarter within an hour; so here each
# round runs the three one after the other, and the median of the rounds' ratios is given.
ratios() {
    name=$1
    shift
    seconds() { "$tool" "$@" --json --report-every 100000 | grep '^{' | sed 's/.*"seconds":\([0-9.]*\).*/\1/'; }
    safe="" change=""
    i=0
    while [ "$i" -lt "$runs" ]; do
        plain=$(seconds "$@")
        safe="$safe $(awk -v a="$(seconds "$@" --collision-safe)" -v b="$plain" 'BEGIN { printf "%.4f", a / b }')"
        change="$change $(awk -v a="$(seconds "$@" --topology-change)" -v b="$plain" 'BEGIN { printf "%.4f", a / b }')"
        i=$((i + 1))
    done
    printf '{"bench":"cost_ratio","experiment":"%s","rounds":%d,"collision_safe":%s,"topology_change":%s}\n' \
        "$name" "$runs" "$(median "$safe" %.3f)" "$(median "$change" %.3f)"
}

ratios enright enright
ratios vortex_t2 vortex --period 2
