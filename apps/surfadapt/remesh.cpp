// SPDX-License-Identifier: BSD-3-Clause
// surfadapt remesh IN OUT: the static use of the library (paper §5.1).
#include "remesh.hpp"

#include "cli.hpp"
#include "commands.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

void print_quality_row(const char *label, const Quality &q, double volume0, double seconds)
{
    std::printf("  %-8s %9d %9d %13.2e %10.4f %9.2f %9.2f %9.1f %8d %8d %8.2f\n", label, q.vertices, q.triangles,
                (q.volume - volume0) / volume0, q.mean_edge, q.min_angle, q.max_angle, 100 * q.good_share, q.corners,
                q.ridge_edges, seconds);
}

} // namespace

int remesh_surface(sfa_surface *s, const char *name, double edge_length, bool isotropic, const char *out)
{
    if (sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, edge_length) != SFA_OK ||
        sfa_set_param(s, SFA_PARAM_ANISOTROPIC, isotropic ? 0 : 1) != SFA_OK) {
        std::fprintf(stderr, "surfadapt: %s\n", sfa_last_error(s));
        return 1;
    }
    const Quality before = quality_of(s);
    std::printf("%s remeshed %s at edge length %g:\n", name, isotropic ? "isotropically" : "anisotropically",
                edge_length);
    print_components(s);
    std::printf("  %-8s %9s %9s %13s %10s %9s %9s %9s %8s %8s %8s\n", "", "vertices", "triangles", "volume change",
                "mean edge", "min angle", "max angle", "% good", "corners", "ridges", "seconds");
    print_quality_row("input", before, before.volume, 0);
    const auto start = std::chrono::steady_clock::now();
    for (int call = 0; call < 3; ++call)
        if (sfa_adapt(s) != SFA_OK) {
            std::fprintf(stderr, "surfadapt: sfa_adapt: %s\n", sfa_last_error(s));
            return 1;
        }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print_quality_row("output", quality_of(s), before.volume, seconds);
    std::printf("  (%% good: triangles with every angle in [15, 160] degrees; corners and ridges as detected)\n");
    std::printf("  the operations of the last sfa_adapt changed a closed component's volume by at most %.2g "
                "(relative), which the volume correction took back\n",
                measure(s, SFA_MEASURE_VOLUME_CORRECTION));
    if (out) {
        std::string error;
        if (!write_surface(s, out, std::string("surfadapt remesh of ") + name, error)) {
            std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
            return 1;
        }
        std::printf("  written to %s\n", out);
    }
    return 0;
}

int remesh_command(int argc, char **argv)
{
    if (argc < 4) {
        std::fprintf(stderr, "surfadapt remesh: needs an input and an output mesh file\n%s", usage);
        return 2;
    }
    const char *in = argv[2], *out = argv[3];
    double edge_length = 0;
    bool isotropic = false, drop = false;
    for (int i = 4; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--edge-length"))
            edge_length = positive_option(argc, argv, i);
        else if (!std::strcmp(argv[i], "--isotropic"))
            isotropic = true;
        else if (!std::strcmp(argv[i], "--drop-unreferenced"))
            drop = true;
        else {
            std::fprintf(stderr, "surfadapt remesh: unknown option '%s'\n%s", argv[i], usage);
            return 2;
        }
    }
    // Before the work, not after it: an output the tool cannot write is a usage error.
    if (!known_output_format(out))
        return 2;
    sfa_surface *s = surface_from_file(in, drop);
    if (!s)
        return 1;
    if (edge_length == 0)
        edge_length = measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH);
    const int status = remesh_surface(s, in, edge_length, isotropic, out);
    sfa_destroy(s);
    return status;
}
