// SPDX-License-Identifier: BSD-3-Clause
// surfadapt remesh IN OUT: the static use of the library (paper §5.1).
#include "remesh.hpp"

#include "cli.hpp"
#include "commands.hpp"
#include "component_report.hpp"
#include "progress.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

double parameter(const sfa_surface *s, int key)
{
    double value = 0;
    sfa_get_param(s, key, &value);
    return value;
}

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
    const std::vector<ComponentSummary> components = summarize_components(s);
    print_components(components);
    std::printf("  %-8s %9s %9s %13s %10s %9s %9s %9s %8s %8s %8s\n", "", "vertices", "triangles", "volume change",
                "mean edge", "min angle", "max angle", "% good", "corners", "ridges", "seconds");
    print_quality_row("input", before, before.volume, 0);
    // One sfa_adapt call changes the size by a bounded factor (a contraction at most
    // halves an edge's count along a line per pass), so a mesh far from l needs several.
    // The calls stop when one changes the vertex count by less than settled_change.
    constexpr int most_calls = 12;
    constexpr double settled_change = 0.01;
    const auto start = std::chrono::steady_clock::now();
    int calls = 0;
    double change = 1;
    Progress progress;
    for (int32_t vertices = before.vertices; calls < most_calls && change >= settled_change;) {
        progress.show("sfa_adapt call %d, from %d vertices", calls + 1, vertices);
        if (sfa_adapt(s) != SFA_OK) {
            std::fprintf(stderr, "surfadapt: sfa_adapt: %s\n", sfa_last_error(s));
            return 1;
        }
        ++calls;
        int32_t now = 0, triangles = 0;
        sfa_get_counts(s, &now, &triangles);
        change = std::fabs(static_cast<double>(now - vertices)) / vertices;
        vertices = now;
    }
    progress.clear();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const Quality after = quality_of(s);
    print_quality_row("output", after, before.volume, seconds);
    std::printf("  (%% good: triangles with every angle in [15, 160] degrees; corners and ridges as detected)\n");
    std::printf("  after:\n");
    print_components(summarize_components(s), &components);
    if (change < settled_change)
        std::printf("  settled after %d sfa_adapt calls (the last changed the vertex count by %.2g %%): mean edge "
                    "%.4g, %.2f l;\n  edges settle between %g l and %g l, shorter across ridges and tight curves\n",
                    calls, 100 * change, after.mean_edge, after.mean_edge / edge_length,
                    parameter(s, SFA_PARAM_SHORT_EDGE_RATIO), parameter(s, SFA_PARAM_SPLIT_LENGTH_RATIO));
    else
        std::printf("  not settled after %d sfa_adapt calls: the last changed the vertex count by %.2g %%; mean edge "
                    "%.4g, %.2f l\n",
                    calls, 100 * change, after.mean_edge, after.mean_edge / edge_length);
    if (std::any_of(components.begin(), components.end(), [](const ComponentSummary &c) { return c.closed(); }))
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
        std::fprintf(stderr, "surfadapt remesh: needs an input and an output mesh file\n");
        print_synopsis("remesh");
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
            std::fprintf(stderr, "surfadapt remesh: unknown option '%s'\n", argv[i]);
            print_synopsis("remesh");
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
