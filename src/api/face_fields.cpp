// SPDX-License-Identifier: BSD-3-Clause
// Face fields: sfa_add_face_field, sfa_add_face_field_checked, sfa_get_face_field,
// sfa_set_face_field (carried by fields/face_values.hpp).
#include "api/field_arrays.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_add_face_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    return call(s, "sfa_add_face_field", [&] {
        require_field_arguments(s, ncomp, values, field_id, triangle_count, "ntris");
        add_field_to(s->face_fields, ncomp, values, s->mesh.num_triangles(), s->index_base, "triangle", field_id);
    });
}

SFA_EXPORT int sfa_add_face_field_checked(sfa_surface *s, int32_t ntris, int32_t ncomp, const double *values,
                                          int32_t *field_id)
{
    return call(s, "sfa_add_face_field_checked", [&] {
        require_field_arguments(s, ncomp, values, field_id, triangle_count, "ntris");
        require_count(s, "triangles", s->mesh.num_triangles(), ntris);
        add_field_to(s->face_fields, ncomp, values, s->mesh.num_triangles(), s->index_base, "triangle", field_id);
    });
}

SFA_EXPORT int sfa_get_face_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values)
{
    return call(s, "sfa_get_face_field", [&] {
        require(values != nullptr, "values is NULL");
        require_mesh(s);
        copy_field_out(s->face_fields, "face field", field_id, capacity, values);
    });
}

SFA_EXPORT int sfa_set_face_field(sfa_surface *s, int32_t field_id, int32_t ntris, const double *values)
{
    return call(s, "sfa_set_face_field", [&] {
        require_mesh(s);
        require_count(s, "triangles", s->mesh.num_triangles(), ntris);
        replace_field_values(s->face_fields, "face field", field_id, values, ntris, s->index_base, "triangle");
    });
}

} // extern "C"
