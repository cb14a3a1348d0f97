// SPDX-License-Identifier: BSD-3-Clause
// Global measures a host watches on its interface: enclosed volume (divergence theorem),
// area, angles, edge lengths, triangle aspect ratio.
#pragma once

#include "mesh/components.hpp"
#include "mesh/tri_mesh.hpp"

namespace sfa {

// Signed volume sum over triangles of a.(b x c)/6: positive for a closed surface whose
// normals point out; for an open surface the same sum, which depends on the origin. A
// closed component's sum does not, and is taken about its own centre (component_centres):
// about the origin, the terms of a unit sphere at (1e5, 1e5, 1e5) are 1e15 each and cancel
// to a volume of 4, with 15 of the 16 digits lost; about its centre they lose none.
double enclosed_volume(const TriMesh &mesh);
// The same with the mesh's components known (a handle keeps them: finding them again cost
// as much as the sum itself).
double enclosed_volume(const TriMesh &mesh, const Components &components);

// The centre of each component's bounding box (label[v] in [0, count) the component of
// vertex v; a component without vertices gets the origin): the point about which its
// volume and everything else summed over it is computed, so that the sums keep as many
// digits as the coordinates give its shape wherever it lies. Min and max are exact: the
// same centres for any order of the vertices.
std::vector<Vec3> component_centres(const std::vector<Vec3> &positions, const std::vector<int32_t> &label,
                                    int32_t count);

// The gradient of a closed component's enclosed volume with respect to vertex v's
// position: moving v alone by d changes the volume by exactly gradient.d, since each term
// a.(b x c) is linear in v. Summed about v itself, sum (b - v) x (c - v) / 6 over v's fan,
// which for a closed fan is the same as about any point and loses no digits to the
// distance from the origin (for a boundary vertex it is the gradient of the sum about v).
// It points outward; its length is a third of the area of v's fan when the fan is flat.
Vec3 volume_gradient(const TriMesh &mesh, int32_t v);
double surface_area(const TriMesh &mesh);

struct AngleRange {
    double min_degrees;
    double max_degrees;
};
// Over every triangle, or with `left_out`, over those with left_out[t] == 0; with none
// left, min_degrees is infinite and max_degrees 0.
AngleRange angle_range(const TriMesh &mesh, const std::vector<char> *left_out = nullptr);

struct EdgeLengths {
    double min;
    double mean;
    double max;
};
// Each undirected edge once.
EdgeLengths edge_lengths(const TriMesh &mesh);

// Worst circumradius / (2 inradius) over the triangles: 1 for equilateral ones.
double max_aspect_ratio(const TriMesh &mesh);

// Largest angle between the normals of two triangles sharing an edge, degrees (180 at a
// fold); 0 for a mesh without interior edges.
double max_normal_turn_degrees(const TriMesh &mesh);

} // namespace sfa
