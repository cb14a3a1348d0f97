// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of what face fields cost a smoothing sweep: FaceValues remaps every moved
// vertex's fan by overlap (fields/face_values.hpp), one vertex after another, serially,
// where the sweep computes its positions in parallel. On a 20k-vertex jittered sphere (the
// input of bench_smooth, coarser): the analysis and the sweep, then the move through an
// edit without a listener and with FaceValues of 1 and of 4 components, timed apart; on
// one thread and on every core. Internal: links the static library. One JSON line per
// case: the median of several runs.
#include "adapt/smooth.hpp"
#include "fields/face_values.hpp"
#include "mesh/parallel.hpp"
#include "mesh/validate.hpp"

extern "C" {
#include "jittered_sphere.h"
#include "timing.h"
}

#include <cstdio>
#include <cstdlib>
#include <unistd.h>
#include <vector>

using namespace sfa;

namespace {

constexpr int runs = 5, frequency = 45;
constexpr double pi = 3.14159265358979323846;

void time_sweep(const TriMesh &mesh, int threads)
{
    const ThreadLimit limit(threads);
    const FeatureThresholds thresholds{45 * pi / 180, 20 * pi / 180, 40 * pi / 180};
    const MetricBounds bounds{8 * pi / 180, 30 * pi / 180, true};
    double analysis[runs], sweep[runs], bare[runs], one[runs], four[runs];
    int64_t shared = 0;
    for (int r = 0; r < runs; ++r) {
        TriMesh copy = mesh;
        const double t0 = now();
        const SurfaceAnalysis surface = analyze_surface(copy, thresholds, bounds);
        const double t1 = now();
        const std::vector<Vec3> moved = smoothing_sweep(copy, surface);
        const double t2 = now();
        analysis[r] = t1 - t0;
        sweep[r] = t2 - t1;
        // The same move thrice from the same mesh: no listener, then 1 and 4 components.
        double *samples[3] = {bare + r, one + r, four + r};
        for (int k = 0; k < 3; ++k) {
            TriMesh moving = mesh;
            MeshEdit edit(moving);
            const int32_t ncomp = k < 2 ? 1 : 4;
            FaceValues values(ncomp, std::vector<double>(static_cast<size_t>(ncomp) * moving.num_triangles(), 1.0));
            if (k > 0)
                edit.attach(values);
            std::vector<Vec3> positions = moved;
            const double t3 = now();
            edit.move(positions);
            *samples[k] = now() - t3;
            shared += values.shared_remaps();
        }
    }
    const double n = mesh.num_vertices();
    const double a = median(analysis, runs), s = median(sweep, runs), m = median(bare, runs), f1 = median(one, runs),
                 f4 = median(four, runs);
    std::printf("{\"bench\":\"face_remap_sweep\",\"threads\":%d,\"vertices\":%d,\"analysis_s\":%.6f,\"sweep_s\":%.6f,"
                "\"move_s\":%.6f,\"move_1_field_s\":%.6f,\"move_4_fields_s\":%.6f,\"remap_ns_per_vertex\":%.1f,"
                "\"remap_over_sweep\":%.2f,\"shared_fans\":%lld,\"runs\":%d}\n",
                threads, mesh.num_vertices(), a, s, m, f1, f4, 1e9 * (f1 - m) / n, (f1 - m) / s,
                static_cast<long long>(shared), runs);
    std::fflush(stdout);
}

} // namespace

int main()
{
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
    if (jittered_sphere(frequency, &nverts, &xyz, &ntris, &tris) != 0)
        return 1;
    const TriMesh mesh = validated_mesh(MeshInput{nverts, xyz, ntris, tris, 0, false});
    std::free(xyz);
    std::free(tris);
    time_sweep(mesh, 1);
    time_sweep(mesh, static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN)));
    return 0;
}
