#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The `surfadapt remesh` command: refines a unit cube written as OBJ under build/, checks the
# summary and the VTK file it writes, and the failures (missing input, bad edge length,
# unknown option, missing arguments). Needs the tool built (`make`).
# Ends with "cli: N passed, M failed" and a non-zero status if anything failed.
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh

# [0,1]^3, two triangles per face, outward and counter-clockwise (1-based OBJ indices).
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n' >"$work/cube.obj"
printf 'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n' >>"$work/cube.obj"
printf 'f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n' >>"$work/cube.obj"

vtk=$work/cube.vtk
check "remesh the cube at edge length 0.25 exits 0" \
  sh -c "'$tool' remesh '$work/cube.obj' '$vtk' --edge-length 0.25 >'$work/out'"
check "the summary has the input and output rows" sh -c "grep -q '^  input ' '$work/out' && grep -q '^  output ' '$work/out'"
# output row: label, vertices, triangles, volume change, ...
rows=$(awk '$1 == "output" { print $2, $4 }' "$work/out")
vertices=${rows% *}
volume_change=${rows#* }
check "more vertices than the cube's 8 (got $vertices)" [ "${vertices:-0}" -gt 8 ]
check "volume unchanged (got $volume_change)" \
  awk -v c="$volume_change" 'BEGIN { exit !(c != "" && c + 0 < 1e-12 && c + 0 > -1e-12) }'
check "the VTK file has those points" grep -q "^POINTS $vertices double$" "$vtk"
check "and still the 8 corners' ranks among them" sh -c "grep -q '^SCALARS rank int 1$' '$vtk'"
check "the summary counts one closed component" grep -q "^  1 component: 1 closed, 0 open$" "$work/out"

# The same cube and, apart from it, one with every triangle turned round: inside-out.
awk '/^v / { print; printf "v %g %g %g\n", $2 + 3, $3, $4 }' "$work/cube.obj" >"$work/pair.obj"
awk '/^f / { printf "f %d %d %d\nf %d %d %d\n", 2 * $2 - 1, 2 * $3 - 1, 2 * $4 - 1, 2 * $2, 2 * $4, 2 * $3 }' \
  "$work/cube.obj" >>"$work/pair.obj"
check "info on two cubes exits 0" sh -c "'$tool' info '$work/pair.obj' >'$work/info'"
check "... and counts two closed components" grep -q "^  2 components: 2 closed, 0 open$" "$work/info"
check "... and warns that the second is inside-out" grep -q "closed component 1 is inside-out" "$work/info"
check "... and not the first" sh -c "! grep -q 'component 0 is inside-out' '$work/info'"
# From 8 vertices to an edge of 0.05 is more than one sfa_adapt call can do: the command
# keeps calling until the size settles, and says so.
check "remesh the cube at edge length 0.05 exits 0" \
  sh -c "'$tool' remesh '$work/cube.obj' '$vtk' --edge-length 0.05 >'$work/fine'"
ratio=$(sed -n 's/.*settled after [0-9]* sfa_adapt calls.*mean edge [0-9.e+-]*, \([0-9.]*\) l;$/\1/p' "$work/fine")
check "... says that it settled, with the mean edge in units of l (got '$ratio')" [ -n "$ratio" ]
check "... between 0.8 l and 1.2 l" awk -v r="$ratio" 'BEGIN { exit !(r >= 0.8 && r <= 1.2) }'
# A torus (genus 1) of 12 x 8 quads, and the cube without its top (one boundary loop).
awk 'BEGIN { n = 12; m = 8; pi = atan2(0, -1)
  for (i = 0; i < n; ++i) for (j = 0; j < m; ++j) {
    u = 2 * pi * i / n; w = 2 * pi * j / m
    printf "v %.12g %.12g %.12g\n", (1 + 0.4 * cos(w)) * cos(u), (1 + 0.4 * cos(w)) * sin(u), 0.4 * sin(w) }
  for (i = 0; i < n; ++i) for (j = 0; j < m; ++j) {
    a = i * m + j + 1; b = ((i + 1) % n) * m + j + 1; c = ((i + 1) % n) * m + (j + 1) % m + 1; d = i * m + (j + 1) % m + 1
    printf "f %d %d %d\nf %d %d %d\n", a, b, c, a, c, d } }' >"$work/torus.obj"
check "info on a torus exits 0" sh -c "'$tool' info '$work/torus.obj' >'$work/info'"
check "... and gives it genus 1" grep -q "^    0: closed, genus 1, volume" "$work/info"
check "... and the cube genus 0" sh -c "'$tool' info '$work/cube.obj' | grep -q '^    0: closed, genus 0, volume'"
grep -v '^f 5 6 7$' "$work/cube.obj" | grep -v '^f 5 7 8$' >"$work/open.obj"
check "info on the cube without its top exits 0" sh -c "'$tool' info '$work/open.obj' >'$work/info'"
check "... and finds one boundary loop of 4 edges" \
  grep -q "^    0: open, genus 0, 1 boundary loop (4 edges), area 5$" "$work/info"
check "remesh gives each closed component's volume change" \
  sh -c "'$tool' remesh '$work/pair.obj' '$work/pair.vtk' --edge-length 0.3 | grep -c 'closed, genus 0, .*volume change' | grep -qx 2"
check "--isotropic works too" "$tool" remesh "$work/cube.obj" "$work/iso.vtk" --edge-length 0.25 --isotropic

check "a missing input fails" sh -c "! '$tool' remesh '$work/missing.obj' '$work/x.vtk' 2>'$work/err'"
check "... naming the file" grep -q "missing.obj" "$work/err"
check "a negative edge length is refused" \
  sh -c "'$tool' remesh '$work/cube.obj' '$vtk' --edge-length -1 2>'$work/err'; [ \$? -eq 2 ]"
check "... saying what is wrong" grep -q "positive" "$work/err"
check "an unknown option is refused" sh -c "'$tool' remesh '$work/cube.obj' '$vtk' --bogus 2>/dev/null; [ \$? -eq 2 ]"
check "missing arguments are refused" sh -c "'$tool' remesh '$work/cube.obj' 2>/dev/null; [ \$? -eq 2 ]"
check "--version names the version, the ABI and the license" \
  sh -c "'$tool' --version | grep -Eq '^surfadapt [0-9]+[.][0-9]+[.][0-9]+ [(]ABI 1[)], BSD-3-Clause$'"

finish
