// SPDX-License-Identifier: BSD-3-Clause
// Keeping remeshing from passing a surface through itself where it is thinner than an edge.
// There (the filaments of the vortex flows, a narrow gap between two sheets) the other side
// is nearer in space than an edge but far away in the mesh, and the local test of each
// step (no face turns over) does not see it: a smoothing move, a flip, a new vertex or a
// merged one can land beyond it. Everywhere else no step reaches another part of the
// surface, so only the faces near such a place are watched, and the check costs little.
#pragma once

#include "geometry/spatial_grid.hpp"
#include "mesh/tri_mesh.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sfa {

// 1 for the vertices near a facing sheet, 0 elsewhere: vertices v and w that are not
// neighbours are marked if their normals point against each other (the two sides of a thin
// sheet, or of a narrow gap, face each other) and they are nearer than the sum of their
// longest edges (their fans can meet); then so is every neighbour of a marked vertex.
std::vector<char> near_facing_sheet(const TriMesh &mesh);

// The faces with a watched corner, in a spatial grid, to ask whether a face would meet
// one of them. The watched vertices are carried through the changes of an adaptation
// (add_vertex, renumber); the grid is built anew (index_faces) after vertices moved or
// faces were renumbered, and a face an operation changed is entered again (refresh).
class CrossingGuard {
public:
    CrossingGuard() = default;
    explicit CrossingGuard(std::vector<char> watched) : watched_(std::move(watched)) {}

    bool watches(int32_t v) const { return watched_[v] != 0; }
    // Watched for a facing sheet nearer than its edges (near_facing_sheet), not only as a
    // feature (watch_features).
    bool near_sheet(int32_t v) const { return watched_[v] == sheet_mark; }
    const std::vector<char> &watched() const { return watched_; }
    bool watches_any(const Triangle &t) const { return watches(t[0]) || watches(t[1]) || watches(t[2]); }
    // A new vertex on the edge between a and b: near a sheet if either is, else watched as
    // a feature if either is watched.
    void add_vertex_between(int32_t a, int32_t b)
    {
        watched_.push_back(near_sheet(a) || near_sheet(b) ? sheet_mark : watches(a) || watches(b) ? feature_mark : 0);
    }
    // Also watches every ridge and corner vertex (rank > 0). There the surface bends so
    // sharply that two faces a hop apart, sharing no vertex, meet at an angle, and moving a
    // ridge vertex along its ridge can carry one through the other; the fold checks, made
    // for smooth corners, do not see it (a soak finding: a crumpled sphere's ridges, faces
    // 77 degrees apart, crossed in a smoothing sweep of sfa_adapt). Costs little: ridges
    // are few on a flow, and on a CAD model the guard's queries there are cheap.
    void watch_features(const std::vector<int8_t> &rank);
    // vertex_map[v] is v's new number, or -1 if v is gone.
    void renumber(const std::vector<int32_t> &vertex_map);

    // Every face with a watched corner, with its corners at `pos` (mesh.pos, or the
    // positions a sweep would move the vertices to); returns them.
    const std::vector<int32_t> &index_faces(const TriMesh &mesh, const std::vector<Vec3> &pos);
    // The same faces and their boxes at `pos`, for faces_meeting alone: the grid's index is
    // not built, and stays as it was until index_faces builds it again.
    const std::vector<int32_t> &list_faces(const TriMesh &mesh, const std::vector<Vec3> &pos);
    // Enters face f again, at `pos`, after an operation changed it or made it.
    void refresh(const TriMesh &mesh, const std::vector<Vec3> &pos, int32_t f);

    // True if a face with corners `corner` at `at` would meet an indexed face (its corners
    // at `pos`) that is alive and shares no vertex with it nor is a face of vertex `also`
    // (-1 for none: a contraction's vanishing end). Allocates nothing, and may be called
    // from parallel loops.
    bool crosses(const TriMesh &mesh, const std::vector<Vec3> &pos, const Triangle &corner, const Vec3 (&at)[3],
                 int32_t also = -1) const
    {
        return face_crossed(mesh, pos, corner, at, also) >= 0;
    }
    // The same, naming an indexed face the new face would meet (-1 for none).
    int32_t face_crossed(const TriMesh &mesh, const std::vector<Vec3> &pos, const Triangle &corner,
                         const Vec3 (&at)[3], int32_t also = -1) const;
    // For the faces list_faces or index_faces returned last, in its order, as they are at
    // `pos` (the positions they were listed at): 1 for each face m with asking[m] that
    // meets another of them sharing no vertex with it, 0 for the others. The same as asking
    // crosses() of each such face, but each pair of overlapping boxes is compared once
    // (swept_pairs.hpp, at rest): cheaper where most faces ask. The pairs are kept for the
    // next call, which compares them alone if the same faces are listed, with the same
    // corners, each within a thousandth of its size of where it was (a sweep and then the
    // volume offsets, which move vertices by some 1e-4 of an edge).
    std::vector<char> faces_meeting(const TriMesh &mesh, const std::vector<Vec3> &pos, const std::vector<char> &asking);

private:
    // A face in a cell, with its box and first cell as they were when it was entered: most
    // candidates of a query are settled without reading the mesh.
    struct FaceEntry {
        Vec3 lo, hi;
        GridCell first; // the cell of lo
        int32_t face;
    };

    // A vertex near a facing sheet (near_facing_sheet's mark), and one watched only as a
    // feature.
    static constexpr char sheet_mark = 1, feature_mark = 2;
    std::vector<char> watched_; // 0, sheet_mark or feature_mark
    std::vector<int32_t> faces_;
    std::vector<std::array<Vec3, 2>> boxes_; // of faces_, while they are listed
    CellFrame cells_;                        // for them: cells of two mean edges

    // faces_meeting's pairs, by place in the list: every two listed faces that share no
    // corner and whose boxes, grown by a margin, overlapped; and each face's number,
    // corners and grown box when they were found.
    bool pairs_still_hold(const TriMesh &mesh) const;
    void find_pairs(const TriMesh &mesh, const std::vector<Vec3> &pos);
    std::vector<std::pair<int32_t, int32_t>> pairs_;
    std::vector<int32_t> paired_faces_;
    std::vector<Triangle> paired_corners_;
    std::vector<std::array<Vec3, 2>> paired_boxes_;
    // The faces indexed together, sorted bucket by bucket: a query reads one contiguous run
    // per cell; the faces refreshed since, chained per bucket.
    SpatialGrid<FaceEntry> grid_;
};

} // namespace sfa
