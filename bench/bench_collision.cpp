// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of collision-safe motion's search (geometry/collision_time): how long the
// first approach of a whole surface takes, which is what collision-safe motion adds to
// every step. On the 100k-vertex jittered sphere of bench_smooth, moved by the Enright
// deformation field at t = 0 over one step of the paper's dt (every triangle moves
// relative to its neighbours, none comes near another), and on the same sphere pressed
// flat to a lens a hundredth as thick, whose two sides face each other nearer than an edge
// all over, moved by the same field pressed flat. Internal: links the static library. One JSON line per
// surface: the median of several runs on one thread, and the time per triangle. With
// arguments `--dt DT CHECKPOINT...` (a flow run's checkpoints, `surfadapt enright
// --checkpoints DIR`), the same on each checkpoint's mesh moved by its flow's velocity at
// its time over DT, instead: `make bench` times Enright's at T/4, T/2 and 3T/4.
#include "flows.hpp"
#include "geometry/collision_time.hpp"
#include "mesh/parallel.hpp"

#include "checkpoint_mesh.hpp"
#include "jittered_sphere_mesh.hpp"

extern "C" {
#include "timing.h"
}

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace sfa;

namespace {

constexpr int runs = 7, frequency = 100;

// The Enright deformation field (the tool's, paper §5.2.2) at t = 0 on a sphere of radius
// 0.15 around (0.35, 0.35, 0.35), as the flow's start, scaled to the unit sphere.
std::vector<Vec3> enright_velocity_on_unit_sphere(const std::vector<Vec3> &unit)
{
    constexpr double radius = 0.15;
    std::vector<double> xyz, velocity(3 * unit.size());
    for (const Vec3 &u : unit)
        for (int k = 0; k < 3; ++k)
            xyz.push_back(0.35 + radius * u[k]);
    FlowPeriod period{3};
    enright_velocity(&period, static_cast<int32_t>(unit.size()), xyz.data(), 0, velocity.data());
    std::vector<Vec3> scaled(unit.size());
    for (size_t v = 0; v < unit.size(); ++v)
        scaled[v] = Vec3(velocity[3 * v], velocity[3 * v + 1], velocity[3 * v + 2]) / radius;
    return scaled;
}

void time_first_approach(const char *surface, const TriMesh &mesh, const std::vector<Vec3> &velocity, double dt)
{
    double samples[runs];
    Approach first;
    for (int r = 0; r < runs; ++r) {
        const double t0 = now();
        first = first_approach(mesh, velocity, dt);
        samples[r] = now() - t0;
    }
    const double seconds = median(samples, runs);
    std::printf("{\"bench\":\"collision\",\"surface\":\"%s\",\"step\":\"first_approach\",\"triangles\":%d,"
                "\"median_s\":%.6f,\"ns_per_triangle\":%.1f,\"time_allowed\":%.6g,\"runs\":%d}\n",
                surface, mesh.num_triangles(), seconds, 1e9 * seconds / mesh.num_triangles(), first.time / dt,
                runs);
    std::fflush(stdout);
}

int usage()
{
    std::fprintf(stderr, "usage: bench_collision [--sphere-only | --dt DT CHECKPOINT...]\n");
    return 2;
}

} // namespace

int main(int argc, char **argv)
{
    const ThreadLimit one_thread(1);
    if (argc > 1 && std::strcmp(argv[1], "--dt") == 0) {
        const double dt = argc > 2 ? std::atof(argv[2]) : 0;
        if (!(dt > 0) || argc < 4)
            return usage();
        for (int k = 3; k < argc; ++k) {
            CheckpointMesh checkpoint;
            if (!read_checkpoint_mesh(argv[k], checkpoint))
                return 1;
            time_first_approach(checkpoint.name.c_str(), checkpoint.mesh, checkpoint.velocity, dt);
        }
        return 0;
    }
    const bool sphere_only = argc > 1; // for a profile of the common case alone
    if (sphere_only && std::strcmp(argv[1], "--sphere-only") != 0)
        return usage();
    TriMesh mesh = jittered_sphere_mesh(frequency);
    std::vector<Vec3> velocity = enright_velocity_on_unit_sphere(mesh.pos);
    const double dt = 0.015; // the paper's Enright step
    time_first_approach("jittered_sphere", mesh, velocity, dt);
    if (sphere_only)
        return 0;
    for (size_t v = 0; v < velocity.size(); ++v) { // the field pressed flat with the sphere
        mesh.pos[v].z() *= 0.01;
        velocity[v].z() *= 0.01;
    }
    time_first_approach("lens", mesh, velocity, dt);
    return 0;
}
