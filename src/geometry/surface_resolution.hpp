// SPDX-License-Identifier: BSD-3-Clause
// Where a mesh does not resolve its surface (SFA_MEASURE_UNRESOLVED_AREA,
// SFA_MEASURE_MIN_ANGLE_RESOLVED). A triangle is in such a place when the surface turns by
// more than a right angle within the triangle's own size: the surface connected to it
// within its longest edge of its centroid holds two triangles whose normals are more than
// 90 degrees apart. That is the rim of a sheet thinner than the triangle (its two sides
// face each other there), a filament thinner than it, or a crease sharper than a right
// angle; in each the triangle would have to bend round something smaller than itself, and
// no placement of its corners gives it good angles (the vortex flow with T = 6 leaves all
// its triangles below 5 degrees in such places, doc/flows.md). On a mesh that resolves
// its surface (a sphere of 15 edges round turns by 24 degrees an edge) no triangle
// qualifies.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

// 1 for each triangle near which the surface turns by more than a right angle within its
// own size (above), 0 for the others. The surface round triangle t is what a walk from t
// across edges reaches through triangles that come nearer to t's centroid than t's longest
// edge: the far side of a thin sheet, across the sheet, is not part of it (each side of a
// flat film may be meshed well), the sheet's rim is. A triangle without area has no
// normal and faces against nothing. Each walk visits at most 512 triangles (a ball holds a
// few dozen on a mesh of any quality; a fan of hundreds of slivers stops there).
std::vector<char> unresolved_triangles(const TriMesh &mesh);

struct ResolvedAngles {
    double unresolved_area; // the share of the area in triangles marked, in [0, 1]; 0 without area
    double min_degrees;     // the smallest angle of any triangle not marked; 180 if every one is
};

// `unresolved`: unresolved_triangles(mesh).
ResolvedAngles resolved_angles(const TriMesh &mesh, const std::vector<char> &unresolved);

} // namespace sfa
