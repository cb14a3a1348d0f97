// SPDX-License-Identifier: BSD-3-Clause
// surfadapt demo: the static case (a generated machined part remeshed) and the dynamic one
// (the paper's Enright test with adaptation).
#include "cli.hpp"
#include "commands.hpp"
#include "flow_run.hpp"
#include "machined_part.h"
#include "remesh.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

// The machined part's edge length, as the tests use it (tests/c/test_machined_part.c): about
// 12 edges across its thickness and 47 round the hole.
constexpr double part_edge_length = 0.08;
// A 45-degree chamfer turns the surface by 45 degrees at each of its edges, which is the
// default ridge angle itself: at the default the chamfer's vertical edges are not found.
// The fillet's and the hole's segments turn by 15 degrees, far below 30.
constexpr double part_ridge_angle = 30;

machined_part_features part_features(const sfa_surface *s)
{
    int32_t nv = 0, nt = 0, nridges = 0;
    sfa_get_counts(s, &nv, &nt);
    std::vector<double> xyz(3 * static_cast<size_t>(nv));
    std::vector<int32_t> tris(3 * static_cast<size_t>(nt)), ranks(static_cast<size_t>(nv));
    sfa_get_mesh(s, nv, xyz.data(), nt, tris.data(), 0);
    sfa_get_feature_ranks(s, nv, ranks.data());
    sfa_get_ridge_edges(s, 0, nullptr, &nridges, 0);
    std::vector<int32_t> ridges(2 * static_cast<size_t>(nridges));
    sfa_get_ridge_edges(s, nridges, ridges.data(), &nridges, 0);
    machined_part_features f;
    // Points within 0.02 of a feature are on it: the arcs' chords stay within 0.009 of them.
    machined_part_features_of(nv, xyz.data(), ranks.data(), nridges, ridges.data(), 0.02, &f);
    return f;
}

// Ridge curves of the part found whole, among curves first to last.
int curves_found(const machined_part_features &f, int first, int last)
{
    int n = 0;
    for (int k = first; k <= last; ++k)
        n += machined_part_ridge_found(&f, k);
    return n;
}

void print_part_features(const machined_part_features &in, const machined_part_features &out)
{
    std::printf("\n  the part's sharp features, expected and as detected (ridge angle %g degrees)\n", part_ridge_angle);
    std::printf("  %-52s %8s %8s %8s\n", "", "expected", "input", "output");
    const auto row = [](const char *label, int expected, int a, int b) {
        std::printf("  %-52s %8d %8d %8d\n", label, expected, a, b);
    };
    row("corners: the 4 vertical edges' ends", MACHINED_PART_CORNERS, in.corners_found, out.corners_found);
    row("ridge curves found whole", MACHINED_PART_RIDGES, in.ridges_found, out.ridges_found);
    row("  outlines of top and bottom (2 round the fillet)", 8, curves_found(in, 0, 7), curves_found(out, 0, 7));
    row("  vertical edges: 2 of the block, 2 of the chamfer", 4, curves_found(in, 8, 11), curves_found(out, 8, 11));
    row("  the hole's 2 rims", 2, curves_found(in, 12, 13), curves_found(out, 12, 13));
    std::printf("  %-52s %8s %8d %8d\n", "ridge edges along the 14 curves", "", in.ridge_edges, out.ridge_edges);
    row("corners anywhere else", 0, in.corners_elsewhere, out.corners_elsewhere);
    row("ridge edges anywhere else", 0, in.ridge_edges_elsewhere, out.ridge_edges_elsewhere);
    row("  of them on the fillet (its tangent lines included)", 0, in.on_fillet, out.on_fillet);
    row("  of them on the hole's wall", 0, in.on_hole_wall, out.on_hole_wall);
}

// The static case. By default the machined part of machined_part.h, generated here, so that
// every machine shows the same: tessellated as a CAD program exports it and remeshed at
// edge length 0.08, its features checked against the ones it has. With --mesh, that file,
// remeshed at half its mean edge length.
int remesh_demo(const char *mesh_file, const std::string &out_dir)
{
    const std::string out = out_dir + "/remeshed.vtk";
    if (mesh_file) {
        sfa_surface *s = surface_from_file(mesh_file, false);
        if (!s)
            return 1;
        const int status = remesh_surface(s, mesh_file, 0.5 * measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), false,
                                          out.c_str());
        sfa_destroy(s);
        return status;
    }
    int32_t nv = 0, nt = 0;
    double *xyz = nullptr;
    int32_t *tris = nullptr;
    if (machined_part(24, &nv, &xyz, &nt, &tris) != 0) {
        std::fprintf(stderr, "surfadapt: out of memory\n");
        return 1;
    }
    sfa_surface *s = nullptr;
    const int created = sfa_create(&s);
    const int set = created == SFA_OK ? sfa_set_mesh(s, nv, xyz, nt, tris, 0) : created;
    std::free(xyz);
    std::free(tris);
    if (created != SFA_OK)
        return 1;
    if (set != SFA_OK)
        return fail(s, "sfa_set_mesh");
    if (sfa_set_param(s, SFA_PARAM_RIDGE_ANGLE, part_ridge_angle) != SFA_OK)
        return fail(s, "sfa_set_param");
    const std::string in = out_dir + "/part.vtk";
    std::string error;
    if (!write_surface_vtk(s, in.c_str(), "surfadapt demo: the machined part as generated", error)) {
        std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
        sfa_destroy(s);
        return 1;
    }
    std::printf("A machined part, generated: a 4 x 3 x 1 block with a hole of radius 0.6 drilled through it,\n"
                "one vertical edge chamfered (45 degrees, 0.6 wide) and one filleted (radius 1). Tessellated\n"
                "as a CAD program exports it: walls of triangles as tall as the part, fans of long thin\n"
                "triangles on the top and the bottom. Written to %s.\n\n",
                in.c_str());
    const machined_part_features before = part_features(s);
    const int status = remesh_surface(s, "the machined part", part_edge_length, false, out.c_str());
    if (status == 0)
        print_part_features(before, part_features(s));
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
            std::fprintf(stderr, "surfadapt demo: unknown option '%s'\n", argv[i]);
            print_synopsis("demo");
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
