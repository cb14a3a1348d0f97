// SPDX-License-Identifier: BSD-3-Clause
// The area two triangles have in common in a plane, and the conservative remap it gives:
// values per unit area on one set of triangles carried to another set covering the same
// region, each new triangle taking the old values in proportion to how much of it lies
// over each old triangle (first-order conservative remapping: Dukowicz and Kodis 1987,
// "Accurate conservative remapping (rezoning) for arbitrary Lagrangian-Eulerian
// computations"; Farrell et al. 2009, "Conservative interpolation between unstructured
// meshes via supermesh construction"). FaceValues uses it for every change of a fan.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <array>
#include <cstdint>

namespace sfa {

// A point of a 2-D chart. Plain doubles rather than Eigen: the clipping loop below is the
// remap's inner loop and its buffers are small arrays on the stack.
struct ChartPoint {
    double x, y;
};

// The area common to triangles a and b, in either orientation: b's three half-planes clip
// a (Sutherland-Hodgman; a triangle is convex, so the clipped polygon is their
// intersection). Robust to degenerate and sliver triangles: never NaN or negative (for
// finite corners), 0 where either is degenerate or they are disjoint, and never more than
// the smaller of the two areas.
double overlap_area(const ChartPoint a[3], const ChartPoint b[3]);

// A triangle's corners in space.
using Corners = std::array<Vec3, 3>;

// The area of triangle (a, b, c) in space, as the remap measures every integral (and
// FaceValues with it, so that every change counts integrals alike).
double triangle_area(const Vec3 &a, const Vec3 &b, const Vec3 &c);

// How remap_by_overlap shared the integral.
enum class RemapPath {
    overlap, // by overlap in the chart, then one correction that makes the total exact
    shared,  // by area alone: the region's mean density on every new triangle (the fallback)
};

// The largest number of old or new triangles remap_by_overlap maps by overlap; beyond it
// (a fan no remeshing operation makes: a contracted edge's fan is the two ends' valences)
// it shares by area. Bounds its stack buffers.
constexpr int32_t max_overlap_faces = 64;

// Remaps ncomp densities per unit area from n_old triangles old_faces (old_values[ncomp *
// i + c]) to n_new triangles new_faces covering the same region (new_values[ncomp * j +
// c], written), both projected onto a plane normal to `normal` (any length; the region's
// area-weighted normal, for a fan). Where a triangle is turned over seen along it (a steep
// fan), the normal is tilted until every triangle faces it, if a few rounds find such a
// direction.
//
// Each new triangle takes the mean of the old densities weighted by its overlap with each
// old triangle in the chart: the integral of the old piecewise-constant density over it,
// per unit of the area it has over old triangles (dividing by that area rather than by the
// triangle's own keeps a constant density constant to round-off, slivers included, where
// the two sets tile the same region). Then the total is made to match the old one, sum of
// old density x old 3-D area, exactly to round-off: a component whose new densities are all
// of one sign is scaled by the ratio of the totals (which keeps the sign of a
// concentration); one of both signs, whose sum may be near zero, gets the difference spread
// in proportion to area. The mismatch so removed is round-off, and what a curved region
// leaves: the 3-D areas of the two sets differ where the region is not flat.
//
// It falls back to sharing by area (RemapPath::shared; conservative, but it smears the
// region to its mean) where the overlap cannot be trusted: a triangle turned over in every
// chart tried (the sets then do not tile one region once: a folded fan), a degenerate
// normal or region, or more than max_overlap_faces triangles on either side. A new
// triangle of zero area takes the region's mean density (it carries nothing, and a
// constant stays constant). No allocation.
RemapPath remap_by_overlap(const Corners *old_faces, const double *old_values, int32_t n_old,
                           const Corners *new_faces, double *new_values, int32_t n_new, int32_t ncomp,
                           const Vec3 &normal);

} // namespace sfa
