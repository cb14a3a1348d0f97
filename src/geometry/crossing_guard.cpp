// SPDX-License-Identifier: BSD-3-Clause
#include "geometry/crossing_guard.hpp"

#include "geometry/box_pairs.hpp"
#include "geometry/direction_classes.hpp"
#include "geometry/quadric.hpp"
#include "geometry/swept_pairs.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace sfa {
namespace {

// The cells for the search of near_facing_sheet: of size `cell` from the points' lowest
// corner, larger if the box around the points would hold more than 8 cells per point (a
// thin surface in a large box). The grid would not need the limit, its memory grows with
// the points; but which partner a vertex records depends on the order in which it meets
// the others, cell by cell, so the cells stay those the search has always had.
CellFrame facing_search_cells(const std::vector<Vec3> &points, double cell)
{
    Vec3 origin = points[0], high = points[0];
    for (const Vec3 &p : points) {
        origin = origin.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const auto cells_for = [&](double size) -> Eigen::Array3d { return ((high - origin) / size).array().floor() + 1; };
    const double limit = 8.0 * static_cast<double>(points.size()) + 64;
    if (cells_for(cell).prod() > limit)
        cell *= std::cbrt(cells_for(cell).prod() / limit) * 1.01;
    return CellFrame{origin, cell};
}

} // namespace

std::vector<char> near_facing_sheet(const TriMesh &mesh)
{
    const int32_t n = mesh.num_vertices();
    static const DirectionClasses classes(0); // normals more than 90 degrees apart
    std::vector<Vec3> normal(n, Vec3::Zero());
    std::vector<double> reach(n, 0); // the longest edge: how far the vertex's fan reaches
    std::vector<Box> around(static_cast<size_t>(n));        // the box of its reach
    std::vector<int16_t> normal_class(static_cast<size_t>(n)); // of its normal
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t v = 0; v < n; ++v) {
        mesh.for_each_outgoing(v, [&](int32_t h) {
            normal[v] += face_area_vector(mesh, TriMesh::face(h));
            reach[v] = std::max(reach[v], (mesh.pos[mesh.head(h)] - mesh.pos[v]).squaredNorm());
        });
        reach[v] = std::sqrt(reach[v]);
        const Vec3 r = Vec3::Constant(reach[v]);
        around[v] = {mesh.pos[v] - r, mesh.pos[v] + r};
        normal_class[v] = static_cast<int16_t>(classes.of(normal[v]));
    }
    std::vector<char> marked(n, 0);
    const double mean_reach = ordered_sum(n, 0.0, [&](int32_t v) { return reach[v]; }) / std::max(n, 1);
    if (!(mean_reach > 0))
        return marked;
    // Two fans can meet if their vertices are nearer than the sum of their reaches, so the
    // boxes of their reaches overlap; and their normals point against each other, so their
    // classes may pair. Only the vertices near one whose class may pair with theirs are
    // searched (box_pairs.hpp), in coarse cells of twice the mean reach, a box's width:
    // this search took 3.4 G of a plain vortex T = 2 run's 63 G instructions, and now 1.7
    // G (cells of four and eight mean reaches: 0.2 and 0.7 G more). Vertices whose
    // position or reach is not a number meet none.
    std::vector<int32_t> finite;
    for (int32_t v = 0; v < n; ++v)
        if (around[v][0].allFinite() && around[v][1].allFinite())
            finite.push_back(v);
    const std::vector<int32_t> searched =
        finite.empty() ? finite
                       : detail::boxes_near_a_pairing_group(
                             around, finite, DirectionClasses::count, [&](int32_t v) { return normal_class[v]; },
                             [&](int a, int b) { return classes.may_pair(a, b); }, 2 * mean_reach);
    const int32_t count = static_cast<int32_t>(searched.size());
    if (count < 2)
        return marked;
    // Cells of twice the mean reach, the distance most vertices search: a ball's box meets
    // two or three cells on each axis. Each vertex is in the grid with what the search reads
    // of it, so that the vertices of a cell are read one after another. The cells are
    // those of all the vertices, and the searched ones in the order of their numbers: the
    // partner each one meets first is the same as among all.
    struct Point {
        Vec3 position, normal;
        double reach;
        int32_t vertex;
    };
    SpatialGrid<Point> grid;
    grid.build(
        facing_search_cells(mesh.pos, 2 * mean_reach), count,
        [&](int32_t m) { return std::array<Vec3, 2>{mesh.pos[searched[m]], mesh.pos[searched[m]]}; },
        [&](int32_t m, const GridCell &) {
            const int32_t v = searched[m];
            return Point{mesh.pos[v], normal[v], reach[v], v};
        });

