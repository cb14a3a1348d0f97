// SPDX-License-Identifier: BSD-3-Clause
#include "fields/vertex_fields.hpp"

#include "mesh/error.hpp"

#include <cmath>
#include <cstdio>

namespace sfa {

VertexField checked_field(int32_t ncomp, const double *values, int32_t num_elements, int32_t index_base,
                          const char *element)
{
    const size_t count = static_cast<size_t>(ncomp) * static_cast<size_t>(num_elements);
    for (size_t i = 0; i < count; ++i) {
        if (!std::isfinite(values[i])) {
            char message[160];
            std::snprintf(message, sizeof message, "%s %zu has a non-finite value %g in component %zu of the field",
                          element, i / static_cast<size_t>(ncomp) + static_cast<size_t>(index_base), values[i],
                          i % static_cast<size_t>(ncomp));
            throw Error(Status::numeric, message);
        }
    }
    return VertexField{ncomp, std::vector<double>(values, values + count)};
}

} // namespace sfa
