// SPDX-License-Identifier: BSD-3-Clause
// Which side of the surface a triangle faces, and the rule that no operation of an
// adaptation or a smoothing turns a face over against it (issue 18).
//
// The paper fits and smooths each smooth vertex's fan as a height over the vertex's tangent
// plane (§2.2, §3.2). That holds while every face of the fan projects onto the plane with
// its own orientation: while each face's normal has a positive component along the side
// the surface faces at that vertex. A face that turns over is where the surface folds
// through itself.
//
// Each operation bounds how far one change turns a face relative to the face just before
// it: a contraction by 60 degrees (§4.2), a split's halves, a flip's faces (§3.3) and a
// smoothing sweep (§3.2) short of a right angle. A chain of changes can still turn a face
// over step by step: on a shallow cone of 200 or 1000 slivers, splits put the spokes'
// midpoints on the fitted paraboloid and tilted the slivers by up to 83 degrees,
// contractions tilted them further, and a sweep turned them the rest of the way; the next
// passes folded the fan through itself. The side the surface faces at a vertex is an
// absolute reference that no face's own turning walks along:
//
//  - it is the sum of the area vectors of the vertex's faces (SurfaceAnalysis::fan_area),
//    which around an interior vertex is the vector area of the closed loop of its
//    neighbours, whatever the faces between the vertex and that loop do;
//  - not the quadric's normal e1 (§2.2): its normal-voting tensor weighs each face by its
//    area but is blind to the sign of its normal, so a fan made only of tilted slivers
//    (the cone's apex) votes for a normal in the tangent plane.
//
// The rule applies at smooth vertices (rank 0): at a ridge or a corner the faces have no
// one side, and a boundary vertex's loop is open. A face that already faced away (the tip
// of a sheet folded back within one fan) is left to the operations' own bounds.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <algorithm>
#include <vector>

namespace sfa {

// The steepest a face may stand to the side the surface faces at a smooth corner, as the
// cosine of the angle between the two: 60 degrees, the turn a contraction allows a face
// (§4.2, contract.cpp), measured here from the surface instead of from the face before the
// change. On a smooth mesh a face stands far less steeply at its corners (at most 37
// degrees on an icosahedron; a vertex where its faces differ by more than the ridge angle
// is a feature), so the bound binds only where a change would stand a face on its side:
// the vortex flow of T = 2 gives the same figures to every printed digit. Not 90 degrees
// (turned over only): a face standing on its side has no reliable orientation, and once a
// vertex's fan is all such slivers its own side tilts with them. Measured on the shallow
// fans of 200 and 1000 slivers (three calls each): a bound of 90 degrees left 2 and 28
// triangles facing down, 70 degrees 1 and 0, 80 degrees none but neighbours folded by up
// to 145 degrees; 60 left none, neighbours within 59 degrees, as split points that would
// have stood the slivers up fell back to the edge's centre.
constexpr double cos_steepest_face = 0.5;

// True if a change that makes a face's area vector `after` from `before` turns it from
// the side `side` (a vertex's fan_area): the face faced that side and now stands steeper
// than cos_steepest_face (or turns away, or is flat); a face already that steep may not
// stand any steeper. A face that faced away (or stood on its side) is left alone.
// `before_length` and `after_length` are the norms of the two (a face's corners share them).
inline bool turns_from_surface(const Vec3 &before, const Vec3 &after, const Vec3 &side, double before_length,
                               double after_length)
{
    const double along = before.dot(side);
    if (!(along > 0))
        return false;
    // Nearly every face stands within 56 degrees of the side (cosine above sqrt(0.3), with
    // room for the rounding of both tests), which it may whatever it did before: no roots.
    const double after_along = after.dot(side);
    if (after_along > 0 && after_along * after_along >= 0.3 * (after_length * after_length) * side.squaredNorm())
        return false;
    const double side_length = side.norm();
    const double cos_before = along / (before_length * side_length);
    const double cos_after = after_along / (after_length * side_length);
    return !(cos_after > 0 && cos_after >= std::min(cos_before, cos_steepest_face));
}

inline bool turns_from_surface(const Vec3 &before, const Vec3 &after, const Vec3 &side)
{
    return turns_from_surface(before, after, side, before.norm(), after.norm());
}

// The side the surface faces at v (fan_area: the analysis's, as the pass found it); for a
// vertex made since that analysis (a split of the same pass), its fan's now.
inline Vec3 surface_side(const TriMesh &mesh, const std::vector<Vec3> &fan_area, int32_t v)
{
    if (v < static_cast<int32_t>(fan_area.size()))
        return fan_area[v];
    Vec3 sum = Vec3::Zero();
    mesh.for_each_outgoing(v, [&](int32_t h) {
        const Triangle &t = mesh.tri[TriMesh::face(h)];
        sum += (mesh.pos[t[1]] - mesh.pos[t[0]]).cross(mesh.pos[t[2]] - mesh.pos[t[0]]);
    });
    return sum;
}

// turns_from_surface at corner v of the face, if v is smooth (feature rank 0).
inline bool turns_at_corner(const TriMesh &mesh, const std::vector<Vec3> &fan_area, int rank, int32_t v,
                            const Vec3 &before, const Vec3 &after)
{
    return rank == 0 && turns_from_surface(before, after, surface_side(mesh, fan_area, v));
}

} // namespace sfa
