#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# surfadapt against CGAL's isotropic remeshing in the same run (what `make bench-peers`
# runs, once the programs are built): one JSON line per measurement, then the ratios.
#   1. The Enright test tracked by surfadapt (`surfadapt enright`) and by CGAL
#      (cgal_enright.cpp: the same sphere, steps and velocity field, isotropic_remeshing
#      every 4 steps), each saving its checkpoints; bench/fidelity measures the shape error
#      of both by backtracing at t = T/2 and T.
#   2. Static remeshing of the demo's machined part and of jittered spheres of about 100k
#      and 1M vertices by both (cgal_static.cpp).
# CGAL's remeshing runs on one thread, surfadapt on OpenMP's default: surfadapt's Enright
# runs again on one thread (its results do not depend on the count) for the ratio at equal
# threads, and cgal_static times it on both. The runs go one after another, never two at a
# time, so that neither takes a core from the other; the machine's load at the start and at
# the end is printed, since other work on the cores moves every time here, the more so with
# OpenMP's threads. CGAL_ITERATIONS (default 1) is passed to both CGAL programs.
set -eu
cd "$(dirname "$0")/../.."
tool=${SURFADAPT:-bin/surfadapt}
fidelity=${FIDELITY:-build/bench/fidelity}
peers=${PEERS:-build/bench/peers}
iterations=${CGAL_ITERATIONS:-1}

# field LINE NAME: the number NAME has in the JSON line.
field() {
    echo "$1" | sed -n "s/.*\"$2\":\([-+0-9.eE]*\).*/\1/p"
}
# ratio A B: A / B, or null when B is 0.
ratio() {
    awk -v a="$1" -v b="$2" 'BEGIN { if (b + 0 == 0) print "null"; else printf "%.3g\n", a / b }'
}
# checkpoint DIR K: the K-th checkpoint of DIR by time (1: t = 0, 3: T/2, 5: T).
checkpoint() {
    for mesh in "$1"/t*.obj; do echo "$mesh"; done | sed 's/.*\/t\(.*\)[.]obj$/\1/' | sort -g | sed -n "$2p"
}

# machine WHEN: the cores and the 1-minute load. At the start, a warning when other work
# already had a core's worth or more, which slows OpenMP's threads most (surfadapt's Enright
# ran 3 times slower at a load of 2.5); at the end the load counts this run's own work too.
machine() {
    load=$(cut -d' ' -f1 /proc/loadavg)
    printf '{"bench":"peer_machine","when":"%s","cores":%s,"load_1min":%s}\n' "$1" "$(nproc)" "$load"
    if [ "$1" = start ] && awk -v l="$load" 'BEGIN { exit !(l >= 1) }'; then
        echo "bench/peers/run.sh: load $load at the start: other work shares the cores, the times are not comparable" >&2
    fi
}
machine start

rm -rf "$peers/surfadapt" "$peers/cgal"
ours=$("$tool" enright --json --report-every 100000 --checkpoints "$peers/surfadapt" | grep '^{')
echo "$ours"
ours_1thread=$(OMP_NUM_THREADS=1 "$tool" enright --json --report-every 100000 | grep '^{' |
    sed 's/^{/{"omp_num_threads":1,/')
echo "$ours_1thread"
theirs=$("$peers/cgal_enright" --iterations "$iterations" --checkpoints "$peers/cgal" | grep '^{')
echo "$theirs"
# Both start from the same mesh, headed alike, or the comparison is void.
if ! cmp -s "$peers/surfadapt/t0.obj" "$peers/cgal/t0.obj"; then
    echo "bench/peers/run.sh: the two Enright runs start from different meshes; cgal_enright.cpp no longer" \
         "follows enright_setup (apps/surfadapt/flow_commands.cpp)" >&2
    exit 1
fi

# The shape error of both at T/2 and T, and the ratio CGAL / surfadapt of its RMS and max.
newline='
'
fidelity_ratios=""
for k in 3 5; do
    t=$(checkpoint "$peers/surfadapt" "$k")
    [ "$t" = "$(checkpoint "$peers/cgal" "$k")" ] || { echo "bench/peers/run.sh: checkpoint times differ" >&2; exit 1; }
    a=$("$fidelity" "$peers/surfadapt/t$t.obj" --json | grep '^{' | sed 's/^{/{"tracker":"surfadapt",/')
    b=$("$fidelity" "$peers/cgal/t$t.obj" --json | grep '^{' | sed 's/^{/{"tracker":"cgal_isotropic_remeshing",/')
    echo "$a"
    echo "$b"
    fidelity_ratios="$fidelity_ratios$(printf '{"bench":"peer_ratio","flow":"enright","time":%s,"rms_ratio":%s,"max_ratio":%s,"vertex_rms_ratio":%s}' \
        "$t" "$(ratio "$(field "$b" rms)" "$(field "$a" rms)")" "$(ratio "$(field "$b" max)" "$(field "$a" max)")" \
        "$(ratio "$(field "$b" vertex_rms)" "$(field "$a" vertex_rms)")")$newline"
done

static=$("$peers/cgal_static" --iterations "$iterations" | grep '^{')
echo "$static"

# The ratios, CGAL over surfadapt. The flow's times: the whole loop (both with their per-step
# measuring and checkpoint writing: surfadapt's "seconds", CGAL's "loop_seconds"), the work
# alone (advection and mesh upkeep) and the mesh upkeep alone (CGAL's remeshing against
# surfadapt's sfa_adapt and sfa_smooth calls).
sum() {
    awk -v a="$1" -v b="$2" -v c="${3:-0}" 'BEGIN { print a + b + c }'
}
# flow_ratios SURFADAPT_LINE THREADS: the time ratios against that run of surfadapt.
flow_ratios() {
    printf '{"bench":"peer_ratio","flow":"enright","surfadapt_threads":"%s","seconds_ratio":%s,"work_seconds_ratio":%s,"upkeep_seconds_ratio":%s}\n' \
        "$2" "$(ratio "$(field "$theirs" loop_seconds)" "$(field "$1" seconds)")" \
        "$(ratio "$(field "$theirs" seconds)" \
            "$(sum "$(field "$1" advect_s)" "$(field "$1" smooth_s)" "$(field "$1" adapt_s)")")" \
        "$(ratio "$(field "$theirs" remesh_s)" "$(sum "$(field "$1" smooth_s)" "$(field "$1" adapt_s)")")"
}
flow_ratios "$ours" default
flow_ratios "$ours_1thread" 1
printf '{"bench":"peer_ratio","flow":"enright","vertices_max_ratio":%s,"volume_error_ratio":%s}\n' \
    "$(ratio "$(field "$theirs" vertices_max)" "$(field "$ours" vertices_max)")" \
    "$(ratio "$(field "$theirs" volume_error)" "$(field "$ours" volume_error)")"
printf '%s' "$fidelity_ratios"
echo "$static" | while read -r line; do
    model=$(echo "$line" | sed 's/.*"model":"\([^"]*\)".*/\1/')
    settled=$(field "$line" time_ratio_settled)
    printf '{"bench":"peer_ratio","model":"%s","time_ratio":%s,"time_ratio_1thread":%s%s}\n' "$model" \
        "$(field "$line" time_ratio)" "$(field "$line" time_ratio_1thread)" \
        "${settled:+,\"time_ratio_settled\":$settled}"
done
machine end
