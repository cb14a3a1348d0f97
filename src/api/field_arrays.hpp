// SPDX-License-Identifier: BSD-3-Clause
// What sfa_add_field / sfa_get_field and their face-field twins share: the checks of a
// host's array of ncomp values per element, adding it to a list of fields, and copying one
// out (api/fields.cpp, api/face_fields.cpp).
#pragma once

#include "api/boundary.hpp"
#include "fields/vertex_fields.hpp"

#include <algorithm>

namespace sfa {

// The arguments of an add; count_of(s) elements per component (count_name in messages).
inline void require_field_arguments(const sfa_surface *s, int32_t ncomp, const double *values, const int32_t *field_id,
                                    int32_t (*count_of)(const sfa_surface *), const char *count_name)
{
    require(values && field_id, "values or field_id is NULL");
    require(ncomp >= 1, "ncomp must be >= 1");
    require_mesh(s);
    if (static_cast<int64_t>(ncomp) * count_of(s) > INT32_MAX) {
        char message[120];
        std::snprintf(message, sizeof message, "ncomp * %s must fit in int32_t (capacities are int32_t)", count_name);
        fail(Status::argument, message);
    }
}

// Appends the checked copy of the host's values to `fields`; its id into *field_id.
inline void add_field_to(std::vector<VertexField> &fields, int32_t ncomp, const double *values, int32_t elements,
                         int32_t index_base, const char *element, int32_t *field_id)
{
    VertexField field = checked_field(ncomp, values, elements, index_base, element);
    fields.push_back(std::move(field)); // strong guarantee: unchanged if it throws
    *field_id = static_cast<int32_t>(fields.size()) - 1;
}

// Field `field_id` of `fields`; `kind` names the list ("field", "face field") in the error.
template <class Fields> auto &field_with_id(Fields &fields, const char *kind, int32_t field_id)
{
    if (field_id < 0 || field_id >= static_cast<int32_t>(fields.size())) {
        char message[120];
        std::snprintf(message, sizeof message, "unknown %s id %d (this mesh has %d %ss)", kind, field_id,
                      static_cast<int>(fields.size()), kind);
        fail(Status::argument, message);
    }
    return fields[field_id];
}

// Copies field `field_id` of `fields` out (`values` not NULL); `kind` names the list
// ("field", "face field").
inline void copy_field_out(const std::vector<VertexField> &fields, const char *kind, int32_t field_id,
                           int32_t capacity, double *values)
{
    const VertexField &field = field_with_id(fields, kind, field_id);
    if (capacity < 0 || static_cast<size_t>(capacity) < field.values.size()) {
        char message[140];
        std::snprintf(message, sizeof message, "capacity too small: %s %d has %zu values, room was given for %d", kind,
                      field_id, field.values.size(), capacity);
        fail(Status::argument, message);
    }
    std::copy(field.values.begin(), field.values.end(), values);
}

// Replaces the values of field `field_id` of `fields` by the checked copy of the host's
// `elements` values per component; unchanged if anything is wrong.
inline void replace_field_values(std::vector<VertexField> &fields, const char *kind, int32_t field_id,
                                 const double *values, int32_t elements, int32_t index_base, const char *element)
{
    require(values != nullptr, "values is NULL");
    VertexField &field = field_with_id(fields, kind, field_id);
    field = checked_field(field.ncomp, values, elements, index_base, element);
}

inline int32_t vertex_count(const sfa_surface *s) { return s->mesh.num_vertices(); }
inline int32_t triangle_count(const sfa_surface *s) { return s->mesh.num_triangles(); }

} // namespace sfa
