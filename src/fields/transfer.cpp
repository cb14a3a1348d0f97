#include "fields/transfer.hpp"

#include "mesh/parallel.hpp"

namespace sfa {

Eigen::Vector3d barycentric(const Vec3 &x, const Vec3 &a, const Vec3 &b, const Vec3 &c)
{
    const Vec3 normal = (b - a).cross(c - a);
    const double twice_area = normal.squaredNorm();
    const double wa = (c - b).cross(x - b).dot(normal) / twice_area;
    const double wb = (a - c).cross(x - c).dot(normal) / twice_area;
    return Eigen::Vector3d(wa, wb, 1 - wa - wb);
}

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

} // namespace

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

void append_interpolated(std::vector<VertexField> &fields, const Stencil &stencil)
{
    for (VertexField &field : fields)
        field.values.resize(field.values.size() + static_cast<size_t>(field.ncomp));
    const int32_t v = fields.empty() ? 0 : static_cast<int32_t>(fields[0].values.size() / fields[0].ncomp) - 1;
    set_interpolated(fields, v, stencil);
}

void renumber_fields(std::vector<VertexField> &fields, const std::vector<int32_t> &vertex_map)
{
    size_t count = 0;
    for (int32_t target : vertex_map)
        count += target >= 0;
    for (VertexField &field : fields) {
        const size_t ncomp = static_cast<size_t>(field.ncomp);
        std::vector<double> values(ncomp * count);
        for (size_t v = 0; v < vertex_map.size(); ++v)
            if (vertex_map[v] >= 0)
                for (size_t c = 0; c < ncomp; ++c)
                    values[ncomp * static_cast<size_t>(vertex_map[v]) + c] = field.values[ncomp * v + c];
        field.values.swap(values);
    }
}

std::vector<VertexField> fields_at_moved_vertices(const TriMesh &old_mesh, const std::vector<Vec3> &moved,
                                                  const std::vector<VertexField> &fields)
{
    std::vector<VertexField> out = fields;
    if (fields.empty())
        return out;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < old_mesh.num_vertices(); ++v) {
        if (moved[v] == old_mesh.pos[v])
            continue;
        const Stencil stencil = stencil_over(old_mesh, moved[v], [&](auto &&visit) {
            old_mesh.for_each_outgoing(v, [&](int32_t h) { visit(TriMesh::face(h)); });
        });
        interpolate(fields, stencil, [&](size_t f, size_t c, double value) {
            out[f].values[static_cast<size_t>(out[f].ncomp) * v + c] = value;
        });
    }
    return out;
}

} // namespace sfa
