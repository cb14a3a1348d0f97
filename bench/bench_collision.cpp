// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of collision-safe motion's search (geometry/collision_time): how long the
// first approach of a whole surface takes, which is what collision-safe motion adds to
// every step. On the 100k-vertex jittered sphere of bench_smooth, moved by the Enright
// deformation field at t = 0 over one step of the paper's dt (every triangle moves
// relative to its neighbours, none comes near another), and on the same sphere pressed
// flat to a lens a hundredth as thick, whose two sides face each other nearer than an edge
// all over, moved by the same field pressed flat. Internal: links the static library. One JSON line per
// surface: the median of several runs on one thread, and the time per triangle.
#include "geometry/collision_time.hpp"
#include "mesh/parallel.hpp"
#include "mesh/validate.hpp"

extern "C" {
#include "jittered_sphere.h"
#include "timing.h"
}

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace sfa;

namespace {

constexpr int runs = 7, frequency = 100;

// The Enright deformation field (paper §5.2.2) at t = 0, on a sphere of radius 0.15
// around (0.35, 0.35, 0.35) mapped to the unit sphere.
Vec3 enright_velocity(const Vec3 &unit)
{
    const Vec3 p = Vec3::Constant(0.35) + 0.15 * unit;
    const double pi = 3.14159265358979323846;
    const double sx = std::sin(pi * p.x()), sy = std::sin(pi * p.y()), sz = std::sin(pi * p.z());
    const double s2x = std::sin(2 * pi * p.x()), s2y = std::sin(2 * pi * p.y()), s2z = std::sin(2 * pi * p.z());
    // Scaled back to the unit sphere, as the positions are.
    return Vec3(2 * sx * sx * s2y * s2z, -sy * sy * s2x * s2z, -sz * sz * s2x * s2y) / 0.15;
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

} // namespace

int main(int argc, char **)
{
    const bool sphere_only = argc > 1; // for a profile of the common case alone
    const ThreadLimit one_thread(1);
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
    if (jittered_sphere(frequency, &nverts, &xyz, &ntris, &tris) != 0)
        return 1;
    TriMesh mesh = validated_mesh(MeshInput{nverts, xyz, ntris, tris, 0, false});
    std::free(xyz);
    std::free(tris);
    std::vector<Vec3> velocity(mesh.pos.size());
    for (size_t v = 0; v < velocity.size(); ++v)
        velocity[v] = enright_velocity(mesh.pos[v]);
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
