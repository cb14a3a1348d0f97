// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of one anisotropic flipping pass (§3.3) on the 1M-vertex jittered geodesic
// sphere of bench_smooth, with one thread and with every core, and of the analysis it
// needs, timed apart. Internal (the pass is not a public call): links the static library.
// One JSON line per case: the median of several runs.
#include "adapt/flip.hpp"
#include "mesh/parallel.hpp"
#include "mesh/validate.hpp"

extern "C" {
#include "jittered_sphere.h"
#include "timing.h"
}

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

using namespace sfa;

namespace {

constexpr int runs = 5, frequency = 316;
constexpr double pi = 3.14159265358979323846;

struct Figures {
    double analysis_s, pass_s;
    int32_t flips;
};

Figures time_pass(const TriMesh &mesh, int threads)
{
    const ThreadLimit limit(threads);
    const FeatureThresholds thresholds{45 * pi / 180, 20 * pi / 180, 40 * pi / 180};
    const MetricBounds bounds{8 * pi / 180, 30 * pi / 180, true};
    double analysis_samples[runs], pass_samples[runs];
    int32_t flips = 0;
    for (int r = 0; r < runs; ++r) {
        TriMesh copy = mesh;
        const double t0 = now();
        const SurfaceAnalysis analysis = analyze_surface(copy, thresholds, bounds);
        const double t1 = now();
        flips = flipping_pass(copy, analysis, FlipSettings{bounds, 20 * pi / 180});
        pass_samples[r] = now() - t1;
        analysis_samples[r] = t1 - t0;
    }
    const Figures f{median(analysis_samples, runs), median(pass_samples, runs), flips};
    const double n = mesh.num_vertices();
    std::printf("{\"bench\":\"flip_pass\",\"threads\":%d,\"vertices\":%d,\"flips\":%d,\"median_s\":%.6f,"
                "\"ns_per_vertex\":%.1f,\"analysis_s\":%.6f,\"analysis_ns_per_vertex\":%.1f,\"runs\":%d}\n",
                threads, mesh.num_vertices(), f.flips, f.pass_s, 1e9 * f.pass_s / n, f.analysis_s,
                1e9 * f.analysis_s / n, runs);
    std::fflush(stdout);
    return f;
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

    const int cores = static_cast<int>(sysconf(_SC_NPROCESSORS_ONLN));
    const Figures serial = time_pass(mesh, 1), parallel = time_pass(mesh, cores);
    std::printf("{\"bench\":\"flip_openmp_speedup\",\"vertices\":%d,\"threads\":%d,\"pass_speedup\":%.2f,"
                "\"analysis_speedup\":%.2f}\n",
                nverts, cores, serial.pass_s / parallel.pass_s, serial.analysis_s / parallel.analysis_s);
    return 0;
}
