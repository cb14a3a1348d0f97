#include "adapt/volume.hpp"

#include "geometry/measures.hpp"
#include "mesh/parallel.hpp"
#include "motion/fold_time.hpp"

#include <cmath>
#include <limits>

namespace sfa {
namespace {
constexpr int max_steps = 5;
} // namespace

void restore_enclosed_volume(TriMesh &mesh, const std::vector<int8_t> &rank, double volume)
{
    // The directions (the volume gradients) and the rate d volume / d offset (the sum of
    // their lengths) are taken once: the volume is a cubic polynomial in the offset whose
    // higher terms are of the order of offset x curvature, so that chord steps with this
    // rate reach round-off in two or three steps.
    const int32_t n = mesh.num_vertices();
    std::vector<Vec3> normal(n, Vec3::Zero());
    std::vector<double> rate_of(n, 0.0);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v)
        if (rank[v] == 0) {
            const Vec3 gradient = volume_gradient(mesh, v);
            rate_of[v] = gradient.norm();
            normal[v] = gradient.normalized();
        }
    double rate = 0;
    for (double r : rate_of)
        rate += r;
    if (rate <= 0)
        return;
    std::vector<Vec3> moved = mesh.pos;
    double offset = 0, last_missing = std::numeric_limits<double>::infinity();
    for (int step = 0; step < max_steps; ++step) {
        const double missing = volume - enclosed_volume(mesh, moved);
        if (!(std::abs(missing) < last_missing))
            break; // at round-off
        last_missing = std::abs(missing);
        offset += missing / rate;
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < n; ++v)
            moved[v] = mesh.pos[v] + offset * normal[v];
    }
    if (first_folded_triangle(mesh, moved) < 0)
        mesh.pos.swap(moved);
}

} // namespace sfa
