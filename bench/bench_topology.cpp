// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of the checks for topology change that open every sfa_adapt call with
// SFA_PARAM_TOPOLOGY_CHANGE on (adapt/topology_change): the search for facing sheets near
// enough to merge, for necks thin enough to pinch and for drops too small to keep, and the
// events they make. On the 100k-vertex jittered sphere of bench_smooth, where nothing is
// near enough (the common case: what every call costs), and on the same sphere pressed flat
// to a lens a hundredth as thick, whose two sides come nearer than the merge distance
// towards its rim. Internal: links the static library. One JSON line per surface: the
// median of several calls on one thread, each on a fresh copy of the surface, per vertex.
// With arguments `--checkpoints CHECKPOINT...` (a flow run's, `surfadapt enright
// --checkpoints DIR`), the same on each checkpoint's mesh instead, its mean edge length as
// the desired length: `make bench` times Enright's at T/4, T/2 and 3T/4, whose thin sheet
// the merge search must look at closely.
#include "adapt/topology_change.hpp"
#include "mesh/components.hpp"
#include "mesh/parallel.hpp"

#include "checkpoint_mesh.hpp"
#include "jittered_sphere_mesh.hpp"

extern "C" {
#include "timing.h"
}

#include <cstdio>
#include <cstring>
#include <vector>

using namespace sfa;

namespace {

constexpr int runs = 9, frequency = 100;
constexpr double merge_distance = 0.5; // SFA_PARAM_MERGE_DISTANCE's default

double mean_edge_length(const TriMesh &mesh)
{
    double sum = 0;
    for (const Triangle &t : mesh.tri)
        for (int k = 0; k < 3; ++k)
            sum += (mesh.pos[t[(k + 1) % 3]] - mesh.pos[t[k]]).norm();
    return sum / (3.0 * mesh.num_triangles());
}

void time_checks(const char *surface, const TriMesh &mesh)
{
    const double l = mean_edge_length(mesh);
    const Components components = connected_components(mesh);
    double samples[runs];
    TopologyCounts counts;
    for (int r = 0; r < runs; ++r) {
        TriMesh copy = mesh;
        SurfaceData data;
        Components copy_components = components;
        std::vector<int32_t> hints(mesh.pos.size(), 0);
        const double t0 = now();
        counts = change_topology(copy, data, copy_components, merge_distance, l, hints);
        samples[r] = now() - t0;
    }
    const double seconds = median(samples, runs);
    std::printf("{\"bench\":\"topology_checks\",\"surface\":\"%s\",\"vertices\":%d,\"median_s\":%.6f,"
                "\"ns_per_vertex\":%.1f,\"merges\":%d,\"pinches\":%d,\"drops_removed\":%d,\"runs\":%d}\n",
                surface, mesh.num_vertices(), seconds, 1e9 * seconds / mesh.num_vertices(), counts.merges,
                counts.pinches, counts.removals, runs);
    std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv)
{
    const ThreadLimit one_thread(1);
    if (argc > 1 && std::strcmp(argv[1], "--checkpoints") == 0) {
        for (int k = 2; k < argc; ++k) {
            CheckpointMesh checkpoint;
            if (!read_checkpoint_mesh(argv[k], checkpoint))
                return 1;
            time_checks(checkpoint.name.c_str(), checkpoint.mesh);
        }
        return 0;
    }
    const bool sphere_only = argc > 1; // for a profile of the common case alone
    if (sphere_only && std::strcmp(argv[1], "--sphere-only") != 0) {
        std::fprintf(stderr, "usage: bench_topology [--sphere-only | --checkpoints CHECKPOINT...]\n");
        return 2;
    }
    TriMesh mesh = jittered_sphere_mesh(frequency);
    time_checks("jittered_sphere", mesh);
    if (sphere_only)
        return 0;
    for (Vec3 &p : mesh.pos)
        p.z() *= 0.01;
    time_checks("lens", mesh);
    return 0;
}
