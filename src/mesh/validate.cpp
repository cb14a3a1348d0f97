// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/validate.hpp"

#include "mesh/coordinate_range.hpp"
#include "mesh/error.hpp"
#include "mesh/vertex_star.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace sfa {
namespace {

template <class... Args>
[[noreturn]] void reject(const char *format, Args... args)
{
    char message[512];
    std::snprintf(message, sizeof message, format, args...);
    throw Error(Status::mesh, message);
}

// Copies the triangles to 0-based indices, checking range and repeated corners.
std::vector<Triangle> checked_triangles(const MeshInput &in)
{
    const int32_t base = in.index_base;
    std::vector<Triangle> tri(in.num_triangles);
    for (int32_t t = 0; t < in.num_triangles; ++t) {
        for (int k = 0; k < 3; ++k) {
            const int32_t v = in.tris[3 * t + k];
            if (v < base || v - base >= in.num_vertices)
                reject("triangle %d uses vertex %d, but there are %d vertices (numbered %d to %d)", t + base, v,
                       in.num_vertices, base, in.num_vertices - 1 + base);
            tri[t][k] = v - base;
        }
        const Triangle &c = tri[t];
        if (c[0] == c[1] || c[0] == c[2] || c[1] == c[2]) {
            const int32_t twice = (c[0] == c[1] || c[0] == c[2]) ? c[0] : c[1];
            reject("triangle %d uses vertex %d twice", t + base, twice + base);
        }
    }
    return tri;
}

std::vector<Vec3> checked_positions(const MeshInput &in)
{
    std::vector<Vec3> pos(in.num_vertices);
    for (int32_t v = 0; v < in.num_vertices; ++v) {
        const double *p = in.xyz + 3 * static_cast<size_t>(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            reject("vertex %d has a non-finite coordinate (%g, %g, %g)", v + in.index_base, p[0], p[1], p[2]);
        pos[v] = Vec3(p[0], p[1], p[2]);
        if (!coordinate_in_range(pos[v]))
            reject("vertex %d at (%g, %g, %g) has a coordinate outside the range the library computes in (%s)",
                   v + in.index_base, p[0], p[1], p[2], coordinate_range_text());
    }
    return pos;
}

// The mesh's size, once the unreferenced vertices are gone: below the range, every product
// of its coordinate differences underflows (a good sphere of radius 1e-100 looked flat).
void check_extent(const std::vector<Vec3> &pos)
{
    const double extent = extent_of(pos);
    if (!(extent >= min_extent))
        reject("the mesh spans only %g (the diagonal of its bounding box), outside the range the library computes "
               "in (%s); give it in other units",
               extent, coordinate_range_text());
}

// Unreferenced vertices: an error, or removed with the triangles renumbered.
void handle_unreferenced(const MeshInput &in, std::vector<Vec3> &pos, std::vector<Triangle> &tri)
{
    std::vector<int32_t> new_index(pos.size(), -1);
    for (const Triangle &t : tri)
        for (int32_t v : t)
            new_index[v] = 0;
    int32_t kept = 0;
    for (size_t v = 0; v < pos.size(); ++v) {
        if (new_index[v] == 0) {
            new_index[v] = kept;
            pos[kept++] = pos[v];
        } else if (!in.drop_unreferenced) {
            reject("vertex %d is used by no triangle (unreferenced); set SFA_PARAM_DROP_UNREFERENCED to 1 "
                   "to drop such vertices",
                   static_cast<int32_t>(v) + in.index_base);
        }
    }
    if (kept == static_cast<int32_t>(pos.size()))
        return;
    pos.resize(kept);
    for (Triangle &t : tri)
        for (int32_t &v : t)
            v = new_index[v];
}

// Zero area up to round-off: twice the area is no more than a few ulps of the squared
// longest edge, i.e. the corners are collinear or coincide in floating point. Written so
// that NaN fails it too (within the coordinate range none arises).
void check_areas(const std::vector<Vec3> &pos, const std::vector<Triangle> &tri, const std::vector<int32_t> &host_id,
                 int32_t base)
{
    const double tolerance = 4 * std::numeric_limits<double>::epsilon();
    for (size_t t = 0; t < tri.size(); ++t) {
        const Vec3 &a = pos[tri[t][0]], &b = pos[tri[t][1]], &c = pos[tri[t][2]];
        const double longest2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
        if (!((b - a).cross(c - a).norm() > tolerance * longest2))
            reject("triangle %d has zero area (its vertices %d, %d, %d are collinear or coincide)",
                   static_cast<int32_t>(t) + base, host_id[tri[t][0]] + base, host_id[tri[t][1]] + base,
                   host_id[tri[t][2]] + base);
    }
}

// Two triangles on the same three vertices, in any rotation or orientation: both are in
// the star of their smallest vertex, so only that star is searched.
void check_duplicates(const TriMesh &mesh, const VertexStar &star, const std::vector<int32_t> &host_id, int32_t base)
{
    const auto sorted = [](Triangle t) {
        std::sort(t.begin(), t.end());
        return t;
    };
    for (int32_t t = 0; t < mesh.num_triangles(); ++t) {
        const Triangle corners = sorted(mesh.tri[t]);
        for (int32_t k = star.begin(corners[0]); k < star.end(corners[0]); ++k) {
            const int32_t other = TriMesh::face(star.outgoing[k]);
            if (other < t && sorted(mesh.tri[other]) == corners)
                reject("triangles %d and %d use the same three vertices (%d, %d, %d)", other + base, t + base,
                       host_id[corners[0]] + base, host_id[corners[1]] + base, host_id[corners[2]] + base);
        }
    }
}

// Every edge has one or two triangles, and two triangles traverse it in opposite directions.
void check_edges(const TriMesh &mesh, const VertexStar &star, const std::vector<int32_t> &host_id, int32_t base)
{
    std::vector<int32_t> sharing;
    const int32_t num_halfedges = 3 * mesh.num_triangles();
    for (int32_t h = 0; h < num_halfedges; ++h) {
        const int32_t a = mesh.tail(h), b = mesh.head(h);
        sharing.clear();
        for (int32_t k = star.begin(a); k < star.end(a); ++k)
            if (star.head[k] == b)
                sharing.push_back(star.outgoing[k]);
        const size_t same_direction = sharing.size();
        for (int32_t k = star.begin(b); k < star.end(b); ++k)
            if (star.head[k] == a)
                sharing.push_back(star.outgoing[k]);
        if (sharing.size() == 1 || *std::min_element(sharing.begin(), sharing.end()) != h)
            continue; // a boundary edge, or an edge already looked at from its first half-edge
        if (sharing.size() == 2 && same_direction == 1)
            continue; // a proper interior edge
        std::vector<int32_t> faces;
        for (int32_t g : sharing)
            faces.push_back(TriMesh::face(g) + base);
        std::sort(faces.begin(), faces.end());
        const int32_t lo = host_id[std::min(a, b)] + base, hi = host_id[std::max(a, b)] + base;
        if (faces.size() > 2) {
            std::string list;
            for (size_t i = 0; i < faces.size(); ++i)
                list += (i ? ", " : "") + std::to_string(faces[i]);
            reject("edge (%d, %d) is shared by %d triangles: %s (an edge may have at most two)", lo, hi,
                   static_cast<int>(faces.size()), list.c_str());
        }
        reject("triangles %d and %d traverse edge (%d, %d) in the same direction: inconsistent orientation",
                   faces[0], faces[1], lo, hi);
    }
}

// The triangles around each vertex form one fan (a disk or half-disk), not several
// touching at the vertex only.
void check_fans(const TriMesh &mesh, const VertexStar &star, const std::vector<int32_t> &host_id, int32_t base)
{
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        int32_t visited = 0;
        mesh.for_each_outgoing(v, [&](int32_t) { ++visited; });
        if (visited != star.valence(v))
            reject("vertex %d is a bow-tie: its %d triangles do not form one fan, one fan around it has only %d "
                   "(non-manifold vertex)",
                   host_id[v] + base, star.valence(v), visited);
    }
}

} // namespace

TriMesh validated_mesh(const MeshInput &in)
{
    if (in.num_triangles == 0)
        throw Error(Status::mesh, "the mesh has no triangles");
    TriMesh mesh;
    mesh.pos = checked_positions(in);
    mesh.tri = checked_triangles(in);

    // Messages name vertices as the host numbered them, also after dropping some.
    std::vector<int32_t> host_id;
    {
        std::vector<char> used(in.num_vertices, 0);
        for (const Triangle &t : mesh.tri)
            for (int32_t v : t)
                used[v] = 1;
        for (int32_t v = 0; v < in.num_vertices; ++v)
            if (used[v])
                host_id.push_back(v);
    }
    handle_unreferenced(in, mesh.pos, mesh.tri);

    const int32_t base = in.index_base;
    check_extent(mesh.pos);
    check_areas(mesh.pos, mesh.tri, host_id, base);
    const VertexStar star(mesh.num_vertices(), mesh.tri);
    check_duplicates(mesh, star, host_id, base);
    check_edges(mesh, star, host_id, base);
    link_twins(mesh, star);
    assign_vertex_halfedges(mesh, star);
    check_fans(mesh, star, host_id, base);
    return mesh;
}

} // namespace sfa
