// SPDX-License-Identifier: BSD-3-Clause
// Vertex fields: sfa_add_field, sfa_add_field_checked, sfa_get_field, sfa_set_field.
#include "api/field_arrays.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_add_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    return call(s, "sfa_add_field", [&] {
        require_field_arguments(s, ncomp, values, field_id, vertex_count, "nverts");
        add_field_to(s->fields, ncomp, values, s->mesh.num_vertices(), s->index_base, "vertex", field_id);
    });
}

SFA_EXPORT int sfa_add_field_checked(sfa_surface *s, int32_t nverts, int32_t ncomp, const double *values,
                                     int32_t *field_id)
{
    return call(s, "sfa_add_field_checked", [&] {
        require_field_arguments(s, ncomp, values, field_id, vertex_count, "nverts");
        require_count(s, "vertices", s->mesh.num_vertices(), nverts);
        add_field_to(s->fields, ncomp, values, s->mesh.num_vertices(), s->index_base, "vertex", field_id);
    });
}

SFA_EXPORT int sfa_get_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values)
{
    return call(s, "sfa_get_field", [&] {
        require(values != nullptr, "values is NULL");
        require_mesh(s);
        copy_field_out(s->fields, "field", field_id, capacity, values);
    });
}

SFA_EXPORT int sfa_set_field(sfa_surface *s, int32_t field_id, int32_t nverts, const double *values)
{
    return call(s, "sfa_set_field", [&] {
        require_mesh(s);
        require_count(s, "vertices", s->mesh.num_vertices(), nverts);
        replace_field_values(s->fields, "field", field_id, values, nverts, s->index_base, "vertex");
    });
}

} // extern "C"
