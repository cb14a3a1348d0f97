// surfadapt: the command-line tool. A host of the library like any other: it uses only
// the public C interface.
//
//   surfadapt demo            advect a sphere through the Enright flow, print a table
//   surfadapt info FILE       validate an OBJ/OFF mesh and print its measures
//   surfadapt features IN OUT write the detected features of a mesh as VTK for ParaView
#include "flows.hpp"
#include "icosphere.h"
#include "obj_io.h"
#include "vtk_writer.h"

#include "surfadapt.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char *usage = "usage: surfadapt COMMAND [OPTIONS]\n"
                    "\n"
                    "commands:\n"
                    "  demo [--subdivisions K] [--steps N]\n"
                    "        advect a sphere of radius 0.15 at (0.35, 0.35, 0.35) through the Enright\n"
                    "        flow (period T = 3, dt = 0.015) with fourth-order Runge-Kutta and fold\n"
                    "        control, and print volume, area and angles every 20 steps. K (default 5)\n"
                    "        sets the icosphere resolution: 10*4^K+2 vertices. N defaults to 200 (t = 3).\n"
                    "  info FILE [--drop-unreferenced]\n"
                    "        read an OBJ or OFF mesh, validate it and print its measures\n"
                    "  features IN OUT.vtk [--drop-unreferenced]\n"
                    "        read an OBJ or OFF mesh, detect its ridges and corners and write a legacy\n"
                    "        VTK file for ParaView: triangles (POLYGONS) and ridge edges (LINES) with\n"
                    "        cell data 'ridge', point data 'rank' (0 smooth, 1 ridge, 2 corner),\n"
                    "        'aspect_ratio', 'long_direction' and 'normal' of the anisotropic metric\n"
                    "  --help\n"
                    "        this text\n";

int fail(sfa_surface *s, const char *what)
{
    std::fprintf(stderr, "surfadapt: %s: %s\n", what, sfa_last_error(s));
    sfa_destroy(s);
    return 1;
}

double measure(const sfa_surface *s, int quantity)
{
    double value = NAN;
    sfa_measure(s, quantity, &value);
    return value;
}

// Reads an OBJ/OFF file into a new surface; prints why and returns nullptr on failure.
sfa_surface *surface_from_file(const char *path, bool drop_unreferenced)
{
    sfa_mesh_data mesh{};
    char error[512];
    if (mesh_read(path, &mesh, error, sizeof error) != 0) {
        std::fprintf(stderr, "surfadapt: %s\n", error);
        return nullptr;
    }
    sfa_surface *s = nullptr;
    int rc = sfa_create(&s);
    if (rc == SFA_OK) {
        sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, drop_unreferenced ? 1 : 0);
        rc = sfa_set_mesh(s, mesh.nverts, mesh.xyz, mesh.ntris, mesh.tris, 0);
        if (rc != SFA_OK) {
            fail(s, path);
            s = nullptr;
        }
    }
    mesh_free(&mesh);
    return s;
}

// The options after the file names of `info` and `features`: only --drop-unreferenced.
// Prints the usage and returns false on anything else.
bool read_drop_option(int argc, char **argv, int first, const char *command, bool &drop)
{
    for (int i = first; i < argc; ++i) {
        if (std::strcmp(argv[i], "--drop-unreferenced") != 0) {
            std::fprintf(stderr, "surfadapt %s: unknown option '%s'\n%s", command, argv[i], usage);
            return false;
        }
        drop = true;
    }
    return true;
}

// Reads an integer option value, or exits with a message.
int int_option(int argc, char **argv, int &i, int lo, int hi)
{
    if (i + 1 >= argc) {
        std::fprintf(stderr, "surfadapt: %s needs a value\n", argv[i]);
        std::exit(2);
    }
    char *end = nullptr;
    const long value = std::strtol(argv[++i], &end, 10);
    if (*end != '\0' || value < lo || value > hi) {
        std::fprintf(stderr, "surfadapt: %s must be an integer from %d to %d, got '%s'\n", argv[i - 1], lo, hi,
                     argv[i]);
        std::exit(2);
    }
    return static_cast<int>(value);
}

int demo(int argc, char **argv)
{
    int subdivisions = 5, steps = 200;
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--subdivisions"))
            subdivisions = int_option(argc, argv, i, 0, 8);
        else if (!std::strcmp(argv[i], "--steps"))
            steps = int_option(argc, argv, i, 0, 1000000);
        else {
            std::fprintf(stderr, "surfadapt demo: unknown option '%s'\n%s", argv[i], usage);
            return 2;
        }
    }
    const double center[3] = {0.35, 0.35, 0.35}, radius = 0.15, dt = 0.015;
    FlowPeriod flow{3.0};
    int32_t nverts = 0, ntris = 0;
    double *xyz = nullptr;
    int32_t *tris = nullptr;
    if (icosphere(subdivisions, radius, center, &nverts, &xyz, &ntris, &tris) != 0) {
        std::fprintf(stderr, "surfadapt: out of memory\n");
        return 1;
    }
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK)
        return 1;
    const int rc = sfa_set_mesh(s, nverts, xyz, ntris, tris, 0);
    std::free(xyz);
    std::free(tris);
    if (rc != SFA_OK)
        return fail(s, "sfa_set_mesh");

    const double volume0 = measure(s, SFA_MEASURE_VOLUME), area0 = measure(s, SFA_MEASURE_AREA);
    std::printf("Enright flow, T = %g, dt = %g: sphere of %d vertices, %d triangles, advected with RK4 and fold\n"
                "control only (no re-meshing yet: the mesh is stretched as the flow stretches it).\n\n",
                flow.period, dt, nverts, ntris);
    std::printf("%5s %7s %9s %12s %10s %9s %9s %11s %8s\n", "step", "t", "substeps", "volume err %", "area ratio",
                "min angle", "max angle", "max aspect", "seconds");
    const auto start = std::chrono::steady_clock::now();
    double t = 0;
    long substeps = 0;
    for (int step = 1; step <= steps; ++step) {
        const double t_end = step * dt;
        while (t < t_end - 1e-12 * dt) {
            double taken = 0;
            if (sfa_advect(s, enright_velocity, &flow, t, t_end - t, &taken) != SFA_OK)
                return fail(s, "sfa_advect");
            t += taken;
            ++substeps;
        }
        t = t_end;
        if (step % 20 == 0 || step == steps) {
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::printf("%5d %7.3f %9ld %12.5f %10.3f %9.3f %9.3f %11.1f %8.2f\n", step, t, substeps,
                        100 * (measure(s, SFA_MEASURE_VOLUME) - volume0) / volume0,
                        measure(s, SFA_MEASURE_AREA) / area0, measure(s, SFA_MEASURE_MIN_ANGLE),
                        measure(s, SFA_MEASURE_MAX_ANGLE), measure(s, SFA_MEASURE_MAX_ASPECT_RATIO), seconds);
            std::fflush(stdout);
        }
    }
    sfa_destroy(s);
    return 0;
}

