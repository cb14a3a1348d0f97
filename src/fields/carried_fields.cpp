// SPDX-License-Identifier: BSD-3-Clause
#include "fields/carried_fields.hpp"

#include "mesh/parallel.hpp"

namespace sfa {
namespace {

// Every component of every field at the stencil, written through out(field, component, value).
template <class Out>
void interpolate(const std::vector<VertexField> &fields, const Stencil &stencil, Out &&out)
{
    for (size_t f = 0; f < fields.size(); ++f) {
        const size_t ncomp = static_cast<size_t>(fields[f].ncomp);
        for (size_t c = 0; c < ncomp; ++c) {
            double value = 0;
            for (int k = 0; k < 3; ++k)
                value += stencil.weights[k] * fields[f].values[ncomp * static_cast<size_t>(stencil.corners[k]) + c];
            out(f, c, value);
        }
    }
}

// The fields' value at the stencil, into vertex v (which may be one of its corners).
void set_interpolated(std::vector<VertexField> &fields, int32_t v, const Stencil &stencil)
{
    // Computed before written: v may be one of the stencil's corners.
    std::vector<double> values;
    interpolate(fields, stencil, [&](size_t, size_t, double value) { values.push_back(value); });
    size_t k = 0;
    for (VertexField &field : fields)
        for (int32_t c = 0; c < field.ncomp; ++c)
            field.values[static_cast<size_t>(field.ncomp) * v + c] = values[k++];
}

} // namespace

void CarriedFields::split(const TriMesh &, const SplitChange &change)
{
    if (fields_.empty())
        return;
    for (VertexField &field : fields_)
        field.values.resize(field.values.size() + static_cast<size_t>(field.ncomp));
    set_interpolated(fields_, change.record.vertex, change.stencil);
}

void CarriedFields::collapse(const TriMesh &, const CollapseChange &change)
{
    set_interpolated(fields_, change.record.keep, change.stencil);
}

void CarriedFields::move(const TriMesh &mesh, const MoveChange &change)
{
    if (fields_.empty())
        return;
    // Every value from the old ones: interpolated into a copy.
    std::vector<VertexField> out = fields_;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
        if (change.stencils[v].corners[0] < 0)
            continue; // stays, or over no face of its fan
        interpolate(fields_, change.stencils[v], [&](size_t f, size_t c, double value) {
            out[f].values[static_cast<size_t>(out[f].ncomp) * v + c] = value;
        });
    }
    for (size_t f = 0; f < fields_.size(); ++f)
        fields_[f].values.swap(out[f].values); // each field's array object stays where it is
}

void CarriedFields::renumber(const Renumbering &renumbering)
{
    for (VertexField &field : fields_)
        renumbering.apply_to_vertices(field.values, static_cast<size_t>(field.ncomp));
}

} // namespace sfa
