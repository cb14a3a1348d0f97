#include "adapt/volume.hpp"

#include "geometry/measures.hpp"
#include "motion/fold_time.hpp"

#include <cmath>

namespace sfa {

void restore_enclosed_volume(TriMesh &mesh, const std::vector<int8_t> &rank, double volume)
{
    std::vector<Vec3> moved = mesh.pos;
    TriMesh trial = mesh;
    for (int newton = 0; newton < 3; ++newton) {
        // d volume / d offset = sum of |gradient| over the moving vertices.
        std::vector<Vec3> normal(trial.pos.size(), Vec3::Zero());
        double rate = 0;
        for (int32_t v = 0; v < trial.num_vertices(); ++v)
            if (rank[v] == 0) {
                const Vec3 gradient = volume_gradient(trial, v);
                rate += gradient.norm();
                normal[v] = gradient.normalized();
            }
        const double missing = volume - enclosed_volume(trial);
        if (rate <= 0 || missing == 0)
            break;
        const double offset = missing / rate;
        for (int32_t v = 0; v < trial.num_vertices(); ++v)
            trial.pos[v] += offset * normal[v];
    }
    if (first_folded_triangle(mesh, trial.pos) < 0)
        mesh.pos.swap(trial.pos);
}

} // namespace sfa
