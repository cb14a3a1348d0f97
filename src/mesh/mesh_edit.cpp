// SPDX-License-Identifier: BSD-3-Clause
#include "mesh/mesh_edit.hpp"

#include "mesh/compact.hpp"
#include "mesh/locality_order.hpp"
#include "mesh/parallel.hpp"

#include <algorithm>

namespace sfa {
namespace {

// Where the new or merged vertex of edge h lies over none of the faces given (they are all
// degenerate), its values come from the edge's ends, half and half.
Stencil or_the_edge_midpoint(const Stencil &stencil, const TriMesh &mesh, int32_t h)
{
    if (stencil.corners[0] >= 0)
        return stencil;
    return {{mesh.tail(h), mesh.head(h), mesh.head(h)}, Eigen::Vector3d(0.5, 0.5, 0)};
}

} // namespace

void MeshEdit::attach(EditListener &listener)
{
    listeners_.push_back(&listener);
    interpolating_ = interpolating_ || listener.interpolates();
}

void MeshEdit::detach(EditListener &listener)
{
    listeners_.erase(std::remove(listeners_.begin(), listeners_.end(), &listener), listeners_.end());
    interpolating_ = std::any_of(listeners_.begin(), listeners_.end(), [](EditListener *l) { return l->interpolates(); });
}

void MeshEdit::begin_changes()
{
    for (EditListener *listener : listeners_)
        listener->begin_changes(mesh_);
}

int32_t MeshEdit::split(int32_t h, const Vec3 &position)
{
    Stencil stencil{{-1, -1, -1}, Eigen::Vector3d::Zero()};
    if (interpolating_)
        stencil = or_the_edge_midpoint(
            stencil_over(mesh_, position, [&](auto &&visit) { mesh_.for_each_face_of_edge(h, visit); }), mesh_, h);
    fans_.clear();
    mesh_.for_each_face_of_edge(h, [&](int32_t f) {
        for (int32_t v : mesh_.tri[f])
            fans_.push_back(v);
    });
    const SplitRecord record = split_edge(mesh_, h, position);
    fans_.push_back(record.vertex);
    const SplitChange change{record, stencil, fans_};
    for (EditListener *listener : listeners_)
        listener->split(mesh_, change);
    return record.vertex;
}

void MeshEdit::collapse(int32_t h, const Vec3 &position)
{
    Stencil stencil{{-1, -1, -1}, Eigen::Vector3d::Zero()};
    if (interpolating_)
        stencil = or_the_edge_midpoint(
            stencil_over(mesh_, position, [&](auto &&visit) { mesh_.for_each_face_around_edge(h, visit); }), mesh_, h);
    for (EditListener *listener : listeners_)
        listener->before_collapse(mesh_, h);
    const CollapseRecord record = collapse_edge(mesh_, h, position);
    fans_.assign(1, record.keep);
    mesh_.for_each_neighbour(record.keep, [&](int32_t w, int32_t) { fans_.push_back(w); });
    const CollapseChange change{record, stencil, fans_};
    for (EditListener *listener : listeners_)
        listener->collapse(mesh_, change);
}

void MeshEdit::flip(int32_t h)
{
    const FlipQuad quad = flip_quad(mesh_, h);
    const int32_t twin = mesh_.opp[h];
    const FlipMoves moves = flip_edge(mesh_, h);
    fans_.assign({quad.a, quad.b, quad.p, quad.q});
    const FlipChange change{quad, {TriMesh::face(h), TriMesh::face(twin)}, {h, twin}, moves, fans_};
    for (EditListener *listener : listeners_)
        listener->flip(mesh_, change);
}

void MeshEdit::move(std::vector<Vec3> &positions)
{
    const int32_t n = mesh_.num_vertices();
    const Stencil none{{-1, -1, -1}, Eigen::Vector3d::Zero()};
    stencils_.assign(interpolating_ ? n : 0, none);
    if (interpolating_) {
#pragma omp parallel for num_threads(loop_threads()) schedule(static)
        for (int32_t v = 0; v < n; ++v)
            if (positions[v] != mesh_.pos[v])
                stencils_[v] = stencil_over(mesh_, positions[v], [&](auto &&visit) {
                    mesh_.for_each_outgoing(v, [&](int32_t g) { visit(TriMesh::face(g)); });
                });
    }
    const MoveChange change{positions, stencils_};
    for (EditListener *listener : listeners_)
        listener->move(mesh_, change);
    mesh_.pos.swap(positions);
}

void MeshEdit::offset(std::vector<Vec3> &positions)
{
    for (EditListener *listener : listeners_)
        listener->offset(mesh_, positions);
    mesh_.pos.swap(positions);
}

void MeshEdit::compact()
{
    const int32_t vertices = mesh_.num_vertices(), triangles = mesh_.num_triangles();
    const Renumbering renumbering = sfa::compact(mesh_);
    if (mesh_.num_vertices() != vertices || mesh_.num_triangles() != triangles)
        renumbered(renumbering);
}

void MeshEdit::order_for_locality() { renumbered(sfa::order_for_locality(mesh_)); }

void MeshEdit::renumbered(const Renumbering &renumbering)
{
    for (EditListener *listener : listeners_)
        listener->renumber(renumbering);
}

} // namespace sfa
