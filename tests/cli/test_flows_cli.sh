#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Short runs of the paper's flows through the command-line tool (coarse spheres, part of a
# period; the full runs are `make bench`): they finish, keep the volume within 0.5 %, never
# fold the surface (no two neighbouring triangles' normals more than 150 degrees apart, no
# two triangles crossing at any row of the table), and write a VTK time series ParaView
# can open: binary appended .vtu steps with the point data rank, component and velocity,
# and a .pvd of increasing times. Needs the tool built (`make`).
# Ends with "cli: N passed, M failed" and a non-zero status if anything failed.
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh

# The summary line: "volume error at the end V % (worst W %), ... largest normal turn N deg,
# self-intersections at most X"
summary_ok() { # $1 = output file
  awk '/^volume error at the end/ {
         v = $6; w = $9; sub(/\(worst /, "", w)
         n = 180; x = -1
         for (i = 1; i <= NF; i++) { if ($i == "turn") n = $(i + 1); if ($i == "most") x = $(i + 1) }
         found = 1
         if (v < 0) v = -v; if (w < 0) w = -w
         exit !(v < 0.5 && w < 0.5 && n < 150 && x == 0)
       }
       END { if (!found) exit 1 }' "$1"
}

check "enright (a coarse sphere of 1002 vertices, 60 steps) exits 0" \
  sh -c "'$tool' enright --resolution 10 --steps 60 --report-every 20 --out '$work/enright' >'$work/enright.txt'"
cat "$work/enright.txt"
check "enright: volume within 0.5 %, no fold" summary_ok "$work/enright.txt"
check "enright: the time series lists 4 saved steps" \
  sh -c "[ \$(grep -c '<DataSet ' '$work/enright/surface.pvd') -eq 4 ]"
check "enright: each step is a VTK unstructured grid" grep -q 'UnstructuredGrid' "$work/enright/surface_0003.vtu"
# Binary appended, not ASCII: the XML part says so and no array is inline text.
step="$work/enright/surface_0003.vtu"
check "enright: the steps are binary appended raw" \
  sh -c "grep -aq '<AppendedData encoding=\"raw\">' '$step' && ! grep -aq 'format=\"ascii\"' '$step' &&
         ! grep -aq 'format=\"binary\"' '$step'"
for array in 'Int32" Name="rank" NumberOfComponents="1"' 'Int32" Name="component" NumberOfComponents="1"' \
             'Float64" Name="velocity" NumberOfComponents="3"'; do
  check "enright: point data $array" \
    awk -v a="$array" '/<PointData>/ { p = 1 } /<\/PointData>/ { p = 0 } p && index($0, a) { f = 1 } END { exit !f }' "$step"
done
got=$("$tool" info "$step" 2>&1 | awk 'NR == 1 { print $2, $4 }')
check "enright: info reads a step back, as the file says ('$got')" \
  [ "$got" = "$(sed -n 's/.*<Piece NumberOfPoints="\([0-9]*\)" NumberOfCells="\([0-9]*\)".*/\1 \2/p' "$step")" ]
check "enright: the collection's times increase from 0, each with its file" \
  awk -F'"' '/<DataSet / { n++; t = $2 + 0; f = $8
                            if ((n == 1 && t != 0) || (n > 1 && t <= last) || f != sprintf("surface_%04d.vtu", n - 1)) bad = 1
                            last = t }
             END { exit bad || n != 4 }' "$work/enright/surface.pvd"

check "vortex --period 2 (coarse, 60 steps) exits 0" \
  sh -c "'$tool' vortex --period 2 --resolution 10 --steps 60 --report-every 20 --json >'$work/vortex.txt'"
cat "$work/vortex.txt"
check "vortex: volume within 0.5 %, no fold" summary_ok "$work/vortex.txt"
check "vortex --json: the summary as one JSON line with the phase times" \
  grep -q '^{"bench":"flow","flow":"Vortex flow, T = 2",.*"advect_s":.*"adapt_s":' "$work/vortex.txt"

check "enright --denoise 1 (coarse, 60 steps) exits 0" \
  sh -c "'$tool' enright --resolution 10 --steps 60 --report-every 60 --denoise 1 >'$work/denoised.txt'"
cat "$work/denoised.txt"
check "enright --denoise 1: volume within 0.5 %, no fold" summary_ok "$work/denoised.txt"

check "--no-volume-correction turns the correction off (and the run says so)" \
  sh -c "'$tool' enright --resolution 4 --steps 4 --no-volume-correction --json >'$work/nocorr.txt' &&
         grep -q 'volume correction off' '$work/nocorr.txt' && grep -q '\"volume_correction\":0,' '$work/nocorr.txt'"
check "--no-crossing-guard turns the guard off (and the run says so)" \
  sh -c "'$tool' enright --resolution 4 --steps 2 --no-crossing-guard | grep -q 'crossing guard off'"
check "--help after a command prints the usage and exits 0" \
  sh -c "'$tool' vortex --help | grep -q -- '--denoise W'"
check "a denoising weight outside [0, 1] is refused" sh -c "'$tool' enright --denoise 2 2>/dev/null; [ \$? -eq 2 ]"
check "vortex refuses a period other than 2 or 6" \
  sh -c "'$tool' vortex --period 3 2>/dev/null; [ \$? -eq 2 ]"
check "an unknown option is refused" sh -c "'$tool' enright --bogus 2>/dev/null; [ \$? -eq 2 ]"
# The error stays on the screen: the command's synopsis follows it, not the whole help.
check "an unknown option is named, then the command's synopsis only" \
  sh -c "'$tool' enright --bogus 2>'$work/bogus.txt'; head -n 1 '$work/bogus.txt' | grep -q \"unknown option '--bogus'\" &&
         grep -q '^usage: surfadapt enright .*--resolution N' '$work/bogus.txt' &&
         grep -q -- '--json' '$work/bogus.txt' && [ \$(wc -l <'$work/bogus.txt') -le 8 ]"
check "an unknown command lists the commands" \
  sh -c "'$tool' bogus 2>&1 | grep -q 'the commands are demo, enright, vortex, remesh, info, repair, features and convert'"
check "an unwritable output directory fails" \
  sh -c "! '$tool' enright --resolution 4 --steps 1 --out '$work/no/such/dir' >/dev/null 2>&1"

finish
