// SPDX-License-Identifier: BSD-3-Clause
// fidelity CHECKPOINT.obj [--steps-per-period N] [--check-step] [--worst K] [--by-turn] [--angles-only] [--json]
//
// The shape error of a tracked surface, measured by backtracing (issue "many bubbles",
// item 3). The paper's flows are time-reversible: every point of the exact surface at time
// t, carried backward by the same velocity field to t = 0, lands on the start sphere. So
// each sample of the tracked mesh at time t is integrated back to t = 0 with RK4, and its
// error is d = | |p0 - c| - r | / r. The samples are the vertices, the edge midpoints and
// four points inside every triangle (its centroid and the three points (2/3, 1/6, 1/6)),
// so a mesh that keeps its vertices on the surface but lets its triangles cut across it is
// seen. Reported: the largest d of any sample, the area-weighted RMS and 99th percentile
// over the triangles' points (each stands for a quarter of its triangle's area), the
// largest d and the RMS over the vertices alone, and the area-weighted mean of the signed error
// (|p0 - c| - r) / r, which shows a bias such as a global offset of the surface; and the
// mesh's smallest and largest angle; and where the mesh resolves the surface
// (bench/surface_resolution.hpp), the largest and RMS d and the smallest angle, with the
// share of the area left out for that and how many triangles below 5 degrees lie there.
// --angles-only gives the angles alone, without the backtrace (which takes minutes on the
// largest meshes).
//
// The mesh is a flow run's checkpoint (surfadapt enright|vortex --checkpoints DIR), whose
// first line names the flow, its period, the time and the start sphere. The RK4 step is
// T / N (N = 1000 by default: halving it changes the figures by about 1e-8); --check-step integrates again at half the step and prints
// how much that changes each figure, which must be nothing that matters. --worst K lists
// the K samples of the largest error (a vertex with its number in the file); --by-turn
// tells where the error lies (print_by_turn).
#include "checkpoint.hpp"
#include "flows.hpp"
#include "obj_io.h"
#include "surface_resolution.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

struct Samples {
    std::vector<double> xyz;    // 3 per sample
    std::vector<double> weight; // area each stands for; 0 for vertices and edge midpoints
    std::vector<char> resolved; // on a triangle where the surface is resolved (surface_resolution.hpp)
    int32_t vertices = 0;       // the first samples are the vertices
};

// The samples of the mesh; `unresolved` marks its triangles where the surface is not
// resolved, and a sample counts as resolved if any triangle it lies on is.
Samples sample_mesh(const sfa_mesh_data &mesh, const std::vector<char> &unresolved)
{
    Samples samples;
    samples.vertices = mesh.nverts;
    samples.xyz.assign(mesh.xyz, mesh.xyz + 3 * static_cast<size_t>(mesh.nverts));
    samples.weight.assign(mesh.nverts, 0.0);
    samples.resolved.assign(mesh.nverts, 0);
    const auto add = [&](const double *a, const double *b, const double *c, double wa, double wb, double wc,
                         double weight, bool resolved) {
        for (int k = 0; k < 3; ++k)
            samples.xyz.push_back(wa * a[k] + wb * b[k] + wc * c[k]);
        samples.weight.push_back(weight);
        samples.resolved.push_back(resolved);
    };
    std::vector<std::pair<uint64_t, char>> edges; // (key, whether the triangle is resolved)
    for (int32_t t = 0; t < mesh.ntris; ++t) {
        const int32_t *v = mesh.tris + 3 * t;
        const double *a = mesh.xyz + 3 * v[0], *b = mesh.xyz + 3 * v[1], *c = mesh.xyz + 3 * v[2];
        double u[3], w[3];
        for (int k = 0; k < 3; ++k) {
            u[k] = b[k] - a[k];
            w[k] = c[k] - a[k];
        }
        const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        const double quarter = 0.125 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        const bool resolved = !unresolved[t];
        add(a, b, c, 1.0 / 3, 1.0 / 3, 1.0 / 3, quarter, resolved);
        add(a, b, c, 2.0 / 3, 1.0 / 6, 1.0 / 6, quarter, resolved);
        add(a, b, c, 1.0 / 6, 2.0 / 3, 1.0 / 6, quarter, resolved);
        add(a, b, c, 1.0 / 6, 1.0 / 6, 2.0 / 3, quarter, resolved);
        for (int k = 0; k < 3; ++k) {
            const uint64_t i = static_cast<uint32_t>(v[k]), j = static_cast<uint32_t>(v[(k + 1) % 3]);
            edges.push_back({std::min(i, j) << 32 | std::max(i, j), resolved});
            samples.resolved[v[k]] |= resolved;
        }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t e = 0; e < edges.size(); ++e) {
        const uint64_t key = edges[e].first;
        bool resolved = edges[e].second;
        for (; e + 1 < edges.size() && edges[e + 1].first == key; ++e)
            resolved |= edges[e + 1].second;
        const double *a = mesh.xyz + 3 * (key >> 32), *b = mesh.xyz + 3 * (key & 0xffffffffu);
        add(a, b, a, 0.5, 0.5, 0.0, 0.0, resolved);
    }
    return samples;
}

