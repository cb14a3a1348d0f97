// SPDX-License-Identifier: BSD-3-Clause
#include "component_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <utility>

namespace {

// Union-find over the vertices, to count each component's boundary loops as the groups of
// boundary vertices that boundary edges join.
struct Groups {
    std::vector<int32_t> parent;
    explicit Groups(int32_t n) : parent(static_cast<size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
    int32_t root(int32_t v)
    {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    }
    void join(int32_t a, int32_t b) { parent[root(a)] = root(b); }
};

double squared_distance(const double a[3], const double b[3])
{
    double d = 0;
    for (int k = 0; k < 3; ++k)
        d += (a[k] - b[k]) * (a[k] - b[k]);
    return d;
}

} // namespace

std::vector<ComponentSummary> summarize_components(const sfa_surface *s)
{
    int32_t nverts = 0, ntris = 0, count = 0;
    sfa_get_counts(s, &nverts, &ntris);
    if (sfa_get_component_count(s, &count) != SFA_OK)
        return {};
    std::vector<double> xyz(3 * static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris)), component(static_cast<size_t>(nverts));
    sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0);
    sfa_get_components(s, nverts, component.data());

    std::vector<ComponentSummary> summary(static_cast<size_t>(count));
    for (int32_t v = 0; v < nverts; ++v) {
        ComponentSummary &c = summary[component[v]];
        ++c.vertices;
        for (int k = 0; k < 3; ++k)
            c.centroid[k] += xyz[3 * v + k];
    }
    for (int32_t t = 0; t < ntris; ++t)
        ++summary[component[tris[3 * t]]].triangles;

    // Every edge once per triangle side, as (smaller, larger); an edge seen once is on the
    // boundary (the library accepts only manifold meshes, so no edge is seen more than twice).
    std::vector<std::pair<int32_t, int32_t>> sides;
    sides.reserve(3 * static_cast<size_t>(ntris));
    for (int32_t t = 0; t < ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            const int32_t a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
            sides.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(sides.begin(), sides.end());
    Groups loops(nverts);
    std::vector<char> on_boundary(static_cast<size_t>(nverts), 0);
    for (size_t i = 0; i < sides.size();) {
        size_t j = i + 1;
        while (j < sides.size() && sides[j] == sides[i])
            ++j;
        ComponentSummary &c = summary[component[sides[i].first]];
        ++c.edges;
        if (j - i == 1) {
            ++c.boundary_edges;
            loops.join(sides[i].first, sides[i].second);
            on_boundary[sides[i].first] = on_boundary[sides[i].second] = 1;
        }
        i = j;
    }
    for (int32_t v = 0; v < nverts; ++v)
        if (on_boundary[v] && loops.root(v) == v)
            ++summary[component[v]].boundary_loops;

    for (int32_t i = 0; i < count; ++i) {
        ComponentSummary &c = summary[i];
        for (double &x : c.centroid)
            x /= c.vertices;
        const int32_t euler = c.vertices - c.edges + c.triangles;
        c.genus = (2 - euler - c.boundary_loops) / 2;
        sfa_measure_component(s, i, SFA_MEASURE_VOLUME, &c.volume);
        sfa_measure_component(s, i, SFA_MEASURE_AREA, &c.area);
    }
    return summary;
}

void print_components(const std::vector<ComponentSummary> &now, const std::vector<ComponentSummary> *before)
{
    const auto count = static_cast<int32_t>(now.size());
    const auto open = static_cast<int32_t>(
        std::count_if(now.begin(), now.end(), [](const ComponentSummary &c) { return !c.closed(); }));
    std::printf("  %d component%s: %d closed, %d open\n", count, count == 1 ? "" : "s", count - open, open);
    if (before && before->size() != now.size())
        before = nullptr;
    for (int32_t i = 0; i < count; ++i) {
        const ComponentSummary &c = now[i];
        if (i == 10) {
            std::printf("    ... and %d more\n", count - 10);
        } else if (i < 10) {
            if (c.closed())
                std::printf("    %d: closed, genus %d, volume %.6g, area %.6g", i, c.genus, c.volume, c.area);
            else
                std::printf("    %d: open, genus %d, %d boundary loop%s (%d edges), area %.6g", i, c.genus,
                            c.boundary_loops, c.boundary_loops == 1 ? "" : "s", c.boundary_edges, c.area);
            if (before && c.closed()) {
                const auto was = std::min_element(
                    before->begin(), before->end(), [&c](const ComponentSummary &a, const ComponentSummary &b) {
                        return squared_distance(a.centroid, c.centroid) < squared_distance(b.centroid, c.centroid);
                    });
                if (was->closed() && was->volume != 0)
                    std::printf(", volume change %.2e", (c.volume - was->volume) / std::fabs(was->volume));
            }
            std::printf("\n");
        }
        if (c.closed() && c.volume < 0)
            std::printf("  warning: closed component %d is inside-out (volume %.6g < 0): its triangles are "
                        "clockwise seen from outside\n",
                        i, c.volume);
    }
}
