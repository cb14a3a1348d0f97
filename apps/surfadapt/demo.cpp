// SPDX-License-Identifier: BSD-3-Clause
// surfadapt demo: the static case (a CAD part remeshed) and the dynamic one (the paper's
// Enright test with adaptation).
#include "cli.hpp"
#include "commands.hpp"
#include "flow_run.hpp"
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

} // namespace

int demo_command(int argc, char **argv)
{
    FlowRun enright = enright_setup();
    const char *mesh_file = nullptr;
    std::string out_dir = ".";
    for (int i = 2; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--resolution"))
            enright.frequency = int_option(argc, argv, i, 1, 2000);
        else if (!std::strcmp(argv[i], "--steps"))
            enright.steps = int_option(argc, argv, i, 0, 1000000);
        else if (!std::strcmp(argv[i], "--mesh") && i + 1 < argc)
            mesh_file = argv[++i];
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            out_dir = argv[++i];
        else {
            std::fprintf(stderr, "surfadapt demo: unknown option '%s'\n%s", argv[i], usage);
            return 2;
        }
    }
    if (!ensure_directory(out_dir)) {
        std::fprintf(stderr, "surfadapt demo: cannot create %s\n", out_dir.c_str());
        return 1;
    }
    std::printf("== Static: remeshing a surface with sharp features\n\n");
    if (const int status = remesh_demo(mesh_file, out_dir))
        return status;
    std::printf("\n== Dynamic: a sphere through the Enright flow, adapted as it deforms\n\n");
    enright.out_dir = out_dir + "/enright";
    FlowResult result;
    return run_flow(enright, result);
}
