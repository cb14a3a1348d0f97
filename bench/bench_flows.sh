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
# about equal vertex counts, and T = 6 with finer edges where its sheets are thinner than
# an edge; the collision and topology searches are timed alone on the
# Enright run's meshes. The shape error of
# each experiment comes from its checkpoints (bench/fidelity.cpp says how it is measured).
# Last, Enright and vortex T = 6 run again from spheres of five sizes, for how much the
# figures one triangle or one sample decides vary from run to run (spread, below).
set -eu
cd "$(dirname "$0")/.."
tool=${SURFADAPT:-bin/surfadapt}
runs=${RUNS:-3}
fidelity=${FIDELITY:-build/bench/fidelity}
checkpoints=${CHECKPOINTS:-build/bench/checkpoints}

# words LIST: the space-separated words of LIST, one a line.
words() { echo "$1" | tr ' ' '\n' | grep .; }

# checkpoint_times DIR: the times of the checkpoints in DIR (t<time>.obj), in order.
checkpoint_times() { ls "$1"/t*.obj | sed 's/.*\/t\(.*\)[.]obj$/\1/' | sort -g; }

# median NUMBERS FORMAT: the median of the space-separated numbers, printed with FORMAT.
median() {
    words "$1" | sort -n | awk -v format="$2" '{ t[NR] = $1 } END {
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
    for mesh in $(checkpoint_times "$checkpoints/$name"); do
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
flow vortex_t6_thin_sheets 1 vortex --period 6 --thin-sheet-ratio 0.5 # SFA_PARAM_THIN_SHEET_EDGE_RATIO
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

# The searches collision-safe motion and topology change add, timed alone (one thread) on
# the Enright run's own meshes at T/4, T/2 and 3T/4, whose thin sheet they must look at
# closely: the benchmarks' spheres show what every call costs where nothing is near.
meshes=$checkpoints/enright
build/bench/bench_collision --dt 0.015 "$meshes/t0.75.obj" "$meshes/t1.5.obj" "$meshes/t2.25.obj" # the run's step
build/bench/bench_topology --checkpoints "$meshes/t0.75.obj" "$meshes/t1.5.obj" "$meshes/t2.25.obj"

# spread NAME QUARTER ARGS...: the figures that one triangle or one sample decides (the
# smallest angle, the largest backtrace error) change from run to run: the flows amplify
# any difference, and Enright's largest error at t = T from a sphere of N = 47 instead of 48
# is half as large. So the flow runs again from spheres of N = 46 to 50 (QUARTER: its steps
# over four), and gives per resolution the smallest angle at T/4, T/2, 3T/4 and T and the
# largest and RMS backtrace error at t = T over the start mesh's own; then over the five
# the medians and range, and how many of the checkpoints keep every angle above 5 degrees.
# The same where the mesh resolves the surface (leaving out the triangles near which the
# surface turns by more than a right angle within their size, bench/surface_resolution.hpp:
# the angles from `fidelity --angles-only`, the largest error at t = T), with the largest
# share of the area left out.
spread() {
    name=$1 quarter=$2
    shift 2
    field() { echo "$1" | sed "s/.*\"$2\":\([-0-9.e+]*\).*/\1/"; }
    ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", a / b }'; }
    all_angles="" max_ratios="" rms_ratios="" all_resolved="" all_left_out="" resolved_max_ratios=""
    for n in 46 47 48 49 50; do
        dir="$checkpoints/${name}_n$n"
        rm -rf "$dir"
        angles=$("$tool" "$@" --resolution "$n" --report-every "$quarter" --checkpoints "$dir" |
            awk '$1 ~ /^[0-9]+$/ && $2 ~ /^[0-9]+[.][0-9]+$/ && $1 > 0 { printf "%s%s", sep, $7; sep = " " }')
        times=$(checkpoint_times "$dir")
        floor=$("$fidelity" "$dir/t$(echo "$times" | head -1).obj" --json | grep '^{')
        end=$("$fidelity" "$dir/t$(echo "$times" | tail -1).obj" --json | grep '^{')
        max_ratio=$(ratio "$(field "$end" max)" "$(field "$floor" max)")
        rms_ratio=$(ratio "$(field "$end" rms)" "$(field "$floor" rms)")
        resolved_max_ratio=$(ratio "$(field "$end" resolved_max)" "$(field "$floor" max)")
        resolved="" left_out=""
        for t in $(echo "$times" | tail -n +2); do
            figures=$("$fidelity" "$dir/t$t.obj" --angles-only --json | grep '^{')
            resolved="$resolved $(field "$figures" min_angle_resolved)"
            left_out="$left_out $(field "$figures" unresolved_area)"
        done
        printf '{"bench":"spread","experiment":"%s","resolution":%d,"min_angles":[%s],"min_angles_resolved":[%s],"unresolved_area":[%s],"max_over_floor":%s,"max_over_floor_where_resolved":%s,"rms_over_floor":%s}\n' \
            "$name" "$n" "$(echo "$angles" | tr ' ' ',')" "$(words "$resolved" | paste -sd,)" \
            "$(words "$left_out" | paste -sd,)" "$max_ratio" "$resolved_max_ratio" "$rms_ratio"
        all_angles="$all_angles $angles" max_ratios="$max_ratios $max_ratio" rms_ratios="$rms_ratios $rms_ratio"
        all_resolved="$all_resolved $resolved" all_left_out="$all_left_out $left_out"
        resolved_max_ratios="$resolved_max_ratios $resolved_max_ratio"
        rm -rf "$dir" # 20 to 60 MB a run; the line above keeps what they showed
    done
    above=$(words "$all_angles" | awk '$1 > 5 { n++ } END { print n + 0 }')
    checkpoints_seen=$(words "$all_angles" | wc -l)
    lowest=$(words "$max_ratios" | sort -n | head -1)
    highest=$(words "$max_ratios" | sort -n | tail -1)
    above_resolved=$(words "$all_resolved" | awk '$1 > 5 { n++ } END { print n + 0 }')
    largest_left_out=$(words "$all_left_out" | sort -g | tail -1)
    printf '{"bench":"spread_summary","experiment":"%s","resolutions":5,"median_max_over_floor":%s,"max_over_floor_range":[%s,%s],"median_max_over_floor_where_resolved":%s,"median_rms_over_floor":%s,"median_min_angle":%s,"checkpoints_above_5_degrees":%d,"checkpoints_above_5_degrees_where_resolved":%d,"largest_unresolved_area":%s,"checkpoints":%d}\n' \
        "$name" "$(median "$max_ratios" %.2f)" "$lowest" "$highest" "$(median "$resolved_max_ratios" %.2f)" \
        "$(median "$rms_ratios" %.2f)" \
        "$(median "$all_angles" %.2f)" "$above" "$above_resolved" "$largest_left_out" "$checkpoints_seen"
}

spread enright 50 enright
spread vortex_t6 100 vortex --period 6
