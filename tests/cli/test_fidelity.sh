#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The backtrace measure of shape error (bench/fidelity) on a coarse Enright run: the flow
# saves its checkpoints, the tool finds the start sphere's own error at t = 0, the tracked
# surface's at t = T within a few times that, and a surface that is never remeshed out of
# reach however well its vertices follow the flow. Needs the tool and build/bench/fidelity
# built (`make check` builds both).
# Ends with "cli: N passed, M failed" and a non-zero status if anything failed.
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh
fidelity=${FIDELITY:-build/bench/fidelity}

# figure FILE KEY: the number after "KEY": in the JSON line of FILE.
figure() { sed -n "s/.*\"$2\":\([-0-9.e+]*\).*/\1/p" "$1"; }
# below A B [FACTOR]: A < FACTOR * B (FACTOR 1 if not given).
below() { [ -n "$1" ] && [ -n "$2" ] && awk -v a="$1" -v b="$2" -v f="${3:-1}" 'BEGIN { exit !(a < f * b) }'; }

check "enright (2,562 vertices, a whole period) saves its checkpoints at 0, T/4, T/2, 3T/4 and T" \
  sh -c "'$tool' enright --resolution 16 --report-every 1000 --checkpoints '$work/tracked' >/dev/null &&
         for t in 0 0.75 1.5 2.25 3; do head -1 '$work/tracked/t'\$t.obj | grep -q \"time \$t \" || exit 1; done"
"$fidelity" "$work/tracked/t0.obj" --json >"$work/start.txt"
"$fidelity" "$work/tracked/t3.obj" --json --check-step >"$work/end.txt"
cat "$work/start.txt" "$work/end.txt"
start_is_floor() {
  below "$(figure "$work/start.txt" vertex_max)" 1e-12 && below "$(figure "$work/start.txt" bias)" 0 &&
    below 1e-4 "$(figure "$work/start.txt" rms)"
}
check "at t = 0 the vertices lie on the sphere and the triangles inside it (the floor)" start_is_floor
check "halving the RK4 step changes no figure by 1e-6" below "$(figure "$work/end.txt" step_change)" 1e-6
# New and merged vertices placed by the quadric error of the faces around them (the
# paper's placement) gave 2.3 times the RMS; placed on the local fit, 1.7 to 1.8 times.
# The largest error at this coarse resolution is one vertex of the sheet at T/2, where the
# flow has squeezed the sheet thin, so that a small bump across it traces back to a large
# error at t = 0: it changes with any setting of the adaptation (8 to 46 times the floor
# among those tried), so the test bounds the 99th percentile (3.7 to 3.8 times).
check "at t = T the RMS error is within 2 times the start mesh's" \
  below "$(figure "$work/end.txt" rms)" "$(figure "$work/start.txt" rms)" 2
check "at t = T the 99th percentile of the error is within 4.5 times the start mesh's largest" \
  below "$(figure "$work/end.txt" p99)" "$(figure "$work/start.txt" max)" 4.5

check "the same run never remeshed (advection only) exits 0, its checkpoints in a directory it creates with its parent" \
  sh -c "'$tool' enright --resolution 16 --steps 50 --adapt-every 0 --no-smoothing --report-every 1000 \
           --checkpoints '$work/missing/advected' >/dev/null"
"$fidelity" "$work/tracked/t0.75.obj" --json >"$work/tracked.txt"
"$fidelity" "$work/missing/advected/t0.75.obj" --json >"$work/advected.txt"
cat "$work/tracked.txt" "$work/advected.txt"
check "without remeshing the vertices follow the flow (error below 1e-4)" \
  below "$(figure "$work/advected.txt" vertex_max)" 1e-4
check "but the stretched triangles between them leave the surface: RMS 10 times the tracked one's" \
  below "$(figure "$work/tracked.txt" rms)" "$(figure "$work/advected.txt" rms)" 0.1

