#include "geometry/self_intersection.hpp"

#include "geometry/spatial_grid.hpp"
#include "geometry/triangle_intersection.hpp"
#include "mesh/parallel.hpp"

#include <array>
#include <cstdint>

namespace sfa {

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
