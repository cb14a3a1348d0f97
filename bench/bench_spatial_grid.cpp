// SPDX-License-Identifier: BSD-3-Clause
// Benchmark of the three searches that share the spatial grid: the self-intersection count,
// the search for facing sheets, and the crossing guard (index, then one query per face with
// its corners moved by up to a tenth of an edge). On the 100k-vertex jittered sphere of
// bench_smooth, where the guard watches nothing, and on the same sphere pressed flat to a
// lens a hundredth as thick, whose two sides face each other nearer than an edge all over
// and which the guard watches everywhere. Internal: links the static library. One JSON line
// per surface and step: the median of several runs, on one thread (the figures are for
// comparing one build with another, and a shared machine disturbs one thread least).
#include "geometry/crossing_guard.hpp"
#include "geometry/self_intersection.hpp"
#include "mesh/parallel.hpp"

#include "jittered_sphere_mesh.hpp"

extern "C" {
#include "timing.h"
}

#include <algorithm>
#include <cstdio>
#include <vector>

using namespace sfa;

namespace {

constexpr int runs = 5, frequency = 100;

template <class Step>
double median_seconds(Step &&step)
{
    double samples[runs];
    for (int r = 0; r < runs; ++r) {
        const double t0 = now();
        step();
        samples[r] = now() - t0;
    }
    return median(samples, runs);
}

void report(const char *surface, const char *step, int32_t vertices, double seconds, long long result)
{
    std::printf("{\"bench\":\"spatial_grid\",\"surface\":\"%s\",\"step\":\"%s\",\"vertices\":%d,\"median_s\":%.6f,"
                "\"result\":%lld,\"runs\":%d}\n",
                surface, step, vertices, seconds, result, runs);
    std::fflush(stdout);
}

void time_searches(const char *surface, const TriMesh &mesh)
{
    int32_t intersections = 0;
    double seconds = median_seconds([&] { intersections = self_intersection_count(mesh); });
    report(surface, "self_intersection_count", mesh.num_vertices(), seconds, intersections);

    std::vector<char> watched;
    seconds = median_seconds([&] { watched = near_facing_sheet(mesh); });
    report(surface, "near_facing_sheet", mesh.num_vertices(), seconds, std::count(watched.begin(), watched.end(), 1));

    CrossingGuard guard(watched);
    size_t indexed = 0;
    seconds = median_seconds([&] { indexed = guard.index_faces(mesh, mesh.pos).size(); });
    report(surface, "index_faces", mesh.num_vertices(), seconds, static_cast<long long>(indexed));

    // Each face with its first corner moved by a tenth of an edge, along a fixed direction
    // that changes from face to face.
    const double shift = 0.1 * 1.1 / frequency;
    long long crossing = 0;
    seconds = median_seconds([&] {
        crossing = 0;
        for (int32_t f = 0; f < mesh.num_triangles(); ++f) {
            const Triangle &t = mesh.tri[f];
            const Vec3 direction(f % 3 - 1.0, f % 5 - 2.0, f % 7 - 3.0);
            const Vec3 at[3] = {mesh.pos[t[0]] + shift * direction.normalized(), mesh.pos[t[1]], mesh.pos[t[2]]};
            crossing += guard.watches_any(t) && guard.crosses(mesh, mesh.pos, t, at);
        }
    });
    report(surface, "crosses", mesh.num_vertices(), seconds, crossing);
}

} // namespace

int main()
{
    const ThreadLimit one_thread(1);
    TriMesh mesh = jittered_sphere_mesh(frequency);
    time_searches("jittered_sphere", mesh);
    for (Vec3 &p : mesh.pos)
        p.z() *= 0.01;
    time_searches("lens", mesh);
    return 0;
}