int info(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "surfadapt info: which file?\n%s", usage);
        return 2;
    }
    bool drop = false;
    if (!read_drop_option(argc, argv, 3, "info", drop))
        return 2;
    sfa_surface *s = surface_from_file(argv[2], drop);
    if (!s)
        return 1;
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::printf("%s: %d vertices, %d triangles\n", argv[2], nverts, ntris);
    std::printf("  volume %.9g, area %.9g\n", measure(s, SFA_MEASURE_VOLUME), measure(s, SFA_MEASURE_AREA));
    std::printf("  angles %.3f to %.3f degrees, worst aspect ratio %.3f\n", measure(s, SFA_MEASURE_MIN_ANGLE),
                measure(s, SFA_MEASURE_MAX_ANGLE), measure(s, SFA_MEASURE_MAX_ASPECT_RATIO));
    std::printf("  edge length: min %.6g, mean %.6g, max %.6g\n", measure(s, SFA_MEASURE_MIN_EDGE_LENGTH),
                measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), measure(s, SFA_MEASURE_MAX_EDGE_LENGTH));
    sfa_destroy(s);
    return 0;
}

int features(int argc, char **argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "surfadapt features: needs an input mesh and an output .vtk file\n%s", usage);
        return 2;
    }
    bool drop = false;
    if (!read_drop_option(argc, argv, 4, "features", drop))
        return 2;
    const char *in = argv[2], *out = argv[3];
    sfa_surface *s = surface_from_file(in, drop);
    if (!s)
        return 1;

    // Read the mesh back: dropping unreferenced vertices renumbers them, and the ranks and
    // frames follow the library's numbering.
    int32_t nverts = 0, ntris = 0, nlines = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::vector<double> xyz(3 * static_cast<size_t>(nverts)), long_direction(xyz.size()), normal(xyz.size());
    std::vector<double> aspect_ratio(static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris)), rank(static_cast<size_t>(nverts));
    if (sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0) != SFA_OK)
        return fail(s, "sfa_get_mesh");
    if (sfa_get_feature_ranks(s, nverts, rank.data()) != SFA_OK)
        return fail(s, "sfa_get_feature_ranks");
    if (sfa_get_vertex_frames(s, nverts, normal.data(), long_direction.data(), aspect_ratio.data()) != SFA_OK)
        return fail(s, "sfa_get_vertex_frames");
    if (sfa_get_ridge_edges(s, 0, nullptr, &nlines, 0) != SFA_OK)
        return fail(s, "sfa_get_ridge_edges");
    std::vector<int32_t> lines(2 * static_cast<size_t>(nlines) + 1);
    if (sfa_get_ridge_edges(s, nlines, lines.data(), &nlines, 0) != SFA_OK)
        return fail(s, "sfa_get_ridge_edges");
    sfa_destroy(s);

    VtkFeatureMesh vtk;
    vtk.nverts = nverts;
    vtk.ntris = ntris;
    vtk.nlines = nlines;
    vtk.xyz = xyz.data();
    vtk.tris = tris.data();
    vtk.lines = lines.data();
    vtk.rank = rank.data();
    vtk.aspect_ratio = aspect_ratio.data();
    vtk.long_direction = long_direction.data();
    vtk.normal = normal.data();
    std::string write_error;
    const std::string title = std::string("surfadapt features of ") + in;
    // The title is one line of at most 256 characters in the legacy format.
    if (!write_vtk_features(out, title.substr(0, 255).c_str(), vtk, write_error)) {
        std::fprintf(stderr, "surfadapt: %s\n", write_error.c_str());
        return 1;
    }
    int32_t count[3] = {0, 0, 0};
    for (const int32_t r : rank)
        if (r >= 0 && r <= 2)
            ++count[r];
    std::printf("%s: %d vertices, %d triangles: %d smooth, %d ridge, %d corner vertices, %d ridge edges -> %s\n", in,
                nverts, ntris, count[0], count[1], count[2], nlines, out);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        std::fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    if (command == "demo")
        return demo(argc, argv);
    if (command == "info")
        return info(argc, argv);
    if (command == "features")
        return features(argc, argv);
    std::fprintf(stderr, "surfadapt: unknown command '%s'\n%s", argv[1], usage);
    return 2;
}
