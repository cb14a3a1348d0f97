#include "adapt/volume.hpp"

#include "geometry/measures.hpp"
#include "mesh/parallel.hpp"
#include "motion/fold_time.hpp"

#include <cmath>
#include <limits>

namespace sfa {
namespace {
constexpr int max_newton_steps = 8;
} // namespace

void restore_enclosed_volume(TriMesh &mesh, const std::vector<int8_t> &rank, double volume)
{
    // Every smooth vertex moves by the offset o along its unit volume gradient n_v; the six-
    // fold volume is then the cubic sum over the triangles of det(p_0 + o n_0, p_1 + o n_1,
    // p_2 + o n_2). One pass gathers its four coefficients, and Newton's method on the cubic
    // finds the offset to round-off without touching the mesh again.
    const int32_t n = mesh.num_vertices();
    std::vector<Vec3> normal(n, Vec3::Zero());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        if (rank[v] == 0)
            normal[v] = volume_gradient(mesh, v).normalized();
    const auto det = [](const Vec3 &x, const Vec3 &y, const Vec3 &z) { return x.dot(y.cross(z)); };
    const Eigen::Vector4d c = ordered_sum(mesh.num_triangles(), Eigen::Vector4d::Zero().eval(), [&](int32_t k) {
        const Triangle &t = mesh.tri[k];
        const Vec3 &p0 = mesh.pos[t[0]], &p1 = mesh.pos[t[1]], &p2 = mesh.pos[t[2]];
        const Vec3 &n0 = normal[t[0]], &n1 = normal[t[1]], &n2 = normal[t[2]];
        return Eigen::Vector4d(det(p0, p1, p2), det(n0, p1, p2) + det(p0, n1, p2) + det(p0, p1, n2),
                               det(p0, n1, n2) + det(n0, p1, n2) + det(n0, n1, p2), det(n0, n1, n2));
    });
    const auto six_volume = [&](double o) { return c[0] + o * (c[1] + o * (c[2] + o * c[3])); };
    const auto slope = [&](double o) { return c[1] + o * (2 * c[2] + o * 3 * c[3]); };
    if (!(c[1] > 0))
        return; // nothing can move: every vertex is a feature
    double offset = 0, last_missing = std::numeric_limits<double>::infinity();
    for (int step = 0; step < max_newton_steps; ++step) {
        const double missing = 6 * volume - six_volume(offset);
        if (!(std::abs(missing) < last_missing))
            break; // at round-off
        last_missing = std::abs(missing);
        offset += missing / slope(offset);
    }
    std::vector<Vec3> moved(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        moved[v] = mesh.pos[v] + offset * normal[v];
    if (first_folded_triangle(mesh, moved) < 0)
        mesh.pos.swap(moved);
}

} // namespace sfa