check "--resume goes on from the T/2 checkpoint to t = T, saving the later checkpoints" \
  sh -c "'$tool' enright --resolution 16 --report-every 1000 --resume '$work/tracked/t1.5.obj' \
           --checkpoints '$work/resumed' >'$work/resumed.log' &&
         grep -q 'resumed from .* at t = 1.5 (step 100)' '$work/resumed.log' &&
         ls '$work/resumed' | tr '\\n' ' ' | grep -qx 't1.5.obj t2.25.obj t3.obj '"
"$fidelity" "$work/resumed/t3.obj" --json >"$work/resumed.txt"
check "and ends within 2 times the start mesh's RMS error, as the whole run does" \
  below "$(figure "$work/resumed.txt" rms)" "$(figure "$work/start.txt" rms)" 2
check "a checkpoint of another flow is refused with the reason" \
  sh -c "'$tool' vortex --period 2 --resume '$work/tracked/t1.5.obj' 2>&1 | grep -q 'a checkpoint of enright with T = 3, not of this run (vortex, T = 2)'"

# Angles where the mesh resolves the surface (--angles-only; bench/surface_resolution.hpp).
"$fidelity" "$work/tracked/t0.obj" --angles-only --json >"$work/sphere_angles.txt"
cat "$work/sphere_angles.txt"
sphere_resolved() {
  [ "$(figure "$work/sphere_angles.txt" unresolved_area)" = "0.00e+00" ] &&
    [ "$(figure "$work/sphere_angles.txt" min_angle_resolved)" = "$(figure "$work/sphere_angles.txt" min_angle)" ]
}
check "on the start sphere the surface is resolved everywhere: no triangle left out of its angles" sphere_resolved
sphere_error_resolved() {
  [ "$(figure "$work/start.txt" resolved_max)" = "$(figure "$work/start.txt" max)" ] &&
    [ "$(figure "$work/start.txt" resolved_rms)" = "$(figure "$work/start.txt" rms)" ]
}
check "and no sample is left out of its error" sphere_error_resolved
# A mesh never remeshed has needles all over its stretched sheet: most of it is unresolved.
advected_left_out() {
  below 0.5 "$(figure "$work/advected.txt" unresolved_area)" &&
    below "$(figure "$work/advected.txt" resolved_max)" "$(figure "$work/advected.txt" max)"
}
check "the mesh never remeshed leaves more than half its area unresolved, and its worst error there" advected_left_out
# A hairpin: a strip folded back onto itself, its two layers 0.005 apart and joined at the
# fold by needles (3 degrees) across the gap; the layers are right triangles of edge
# 0.125. The needles bend round something smaller than themselves, the layers do not.
awk 'BEGIN {
  print "# surfadapt checkpoint: flow enright period 3 time 0 centre 0 0 0 radius 1"
  for (j = 0; j <= 2; ++j) for (i = 0; i <= 8; ++i) printf "v %.17g %.17g 0\n", i / 8, j / 8
  for (j = 0; j <= 2; ++j) for (i = 0; i <= 8; ++i) printf "v %.17g %.17g 0.005\n", i < 8 ? i / 8 : 0.995, j / 8
  for (layer = 0; layer < 2; ++layer) for (j = 0; j < 2; ++j) for (i = 0; i < 8; ++i) {
    a = 27 * layer + 9 * j + i + 1; b = a + 1; c = a + 9; d = c + 1
    if (layer == 0) { print "f", a, c, b; print "f", b, c, d } else { print "f", a, b, c; print "f", b, d, c }
  }
  for (j = 0; j < 2; ++j) {
    a = 9 * j + 9; c = a + 9; e = 27 + a; g = 27 + c
    print "f", a, c, e; print "f", c, g, e
  }
}' >"$work/hairpin.obj"
"$fidelity" "$work/hairpin.obj" --angles-only --json >"$work/hairpin_angles.txt"
cat "$work/hairpin_angles.txt"
hairpin_judged() {
  below "$(figure "$work/hairpin_angles.txt" min_angle)" 5 &&
    [ "$(figure "$work/hairpin_angles.txt" below_5)" = 4 ] &&
    [ "$(figure "$work/hairpin_angles.txt" below_5_unresolved)" = 4 ] &&
    below 44.9 "$(figure "$work/hairpin_angles.txt" min_angle_resolved)" &&
    below 0 "$(figure "$work/hairpin_angles.txt" unresolved_area)" &&
    below "$(figure "$work/hairpin_angles.txt" unresolved_area)" 0.5
}
check "on a hairpin the needles across its fold are left out, the layers' right triangles kept" hairpin_judged
# The library's own measures of the same rule (SFA_MEASURE_UNRESOLVED_AREA and
# SFA_MEASURE_MIN_ANGLE_RESOLVED), as info prints them: the same figures (fidelity prints
# the share to three digits).
info_agrees() { # info_agrees MESH FIDELITY_JSON
  line=$("$tool" info "$1" | grep 'unresolved') || return 1
  echo "$line"
  share=$(echo "$line" | sed -n 's/.*: \([0-9.]*\) % of the area.*/\1/p')
  angle=$(echo "$line" | sed -n 's/.*angles from \([0-9.]*\) degrees.*/\1/p')
  awk -v s="$share" -v a="$angle" -v fs="$(figure "$2" unresolved_area)" -v fa="$(figure "$2" min_angle_resolved)" \
    'BEGIN { d = s - 100 * fs; e = a - fa; exit !(s != "" && a != "" && d * d < 1e-2 && e * e < 1e-4) }'
}
check "info gives the library's share left out and angle elsewhere, as fidelity does: the hairpin" \
  info_agrees "$work/hairpin.obj" "$work/hairpin_angles.txt"
