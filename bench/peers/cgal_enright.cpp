// SPDX-License-Identifier: BSD-3-Clause
// cgal_enright [--checkpoints DIR] [--iterations N]
//
// The paper's Enright test (§5.2.2) tracked with CGAL's isotropic remeshing in place of
// surfadapt, set up as `surfadapt enright` is (enright_setup in apps/surfadapt/
// flow_commands.cpp): the geodesic sphere of frequency 48 (23,042 vertices) of radius 0.15
// at (0.35, 0.35, 0.35), T = 3, dt = 0.015, 200 steps; every step the vertices move by one
// RK4 step of the same velocity field (flows.hpp, linked, not copied), and every 4 steps
// CGAL::Polygon_mesh_processing::isotropic_remeshing runs on the whole surface with the
// start mesh's mean edge length as its target (the length surfadapt adapts to when
// SFA_PARAM_EDGE_LENGTH is 0).
//
// One remeshing iteration per call by default: surfadapt's run adapts with one pass per
// call (SFA_PARAM_ADAPT_PASSES = 1) and lets the next call pick up the rest, and one
// iteration is CGAL's own default. What differs, by design of the comparison: CGAL's
// target is uniform (no curvature or anisotropy), the steps between remeshings are not
// smoothed, nothing keeps the volume, and no fold control cuts a step.
//
// Prints one JSON line ("bench":"peer_flow"). With --checkpoints DIR the mesh at t = 0,
// T/4, T/2, 3T/4 and T goes to DIR/t<time>.obj through the tool's own save_checkpoint
// (apps/surfadapt/checkpoint.cpp), so that build/bench/fidelity measures CGAL's shape error
// by backtracing exactly as it measures surfadapt's.
#include "checkpoint.hpp"
#include "flows.hpp"
#include "icosphere.h"
#include "peer_mesh.hpp"

#include "surfadapt.h"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// enright_setup() of the tool; bench/peers/run.sh checks that the checkpoints at t = 0 of
// both runs are the same file.
constexpr double period = 3.0, dt = 0.015, radius = 0.15;
constexpr double centre[3] = {0.35, 0.35, 0.35};
constexpr int steps = 200, frequency = 48, remesh_every = 4;

int usage()
{
    std::fprintf(stderr, "usage: cgal_enright [--checkpoints DIR] [--iterations N]\n");
    return 2;
}

// The vertices' positions, in the mesh's vertex order (the caller keeps it dense).
void get_positions(const PeerMesh &mesh, std::vector<double> &xyz)
{
    xyz.resize(3 * mesh.number_of_vertices());
    for (PeerMesh::Vertex_index v : mesh.vertices()) {
        const Point &p = mesh.point(v);
        double *x = &xyz[3 * v.idx()];
        x[0] = p.x();
        x[1] = p.y();
        x[2] = p.z();
    }
}

void set_positions(PeerMesh &mesh, const std::vector<double> &xyz)
{
    for (PeerMesh::Vertex_index v : mesh.vertices()) {
        const double *x = &xyz[3 * v.idx()];
        mesh.point(v) = Point(x[0], x[1], x[2]);
    }
}

// One classical RK4 step of the flow from t to t + h, in place.
void rk4_step(std::vector<double> &xyz, double t, double h)
{
    FlowPeriod flow{period};
    const int32_t n = static_cast<int32_t>(xyz.size() / 3);
    static std::vector<double> k1, k2, k3, k4, stage;
    for (std::vector<double> *k : {&k1, &k2, &k3, &k4, &stage})
        k->resize(xyz.size());
    // In parallel like the velocity field and the library's own RK4 step.
    const auto offset = [&](const std::vector<double> &k, double scale) {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < xyz.size(); ++i)
            stage[i] = xyz[i] + scale * k[i];
    };
    enright_velocity(&flow, n, xyz.data(), t, k1.data());
    offset(k1, h / 2);
    enright_velocity(&flow, n, stage.data(), t + h / 2, k2.data());
    offset(k2, h / 2);
    enright_velocity(&flow, n, stage.data(), t + h / 2, k3.data());
    offset(k3, h);
    enright_velocity(&flow, n, stage.data(), t + h, k4.data());
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < xyz.size(); ++i)
        xyz[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
}

bool make_directory(const std::string &path)
{
    return mkdir(path.c_str(), 0777) == 0 || errno == EEXIST;
}

// The mesh at time t as DIR/t<time>.obj, named and headed as the tool names its own: the
// mesh passes through a surfadapt handle only so that save_checkpoint writes it (a mesh the
// library refuses, such as one with a zero-area triangle, is reported and not written).
bool write_checkpoint(const std::string &dir, const PeerMesh &mesh, double t, std::string &error)
{
    const FlatMesh flat = to_flat_mesh(mesh);
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK) {
        error = "sfa_create failed";
        return false;
    }
    bool written = false;
    if (sfa_set_mesh(s, flat.vertices(), flat.xyz.data(), flat.triangles(), flat.tris.data(), 0) != SFA_OK) {
        error = "the mesh at t = " + std::to_string(t) + " is not one surfadapt accepts: " + sfa_last_error(s);
    } else {
        char name[64];
        std::snprintf(name, sizeof name, "/t%g.obj", t);
        const Checkpoint info{"enright", period, t, {centre[0], centre[1], centre[2]}, radius};
        written = save_checkpoint(s, info, dir + name, error);
    }
    sfa_destroy(s);
    return written;
}

} // namespace