    // Each vertex looks within twice its own reach, so the one with the longer reach of such
    // a pair finds it; it records the first partner it meets (in parallel, one write each),
    // and both are marked after.
    std::vector<int32_t> partner(n, -1);
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 256)
    for (int32_t m = 0; m < count; ++m) {
        const int32_t v = searched[m];
        const Vec3 &p = mesh.pos[v], &nv = normal[v];
        const auto is_neighbour = [&](int32_t w) {
            bool found = false;
            mesh.for_each_neighbour(v, [&](int32_t u, int32_t) { found = found || u == w; });
            return found;
        };
        const Vec3 r = Vec3::Constant(2 * reach[v]);
        const CellFrame &cells = grid.frame();
        grid.any_built_in_cells(cells.cell_of(p - r), cells.cell_of(p + r), [&](const Point &w) {
            if (!(nv.dot(w.normal) < 0) || !((w.position - p).norm() < reach[v] + w.reach) || w.vertex == v ||
                is_neighbour(w.vertex))
                return false;
            partner[v] = w.vertex;
            return true;
        });
    }
    for (int32_t v = 0; v < n; ++v)
        if (partner[v] >= 0)
            marked[v] = marked[partner[v]] = 1;
    std::vector<char> watched = marked;
    for (int32_t v = 0; v < n; ++v)
        if (marked[v])
            mesh.for_each_neighbour(v, [&](int32_t w, int32_t) { watched[w] = 1; });
    return watched;
}

void CrossingGuard::watch_features(const std::vector<int8_t> &rank)
{
    for (size_t v = 0; v < watched_.size(); ++v)
        if (rank[v] > 0 && watched_[v] == 0)
            watched_[v] = feature_mark;
}

void CrossingGuard::renumber(const std::vector<int32_t> &vertex_map)
{
    std::vector<char> watched(vertex_map.size() - std::count(vertex_map.begin(), vertex_map.end(), -1), 0);
    for (size_t v = 0; v < vertex_map.size(); ++v)
        if (vertex_map[v] >= 0)
            watched[vertex_map[v]] = watched_[v];
    watched_.swap(watched);
}

