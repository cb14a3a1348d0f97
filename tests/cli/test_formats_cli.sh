#!/bin/sh
# SPDX-License-Identifier: BSD-3-Clause
# Mesh file formats of the tool, chosen by extension both ways: every format is written
# (by convert, remesh and features) and read back by info with the same counts and volume;
# binary STL whose header says "solid", ASCII STL corners merged, PLY big-endian with
# other elements, Medit quadrilaterals, legacy VTK 5.1 and ASCII .vtu are read; an
# unknown extension is an error naming the supported ones; messages number vertices as
# the file does (OBJ and Medit from 1), and reader errors name the line or byte.
# Needs the tool built (`make`). Ends with "cli: N passed, M failed".
set -u
cd "$(dirname "$0")/../.." || exit 1

. tests/cli/cli_testing.sh
export OMP_WAIT_POLICY=${OMP_WAIT_POLICY:-passive}

# [0,1]^3, two triangles per face, outward and counter-clockwise (1-based OBJ indices).
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n' >"$work/cube.obj"
printf 'f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n' >>"$work/cube.obj"
printf 'f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n' >>"$work/cube.obj"

# "VERTICES TRIANGLES VOLUME" from info's first two lines.
counts() { "$tool" info "$1" 2>&1 | awk 'NR == 1 { v = $2; t = $4 } NR == 2 { sub(",", "", $2); print v, t, $2 }'; }

for ext in obj off stl ply mesh vtk vtu OBJ Ply; do
  check "convert the cube to .$ext" sh -c "'$tool' convert '$work/cube.obj' '$work/cube.$ext' >/dev/null"
  got=$(counts "$work/cube.$ext")
  check "info reads .$ext back: 8 vertices, 12 triangles, volume 1 (got '$got')" [ "$got" = "8 12 1" ]
done

# The remeshed cube: its coordinates are no longer small binary fractions, so exact
# formats must give the volume to every digit info prints and binary STL (float32) close.
check "remesh the cube to .obj" sh -c "'$tool' remesh '$work/cube.obj' '$work/r.obj' --edge-length 0.3 >/dev/null"
reference=$(counts "$work/r.obj")
check "the remeshed cube has more than 8 vertices (got '$reference')" [ "${reference%% *}" -gt 8 ]
for ext in off ply mesh vtk vtu stl; do
  check "remesh the cube to .$ext" sh -c "'$tool' remesh '$work/cube.obj' '$work/r.$ext' --edge-length 0.3 >/dev/null"
  got=$(counts "$work/r.$ext")
  if [ "$ext" = stl ]; then
    check "binary STL reads back with the counts and the volume within float precision ($got, $reference)" \
      awk -v a="$got" -v b="$reference" 'BEGIN { split(a, x); split(b, y)
        exit !(x[1] == y[1] && x[2] == y[2] && x[3] - y[3] < 1e-6 && y[3] - x[3] < 1e-6) }'
  else
    check ".$ext reads back the same ('$got', '$reference')" [ "$got" = "$reference" ]
  fi
done
check "features to .vtu exits 0" sh -c "'$tool' features '$work/cube.obj' '$work/f.vtu' >/dev/null"
check "... with the rank as point data" grep -q 'Name="rank"' "$work/f.vtu"
check "... binary appended, UInt64 headers" grep -q 'header_type="UInt64"' "$work/f.vtu"
got=$(counts "$work/f.vtu")
check "... and info reads it (got '$got')" [ "$got" = "8 12 1" ]
check "features to .vtk still writes the ridges" sh -c "'$tool' features '$work/cube.obj' '$work/f.vtk' >/dev/null &&
  grep -q '^LINES 12 36$' '$work/f.vtk'"
got=$(counts "$work/f.vtk")
check "... and info reads its own .vtk with the lines in it (got '$got')" [ "$got" = "8 12 1" ]

# Unknown extensions: an error naming the supported ones, before any work.
supported='.obj, .off, .stl, .ply, .mesh, .vtk, .vtu'
check "remesh to .foo is refused with status 2" \
  sh -c "'$tool' remesh '$work/cube.obj' '$work/x.foo' >/dev/null 2>'$work/err'; [ \$? -eq 2 ]"
check "... naming the supported extensions" grep -qF "$supported" "$work/err"
check "... and writes nothing" [ ! -e "$work/x.foo" ]
check "info on .foo fails naming them" sh -c "cp '$work/cube.obj' '$work/cube.foo'; ! '$tool' info '$work/cube.foo' 2>'$work/err' &&
  grep -qF '$supported' '$work/err'"
check "a file without an extension too" sh -c "! '$tool' convert '$work/cube.obj' '$work/noext' 2>'$work/err' &&
  grep -qF '$supported' '$work/err'"

