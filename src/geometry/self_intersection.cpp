#include "geometry/self_intersection.hpp"

#include "geometry/spatial_grid.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace sfa {
namespace {

// The interval in which a triangle's corners p (projected on the line where the two planes
// meet) and signed distances d to the other plane cut that line; false if the triangle
// lies in the plane.
bool interval_on_line(const double p[3], const double d[3], double &lo, double &hi)
{
    int k; // the corner alone on its side of the plane
    if (d[0] * d[1] > 0)
        k = 2;
    else if (d[0] * d[2] > 0)
        k = 1;
    else if (d[1] * d[2] > 0 || d[0] != 0)
        k = 0;
    else if (d[1] != 0)
        k = 1;
    else if (d[2] != 0)
        k = 2;
    else
        return false;
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double t1 = p[k] + (p[i] - p[k]) * d[k] / (d[k] - d[i]);
    const double t2 = p[k] + (p[j] - p[k]) * d[k] / (d[k] - d[j]);
    lo = std::min(t1, t2);
    hi = std::max(t1, t2);
    return true;
}

using Point2 = std::array<double, 2>;

double orient(const Point2 &a, const Point2 &b, const Point2 &c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool segments_meet(const Point2 &p, const Point2 &q, const Point2 &r, const Point2 &s)
{
    const double o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p), o4 = orient(r, s, q);
    if (o1 * o2 > 0 || o3 * o4 > 0)
        return false;
    if (o1 == 0 && o2 == 0) // collinear: overlapping projections on both axes
        for (int k = 0; k < 2; ++k)
            if (std::max(p[k], q[k]) < std::min(r[k], s[k]) || std::max(r[k], s[k]) < std::min(p[k], q[k]))
                return false;
    return true;
}

bool inside(const Point2 &x, const Point2 t[3])
{
    const double o0 = orient(t[0], t[1], x), o1 = orient(t[1], t[2], x), o2 = orient(t[2], t[0], x);
    return (o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0);
}

// Two triangles in one plane of normal n: an edge of one crosses an edge of the other, or
// one lies inside the other.
bool coplanar_triangles_meet(const Vec3 a[3], const Vec3 b[3], const Vec3 &n)
{
    int drop = 0; // project along the normal's largest axis
    n.cwiseAbs().maxCoeff(&drop);
    const int x = (drop + 1) % 3, y = (drop + 2) % 3;
    Point2 p[3], q[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = {a[k][x], a[k][y]};
        q[k] = {b[k][x], b[k][y]};
    }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segments_meet(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3]))
                return true;
    return inside(p[0], q) || inside(q[0], p);
}

// Signed distances (times |n|) of three points to the plane through `on` with normal n,
// with those below `tolerance` set to zero.
void plane_distances(const Vec3 pts[3], const Vec3 &on, const Vec3 &n, double tolerance, double d[3])
{
    for (int k = 0; k < 3; ++k) {
        d[k] = n.dot(pts[k] - on);
        if (std::abs(d[k]) < tolerance)
            d[k] = 0;
    }
}

} // namespace