const std::vector<int32_t> &CrossingGuard::list_faces(const TriMesh &mesh, const std::vector<Vec3> &pos)
{
    // Which faces are watched, and their boxes, in parallel: finding them means looking at
    // every face of the mesh.
    const int32_t nt = mesh.num_triangles();
    std::vector<char> indexed(nt);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t f = 0; f < nt; ++f)
        indexed[f] = mesh.tri[f][0] >= 0 && watches_any(mesh.tri[f]);
    faces_.clear();
    for (int32_t f = 0; f < nt; ++f)
        if (indexed[f])
            faces_.push_back(f);
    const int32_t n = static_cast<int32_t>(faces_.size());
    boxes_.resize(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int32_t m = 0; m < n; ++m) {
        const Triangle &t = mesh.tri[faces_[m]];
        boxes_[m] = {pos[t[0]].cwiseMin(pos[t[1]]).cwiseMin(pos[t[2]]), pos[t[0]].cwiseMax(pos[t[1]]).cwiseMax(pos[t[2]])};
    }
    const double edge_sum = ordered_sum(n, 0.0, [&](int32_t m) {
        const Triangle &t = mesh.tri[faces_[m]];
        return (pos[t[1]] - pos[t[0]]).norm() + (pos[t[2]] - pos[t[1]]).norm() + (pos[t[0]] - pos[t[2]]).norm();
    });
    Vec3 origin = n > 0 ? boxes_[0][0] : Vec3::Zero();
    for (const std::array<Vec3, 2> &box : boxes_)
        origin = origin.cwiseMin(box[0]);
    // Cells of twice the mean edge: a face's box covers one to a few cells, a cell holds
    // about ten faces. A face far larger than that (a corner pulled out hundreds of edges)
    // the grid keeps apart, compared with every query, rather than entering it in the cube
    // of its extent in cells (spatial_grid.hpp; issue 18: 645 MB for one such corner).
    double cell_size = n > 0 ? 2 * edge_sum / (3.0 * n) : 1;
    if (!(cell_size > 0))
        cell_size = 1;
    cells_ = CellFrame{origin, cell_size};
    return faces_;
}

const std::vector<int32_t> &CrossingGuard::index_faces(const TriMesh &mesh, const std::vector<Vec3> &pos)
{
    list_faces(mesh, pos);
    grid_.build(
        cells_, static_cast<int32_t>(faces_.size()), [&](int32_t m) { return boxes_[m]; },
        [&](int32_t m, const GridCell &first) { return FaceEntry{boxes_[m][0], boxes_[m][1], first, faces_[m]}; });
    return faces_;
}

void CrossingGuard::refresh(const TriMesh &mesh, const std::vector<Vec3> &pos, int32_t f)
{
    const Triangle &t = mesh.tri[f];
    if (t[0] < 0 || !watches_any(t) || !grid_.built())
        return;
    const Vec3 lo = pos[t[0]].cwiseMin(pos[t[1]]).cwiseMin(pos[t[2]]);
    const Vec3 hi = pos[t[0]].cwiseMax(pos[t[1]]).cwiseMax(pos[t[2]]);
    // A face entered before keeps its old entries too; they only bring it up again.
    grid_.add(lo, hi, [&](const GridCell &first) { return FaceEntry{lo, hi, first, f}; });
}

bool CrossingGuard::pairs_still_hold(const TriMesh &mesh) const
{
    if (faces_ != paired_faces_)
        return false;
    const int32_t n = static_cast<int32_t>(faces_.size());
    char holds = 1;
#pragma omp parallel for num_threads(loop_threads()) schedule(static) reduction(&& : holds)
    for (int32_t m = 0; m < n; ++m) {
        const Box &box = boxes_[m], &was = paired_boxes_[m];
        holds = holds && mesh.tri[faces_[m]] == paired_corners_[m] && (was[0].array() <= box[0].array()).all() &&
                (box[1].array() <= was[1].array()).all();
    }
    return holds != 0;
}

