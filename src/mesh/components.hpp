// SPDX-License-Identifier: BSD-3-Clause
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
    // the mesh (vertex_labels.hpp) keeps the numbers of the mesh it was made for, until
    // index_components numbers it in that order again.
    std::vector<int32_t> of_vertex;
    // Per component: whether it has no boundary edge.
    std::vector<char> closed;
    // Component c's triangles, in mesh order: triangles[triangle_start[c] ... triangle_start[c + 1]).
    // Filled by connected_components and index_components; empty in a carried labelling.
    std::vector<int32_t> triangle_start, triangles;
};

// The components, numbered and indexed.
Components connected_components(const TriMesh &mesh);

// Numbers `components` (a labelling of `mesh`'s vertices, carried through its changes) in
// the order in which each component's first vertex comes, as connected_components would,
// and lists each component's triangles. O(vertices + triangles).
void index_components(const TriMesh &mesh, Components &components);

// The triangles of component c as a mesh of their own: its vertices in the order they have
// in `mesh`, its triangles likewise, with their adjacency. O(size of the component):
// `components` must be indexed.
TriMesh component_mesh(const TriMesh &mesh, const Components &components, int32_t c);

} // namespace sfa