// Carries every point from time t back to 0 by RK4 with `steps` equal steps.
void backtrace(sfa_velocity_fn velocity, double period, double t, int steps, std::vector<double> &xyz)
{
    FlowPeriod flow{period};
    const int32_t n = static_cast<int32_t>(xyz.size() / 3);
    const double h = -t / steps;
    std::vector<double> k1(xyz.size()), k2(xyz.size()), k3(xyz.size()), k4(xyz.size()), stage(xyz.size());
    const auto offset = [&](const std::vector<double> &k, double scale) {
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < xyz.size(); ++i)
            stage[i] = xyz[i] + scale * k[i];
    };
    for (int step = 0; step < steps; ++step) {
        const double time = t + step * h;
        velocity(&flow, n, xyz.data(), time, k1.data());
        offset(k1, h / 2);
        velocity(&flow, n, stage.data(), time + h / 2, k2.data());
        offset(k2, h / 2);
        velocity(&flow, n, stage.data(), time + h / 2, k3.data());
        offset(k3, h);
        velocity(&flow, n, stage.data(), time + h, k4.data());
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < xyz.size(); ++i)
            xyz[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
}

struct Figures {
    double max = 0, rms = 0, p99 = 0, vertex_max = 0, vertex_rms = 0, bias = 0;
    double resolved_max = 0, resolved_rms = 0; // of the samples where the surface is resolved
    size_t worst = 0; // the sample of the largest error
};

// (|p0 - c| - r) / r of every sample, from where it started (`start`, 3 per sample).
std::vector<double> signed_errors(const std::vector<double> &start, const Checkpoint &info)
{
    std::vector<double> error(start.size() / 3);
    for (size_t i = 0; i < error.size(); ++i) {
        const double dx = start[3 * i] - info.centre[0], dy = start[3 * i + 1] - info.centre[1],
                     dz = start[3 * i + 2] - info.centre[2];
        error[i] = (std::sqrt(dx * dx + dy * dy + dz * dz) - info.radius) / info.radius;
    }
    return error;
}