check "... and the start sphere, nothing left out" info_agrees "$work/tracked/t0.obj" "$work/sphere_angles.txt"
# A tetrahedron turns by more than a right angle within every triangle: nothing is left to
# give an angle, and info says so rather than print the measure's "none" (180) as one.
check "info on a mesh unresolved everywhere says no triangle is left" \
  sh -c "printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' >'$work/tet.obj' &&
         '$tool' info '$work/tet.obj' | grep -q '100.00 % of the area; no triangle elsewhere'"

# The command line: options before the checkpoint as after it; --help on standard output;
# a wrong option or value named, with status 2.
check "options may come before the checkpoint: the same figures" \
  sh -c "'$fidelity' --angles-only --json '$work/tracked/t3.obj' >'$work/first.txt' &&
         '$fidelity' '$work/tracked/t3.obj' --angles-only --json >'$work/after.txt' && cmp -s '$work/first.txt' '$work/after.txt'"
check "--help explains the options on standard output and exits 0" \
  sh -c "'$fidelity' --help 2>/dev/null | grep -q -- '--worst K lists the K largest'"
check "an unknown option is named, with status 2" \
  sh -c "'$fidelity' '$work/tracked/t3.obj' --bogus 2>'$work/bogus.txt'; [ \$? -eq 2 ] && grep -q \"unknown option '--bogus'\" '$work/bogus.txt'"
check "a value that is not a count is named, not read as 0" \
  sh -c "'$fidelity' '$work/tracked/t3.obj' --worst --json 2>'$work/worst.txt'; [ \$? -eq 2 ] && grep -q \"at least 0, not '--json'\" '$work/worst.txt'"
check "a checkpoint named like an option is read after --" \
  sh -c "cp '$work/tracked/t0.obj' '$work/-t0.obj' && cd '$work' && '$PWD/$fidelity' --angles-only -- -t0.obj | grep -q '^-t0.obj: enright, T = 3, t = 0, '"
check "a mesh that is not a checkpoint is refused with the reason" \
  sh -c "printf 'v 0 0 0\n' >'$work/plain.obj'; '$fidelity' '$work/plain.obj' 2>&1 | grep -q 'not a surfadapt checkpoint'"

finish