# STL: a binary file whose header starts with "solid" is binary by its size; ASCII corners
# with equal coordinates are one vertex.
{
  echo "solid tetra"
  for f in "0 0 0|0 1 0|1 0 0" "0 0 0|1 0 0|0 0 1" "0 0 0|0 0 1|0 1 0" "1 0 0|0 1 0|0 0 1"; do
    printf '  facet normal 0 0 0\n    outer loop\n'
    echo "$f" | tr '|' '\n' | sed 's/^/      vertex /'
    printf '    endloop\n  endfacet\n'
  done
  echo "endsolid tetra"
} >"$work/ascii.stl"
got=$(counts "$work/ascii.stl")
check "ASCII STL: shared corners merged to 4 vertices (got '$got')" [ "$got" = "4 4 0.166666667" ]
"$tool" convert "$work/ascii.stl" "$work/tetra.stl" >/dev/null
printf 'solid' | dd of="$work/tetra.stl" conv=notrunc 2>/dev/null
check "the binary STL now starts with 'solid'" [ "$(head -c 5 "$work/tetra.stl")" = solid ]
got=$(counts "$work/tetra.stl")
check "binary STL with a 'solid' header: 4 vertices, 4 triangles (got '$got')" [ "$got" = "4 4 0.166666667" ]

# PLY: ASCII with other properties and elements.
cat >"$work/tetra.ply" <<'PLY'
ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
property uchar red
element face 4
property list uchar int vertex_index
property int flags
element edge 1
property int vertex1
property int vertex2
end_header
0 0 0 255
1 0 0 0
0 1 0 0
0 0 1 0
3 0 2 1 7
3 0 1 3 7
3 0 3 2 7
3 1 2 3 7
0 1
PLY
got=$(counts "$work/tetra.ply")
check "ASCII PLY with other properties and elements (got '$got')" [ "$got" = "4 4 0.166666667" ]

# Medit: quadrilaterals become two triangles; the sections MMG adds are read past.
cat >"$work/quads.mesh" <<'MESH'
MeshVersionFormatted 1
Dimension
3
Vertices
8
0 0 0 1
1 0 0 1
1 1 0 1
0 1 0 1
0 0 1 1
1 0 1 1
1 1 1 1
0 1 1 1
Quadrilaterals
6
1 4 3 2 1
5 6 7 8 1
1 2 6 5 1
4 8 7 3 1
1 5 8 4 1
2 3 7 6 1
Edges
1
1 2 0
Corners
1
1
Ridges
1
1
End
MESH
got=$(counts "$work/quads.mesh")
check "Medit quadrilaterals, edges, corners, ridges (got '$got')" [ "$got" = "8 12 1" ]

# Numbers in messages are the file's: 1-based for OBJ and Medit, 0-based for OFF.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 2 1 0\nv 2 2 0\nf 1 2 3\nf 3 4 5\n' >"$work/bowtie.obj"
check "a bow-tie in OBJ is named by its OBJ number" sh -c "! '$tool' info '$work/bowtie.obj' 2>'$work/err' &&
  grep -q 'vertex 3 is a bow-tie' '$work/err'"
"$tool" convert "$work/bowtie.obj" "$work/bowtie.off" >/dev/null
"$tool" convert "$work/bowtie.obj" "$work/bowtie.mesh" >/dev/null
check "... in OFF by its OFF number" sh -c "! '$tool' info '$work/bowtie.off' 2>'$work/err' &&
  grep -q 'vertex 2 is a bow-tie' '$work/err'"
check "... in Medit by its Medit number" sh -c "! '$tool' info '$work/bowtie.mesh' 2>'$work/err' &&
  grep -q 'vertex 3 is a bow-tie' '$work/err'"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' >"$work/range.obj"
check "an OBJ index past the last vertex is named as in the file" sh -c "! '$tool' info '$work/range.obj' 2>'$work/err' &&
  grep -q 'triangle 1 uses vertex 9, but there are 3 vertices (numbered 1 to 3)' '$work/err'"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\n# a comment\nf 1 2 0\n' >"$work/zero.obj"
check "OBJ index 0 is a reader error naming the line" sh -c "! '$tool' info '$work/zero.obj' 2>'$work/err' &&
  grep -q 'zero.obj:5: index 0: OBJ indices start at 1' '$work/err'"

# Reader errors name the line (text) or the byte (binary data).
printf 'MeshVersionFormatted 2\nDimension 3\nVertices\n2\n0 0 0 0\n1 x 0 0\nEnd\n' >"$work/bad.mesh"
check "a Medit error names its line" sh -c "! '$tool' info '$work/bad.mesh' 2>'$work/err' && grep -q 'bad.mesh:6: vertex 2' '$work/err'"
head -c 400 "$work/r.ply" >"$work/cut.ply"
check "a binary PLY cut short names the byte" sh -c "! '$tool' info '$work/cut.ply' 2>'$work/err' &&
  grep -q 'cut.ply: byte [0-9]*: element vertex' '$work/err'"
printf '# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 double\n0 0 0\n1 0 0\n0 1\nPOLYGONS 1 4\n3 0 1 2\n' \
  >"$work/bad.vtk"
check "a legacy VTK error names its line" sh -c "! '$tool' info '$work/bad.vtk' 2>'$work/err' && grep -q 'bad.vtk:9: point 2' '$work/err'"

finish
