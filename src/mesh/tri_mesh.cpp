// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/tri_mesh.hpp"

#include "mesh/vertex_star.hpp"

namespace sfa {

void build_adjacency(TriMesh &mesh)
{
    const VertexStar star(mesh.num_vertices(), mesh.tri);
    link_twins(mesh, star);
    assign_vertex_halfedges(mesh, star);
}

} // namespace sfa
