// The connected components of a mesh (vertices joined by edges): the bubbles, drops and
// sheets of a multiphase interface. Each closed component encloses a volume of its own.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

struct Components {
    int32_t count = 0;
    // Per vertex, 0 ... count-1. connected_components numbers them in the order in which
    // each component's first vertex comes (API.md); a labelling carried through changes of
    // the mesh (vertex_labels.hpp) keeps the numbers of the mesh it was made for.
    std::vector<int32_t> of_vertex;
    // Per component: whether it has no boundary edge.
    std::vector<char> closed;
};

Components connected_components(const TriMesh &mesh);

// The triangles of component c as a mesh of their own: its vertices in the order they have
// in `mesh`, its triangles likewise, with their adjacency.
TriMesh component_mesh(const TriMesh &mesh, const Components &components, int32_t c);

} // namespace sfa
