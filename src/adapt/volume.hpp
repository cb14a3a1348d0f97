// Keeping the enclosed volume of a closed surface through adaptation.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

// Moves every smooth vertex (rank 0) along its outward normal (the direction of its volume
// gradient) by one common distance, so that the enclosed volume becomes `volume` again.
// Splitting and contraction put vertices on the quadric error minimum, which smooths the
// surface and so changes its volume at second order in the edge length (+1.1 % when a
// coarse model like spot is refined to half its edge length); a uniform offset is the
// smallest change of shape that gives it back. Features do not move. The volume is an
// exact cubic in the offset, solved by Newton's method, so the result is exact to
// round-off; nothing
// moves if the offset would fold a triangle. Only for closed surfaces (an open one
// encloses no volume).
void restore_enclosed_volume(TriMesh &mesh, const std::vector<int8_t> &rank, double volume);

} // namespace sfa
