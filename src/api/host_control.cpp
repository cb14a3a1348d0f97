// SPDX-License-Identifier: BSD-3-Clause
// What a coupled solver controls: sfa_set_size_field, sfa_set_fixed_vertices,
// sfa_set_required_edges (the size field and the constraints are carried by
// adapt/size_field.hpp and adapt/constraints.hpp).
#include "api/boundary.hpp"

#include <algorithm>
#include <cmath>

using namespace sfa;

namespace {

// For a mesh that is set, `edge_length` not NULL.
void set_size_field(sfa_surface *s, const double *edge_length)
{
    // A length that is not a number or infinite is a non-finite field value, as for the
    // other fields (SFA_ERR_NUMERIC); a finite one <= 0 is out of range (SFA_ERR_ARGUMENT).
    const int32_t n = s->mesh.num_vertices();
    for (int32_t v = 0; v < n; ++v)
        if (!(std::isfinite(edge_length[v]) && edge_length[v] > 0)) {
            char message[160];
            std::snprintf(message, sizeof message,
                          "vertex %d has the desired edge length %g; it must be finite and > 0", v + s->index_base,
                          edge_length[v]);
            fail(std::isfinite(edge_length[v]) ? Status::argument : Status::numeric, message);
        }
    std::vector<double> size(edge_length, edge_length + n);
    s->size_field.swap(size);
}

void require_index_list(int32_t count, const int32_t *indices, int32_t index_base)
{
    require(count >= 0, "count must be >= 0");
    require(indices != nullptr || count == 0, "the index array is NULL and count > 0");
    require(index_base == 0 || index_base == 1, "index_base must be 0 or 1");
}

// The vertex that `index` (at position `position` of the host's array) names, or an error
// in the host's numbering.
int32_t vertex_named(const sfa_surface *s, const char *array, int64_t position, int32_t index, int32_t index_base)
{
    const int32_t v = index - index_base;
    if (v < 0 || v >= s->mesh.num_vertices()) {
        char message[200];
        std::snprintf(message, sizeof message, "%s[%lld] = %d is not a vertex: the mesh has %d, numbered from %d",
                      array, static_cast<long long>(position), index, s->mesh.num_vertices(), index_base);
        fail(Status::argument, message);
    }
    return v;
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_set_size_field(sfa_surface *s, const double *edge_length)
{
    return call(s, "sfa_set_size_field", [&] {
        require_mesh(s);
        if (edge_length)
            set_size_field(s, edge_length);
        else
            s->size_field.clear();
    });
}

SFA_EXPORT int sfa_set_size_field_checked(sfa_surface *s, int32_t nverts, const double *edge_length)
{
    return call(s, "sfa_set_size_field_checked", [&] {
        require_mesh(s);
        if (!edge_length) {
            s->size_field.clear();
            return;
        }
        require_count(s, "vertices", s->mesh.num_vertices(), nverts);
        set_size_field(s, edge_length);
    });
}

SFA_EXPORT int sfa_set_fixed_vertices(sfa_surface *s, int32_t count, const int32_t *vertices, int32_t index_base)
{
    return call(s, "sfa_set_fixed_vertices", [&] {
        require_index_list(count, vertices, index_base);
        require_mesh(s);
        std::vector<char> fixed;
        if (count > 0) {
            fixed.assign(s->mesh.pos.size(), 0);
            for (int32_t i = 0; i < count; ++i)
                fixed[vertex_named(s, "vertices", i, vertices[i], index_base)] = 1;
        }
        s->constraints.fixed.swap(fixed);
    });
}

SFA_EXPORT int sfa_set_required_edges(sfa_surface *s, int32_t count, const int32_t *edges, int32_t index_base)
{
    return call(s, "sfa_set_required_edges", [&] {
        require_index_list(count, edges, index_base);
        require(count <= INT32_MAX / 2, "count is too large (2 * count indices must fit in int32_t)");
        require_mesh(s);
        std::vector<std::array<int32_t, 2>> required(count);
        for (int32_t i = 0; i < count; ++i) {
            const int32_t a = vertex_named(s, "edges", 2 * int64_t{i}, edges[2 * i], index_base);
            const int32_t b = vertex_named(s, "edges", 2 * int64_t{i} + 1, edges[2 * i + 1], index_base);
            if (a == b || (s->mesh.halfedge(a, b) < 0 && s->mesh.halfedge(b, a) < 0)) {
                char message[200];
                std::snprintf(message, sizeof message,
                              "edge %d, (%d, %d), is not an edge of the mesh (numbered from %d)", i, edges[2 * i],
                              edges[2 * i + 1], index_base);
                fail(Status::argument, message);
            }
            required[i] = {std::min(a, b), std::max(a, b)};
        }
        std::sort(required.begin(), required.end());
        required.erase(std::unique(required.begin(), required.end()), required.end());
        s->constraints.required.swap(required);
    });
}

} // extern "C"
