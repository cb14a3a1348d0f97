// SPDX-License-Identifier: BSD-3-Clause
// Mesh in and out: sfa_set_mesh, sfa_get_counts, sfa_get_mesh.
#include "api/boundary.hpp"

#include "geometry/measures.hpp"
#include "mesh/components.hpp"
#include "mesh/validate.hpp"

#include <utility>

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_set_mesh(sfa_surface *s, int32_t nverts, const double *xyz, int32_t ntris, const int32_t *tris,
                            int32_t index_base)
{
    return call(s, "sfa_set_mesh", [&] {
        require(nverts >= 0, "nverts must be >= 0");
        require(ntris >= 0, "ntris must be >= 0");
        require(nverts <= INT32_MAX / 3 && ntris <= INT32_MAX / 3, "the mesh is too large for 32-bit indices");
        require(xyz || nverts == 0, "xyz is NULL");
        require(tris || ntris == 0, "tris is NULL");
        require(index_base == 0 || index_base == 1, "index_base must be 0 or 1");
        const bool drop = s->params.get(Param::drop_unreferenced) != 0;
        TriMesh mesh = validated_mesh(MeshInput{nverts, xyz, ntris, tris, index_base, drop});
        const double mean_edge_length = edge_lengths(mesh).mean;
        Components components = connected_components(mesh);

        // Commit: nothing below throws.
        std::swap(s->mesh, mesh);
        std::swap(s->components, components);
        s->has_mesh = true;
        s->index_base = index_base;
        s->counts_set_by = "sfa_set_mesh";
        s->mean_edge_length_at_set = mean_edge_length;
        s->velocity.clear();
        s->fields.clear();
        s->size_field.clear();
        s->face_fields.clear();
        s->constraints = Constraints();
        s->origins = OriginsRecord();
        s->near_sheet.clear();
        s->collision_blocks = BlockPartition();
    });
}

SFA_EXPORT int sfa_get_counts(const sfa_surface *s, int32_t *nverts, int32_t *ntris)
{
    return call(s, "sfa_get_counts", [&] {
        if (nverts)
            *nverts = s->mesh.num_vertices();
        if (ntris)
            *ntris = s->mesh.num_triangles();
    });
}

SFA_EXPORT int sfa_get_mesh(const sfa_surface *s, int32_t vert_capacity, double *xyz, int32_t tri_capacity,
                            int32_t *tris, int32_t index_base)
{
    return call(s, "sfa_get_mesh", [&] {
        require(xyz && tris, "xyz or tris is NULL");
        require(index_base == 0 || index_base == 1, "index_base must be 0 or 1");
        require_mesh(s);
        const TriMesh &mesh = s->mesh;
        if (vert_capacity < mesh.num_vertices() || tri_capacity < mesh.num_triangles()) {
            char message[200];
            std::snprintf(message, sizeof message,
                          "capacity too small: the mesh has %d vertices and %d triangles, room was given for %d "
                          "and %d",
                          mesh.num_vertices(), mesh.num_triangles(), vert_capacity, tri_capacity);
            fail(Status::argument, message);
        }
        for (int32_t v = 0; v < mesh.num_vertices(); ++v)
            for (int k = 0; k < 3; ++k)
                xyz[3 * v + k] = mesh.pos[v][k];
        for (int32_t t = 0; t < mesh.num_triangles(); ++t)
            for (int k = 0; k < 3; ++k)
                tris[3 * t + k] = mesh.tri[t][k] + index_base;
    });
}

} // extern "C"
