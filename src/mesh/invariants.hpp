// SPDX-License-Identifier: BSD-3-Clause
// The one checker of the mesh invariants (DESIGN.md): used by the tests after every
// operation and by the SFA_ERR_INTERNAL guards after operations that change connectivity.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <string>

namespace sfa {

// "" if the mesh is a consistent oriented manifold with valid adjacency; otherwise what
// is wrong, naming the element (0-based).
std::string invariant_violation(const TriMesh &mesh);

} // namespace sfa
