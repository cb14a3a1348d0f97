#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# The `surfadapt repair` command on meshes as they come from elsewhere, each refused by the
# library for one reason: a bow-tie vertex, quadrilaterals with a duplicate and an unused
# vertex, a polygon whose fan has a zero-area triangle, a concave polygon whose fan turns
# over, an inside-out body, one triangle turned round. Each must come out accepted, with
# the change reported; `info` on the broken file names what repair would do.
# Ends with "cli: N passed, M failed" and a non-zero status if anything failed.
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh

# $1 = file, $2 = what the report must say, $3 = expected volume (or "-" for none)
repaired() {
  name=$(basename "$1" .obj)
  check "info refuses $name.obj" sh -c "! '$tool' info '$1' >/dev/null 2>'$work/$name.info'"
  check "... and says that repair would $2" grep -q "^  $2" "$work/$name.info"
  check "repair $name.obj exits 0" sh -c "'$tool' repair '$1' '$work/$name-fixed.off' >'$work/$name.out'"
  check "... reporting that it $2" grep -q "^  $2" "$work/$name.out"
  check "... and that the library accepts the result" grep -q "^  the library accepts it$" "$work/$name.out"
  check "... which info accepts" sh -c "'$tool' info '$work/$name-fixed.off' >'$work/$name.after'"
  if [ "$3" != "-" ]; then
    volume=$(sed -n 's/^  volume \([^,]*\),.*/\1/p' "$work/$name.after")
    check "... with volume $3 (got $volume)" awk -v v="$volume" -v w="$3" 'BEGIN { exit !(v - w < 1e-9 && w - v < 1e-9) }'
  fi
}

# Two tetrahedra that touch at one vertex.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv -1 0 0\nv 0 -1 0\nv 0 0 -1\n' >"$work/bowtie.obj"
printf 'f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nf 1 5 6\nf 1 7 5\nf 1 6 7\nf 5 7 6\n' >>"$work/bowtie.obj"
repaired "$work/bowtie.obj" "split 1 bow-tie vertex" 0.333333333

# The unit cube as quadrilaterals, its top given twice, and a vertex no face uses.
cube_vertices='v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n'
printf "${cube_vertices}v 5 5 5\n" >"$work/quads.obj"
printf 'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\nf 5 6 7 8\n' >>"$work/quads.obj"
repaired "$work/quads.obj" "dropped 2 duplicate triangles" 1
check "... and the unused vertex" grep -q "^  dropped 1 vertex no triangle uses" "$work/quads.out"

# A prism over the pentagon (0,0) (1,0) (2,0) (2,2) (0,2): fanned from its first corner,
# the first triangle has three collinear corners.
printf 'v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\nv 0 0 1\nv 1 0 1\nv 2 0 1\nv 2 2 1\nv 0 2 1\n' >"$work/collinear.obj"
printf 'f 1 5 4 3 2\nf 6 7 8 9 10\nf 1 2 7 6\nf 2 3 8 7\nf 3 4 9 8\nf 4 5 10 9\nf 5 1 6 10\n' >>"$work/collinear.obj"
repaired "$work/collinear.obj" "triangulated 2 polygons by ear clipping" 4

# A prism over the chevron (0,0) (2,1) (0,2) (1,1): fanned from (0,0), one triangle covers
# the notch and the next folds back over it. The library takes that (it checks connectivity,
# not overlap), so the count shows it: the prism's area is 2 + 2 sqrt(5) + 2 sqrt(2) =
# 9.30056, the fans' 13.30056. Ear clipping gives the right one.
printf 'v 0 0 0\nv 2 1 0\nv 0 2 0\nv 1 1 0\nv 0 0 1\nv 2 1 1\nv 0 2 1\nv 1 1 1\n' >"$work/chevron.obj"
printf 'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' >>"$work/chevron.obj"
check "info on the fanned chevron prism counts the folded area" \
  sh -c "'$tool' info '$work/chevron.obj' | grep -q '^  volume 1, area 13.30056'"
check "repair triangulates its polygons" \
  sh -c "'$tool' repair '$work/chevron.obj' '$work/chevron-fixed.obj' | grep -q '^  triangulated 2 polygons by ear clipping'"
check "... into the prism's true area" \
  sh -c "'$tool' info '$work/chevron-fixed.obj' | grep -q '^  volume 1, area 9.30056'"

# The cube inside-out: every triangle clockwise seen from outside.
printf "$cube_vertices" >"$work/inside-out.obj"
printf 'f 1 2 3\nf 1 3 4\nf 5 7 6\nf 5 8 7\nf 1 6 2\nf 1 5 6\nf 2 7 3\nf 2 6 7\nf 3 8 4\nf 3 7 8\nf 4 5 1\nf 4 8 5\n' \
  >>"$work/inside-out.obj"
check "info accepts the inside-out cube but warns" sh -c "'$tool' info '$work/inside-out.obj' | grep -q 'is inside-out'"
check "repair turns it outward" sh -c "'$tool' repair '$work/inside-out.obj' '$work/outward.obj' | grep -q '^  turned 1 closed component outward'"
check "... to volume 1" sh -c "'$tool' info '$work/outward.obj' | grep -q '^  volume 1, '"

# The cube with one triangle turned round.
printf "$cube_vertices" >"$work/one-turned.obj"
printf 'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 8 5\n' \
  >>"$work/one-turned.obj"
repaired "$work/one-turned.obj" "turned 1 triangle round" 1

# Three triangles on one edge (a fin) become three sheets.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n' >"$work/fin.obj"
repaired "$work/fin.obj" "separated the triangles at 1 edge of three or more" -
check "... into three open components" \
  sh -c "'$tool' info '$work/fin-fixed.off' | grep -q '^  3 components: 0 closed, 3 open$'"

# What no repair can decide is left and said: a Moebius strip.
awk 'BEGIN { n = 12; pi = atan2(0, -1)
  for (i = 0; i < n; ++i) for (j = 0; j < 2; ++j) {
    u = 2 * pi * i / n; w = (j - 0.5) * 0.4
    printf "v %.12g %.12g %.12g\n", (1 + w * cos(u / 2)) * cos(u), (1 + w * cos(u / 2)) * sin(u), w * sin(u / 2) }
  for (i = 0; i < n; ++i) {
    a = 2 * i + 1; b = a + 1; c = 2 * ((i + 1) % n) + 1; d = c + 1
    if (i == n - 1) { t = c; c = d; d = t }
    printf "f %d %d %d\nf %d %d %d\n", a, c, d, a, d, b } }' >"$work/moebius.obj"
check "repair of a Moebius strip fails" sh -c "! '$tool' repair '$work/moebius.obj' '$work/m.obj' >'$work/m.out'"
check "... saying it left it" grep -q "^  left 1 component that cannot be oriented" "$work/m.out"
check "... and why the library refuses it" grep -q "^  the library still refuses it: " "$work/m.out"
check "an unknown output extension is refused" sh -c "'$tool' repair '$work/fin.obj' '$work/x.xyz' 2>/dev/null; [ \$? -eq 2 ]"
check "missing arguments are refused" sh -c "'$tool' repair '$work/fin.obj' 2>/dev/null; [ \$? -eq 2 ]"

finish
