// Face fields: sfa_add_face_field, sfa_add_face_field_checked, sfa_get_face_field (carried
// by fields/face_values.hpp).
#include "api/boundary.hpp"

#include <algorithm>
#include <cmath>

using namespace sfa;

namespace {

void require_face_field_arguments(const sfa_surface *s, int32_t ncomp, const double *values, const int32_t *field_id)
{
    require(values && field_id, "values or field_id is NULL");
    require(ncomp >= 1, "ncomp must be >= 1");
    require_mesh(s);
    require(static_cast<int64_t>(ncomp) * s->mesh.num_triangles() <= INT32_MAX,
            "ncomp * ntris must fit in int32_t (capacities are int32_t)");
}

void add_face_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    const size_t count = static_cast<size_t>(ncomp) * static_cast<size_t>(s->mesh.num_triangles());
    for (size_t i = 0; i < count; ++i)
        if (!std::isfinite(values[i])) {
            char message[160];
            std::snprintf(message, sizeof message, "triangle %zu has a non-finite density %g in component %zu",
                          i / static_cast<size_t>(ncomp) + static_cast<size_t>(s->index_base), values[i],
                          i % static_cast<size_t>(ncomp));
            fail(Status::numeric, message);
        }
    FaceField field{ncomp, std::vector<double>(values, values + count)};
    s->face_fields.push_back(std::move(field)); // strong guarantee: unchanged if it throws
    *field_id = static_cast<int32_t>(s->face_fields.size()) - 1;
}

} // namespace

extern "C" {

SFA_EXPORT int sfa_add_face_field(sfa_surface *s, int32_t ncomp, const double *values, int32_t *field_id)
{
    return call(s, "sfa_add_face_field", [&] {
        require_face_field_arguments(s, ncomp, values, field_id);
        add_face_field(s, ncomp, values, field_id);
    });
}

SFA_EXPORT int sfa_add_face_field_checked(sfa_surface *s, int32_t ntris, int32_t ncomp, const double *values,
                                          int32_t *field_id)
{
    return call(s, "sfa_add_face_field_checked", [&] {
        require_face_field_arguments(s, ncomp, values, field_id);
        require_count(s, "triangles", s->mesh.num_triangles(), ntris);
        add_face_field(s, ncomp, values, field_id);
    });
}

SFA_EXPORT int sfa_get_face_field(const sfa_surface *s, int32_t field_id, int32_t capacity, double *values)
{
    return call(s, "sfa_get_face_field", [&] {
        require(values != nullptr, "values is NULL");
        require_mesh(s);
        if (field_id < 0 || field_id >= static_cast<int32_t>(s->face_fields.size())) {
            char message[120];
            std::snprintf(message, sizeof message, "unknown face field id %d (this mesh has %d face fields)",
                          field_id, static_cast<int>(s->face_fields.size()));
            fail(Status::argument, message);
        }
        const FaceField &field = s->face_fields[field_id];
        if (capacity < 0 || static_cast<size_t>(capacity) < field.values.size()) {
            char message[140];
            std::snprintf(message, sizeof message,
                          "capacity too small: face field %d has %zu values, room was given for %d", field_id,
                          field.values.size(), capacity);
            fail(Status::argument, message);
        }
        std::copy(field.values.begin(), field.values.end(), values);
    });
}

} // extern "C"