bool triangles_intersect(const Vec3 &a0, const Vec3 &a1, const Vec3 &a2, const Vec3 &b0, const Vec3 &b1,
                         const Vec3 &b2)
{
    const Vec3 a[3] = {a0, a1, a2}, b[3] = {b0, b1, b2};
    double size2 = 0;
    for (int k = 0; k < 3; ++k)
        size2 = std::max({size2, (a[k] - a[(k + 1) % 3]).squaredNorm(), (b[k] - b[(k + 1) % 3]).squaredNorm()});
    const double size = std::sqrt(size2); // the longest edge
    const Vec3 na = (a1 - a0).cross(a2 - a0), nb = (b1 - b0).cross(b2 - b0);
    double db[3], da[3];
    plane_distances(b, a0, na, 1e-12 * na.norm() * size, db);
    if ((db[0] > 0 && db[1] > 0 && db[2] > 0) || (db[0] < 0 && db[1] < 0 && db[2] < 0))
        return false; // b entirely on one side of a's plane
    plane_distances(a, b0, nb, 1e-12 * nb.norm() * size, da);
    if ((da[0] > 0 && da[1] > 0 && da[2] > 0) || (da[0] < 0 && da[1] < 0 && da[2] < 0))
        return false;
    if (db[0] == 0 && db[1] == 0 && db[2] == 0)
        return coplanar_triangles_meet(a, b, na);
    // Both cross the line where the planes meet: they meet where their intervals on it do.
    const Vec3 line = na.cross(nb);
    int axis = 0; // the coordinate of the line's largest component orders points along it
    line.cwiseAbs().maxCoeff(&axis);
    const double pa[3] = {a0[axis], a1[axis], a2[axis]}, pb[3] = {b0[axis], b1[axis], b2[axis]};
    double lo_a, hi_a, lo_b, hi_b;
    if (!interval_on_line(pa, da, lo_a, hi_a) || !interval_on_line(pb, db, lo_b, hi_b))
        return coplanar_triangles_meet(a, b, na);
    return !(hi_a < lo_b || hi_b < lo_a);
}

int32_t self_intersection_count(const TriMesh &mesh)
{
    const int32_t n = mesh.num_triangles();
    if (n < 2)
        return 0;
    // Cells of twice the mean edge length (from the triangles' first edges), counted from the
    // lowest corner: most triangles' boxes then cover one to four cells.
    double cell = 0;
    Vec3 lowest = mesh.pos[mesh.tri[0][0]];
    for (const Triangle &t : mesh.tri) {
        cell += (mesh.pos[t[1]] - mesh.pos[t[0]]).norm();
        for (int32_t v : t)
            lowest = lowest.cwiseMin(mesh.pos[v]);
    }
    cell = 2 * cell / n;
    if (!(cell > 0))
        return 0;
    SpatialGrid<int32_t> grid; // the triangles in the cells their boxes cover
    grid.build(
        CellFrame{lowest, cell}, n,
        [&](int32_t t) {
            const Triangle &c = mesh.tri[t];
            return std::array<Vec3, 2>{mesh.pos[c[0]].cwiseMin(mesh.pos[c[1]]).cwiseMin(mesh.pos[c[2]]),
                                       mesh.pos[c[0]].cwiseMax(mesh.pos[c[1]]).cwiseMax(mesh.pos[c[2]])};
        },
        [](int32_t t, const GridCell &) { return t; });

    const auto share_a_vertex = [&](int32_t s, int32_t t) {
        for (int32_t v : mesh.tri[s])
            if (v == mesh.tri[t][0] || v == mesh.tri[t][1] || v == mesh.tri[t][2])
                return true;
        return false;
    };
    const int64_t buckets = static_cast<int64_t>(grid.bucket_count());
    int32_t count = 0;
#pragma omp parallel for num_threads(loop_threads()) schedule(dynamic, 64) reduction(+ : count)
    for (int64_t b = 0; b < buckets; ++b)
        // A bucket's entries come in the order of their triangles: s < t.
        grid.for_each_pair_in_bucket(static_cast<size_t>(b), [&](int32_t s, int32_t t, uint64_t here) {
            // Each pair once: in the first cell both boxes cover.
            if (cell_key(first_shared_cell(grid.cells_of(s)[0], grid.cells_of(t)[0])) != here || share_a_vertex(s, t))
                return;
            const Triangle &p = mesh.tri[s], &q = mesh.tri[t];
            if (triangles_intersect(mesh.pos[p[0]], mesh.pos[p[1]], mesh.pos[p[2]], mesh.pos[q[0]], mesh.pos[q[1]],
                                    mesh.pos[q[2]]))
                ++count;
        });
    return count;
}

} // namespace sfa
