// Compaction after contractions: dead vertices and triangles removed, the survivors kept
// in their order, so that the host gets dense arrays in a deterministic order.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// Removes dead elements (see edge_collapse.hpp) and renumbers. Returns, for every old
// vertex, its new number, or -1 if it was dead; callers renumber their vertex data with it.
std::vector<int32_t> compact(TriMesh &mesh);

} // namespace sfa
