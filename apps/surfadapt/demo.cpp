// surfadapt demo: the static case (a CAD part remeshed) and the dynamic one (a sphere
// through the Enright flow).
#include "cli.hpp"
#include "commands.hpp"
#include "flows.hpp"
#include "icosphere.h"
#include "remesh.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

// The static case: fandisk from the data directory ($SFA_DATA_DIR, else ../shared/data)
// or the file given, remeshed at half its mean edge length; without it, the 2 x 1 x 0.5
// box of 8 vertices refined to edge length 0.08 (the paper's Fig. 2).
int remesh_demo(const char *mesh_file, const std::string &out_dir)
{
    std::string path = mesh_file ? mesh_file : "";
    if (path.empty()) {
        const char *dir = std::getenv("SFA_DATA_DIR");
        path = std::string(dir && *dir ? dir : "../shared/data") + "/fandisk.obj";
        if (std::FILE *f = std::fopen(path.c_str(), "r"))
            std::fclose(f);
        else
            path.clear();
    }
    const std::string out = out_dir + (path.empty() ? "/box-remeshed.vtk" : "/remeshed.vtk");
    if (!path.empty()) {
        sfa_surface *s = surface_from_file(path.c_str(), false);
        if (!s)
            return 1;
        const int status = remesh_surface(s, path.c_str(), 0.5 * measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), false,
                                          out.c_str());
        sfa_destroy(s);
        return status;
    }
    const double xyz[] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 0.5, 2, 0, 0.5, 2, 1, 0.5, 0, 1, 0.5};
    const int32_t tris[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                            1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK)
        return 1;
    if (sfa_set_mesh(s, 8, xyz, 12, tris, 0) != SFA_OK)
        return fail(s, "sfa_set_mesh");
    std::printf("(no fandisk.obj in the data directory: a generated box instead)\n");
    const int status = remesh_surface(s, "the 2 x 1 x 0.5 box", 0.08, false, out.c_str());
    sfa_destroy(s);
    return status;
}

int enright_demo(int subdivisions, int steps)
{
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

} // namespace

int demo_command(int argc, char **argv)
{
    int subdivisions = 5, steps = 200;
    const char *mesh_file = nullptr;
    std::string out_dir = ".";
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--subdivisions"))
            subdivisions = int_option(argc, argv, i, 0, 8);
        else if (!std::strcmp(argv[i], "--steps"))
            steps = int_option(argc, argv, i, 0, 1000000);
        else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc)
            mesh_file = argv[++i];
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            out_dir = argv[++i];
        else {
            std::fprintf(stderr, "surfadapt demo: unknown option '%s'\n%s", argv[i], usage);
            return 2;
        }
    }
    std::printf("== Static: remeshing a surface with sharp features\n\n");
    if (const int status = remesh_demo(mesh_file, out_dir))
        return status;
    std::printf("\n== Dynamic: a sphere through the Enright flow\n\n");
    return enright_demo(subdivisions, steps);
}
