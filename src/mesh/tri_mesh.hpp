// SPDX-License-Identifier: BSD-3-Clause
// The array-based half-edge (half-facet) triangle mesh (DESIGN.md, "Data structure").
//
// Half-edge h = 3*t + i is edge i of triangle t, running from corner i to corner i+1.
// opp[h] is the twin half-edge in the neighbouring triangle, or -1 on a boundary.
// v2h[v] is one half-edge leaving v; for a boundary vertex it is the one whose twin is
// missing, so that a counter-clockwise walk from it (rotate_ccw) visits the whole fan.
#pragma once

#include <Eigen/Dense>

#include <array>
#include <cstdint>
#include <vector>

namespace sfa {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int32_t, 3>;

// Whether two triangles have a corner in common (neighbours, for the tests of crossing).
inline bool share_a_vertex(const Triangle &p, const Triangle &q)
{
    for (int32_t v : p)
        if (v == q[0] || v == q[1] || v == q[2])
            return true;
    return false;
}

struct TriMesh {
    std::vector<Vec3> pos;
    std::vector<Triangle> tri;
    std::vector<int32_t> opp;
    std::vector<int32_t> v2h;

    int32_t num_vertices() const { return static_cast<int32_t>(pos.size()); }
    int32_t num_triangles() const { return static_cast<int32_t>(tri.size()); }

    static int32_t face(int32_t h) { return h / 3; }
    static int32_t next(int32_t h) { return h - h % 3 + (h + 1) % 3; }
    static int32_t prev(int32_t h) { return h - h % 3 + (h + 2) % 3; }
    int32_t tail(int32_t h) const { return tri[h / 3][h % 3]; }
    int32_t head(int32_t h) const { return tri[h / 3][(h + 1) % 3]; }
    bool is_boundary_halfedge(int32_t h) const { return opp[h] < 0; }
    bool is_boundary_vertex(int32_t v) const { return opp[v2h[v]] < 0; }
    // No boundary: every half-edge has its twin.
    bool is_closed() const {
        for (int32_t twin : opp)
            if (twin < 0)
                return false;
        return true;
    }

    // The next half-edge leaving the same vertex, counter-clockwise; -1 past a boundary.
    int32_t rotate_ccw(int32_t h) const { return opp[prev(h)]; }

    // Calls fn(w, h) for every neighbour w of v, with h the half-edge of the edge (v, w)
    // seen from v's fans: leaving v (v -> w), or for the last neighbour of a boundary vertex
    // the boundary half-edge arriving at v (w -> v).
    template <class Fn>
    void for_each_neighbour(int32_t v, Fn &&fn) const {
        int32_t last = -1;
        for_each_outgoing(v, [&](int32_t h) {
            fn(head(h), h);
            last = h;
        });
        const int32_t incoming = prev(last);
        if (opp[incoming] < 0)
            fn(tail(incoming), incoming);
    }

    // The half-edge a -> b, or -1 if there is none (a boundary edge has only one of its two
    // directions). O(valence of a).
    int32_t halfedge(int32_t a, int32_t b) const {
        int32_t found = -1;
        for_each_outgoing(a, [&](int32_t h) {
            if (head(h) == b)
                found = h;
        });
        return found;
    }

    // Calls fn(f) for the one or two triangles of the edge of h.
    template <class Fn>
    void for_each_face_of_edge(int32_t h, Fn &&fn) const {
        fn(face(h));
        if (opp[h] >= 0)
            fn(face(opp[h]));
    }

    // Calls fn(f) once for every triangle around either end of h's edge (the edge's own
    // included): the tail's fan counter-clockwise, then the rest of the head's.
    template <class Fn>
    void for_each_face_around_edge(int32_t h, Fn &&fn) const {
        const int32_t a = tail(h);
        for_each_outgoing(a, [&](int32_t g) { fn(face(g)); });
        for_each_outgoing(head(h), [&](int32_t g) {
            const Triangle &t = tri[face(g)];
            if (t[0] != a && t[1] != a && t[2] != a)
                fn(face(g)); // not seen from the tail already
        });
    }

    // Calls fn(h) for every half-edge leaving v, counter-clockwise from v2h[v].
    template <class Fn>
    void for_each_outgoing(int32_t v, Fn &&fn) const {
        const int32_t start = v2h[v];
        int32_t h = start;
        do {
            fn(h);
            h = rotate_ccw(h);
        } while (h >= 0 && h != start);
    }
};

// Builds opp and v2h from pos and tri. Requires a valid oriented manifold (as checked by
// validate_mesh); it does not check anything itself.
void build_adjacency(TriMesh &mesh);

} // namespace sfa
