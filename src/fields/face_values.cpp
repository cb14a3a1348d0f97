#include "fields/face_values.hpp"

namespace sfa {
namespace {

double area(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return 0.5 * (b - a).cross(c - a).norm(); }

double face_area(const TriMesh &mesh, int32_t t)
{
    const Triangle &c = mesh.tri[t];
    return area(mesh.pos[c[0]], mesh.pos[c[1]], mesh.pos[c[2]]);
}

} // namespace

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
    const FlipQuad &q = change.quad;
    const Vec3 &a = mesh.pos[q.a], &b = mesh.pos[q.b], &p = mesh.pos[q.p], &qq = mesh.pos[q.q];
    const double old_areas[2] = {area(a, b, p), area(b, a, qq)}; // faces[0] was (a, b, p)
    const double new_area = face_area(mesh, change.faces[0]) + face_area(mesh, change.faces[1]);
    for (int32_t c = 0; c < ncomp_; ++c) {
        const double integral = at(change.faces[0], c) * old_areas[0] + at(change.faces[1], c) * old_areas[1];
        const double density = new_area > 0 ? integral / new_area : 0;
        at(change.faces[0], c) = at(change.faces[1], c) = density;
    }
}

void FaceValues::before_collapse(const TriMesh &mesh, int32_t h)
{
    integral_before_.assign(ncomp_, 0);
    mesh.for_each_face_around_edge(h, [&](int32_t f) {
        const double a = face_area(mesh, f);
        for (int32_t c = 0; c < ncomp_; ++c)
            integral_before_[c] += value(f, c) * a;
    });
}

void FaceValues::collapse(const TriMesh &mesh, const CollapseChange &change)
{
    std::vector<double> integral_after(ncomp_, 0);
    double area_after = 0;
    mesh.for_each_outgoing(change.record.keep, [&](int32_t g) {
        const double a = face_area(mesh, TriMesh::face(g));
        area_after += a;
        for (int32_t c = 0; c < ncomp_; ++c)
            integral_after[c] += value(TriMesh::face(g), c) * a;
    });
    for (int32_t c = 0; c < ncomp_; ++c)
        mesh.for_each_outgoing(change.record.keep, [&](int32_t g) {
            double &d = at(TriMesh::face(g), c);
            // One factor for every face, or one density where the faces carried none.
            d = integral_after[c] != 0 ? d * integral_before_[c] / integral_after[c]
                                       : (area_after > 0 ? integral_before_[c] / area_after : 0);
        });
}

} // namespace sfa
