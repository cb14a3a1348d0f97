// SPDX-License-Identifier: BSD-3-Clause
#include "fields/face_values.hpp"

#include "mesh/edge_collapse.hpp"

namespace sfa {
namespace {

// The remap's own measure of area, so that every change counts integrals alike.
double area(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return triangle_area(a, b, c); }

double face_area(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return area(mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]]);
}

// Half the cross product: the area times the unit normal. Their sum over a fan is the fan's
// area-weighted normal, the chart's.
Vec3 area_vector(const Corners &t) { return 0.5 * (t[1] - t[0]).cross(t[2] - t[0]); }

Corners corners_of(const Triangle &t, const std::vector<Vec3> &positions)
{
    return {positions[t[0]], positions[t[1]], positions[t[2]]};
}

} // namespace

void FaceValues::add_old(int32_t t, const Corners &corners)
{
    old_corners_.push_back(corners);
    for (int32_t c = 0; c < ncomp_; ++c)
        old_values_.push_back(value(t, c));
}

void FaceValues::remap_fan(const Vec3 &normal)
{
    const int32_t n_old = static_cast<int32_t>(old_corners_.size()), n_new = static_cast<int32_t>(faces_.size());
    new_values_.resize(static_cast<size_t>(ncomp_) * n_new);
    if (remap_by_overlap(old_corners_.data(), old_values_.data(), n_old, new_corners_.data(), new_values_.data(),
                         n_new, ncomp_, normal) == RemapPath::shared)
        ++shared_remaps_;
    for (int32_t k = 0; k < n_new; ++k)
        for (int32_t c = 0; c < ncomp_; ++c)
            at(faces_[k], c) = new_values_[static_cast<size_t>(ncomp_) * k + c];
}

void FaceValues::split(const TriMesh &mesh, const SplitChange &change)
{
    const SplitRecord &r = change.record;
    values_.resize(static_cast<size_t>(ncomp_) * mesh.tri.size());
    const int32_t opposite[2] = {r.p, r.q};
    for (int side = 0; side < 2; ++side) {
        const int32_t kept = r.old_faces[side], made = r.new_faces[side];
        if (kept < 0)
            continue;
        // The old triangle (a, b, p) (or (b, a, q)) is gone; its corners are still there.
        const int32_t from = side == 0 ? r.a : r.b, to = side == 0 ? r.b : r.a;
        const double whole = area(mesh.pos[from], mesh.pos[to], mesh.pos[opposite[side]]);
        const double halves = face_area(mesh, kept) + face_area(mesh, made);
        const double scale = halves > 0 ? whole / halves : 1;
        for (int32_t c = 0; c < ncomp_; ++c)
            at(made, c) = at(kept, c) *= scale;
    }
}

void FaceValues::flip(const TriMesh &mesh, const FlipChange &change)
{
    // faces[0] was (a, b, p) and faces[1] (b, a, q); they still hold those faces' values.
    const FlipQuad &q = change.quad;
    const Vec3 &a = mesh.pos[q.a], &b = mesh.pos[q.b], &p = mesh.pos[q.p], &qq = mesh.pos[q.q];
    old_corners_.clear();
    old_values_.clear();
    add_old(change.faces[0], {a, b, p});
    add_old(change.faces[1], {b, a, qq});
    faces_.assign(change.faces, change.faces + 2);
    new_corners_.clear();
    for (int32_t t : faces_)
        new_corners_.push_back(corners_of(mesh.tri[t], mesh.pos));
    remap_fan(area_vector(old_corners_[0]) + area_vector(old_corners_[1]));
}

void FaceValues::before_collapse(const TriMesh &mesh, int32_t h)
{
    old_corners_.clear();
    old_values_.clear();
    collapse_normal_ = Vec3::Zero();
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const Corners corners = corners_of(mesh.tri[f], mesh.pos);
        add_old(f, corners);
        collapse_normal_ += area_vector(corners);
    });
}

void FaceValues::collapse(const TriMesh &mesh, const CollapseChange &change)
{
    // The faces around the edge less the dead two: the fan of the kept vertex.
    faces_.clear();
    new_corners_.clear();
    mesh.for_each_outgoing(change.record.keep, [&](int32_t g) {
        faces_.push_back(TriMesh::face(g));
        new_corners_.push_back(corners_of(mesh.tri[faces_.back()], mesh.pos));
    });
    remap_fan(collapse_normal_);
}

void FaceValues::move(const TriMesh &mesh, const MoveChange &change)
{
    // Vertex by vertex, each fan's remap seeing the moves before it: every step is a
    // conservative remap of one fan, so the sweep is too, and no step needs to know where
    // the rest of the fan's corners end up.
    sweep_ = mesh.pos;
    const int32_t n = mesh.num_vertices();
    for (int32_t v = 0; v < n; ++v) {
        const Vec3 &to = change.positions[v];
        if (to == sweep_[v] || is_dead_vertex(mesh, v))
            continue;
        old_corners_.clear();
        old_values_.clear();
        faces_.clear();
        new_corners_.clear();
        Vec3 normal = Vec3::Zero();
        mesh.for_each_outgoing(v, [&](int32_t g) {
            const int32_t t = TriMesh::face(g);
            const Corners before = corners_of(mesh.tri[t], sweep_);
            Corners after = before;
            after[g % 3] = to; // g leaves v: v is corner g % 3 of its face
            add_old(t, before);
            faces_.push_back(t);
            new_corners_.push_back(after);
            normal += area_vector(before) + area_vector(after);
        });
        remap_fan(normal);
        sweep_[v] = to;
    }
}

void FaceValues::offset(const TriMesh &mesh, const std::vector<Vec3> &positions)
{
    for (int32_t t = 0; t < mesh.num_triangles(); ++t) {
        if (is_dead_triangle(mesh, t))
            continue;
        const Triangle &c = mesh.tri[t];
        const double before = face_area(mesh, t), after = area(positions[c[0]], positions[c[1]], positions[c[2]]);
        // A face offset to no area at all cannot carry its integral: it keeps its density
        // (it had next to no area before, or the offset would have folded it, which the
        // volume correction does not do).
        if (after > 0)
            for (int32_t k = 0; k < ncomp_; ++k)
                at(t, k) *= before / after;
    }
}

} // namespace sfa