int main(int argc, char **argv)
{
    std::string checkpoint_dir;
    int iterations = 1;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--checkpoints") && i + 1 < argc)
            checkpoint_dir = argv[++i];
        else if (!std::strcmp(argv[i], "--iterations") && i + 1 < argc)
            iterations = std::atoi(argv[++i]);
        else
            return usage();
    }
    if (iterations < 1)
        return usage();
    if (!checkpoint_dir.empty() && !make_directory(checkpoint_dir)) {
        std::fprintf(stderr, "cgal_enright: cannot create %s\n", checkpoint_dir.c_str());
        return 1;
    }

    int32_t nverts = 0, ntris = 0;
    double *sphere_xyz = nullptr;
    int32_t *sphere_tris = nullptr;
    if (geodesic_sphere(frequency, radius, centre, &nverts, &sphere_xyz, &ntris, &sphere_tris) != 0) {
        std::fprintf(stderr, "cgal_enright: out of memory\n");
        return 1;
    }
    PeerMesh mesh;
    const bool built = to_peer_mesh(nverts, sphere_xyz, ntris, sphere_tris, mesh);
    std::free(sphere_xyz);
    std::free(sphere_tris);
    if (!built) {
        std::fprintf(stderr, "cgal_enright: the start sphere is not a valid surface mesh\n");
        return 1;
    }
    const double target = mean_edge_length(mesh);
    const double volume0 = PMP::volume(mesh), area0 = PMP::area(mesh);
    const int vertices_start = static_cast<int>(mesh.number_of_vertices());
    int threads = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
#endif
    std::printf("Enright flow tracked by CGAL %s isotropic_remeshing (%d iteration(s) every %d steps, target edge "
                "length %.6g): %d vertices; T = %g, dt = %g, %d steps; %d thread(s) for the velocity field\n",
                CGAL_VERSION_STR, iterations, remesh_every, target, vertices_start, period, dt, steps, threads);
    std::fflush(stdout);

    std::string error;
    // At t = 0 and every quarter period, as the tool saves them.
    const auto save = [&](int step, double t) {
        return checkpoint_dir.empty() || (4 * step) % steps != 0 || write_checkpoint(checkpoint_dir, mesh, t, error);
    };
    if (!save(0, 0)) {
        std::fprintf(stderr, "cgal_enright: %s\n", error.c_str());
        return 1;
    }
    // The work (advection and remeshing) is timed apart from the measuring and the writing of
    // checkpoints, and the whole loop with them (as the tool's "seconds" is).
    const auto loop_start = PeerClock::now();
    double advect_seconds = 0, remesh_seconds = 0;
    double volume_error = 0, worst_volume_error = 0, max_area_ratio = 1;
    int vertices_max = vertices_start;
    std::vector<double> xyz;
    double t = 0;
    for (int step = 1; step <= steps; ++step) {
        auto phase = PeerClock::now();
        get_positions(mesh, xyz);
        rk4_step(xyz, t, step * dt - t);
        set_positions(mesh, xyz);
        t = step * dt;
        advect_seconds += seconds_since(phase);
        if (step % remesh_every == 0) {
            phase = PeerClock::now();
            PMP::isotropic_remeshing(faces(mesh), target, mesh, CGAL::parameters::number_of_iterations(iterations));
            // Dense vertex numbers again, for the next step's arrays.
            mesh.collect_garbage();
            remesh_seconds += seconds_since(phase);
        }
        volume_error = (PMP::volume(mesh) - volume0) / volume0;
        if (std::abs(volume_error) > std::abs(worst_volume_error))
            worst_volume_error = volume_error;
        max_area_ratio = std::max(max_area_ratio, PMP::area(mesh) / area0);
        vertices_max = std::max(vertices_max, static_cast<int>(mesh.number_of_vertices()));
        if (!save(step, t)) {
            std::fprintf(stderr, "cgal_enright: %s\n", error.c_str());
            return 1;
        }
    }
    const double loop_seconds = seconds_since(loop_start);
    const AngleFigures angles = angle_figures(to_flat_mesh(mesh));
    std::printf("{\"bench\":\"peer_flow\",\"peer\":\"cgal_isotropic_remeshing\",\"cgal\":\"%s\","
                "\"flow\":\"enright\",\"steps\":%d,\"remesh_every\":%d,\"iterations\":%d,"
                "\"target_edge_length\":%.6g,\"threads\":%d,\"vertices_start\":%d,\"vertices_max\":%d,"
                "\"vertices_end\":%d,\"volume_error\":%.3e,\"worst_volume_error\":%.3e,\"max_area_ratio\":%.3f,"
                "\"min_angle\":%.2f,\"max_angle\":%.2f,\"good_angles\":%.3f,\"seconds\":%.2f,\"remesh_s\":%.2f,"
                "\"advect_s\":%.2f,\"loop_seconds\":%.2f}\n",
                CGAL_VERSION_STR, steps, remesh_every, iterations, target, threads, vertices_start, vertices_max,
                static_cast<int>(mesh.number_of_vertices()), volume_error, worst_volume_error, max_area_ratio,
                angles.smallest, angles.largest, angles.good_share, advect_seconds + remesh_seconds, remesh_seconds,
                advect_seconds, loop_seconds);
    return 0;
}
