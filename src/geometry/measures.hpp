// Global measures a host watches on its interface: enclosed volume (divergence theorem),
// area, angles, edge lengths, triangle aspect ratio.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace sfa {

// Signed volume sum over triangles of a.(b x c)/6: positive for a closed surface whose
// normals point out; for an open surface the same sum, which depends on the origin.
double enclosed_volume(const TriMesh &mesh);
// The same with the mesh's vertices at `positions` instead.
double enclosed_volume(const TriMesh &mesh, const std::vector<Vec3> &positions);

// The gradient of enclosed_volume with respect to vertex v's position: moving v alone by d
// changes the volume by exactly gradient.d, since each term a.(b x c) is linear in v. It
// points outward; its length is a third of the area of v's fan when the fan is flat.
Vec3 volume_gradient(const TriMesh &mesh, int32_t v);
double surface_area(const TriMesh &mesh);

struct AngleRange {
    double min_degrees;
    double max_degrees;
};
AngleRange angle_range(const TriMesh &mesh);

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
