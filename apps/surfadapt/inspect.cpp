// SPDX-License-Identifier: BSD-3-Clause
// surfadapt info, features and convert: what the library sees in a mesh, and mesh files
// from one format to another.
#include "cli.hpp"
#include "commands.hpp"
#include "component_report.hpp"
#include "mesh_formats.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

int info_command(int argc, char **argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "surfadapt info: which file?\n");
        print_synopsis("info");
        return 2;
    }
    bool drop = false;
    if (!read_drop_option(argc, argv, 3, "info", drop))
        return 2;
    sfa_surface *s = surface_from_file(argv[2], drop);
    if (!s) {
        suggest_repair(argv[2]);
        return 1;
    }
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::printf("%s: %d vertices, %d triangles\n", argv[2], nverts, ntris);
    std::printf("  volume %.9g, area %.9g\n", measure(s, SFA_MEASURE_VOLUME), measure(s, SFA_MEASURE_AREA));
    std::printf("  angles %.3f to %.3f degrees, worst aspect ratio %.3f\n", measure(s, SFA_MEASURE_MIN_ANGLE),
                measure(s, SFA_MEASURE_MAX_ANGLE), measure(s, SFA_MEASURE_MAX_ASPECT_RATIO));
    std::printf("  edge length: min %.6g, mean %.6g, max %.6g\n", measure(s, SFA_MEASURE_MIN_EDGE_LENGTH),
                measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH), measure(s, SFA_MEASURE_MAX_EDGE_LENGTH));
    std::printf("  unresolved (the surface turns by more than a right angle within a triangle): %.2f %% of the "
                "area; ",
                100 * measure(s, SFA_MEASURE_UNRESOLVED_AREA));
    // 180 is the measure's "none": every triangle is unresolved (no real smallest angle is
    // above 60). NaN: the measure failed.
    const double resolved_angle = measure(s, SFA_MEASURE_MIN_ANGLE_RESOLVED);
    if (std::isnan(resolved_angle))
        std::printf("the angles elsewhere unavailable\n");
    else if (resolved_angle >= 180)
        std::printf("no triangle elsewhere\n");
    else
        std::printf("angles from %.3f degrees elsewhere\n", resolved_angle);
    print_components(summarize_components(s));
    sfa_destroy(s);
    return 0;
}

int features_command(int argc, char **argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "surfadapt features: needs an input and an output mesh file\n");
        print_synopsis("features");
        return 2;
    }
    bool drop = false;
    if (!read_drop_option(argc, argv, 4, "features", drop))
        return 2;
    const char *in = argv[2], *out = argv[3];
    if (!known_output_format(out))
        return 2;
    sfa_surface *s = surface_from_file(in, drop);
    if (!s)
        return 1;
    std::string error;
    if (!write_surface(s, out, std::string("surfadapt features of ") + in, error)) {
        std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
        sfa_destroy(s);
        return 1;
    }
    int32_t nverts = 0, ntris = 0, nlines = 0;
    sfa_get_counts(s, &nverts, &ntris);
    sfa_get_ridge_edges(s, 0, nullptr, &nlines, 0);
    std::vector<int32_t> rank(static_cast<size_t>(nverts));
    sfa_get_feature_ranks(s, nverts, rank.data());
    sfa_destroy(s);
    int32_t count[3] = {0, 0, 0};
    for (const int32_t r : rank)
        if (r >= 0 && r <= 2)
            ++count[r];
    std::printf("%s: %d vertices, %d triangles: %d smooth, %d ridge, %d corner vertices, %d ridge edges -> %s\n", in,
                nverts, ntris, count[0], count[1], count[2], nlines, out);
    return 0;
}

// A file's mesh as it is in another format, without the library: a mesh the library
// refuses can still be converted (and then looked at).
int convert_command(int argc, char **argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "surfadapt convert: needs an input and an output mesh file\n");
        print_synopsis("convert");
        return 2;
    }
    const char *in = argv[2], *out = argv[3];
    if (!known_output_format(out))
        return 2;
    sfa_mesh_data mesh{};
    char error[512];
    if (mesh_file_read(in, &mesh, nullptr, error, sizeof error) != 0) {
        std::fprintf(stderr, "surfadapt: %s\n", error);
        return 1;
    }
    const int rc = mesh_file_write(out, &mesh, (std::string("surfadapt convert of ") + in).c_str(), nullptr, error,
                                   sizeof error);
    if (rc != 0)
        std::fprintf(stderr, "surfadapt: %s\n", error);
    else
        std::printf("%s: %d vertices, %d triangles -> %s\n", in, mesh.nverts, mesh.ntris, out);
    mesh_free(&mesh);
    return rc != 0;
}
