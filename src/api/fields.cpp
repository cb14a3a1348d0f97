// Vertex fields: sfa_add_field, sfa_get_field.
#include "api/boundary.hpp"

#include <algorithm>

using namespace sfa;

namespace {

void require_field_arguments(const sfa_surface *s, int32_t ncomp, const double *values, const int32_t *field_id)
{
    require(values && field_id, "values or field_id is NULL");
    require(ncomp >= 1, "ncomp must be >= 1");
    require_mesh(s);
    require(static_cast<int64_t>(ncomp) * s->mesh.num_vertices() <= INT32_MAX,
            "ncomp * nverts must fit in int32_t (capacities are int32_t)");
}

void add_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    VertexField field = checked_field(ncomp, values, s->mesh.num_vertices(), s->index_base);
    s->fields.push_back(std::move(field)); // strong guarantee: unchanged if it throws
    *field_id = static_cast<int32_t>(s->fields.size()) - 1;
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_add_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    return call(s, "sfa_add_field", [&] {
        require_field_arguments(s, ncomp, values, field_id);
        add_field(s, ncomp, values, field_id);
    });
}

SFA_EXPORT int sfa_add_field_checked(sfa_surface *s, int32_t nverts, int32_t ncomp, const double *values,
                                     int32_t *field_id)
{
    return call(s, "sfa_add_field_checked", [&] {
        require_field_arguments(s, ncomp, values, field_id);
        require_count(s, "vertices", s->mesh.num_vertices(), nverts);
        add_field(s, ncomp, values, field_id);
    });
}

SFA_EXPORT int sfa_get_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values)
{
    return call(s, "sfa_get_field", [&] {
        require(values != nullptr, "values is NULL");
        require_mesh(s);
        if (field_id < 0 || field_id >= static_cast<int32_t>(s->fields.size())) {
            char message[120];
            std::snprintf(message, sizeof message, "unknown field id %d (this mesh has %d fields)", field_id,
                          static_cast<int>(s->fields.size()));
            fail(Status::argument, message);
        }
        const VertexField &field = s->fields[field_id];
        if (static_cast<size_t>(capacity) < field.values.size() || capacity < 0) {
            char message[120];
            std::snprintf(message, sizeof message, "capacity too small: field %d has %zu values, room was given for %d",
                          field_id, field.values.size(), capacity);
            fail(Status::argument, message);
        }
        std::copy(field.values.begin(), field.values.end(), values);
    });
}

} // extern "C"
