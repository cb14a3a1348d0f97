// SPDX-License-Identifier: BSD-3-Clause
// Compaction after contractions: dead vertices and triangles removed, the survivors kept
// in their order, so that the host gets dense arrays in a deterministic order.
#pragma once

#include "mesh/renumbering.hpp"
#include "mesh/tri_mesh.hpp"

namespace sfa {

// Removes dead elements (see edge_collapse.hpp) and renumbers them in order (keeps_order).
// Returns the renumbering; callers renumber their element data with it.
Renumbering compact(TriMesh &mesh);

} // namespace sfa