void CrossingGuard::find_pairs(const TriMesh &mesh, const std::vector<Vec3> &pos)
{
    // The pairs from collision-safe motion's broad phase, the triangles at rest: it sweeps
    // strips of each block's boxes in floats and passes over neighbours four lanes at once
    // (its boxes are a little wider, never narrower: the exact test decides). A grid's
    // pairs of overlapping boxes took twice the instructions. Two faces whose boxes
    // overlap now lie each in its grown box of then, so those overlap too: the pair is
    // listed. Each box grows by a thousandth of its own size, some ten times the volume
    // offsets of the paper's flows, so that a graded mesh's small faces pair no more than
    // their size says; a box that would grow past the largest double stays as it is (the
    // broad phase leaves out a box whose corners are not finite, and a face must not
    // vanish from it by being grown).
    const size_t n = faces_.size();
    std::vector<SweptTriangle> at_rest(n);
    paired_corners_.resize(n);
    paired_boxes_.resize(n);
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (size_t m = 0; m < n; ++m) {
        paired_corners_[m] = mesh.tri[faces_[m]];
        at_rest[m] = resting_triangle(paired_corners_[m], pos);
        Box &box = at_rest[m].start;
        const double margin = 1e-3 * (box[1] - box[0]).maxCoeff();
        const Box grown = {box[0].array() - margin, box[1].array() + margin};
        if (grown[0].allFinite() && grown[1].allFinite())
            box = grown;
        paired_boxes_[m] = box;
    }
    paired_faces_ = faces_;
    std::vector<std::vector<std::pair<int32_t, int32_t>>> found(static_cast<size_t>(loop_threads()));
    for_each_pair_that_may_meet(at_rest, [&](int32_t a, int32_t b, int thread) {
        found[static_cast<size_t>(thread)].push_back({a, b}); // what this throws, the search passes on
    });
    pairs_.clear();
    for (const auto &list : found)
        pairs_.insert(pairs_.end(), list.begin(), list.end());
}

std::vector<char> CrossingGuard::faces_meeting(const TriMesh &mesh, const std::vector<Vec3> &pos,
                                               const std::vector<char> &asking)
{
    if (!pairs_still_hold(mesh))
        find_pairs(mesh, pos);
    const size_t n = faces_.size();
    std::vector<std::atomic<char>> met(n);
    for (std::atomic<char> &m : met)
        m.store(0, std::memory_order_relaxed);
    const int64_t count = static_cast<int64_t>(pairs_.size());
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
    for (int64_t p = 0; p < count; ++p) {
        const auto [a, b] = pairs_[static_cast<size_t>(p)];
        if (!asking[a] && !asking[b])
            continue;
        const Triangle &s = mesh.tri[faces_[a]], &t = mesh.tri[faces_[b]];
        if (!triangles_intersect(pos[s[0]], pos[s[1]], pos[s[2]], pos[t[0]], pos[t[1]], pos[t[2]]))
            continue;
        if (asking[a])
            met[a].store(1, std::memory_order_relaxed);
        if (asking[b])
            met[b].store(1, std::memory_order_relaxed);
    }
    std::vector<char> result(n);
    for (size_t m = 0; m < n; ++m)
        result[m] = met[m].load(std::memory_order_relaxed);
    return result;
}

int32_t CrossingGuard::face_crossed(const TriMesh &mesh, const std::vector<Vec3> &pos, const Triangle &corner,
                                    const Vec3 (&at)[3], int32_t also) const
{
    if (grid_.empty())
        return -1;
    const Vec3 lo = at[0].cwiseMin(at[1]).cwiseMin(at[2]), hi = at[0].cwiseMax(at[1]).cwiseMax(at[2]);
    const GridCell first = grid_.frame().cell_of(lo), last = grid_.frame().cell_of(hi);
    // Entry e, met in cell `here`: true if its face, as it is now, meets the new face.
    int32_t met = -1;
    grid_.any_in_cells(first, last, [&](const FaceEntry &e, const GridCell &here) {
        if ((e.lo - hi).maxCoeff() > 0 || (lo - e.hi).maxCoeff() > 0)
            return false; // boxes apart
        // Each face once, without a list of those seen.
        if (!same_cell(first_shared_cell(first, e.first), here))
            return false;
        const Triangle &t = mesh.tri[e.face];
        if (t[0] < 0)
            return false; // died in a contraction
        for (int32_t v : t)
            if (v == corner[0] || v == corner[1] || v == corner[2] || v == also)
                return false; // a neighbour
        if (!triangles_intersect(at[0], at[1], at[2], pos[t[0]], pos[t[1]], pos[t[2]]))
            return false;
        met = e.face;
        return true;
    });
    return met;
}

} // namespace sfa
