// SPDX-License-Identifier: BSD-3-Clause
// Host data living on the vertices (sfa_add_field): ncomp doubles per vertex, carried
// through every operation that moves or creates vertices.
#pragma once

#include <cstdint>
#include <vector>

namespace sfa {

struct VertexField {
    int32_t ncomp;
    std::vector<double> values; // values[ncomp * v + c]
};

// Copies a host's field of ncomp values per element (vertex, or triangle for a face field)
// after checking every value is finite; throws Error(Status::numeric) naming the first
// element with a non-finite value ("vertex 12"), counted from index_base.
VertexField checked_field(int32_t ncomp, const double *values, int32_t num_elements, int32_t index_base,
                          const char *element = "vertex");

} // namespace sfa
