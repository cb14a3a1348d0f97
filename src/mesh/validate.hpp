// SPDX-License-Identifier: BSD-3-Clause
// Complete validation of a host's mesh (sfa_set_mesh): every defect gets Status::mesh and
// a message that names the element and the rule, in the host's own index base.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cstdint>

namespace sfa {

struct MeshInput {
    int32_t num_vertices;
    const double *xyz;   // 3 * num_vertices
    int32_t num_triangles;
    const int32_t *tris; // 3 * num_triangles, in index_base
    int32_t index_base;  // 0 or 1
    bool drop_unreferenced;
};

// Returns the validated mesh with its adjacency built, or throws Error(Status::mesh).
// Vertices no triangle uses are an error, or dropped (the others keep their order) when
// input.drop_unreferenced is set.
TriMesh validated_mesh(const MeshInput &input);

} // namespace sfa
