// SPDX-License-Identifier: BSD-3-Clause
// What a solver developer checks first about a surface, component by component: closed or
// open (and its boundary loops), inside-out or not, its genus, its volume and area, and how
// much a remesh changed its volume.
#pragma once

#include "surfadapt.h"

#include <cstdint>
#include <vector>

struct ComponentSummary {
    int32_t vertices = 0, edges = 0, triangles = 0;
    int32_t boundary_edges = 0, boundary_loops = 0;
    // From the Euler characteristic V - E + F = 2 - 2 g - b; for a closed sphere-like
    // bubble 0, for a torus 1, for a disc 0 with one loop.
    int32_t genus = 0;
    double volume = 0, area = 0;
    double centroid[3] = {0, 0, 0}; // of the vertices: to find the component again after a remesh
    bool closed() const { return boundary_edges == 0; }
};

// One summary per component, in the library's numbering (sfa_get_components()).
std::vector<ComponentSummary> summarize_components(const sfa_surface *s);

// Prints the count (closed, open), a line for each of the first 10 components, and a
// warning for each closed one that is inside-out (negative volume). With `before` (the
// same surface's summaries before a remesh, as many as now) each closed component's line
// also gives its relative volume change, matched to the component with the nearest centroid.
void print_components(const std::vector<ComponentSummary> &now,
                      const std::vector<ComponentSummary> *before = nullptr);
