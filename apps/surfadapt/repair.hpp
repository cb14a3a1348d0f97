// SPDX-License-Identifier: BSD-3-Clause
// Repairing a mesh as files from the wild come (`surfadapt repair`): what sfa_set_mesh()
// rightly refuses is mended where the mending is unambiguous, and every change is counted,
// so that a user sees what was done to the data. The library itself never repairs: a
// solver's mesh that breaks a rule is a bug in the solver, and saying so is worth more.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

// Faces as read: polygons of any size, 0-based indices (possibly out of range).
struct PolygonMesh {
    std::vector<double> xyz;          // 3 per vertex
    std::vector<int32_t> face_start;  // face f uses indices[face_start[f] .. face_start[f + 1])
    std::vector<int32_t> indices;
    int32_t faces() const { return face_start.empty() ? 0 : static_cast<int32_t>(face_start.size()) - 1; }
};

// What was changed, in the order the steps run.
struct RepairReport {
    int32_t faces_out_of_range = 0;        // a face using a vertex that does not exist: dropped
    int32_t vertices_merged = 0;           // vertices at exactly the position of an earlier one
    int32_t polygons_clipped = 0;          // polygons whose fan folds over or has zero area: ear clipped
    int32_t polygons_not_simple = 0;       // of those, polygons no ear clipping can cut (they cross themselves): fanned
    int32_t degenerate_dropped = 0;        // a repeated corner, or zero area (collinear corners)
    int32_t duplicates_dropped = 0;        // the same three vertices as an earlier triangle
    int32_t triangles_flipped = 0;         // turned to agree with their component's orientation
    int32_t components_turned_outward = 0; // closed components that were inside-out
    // Edges of three or more triangles: their triangles are joined to none across them, so
    // the bow-tie split below gives each sheet through the edge its own copy of it (two
    // bodies touching along an edge come apart; a fin becomes three sheets).
    int32_t edges_with_many_faces = 0;
    int32_t bowties_split = 0;             // vertices where fans only touched: one copy per extra fan
    int32_t unreferenced_dropped = 0;      // vertices no triangle uses any more
    // Left as they are, for the user to see to (no single right answer):
    int32_t non_orientable_components = 0; // Möbius-like: no orientation agrees across every edge
    int32_t edges_with_many_faces_left = 0; // where the sheets through such an edge also meet elsewhere
    int32_t changes() const;
    // One line per nonzero count, e.g. "split 1 bow-tie vertex".
    std::vector<std::string> lines() const;
};

struct TriangleSoup {
    std::vector<double> xyz;
    std::vector<int32_t> tris; // 0-based, 3 per triangle
};

// Repairs `in` into `out`. Bounded: every step is a pass over the faces or a search with a
// visited set; ear clipping is quadratic in a polygon's corners.
RepairReport repair_mesh(const PolygonMesh &in, TriangleSoup &out);
