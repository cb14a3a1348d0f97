#include "motion/fold_time.hpp"

#include "mesh/parallel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sfa {

double first_positive_root(double c0, double c1, double c2)
{
    const double none = std::numeric_limits<double>::infinity();
    // Treat the quadratic term as absent when it cannot matter before the linear root.
    if (c2 == 0 || std::abs(c2) * c0 <= 1e-15 * c1 * c1)
        return c1 < 0 ? -c0 / c1 : none;
    const double discriminant = c1 * c1 - 4 * c2 * c0;
    if (discriminant < 0)
        return none; // c2 > 0 here: the parabola stays above zero
    // Numerically stable pair of roots: q / c2 and c0 / q.
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(discriminant), c1));
    double first = none;
    for (double root : {q / c2, c0 / q})
        if (root > 0)
            first = std::min(first, root);
    return first;
}

bool turned_over(const TriMesh &mesh, const std::vector<Vec3> &moved, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    const Vec3 before = (mesh.pos[c[1]] - mesh.pos[c[0]]).cross(mesh.pos[c[2]] - mesh.pos[c[0]]);
    const Vec3 after = (moved[c[1]] - moved[c[0]]).cross(moved[c[2]] - moved[c[0]]);
    return !(before.dot(after) > 0); // NaN counts as turned over
}

int32_t first_folded_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved)
{
    const int32_t first = first_where(mesh.num_triangles(), [&](int32_t t) { return turned_over(mesh, moved, t); });
    return first < mesh.num_triangles() ? first : -1;
}

int32_t first_folded_moved_triangle(const TriMesh &mesh, const std::vector<Vec3> &moved)
{
    const int32_t first = first_where(mesh.num_triangles(), [&](int32_t t) {
        const Triangle &c = mesh.tri[t];
        const bool any_moved = moved[c[0]] != mesh.pos[c[0]] || moved[c[1]] != mesh.pos[c[1]] ||
                               moved[c[2]] != mesh.pos[c[2]];
        return any_moved && turned_over(mesh, moved, t);
    });
    return first < mesh.num_triangles() ? first : -1;
}

double first_fold_time(const TriMesh &mesh, const std::vector<Vec3> &velocity)
{
    // min is exact, so the reduction gives the same time for any number of threads.
    double first = std::numeric_limits<double>::infinity();
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(min : first)
    for (int32_t k = 0; k < mesh.num_triangles(); ++k) {
        const Triangle &t = mesh.tri[k];
        const Vec3 e1 = mesh.pos[t[1]] - mesh.pos[t[0]], e2 = mesh.pos[t[2]] - mesh.pos[t[0]];
        const Vec3 d1 = velocity[t[1]] - velocity[t[0]], d2 = velocity[t[2]] - velocity[t[0]];
        const Vec3 n0 = e1.cross(e2);
        // n(t) = n0 + t (e1 x d2 + d1 x e2) + t^2 (d1 x d2); fold where n0.n(t) = 0.
        const double c0 = n0.squaredNorm();
        const double c1 = n0.dot(e1.cross(d2) + d1.cross(e2));
        const double c2 = n0.dot(d1.cross(d2));
        first = std::min(first, first_positive_root(c0, c1, c2));
    }
    return first;
}

} // namespace sfa