Figures figures_of(const Samples &samples, const std::vector<double> &signed_error)
{
    const size_t n = samples.weight.size();
    Figures f;
    double area = 0, square = 0, sum = 0, resolved_area = 0, resolved_square = 0;
    std::vector<std::pair<double, double>> weighted; // (d, weight) of the triangles' points
    for (size_t i = 0; i < n; ++i) {
        const double d = std::abs(signed_error[i]);
        if (d > f.max) {
            f.max = d;
            f.worst = i;
        }
        if (samples.resolved[i]) {
            f.resolved_max = std::max(f.resolved_max, d);
            resolved_area += samples.weight[i];
            resolved_square += samples.weight[i] * d * d;
        }
        if (i < static_cast<size_t>(samples.vertices)) {
            f.vertex_max = std::max(f.vertex_max, d);
            f.vertex_rms += d * d;
        }
        if (samples.weight[i] > 0) {
            area += samples.weight[i];
            square += samples.weight[i] * d * d;
            sum += samples.weight[i] * signed_error[i];
            weighted.emplace_back(d, samples.weight[i]);
        }
    }
    f.rms = std::sqrt(square / area);
    f.resolved_rms = resolved_area > 0 ? std::sqrt(resolved_square / resolved_area) : 0;
    f.vertex_rms = std::sqrt(f.vertex_rms / samples.vertices);
    f.bias = sum / area;
    std::sort(weighted.begin(), weighted.end());
    double below = 0;
    for (const auto &[d, w] : weighted) {
        below += w;
        f.p99 = d;
        if (below >= 0.99 * area)
            break;
    }
    return f;
}

// The `count` samples of the largest error: where the error comes from.
void print_worst(const Samples &samples, const std::vector<double> &signed_error, int count)
{
    std::vector<std::pair<double, size_t>> errors;
    for (size_t i = 0; i < signed_error.size(); ++i)
        errors.emplace_back(signed_error[i], i);
    const size_t shown = std::min(errors.size(), static_cast<size_t>(count));
    std::partial_sort(errors.begin(), errors.begin() + shown, errors.end(),
                      [](const auto &p, const auto &q) { return std::abs(p.first) > std::abs(q.first); });
    for (size_t k = 0; k < shown; ++k) {
        const size_t i = errors[k].second;
        const bool vertex = i < static_cast<size_t>(samples.vertices);
        std::printf("  %+.2e at (%.5f, %.5f, %.5f)%s", errors[k].first, samples.xyz[3 * i], samples.xyz[3 * i + 1],
                    samples.xyz[3 * i + 2], vertex ? ", vertex " : "\n");
        if (vertex)
            std::printf("%zu (OBJ %zu)\n", i, i + 1);
    }
}

