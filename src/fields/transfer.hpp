// Carrying host fields to vertices that moved on the surface.
#pragma once

#include "fields/vertex_fields.hpp"
#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// The fields at the moved positions: each moved vertex takes the barycentric interpolation
// of the old values in the triangle of its old star that its new position lies over (the
// one where its smallest barycentric coordinate is largest), so that a field linear on a
// flat region stays exactly linear. Vertices that did not move keep their values.
std::vector<VertexField> fields_at_moved_vertices(const TriMesh &old_mesh, const std::vector<Vec3> &moved,
                                                  const std::vector<VertexField> &fields);

} // namespace sfa
