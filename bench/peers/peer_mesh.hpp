// SPDX-License-Identifier: BSD-3-Clause
// What the peer benchmarks (cgal_enright, cgal_static) share: moving a mesh between the
// flat arrays surfadapt and its generators use and a CGAL::Surface_mesh, and the figures
// both remeshers' results are judged by, computed by one function for either side so that
// a difference is the remeshers', not the measuring's. Header-only: CGAL never enters the
// library or the tool, only these programs (make bench-peers).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using PeerMesh = CGAL::Surface_mesh<Point>;

// A mesh as flat arrays: 3 coordinates per vertex, 3 0-based vertex indices per triangle.
struct FlatMesh {
    std::vector<double> xyz;
    std::vector<int32_t> tris;
    int32_t vertices() const { return static_cast<int32_t>(xyz.size() / 3); }
    int32_t triangles() const { return static_cast<int32_t>(tris.size() / 3); }
};

using PeerClock = std::chrono::steady_clock;
inline double seconds_since(PeerClock::time_point start)
{
    return std::chrono::duration<double>(PeerClock::now() - start).count();
}

// Vertex i of the arrays becomes vertex i of the mesh: the generators' meshes are closed
// and oriented, so every face is accepted (a refused face means the input is broken).
inline bool to_peer_mesh(int32_t nverts, const double *xyz, int32_t ntris, const int32_t *tris, PeerMesh &mesh)
{
    mesh.clear();
    mesh.reserve(nverts, 3 * static_cast<size_t>(ntris) / 2, ntris);
    for (int32_t v = 0; v < nverts; ++v)
        mesh.add_vertex(Point(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]));
    for (int32_t t = 0; t < ntris; ++t) {
        const PeerMesh::Vertex_index a(tris[3 * t]), b(tris[3 * t + 1]), c(tris[3 * t + 2]);
        if (mesh.add_face(a, b, c) == PeerMesh::null_face())
            return false;
    }
    return true;
}

// The mesh as arrays, its vertices numbered as Surface_mesh numbers them once the removed
// elements are collected (the caller collects them: remeshing leaves holes in the numbering).
inline FlatMesh to_flat_mesh(const PeerMesh &mesh)
{
    FlatMesh flat;
    flat.xyz.reserve(3 * mesh.number_of_vertices());
    for (PeerMesh::Vertex_index v : mesh.vertices()) {
        const Point &p = mesh.point(v);
        flat.xyz.insert(flat.xyz.end(), {p.x(), p.y(), p.z()});
    }
    flat.tris.reserve(3 * mesh.number_of_faces());
    for (PeerMesh::Face_index f : mesh.faces())
        for (PeerMesh::Vertex_index v : mesh.vertices_around_face(mesh.halfedge(f)))
            flat.tris.push_back(static_cast<int32_t>(v.idx()));
    return flat;
}

// The triangles' angles: the smallest and largest of any, in degrees (as bench/fidelity
// measures the checkpoints), and the share of triangles with every angle in [15, 160]
// degrees (the paper's bounds; the tool's remesh table calls it "% good").
struct AngleFigures {
    double smallest = 180, largest = 0, good_share = 0;
};

inline AngleFigures angle_figures(const FlatMesh &mesh)
{
    AngleFigures f;
    int32_t good = 0;
    for (int32_t t = 0; t < mesh.triangles(); ++t) {
        bool within = true;
        for (int k = 0; k < 3; ++k) {
            const double *a = &mesh.xyz[3 * mesh.tris[3 * t + k]], *b = &mesh.xyz[3 * mesh.tris[3 * t + (k + 1) % 3]],
                         *c = &mesh.xyz[3 * mesh.tris[3 * t + (k + 2) % 3]];
            const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            const double cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
            const double angle = std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
                                            u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) *
                                 180 / 3.14159265358979323846;
            f.smallest = std::min(f.smallest, angle);
            f.largest = std::max(f.largest, angle);
            within = within && angle >= 15 && angle <= 160;
        }
        good += within;
    }
    f.good_share = mesh.triangles() > 0 ? static_cast<double>(good) / mesh.triangles() : 0;
    return f;
}

// The mean length of the mesh's edges, each counted once (as SFA_MEASURE_MEAN_EDGE_LENGTH).
inline double mean_edge_length(const PeerMesh &mesh)
{
    double sum = 0;
    for (PeerMesh::Edge_index e : mesh.edges())
        sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(mesh.halfedge(e))),
                                                mesh.point(mesh.target(mesh.halfedge(e)))));
    return sum / static_cast<double>(mesh.number_of_edges());
}

// The median of the samples; the upper one of an even count.
inline double median_of(std::vector<double> samples)
{
    std::sort(samples.begin(), samples.end());
    return samples[samples.size() / 2];
}
