// SPDX-License-Identifier: BSD-3-Clause
// Keeping the enclosed volume of every closed component (bubble, drop) on its own.
#pragma once

#include "geometry/crossing_guard.hpp"
#include "mesh/mesh_edit.hpp"

#include <cstdint>
#include <vector>

namespace sfa {

// The enclosed volume of each component: label[v] in [0, count) names the component of
// vertex v, and a triangle belongs to its first corner's.
std::vector<double> component_volumes(const TriMesh &mesh, const std::vector<int32_t> &label, int32_t count);

// For every closed component c (closed[c]) whose volume is no longer volume[c]: moves its
// smooth vertices (rank 0) along their outward normals (the direction of the volume
// gradient) by one distance, so that the component encloses volume[c] again. Splitting
// and contraction put vertices on the quadric error minimum, which smooths the surface and
// so changes its volume at second order in the edge length (+1.1 % when a coarse model
// like spot is refined to half its edge length); a uniform offset per component is the
// smallest change of shape that gives it back, and no volume moves from one component to
// another. Features do not move; open components are not corrected. The volume is an
// exact cubic in the offset, solved by Newton's method, so the result is exact to
// round-off. Where the offset would fold a triangle, bring two sheets together (an offset
// above a hundredth of the component's thickness is certified) or, with a crossing guard,
// carry a face through a watched face (at a fold sharper than the offset is small, the
// two sides can be nearer than the offset), the corners of those triangles are held and
// the rest of the component takes the volume back (a few rounds; then the component is
// left as it is). With `correct` false, nothing moves. The vertices move
// through `edit` (MeshEdit::offset); a guard is left indexed at the new positions.
// Returns, as relative volume changes |V - volume[c]| / |volume[c]| of closed components:
struct VolumeRestoration {
    // the largest before the correction: how far the operations themselves came from
    // keeping the volume;
    double largest_change = 0;
    // the largest the correction left, where it was withheld: a component with no smooth
    // vertex, whose offset would fold a triangle or carry it through another sheet (with
    // `correct` false, every change is left).
    double largest_left = 0;
};
VolumeRestoration restore_enclosed_volumes(MeshEdit &edit, const std::vector<int8_t> &rank,
                                           const std::vector<int32_t> &label, const std::vector<double> &volume,
                                           const std::vector<char> &closed, bool correct,
                                           CrossingGuard *guard = nullptr);

} // namespace sfa
