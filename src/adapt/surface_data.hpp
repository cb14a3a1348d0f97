// SPDX-License-Identifier: BSD-3-Clause
// What the host keeps on the surface besides its geometry, in the form smoothing and
// adaptation carry it: vertex fields (the velocities among them) and the size field are
// interpolated (fields/carried_fields.hpp), face fields remapped by overlap
// (fields/face_values.hpp), the constraints kept (adapt/constraints.hpp). An adaptation also
// gives back where each vertex came from (fields/vertex_origins.hpp).
#pragma once

#include "adapt/constraints.hpp"
#include "fields/vertex_fields.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

// ncomp densities per unit area per triangle, values[ncomp * t + c]: the shape of a vertex
// field, on the triangles.
using FaceField = VertexField;

struct SurfaceData {
    std::vector<VertexField> fields;    // the host's vertex fields, and the velocities if set
    std::vector<double> size;           // the desired edge length per vertex; empty: the global l
    std::vector<FaceField> face_fields; // the host's
    Constraints constraints;            // fixed vertices, required edges
    // Out of an adaptation: a triangle of the mesh as it was near each vertex of the result
    // (OriginHints), from which locate_origins finds the vertex's origin.
    std::vector<int32_t> origin_hints;
};

} // namespace sfa
