// Whether a surface passes through itself: the one sure sign that a surface was folded
// over. A sharp edge or a cusp (the rim of a sheet thinner than an edge) turns the normals
// of two neighbouring triangles by nearly 180 degrees without any crossing; a surface
// folded back over itself crosses itself.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// True if the closed triangles (a0, a1, a2) and (b0, b1, b2) share a point (Moller's
// interval test; coplanar triangles by their edges and corners in the plane). Distances
// to the other triangle's plane below 1e-12 of the pair's size count as zero.
bool triangles_intersect(const Vec3 &a0, const Vec3 &a1, const Vec3 &a2, const Vec3 &b0, const Vec3 &b1,
                         const Vec3 &b2);

// The number of pairs of triangles that share no vertex yet intersect (touching counts).
// Pairs are found through the spatial grid, cells of twice the mean edge length; the count is
// the same for any number of threads.
int32_t self_intersection_count(const TriMesh &mesh);

} // namespace sfa