double triangle_area(const double *xyz, const int32_t *v)
{
    const double *a = xyz + 3 * v[0], *b = xyz + 3 * v[1], *c = xyz + 3 * v[2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// The largest angle, in degrees, between each triangle's normal and an edge neighbour's.
std::vector<double> largest_normal_turns(const sfa_mesh_data &mesh)
{
    std::vector<std::array<double, 3>> normals(mesh.ntris);
    for (int32_t t = 0; t < mesh.ntris; ++t) {
        const int32_t *v = mesh.tris + 3 * t;
        const double *a = mesh.xyz + 3 * v[0], *b = mesh.xyz + 3 * v[1], *c = mesh.xyz + 3 * v[2];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        std::array<double, 3> &n = normals[t];
        n = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double &x : n)
            x /= length > 0 ? length : 1;
    }
    const std::vector<int32_t> across = surface_resolution::neighbours_across_edges(mesh);
    std::vector<double> turn(mesh.ntris, 0.0);
    for (int32_t t = 0; t < mesh.ntris; ++t)
        for (int k = 0; k < 3; ++k)
            if (const int32_t u = across[3 * static_cast<size_t>(t) + k]; u > t) {
                const auto &n = normals[t], &m = normals[u];
                const double cosine = std::max(-1.0, std::min(1.0, n[0] * m[0] + n[1] * m[1] + n[2] * m[2]));
                const double angle = std::acos(cosine) * 180 / 3.14159265358979323846;
                turn[t] = std::max(turn[t], angle);
                turn[u] = std::max(turn[u], angle);
            }
    return turn;
}

// Where the error lies (--by-turn): the triangles grouped by their largest normal turn (how
// far the mesh is from resolving the curvature there). For each group: its share of the
// area and of the squared error, the RMS and the signed mean of d over its inside points,
// and that d split in two: the part the corners' own errors explain (interpolated
// linearly: the vertices are off the surface) and the rest (the chords: the triangle cuts
// across the surface between its corners). And the stretch: the area at time t over the
// area the corners span at t = 0, area-weighted. The flows conserve volume, so a sheet
// stretched J times is J times thinner and a normal error there is J times larger in d.
void print_by_turn(const sfa_mesh_data &mesh, const Samples &samples, const std::vector<double> &signed_error,
                   const std::vector<double> &start)
{
    const std::vector<double> turn = largest_normal_turns(mesh);
    const double bounds[] = {0.5, 1, 2, 4, 8, 15, 30, 180};
    const int groups = sizeof bounds / sizeof bounds[0];
    struct Group {
        int32_t triangles = 0;
        double area = 0, square = 0, sum = 0, corner_square = 0, chord_square = 0, stretch = 0;
    };
    std::vector<Group> group(groups);
    Group all;
    all.triangles = mesh.ntris;
    // The four inside points of sample_mesh, in its order.
    static const double inside[4][3] = {
        {1.0 / 3, 1.0 / 3, 1.0 / 3}, {2.0 / 3, 1.0 / 6, 1.0 / 6}, {1.0 / 6, 2.0 / 3, 1.0 / 6}, {1.0 / 6, 1.0 / 6, 2.0 / 3}};
    for (int32_t t = 0; t < mesh.ntris; ++t) {
        Group &g = group[std::lower_bound(bounds, bounds + groups, turn[t]) - bounds];
        const int32_t *v = mesh.tris + 3 * t;
        const double area = triangle_area(mesh.xyz, v);
        ++g.triangles;
        g.stretch += area * area / triangle_area(start.data(), v);
        for (int k = 0; k < 4; ++k) {
            const size_t i = samples.vertices + 4 * static_cast<size_t>(t) + k;
            const double w = samples.weight[i], d = signed_error[i];
            const double corners = inside[k][0] * signed_error[v[0]] + inside[k][1] * signed_error[v[1]] +
                                   inside[k][2] * signed_error[v[2]];
            for (Group *h : {&g, &all}) {
                h->area += w;
                h->square += w * d * d;
                h->sum += w * d;
                h->corner_square += w * corners * corners;
                h->chord_square += w * (d - corners) * (d - corners);
            }
        }
    }
    std::printf("  largest normal turn | triangles | area | squared error | RMS d | signed mean | RMS corners' part, chords' part | stretch\n");
    for (int k = 0; k <= groups; ++k) {
        const Group &g = k < groups ? group[k] : all;
        if (k < groups && g.triangles == 0)
            continue;
        char range[48] = "all";
        if (k < groups)
            std::snprintf(range, sizeof range, "%g to %g deg", k ? bounds[k - 1] : 0.0, bounds[k]);
        std::printf("  %-14s %8d %5.1f %% %5.1f %%  %.2e  %+.2e  %.2e %.2e", range, g.triangles,
                    100 * g.area / all.area, 100 * g.square / all.square, std::sqrt(g.square / g.area),
                    g.sum / g.area, std::sqrt(g.corner_square / g.area), std::sqrt(g.chord_square / g.area));
        if (k < groups)
            std::printf("  %5.1f", g.stretch / g.area);
        std::printf("\n");
    }
}

// The smallest angle the issue asks every checkpoint to keep, in degrees.
constexpr double small_angle = 5;

const char *const usage_text =
    "usage: fidelity CHECKPOINT.obj [--steps-per-period N] [--check-step] [--worst K] [--by-turn]\n"
    "                [--angles-only] [--json]\n"
    "  the shape error of a checkpoint of 'surfadapt enright|vortex --checkpoints DIR', by\n"
    "  carrying points of the mesh back to t = 0 (RK4, N steps a period; default 1000) and\n"
    "  measuring how far from the start sphere they land; --check-step also with 2N steps,\n"
    "  --worst K lists the K largest, --by-turn groups the error by the normals' turn,\n"
    "  --angles-only prints the angles alone, --json one JSON line; options may come\n"
    "  before or after the checkpoint, and -- ends them (for a file named like one)\n";

// Prints why (if anything is given), then the usage; returns the status of a usage error.
int usage(const char *why = nullptr, const char *what = nullptr)
{
    if (why)
        std::fprintf(stderr, "fidelity: %s '%s'\n", why, what);
    std::fputs(usage_text, stderr);
    return 2;
}

// The whole number after option argv[i], at least `least` (i is advanced); false if there is
// none or it is not such a number.
bool count_option(int argc, char **argv, int &i, int least, int &value)
{
    if (i + 1 >= argc)
        return false;
    char *end = nullptr;
    const long read = std::strtol(argv[++i], &end, 10);
    if (end == argv[i] || *end != '\0' || read < least || read > 1000000000)
        return false;
    value = static_cast<int>(read);
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    const char *path = nullptr;
    int steps_per_period = 1000;
    bool check_step = false, json = false;
    int worst_count = 0;
    bool by_turn = false, angles_only = false, options_end = false;
    for (int i = 1; i < argc; ++i) {
        const char *arg = argv[i], *given = i + 1 < argc ? argv[i + 1] : "";
        if (options_end || arg[0] != '-') {
            if (path)
                return usage("one checkpoint at a time; extra argument", arg);
            path = arg;
        } else if (!std::strcmp(arg, "--")) {
            options_end = true; // what follows is the checkpoint, whatever its name
        } else if (!std::strcmp(arg, "--help") || !std::strcmp(arg, "-h")) {
            std::fputs(usage_text, stdout);
            return 0;
        } else if (!std::strcmp(arg, "--steps-per-period")) {
            if (!count_option(argc, argv, i, 1, steps_per_period))
                return usage("--steps-per-period needs a whole number of at least 1, not", given);
        } else if (!std::strcmp(arg, "--worst")) {
            if (!count_option(argc, argv, i, 0, worst_count))
                return usage("--worst needs a whole number of at least 0, not", given);
        } else if (!std::strcmp(arg, "--check-step")) {
            check_step = true;
        } else if (!std::strcmp(arg, "--by-turn")) {
            by_turn = true;
        } else if (!std::strcmp(arg, "--angles-only")) {
            angles_only = true;
        } else if (!std::strcmp(arg, "--json")) {
            json = true;
        } else {
            return usage("unknown option", arg);
        }
    }
    if (!path)
        return usage();
    Checkpoint info;
    std::string error;
    if (!read_checkpoint_header(path, info, error)) {
        std::fprintf(stderr, "fidelity: %s\n", error.c_str());
        return 1;
    }
    const sfa_velocity_fn velocity = checkpoint_velocity(info);
    if (!velocity || info.period <= 0 || info.radius <= 0 || info.time < 0) {
        std::fprintf(stderr, "fidelity: %s: unknown flow '%s' or bad period, time or radius\n", path,
                     info.flow.c_str());
        return 1;
    }
    sfa_mesh_data mesh{};
    char message[512];
    if (mesh_read(path, &mesh, message, sizeof message) != 0) {
        std::fprintf(stderr, "fidelity: %s\n", message);
        return 1;
    }
    const surface_resolution::Resolution resolution = surface_resolution::resolution_of(mesh);
    const std::vector<char> &unresolved = resolution.unresolved;
    if (unresolved.size() != static_cast<size_t>(mesh.ntris)) {
        std::fprintf(stderr, "fidelity: %s: not a closed or open manifold mesh that sfa_set_mesh would take\n", path);
        mesh_free(&mesh);
        return 1;
    }
    const surface_resolution::AnglesWhereResolved resolved =
        surface_resolution::angles_where_resolved(mesh, unresolved, small_angle);
    char angle_text[300], angle_json[200];
    std::snprintf(angle_text, sizeof angle_text,
                  "angles %.2f to %.2f degrees, from %.2f where the surface is resolved (%d triangles below %g "
                  "degrees, %d of them where it turns by more than a right angle within their size, which is %.2f %% "
                  "of the area)",
                  resolved.smallest_anywhere, resolved.largest_anywhere, resolution.angles.min_degrees, resolved.below,
                  small_angle, resolved.below_unresolved, 100 * resolution.angles.unresolved_area);
    std::snprintf(angle_json, sizeof angle_json,
                  "\"min_angle\":%.2f,\"max_angle\":%.2f,\"min_angle_resolved\":%.2f,\"below_5\":%d,"
                  "\"below_5_unresolved\":%d,\"unresolved_area\":%.2e",
                  resolved.smallest_anywhere, resolved.largest_anywhere, resolution.angles.min_degrees,
                  resolved.below, resolved.below_unresolved, resolution.angles.unresolved_area);
    if (angles_only) {
        std::printf("%s: %s, T = %g, t = %g, %d triangles: %s\n", path, info.flow.c_str(), info.period, info.time,
                    mesh.ntris, angle_text);
        if (json)
            std::printf("{\"bench\":\"angles\",\"flow\":\"%s\",\"period\":%g,\"time\":%g,\"triangles\":%d,%s}\n",
                        info.flow.c_str(), info.period, info.time, mesh.ntris, angle_json);
        mesh_free(&mesh);
        return 0;
    }
    const Samples samples = sample_mesh(mesh, unresolved);
    const int32_t nverts = mesh.nverts;

    const int steps = std::max(1, static_cast<int>(std::ceil(info.time / info.period * steps_per_period)));
    std::vector<double> start = samples.xyz;
    backtrace(velocity, info.period, info.time, steps, start);
    const std::vector<double> errors = signed_errors(start, info);
    if (by_turn)
        print_by_turn(mesh, samples, errors, start);
    mesh_free(&mesh);
    const Figures f = figures_of(samples, errors);
    const double *worst = samples.xyz.data() + 3 * f.worst;
    std::printf("%s: %s, T = %g, t = %g, %d vertices, %zu samples, %d RK4 steps back: d max %.2e, RMS %.2e, "
                "99th percentile %.2e, vertices' max %.2e and RMS %.2e, bias %+.2e; worst at (%.4f, %.4f, %.4f)%s; "
                "where the surface is resolved d max %.2e, RMS %.2e; %s\n",
                path, info.flow.c_str(), info.period, info.time, nverts, samples.weight.size(), steps, f.max, f.rms,
                f.p99, f.vertex_max, f.vertex_rms, f.bias, worst[0], worst[1], worst[2],
                f.worst < static_cast<size_t>(samples.vertices) ? ", a vertex" : "", f.resolved_max, f.resolved_rms,
                angle_text);
    if (worst_count > 0)
        print_worst(samples, errors, worst_count);
    double step_change = 0;
    if (check_step) {
        std::vector<double> finer = samples.xyz;
        backtrace(velocity, info.period, info.time, 2 * steps, finer);
        const Figures g = figures_of(samples, signed_errors(finer, info));
        step_change = std::max({std::abs(g.max - f.max), std::abs(g.rms - f.rms), std::abs(g.p99 - f.p99),
                                std::abs(g.vertex_max - f.vertex_max), std::abs(g.bias - f.bias)});
        std::printf("  halving the step changes the figures by at most %.1e\n", step_change);
    }
    char step_figure[48] = "";
    if (check_step)
        std::snprintf(step_figure, sizeof step_figure, ",\"step_change\":%.1e", step_change);
    if (json)
        std::printf("{\"bench\":\"fidelity\",\"flow\":\"%s\",\"period\":%g,\"time\":%g,\"vertices\":%d,"
                    "\"samples\":%zu,\"rk4_steps\":%d,\"max\":%.3e,\"rms\":%.3e,\"p99\":%.3e,\"vertex_max\":%.3e,"
                    "\"vertex_rms\":%.3e,\"bias\":%.3e,\"resolved_max\":%.3e,\"resolved_rms\":%.3e,%s%s}\n",
                    info.flow.c_str(), info.period, info.time, nverts, samples.weight.size(), steps, f.max, f.rms,
                    f.p99, f.vertex_max, f.vertex_rms, f.bias, f.resolved_max, f.resolved_rms, angle_json, step_figure);
    return 0;
}
