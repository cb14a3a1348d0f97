// SPDX-License-Identifier: BSD-3-Clause
// Renumbering for locality: after adaptation has appended thousands of new vertices and
// triangles, the fans of neighbouring vertices lie far apart in memory, and every
// per-vertex loop (analysis, smoothing, flipping) waits on cache misses. Ordering the
// vertices along a space-filling curve, and the triangles by their first vertex in that
// order, makes those loops about twice as fast on a surface adapted through a flow.
#pragma once

#include "mesh/renumbering.hpp"
#include "mesh/tri_mesh.hpp"

namespace sfa {

// Renumbers the vertices in Morton (Z-curve) order of their positions in the bounding box,
// ties by old number, and the triangles by their smallest new vertex, ties by old number:
// deterministic. Corners keep their order within each triangle. Returns the renumbering;
// callers renumber their element data with it.
Renumbering order_for_locality(TriMesh &mesh);

} // namespace sfa
