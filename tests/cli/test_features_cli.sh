#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The `surfadapt features` command: writes a unit cube as OBJ into a scratch directory
# under build/, converts it, and checks the legacy VTK file (sections, counts, the ranks of
# the cube) and the failures (unreadable input, unwritable output, unknown option,
# unreferenced vertex with and without --drop-unreferenced). Needs the tool built (`make`).
# Ends with "cli: N passed, M failed" and a non-zero status if anything failed.
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh

# [0,1]^3, two triangles per face, outward and counter-clockwise (1-based OBJ indices).
cat >"$work/cube.obj" <<'OBJ'
v 0 0 0
v 1 0 0
v 1 1 0
v 0 1 0
v 0 0 1
v 1 0 1
v 1 1 1
v 0 1 1
f 1 3 2
f 1 4 3
f 5 6 7
f 5 7 8
f 1 2 6
f 1 6 5
f 4 8 7
f 4 7 3
f 1 5 8
f 1 8 4
f 2 3 7
f 2 7 6
OBJ
# The same cube with a ninth vertex no face uses.
{ cat "$work/cube.obj"; echo "v 5 5 5"; } >"$work/extra.obj"

vtk=$work/cube.vtk
check "features on the cube exits 0" "$tool" features "$work/cube.obj" "$vtk"
has() { grep -q "$1" "$vtk"; }
check "legacy VTK header" has '^# vtk DataFile Version'
check "POLYDATA" has '^DATASET POLYDATA$'
check "8 POINTS" has '^POINTS 8 double$'
check "12 POLYGONS" has '^POLYGONS 12 48$'
check "12 LINES (the cube's edges are ridges)" has '^LINES 12 36$'
check "CELL_DATA for 24 cells with scalar ridge" has '^CELL_DATA 24$'
check "SCALARS ridge" has '^SCALARS ridge int 1$'
check "POINT_DATA for 8 points" has '^POINT_DATA 8$'
check "SCALARS rank" has '^SCALARS rank int 1$'
check "SCALARS aspect_ratio" has '^SCALARS aspect_ratio double 1$'
check "VECTORS long_direction" has '^VECTORS long_direction double$'
check "VECTORS normal" has '^VECTORS normal double$'
# The 8 values after the rank header (and its lookup table line) are all 2: corners.
ranks=$(sed -n '/^SCALARS rank/{n;n;p;n;p;n;p;n;p;n;p;n;p;n;p;n;p;}' "$vtk" | sort -u | tr -d '\n')
check "every cube vertex has rank 2 (got '$ranks')" [ "$ranks" = 2 ]
# Cell data: 12 ones (the lines come first in VTK's cell order), then 12 zeros.
ridge=$(sed -n '/^SCALARS ridge/,/^POINT_DATA/p' "$vtk" | sed -n '3,26p' | tr -d '\n')
check "ridge cell data: 12 lines then 12 triangles (got '$ridge')" [ "$ridge" = 111111111111000000000000 ]

check "a missing input fails" sh -c "! '$tool' features '$work/missing.obj' '$work/x.vtk' 2>'$work/err'"
check "... naming the file" grep -q "missing.obj" "$work/err"
check "an unwritable output fails" \
  sh -c "! '$tool' features '$work/cube.obj' '$work/no/such/dir/x.vtk' 2>'$work/err'"
check "... naming the file" grep -q "no/such/dir/x.vtk" "$work/err"
check "an unknown option fails" sh -c "! '$tool' features '$work/cube.obj' '$vtk' --bogus 2>/dev/null"
check "missing arguments fail" sh -c "! '$tool' features '$work/cube.obj' 2>/dev/null"
check "an unreferenced vertex is refused" sh -c "! '$tool' features '$work/extra.obj' '$work/e.vtk' 2>/dev/null"
check "--drop-unreferenced drops it" "$tool" features "$work/extra.obj" "$work/e.vtk" --drop-unreferenced
check "... leaving 8 points" grep -q '^POINT_DATA 8$' "$work/e.vtk"

finish
