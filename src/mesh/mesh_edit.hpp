// SPDX-License-Identifier: BSD-3-Clause
// The one way a mesh is changed during smoothing and adaptation (DESIGN: "one edit
// mechanism"). MeshEdit performs split, collapse, flip, move, compact and renumber on a
// TriMesh, and tells every attached listener what each change did, so that everything that
// lives on the mesh's elements follows: host fields and velocities (interpolated), feature
// ranks and ridge flags (copied or combined), change marks, the crossing guard's index.
// Each of those is one listener that says once, in its own file, how it is carried; a pass
// that splits or contracts knows nothing of them. (The model is geometry-central's
// MutationManager, which calls back before and after each operation, and pmp-library's
// property arrays, which every garbage collection renumbers.)
#pragma once

#include "mesh/edge_collapse.hpp"
#include "mesh/edge_flip.hpp"
#include "mesh/edge_split.hpp"
#include "mesh/renumbering.hpp"
#include "mesh/stencil.hpp"

#include <vector>

namespace sfa {

// What one operation changed. `fans` lists the vertices whose fans (the faces around them)
// changed: an analysis of those alone brings a per-vertex analysis up to date. `stencil`
// places the new or merged vertex over the mesh as it was (only computed when a listener
// interpolates: otherwise its corners are -1; where the vertex lies over no face of the
// edge's, all of them degenerate, it is the edge's midpoint).
struct SplitChange {
    const SplitRecord &record;
    const Stencil &stencil;
    const std::vector<int32_t> &fans; // the corners of the edge's faces and the new vertex
};

struct CollapseChange {
    const CollapseRecord &record;
    const Stencil &stencil;
    const std::vector<int32_t> &fans; // the kept vertex and its neighbours
};

struct FlipChange {
    FlipQuad quad;        // a-b was the edge, p-q is
    int32_t faces[2];     // (q, p, a) and (p, q, b) now; the same indices as before
    int32_t diagonal[2];  // q -> p and p -> q: the new edge
    FlipMoves moves;      // where the quad's four outer half-edges went
    const std::vector<int32_t> &fans; // a, b, p, q
};

// Every vertex moves at once (a smoothing sweep); heard before the positions change.
// stencils[v] places v's new position over its old fan (corners -1 where v stays); empty
// when no listener interpolates.
struct MoveChange {
    const std::vector<Vec3> &positions;
    const std::vector<Stencil> &stencils;
};

class EditListener {
public:
    virtual ~EditListener() = default;
    // True if this listener needs the stencils of new, merged and moved vertices.
    virtual bool interpolates() const { return false; }
    // The changes that follow come one by one on the mesh as it is now (a pass begins):
    // an index of positions is built here.
    virtual void begin_changes(const TriMesh &) {}
    // Heard before a contraction of h, with the mesh as it still is (the faces around the
    // edge's ends are about to change shape or die).
    virtual void before_collapse(const TriMesh &, int32_t /*h*/) {}
    // Heard after the change, with the mesh as it is then.
    virtual void split(const TriMesh &, const SplitChange &) {}
    virtual void collapse(const TriMesh &, const CollapseChange &) {}
    virtual void flip(const TriMesh &, const FlipChange &) {}
    // Heard before: the mesh still has the old positions.
    virtual void move(const TriMesh &, const MoveChange &) {}
    // Vertices move off the surface, along their normals, to the given positions (the
    // volume correction): what lives on a vertex stays with it. Heard before, as move().
    virtual void offset(const TriMesh &, const std::vector<Vec3> & /*positions*/) {}
    virtual void renumber(const Renumbering &) {}
};

class MeshEdit {
public:
    explicit MeshEdit(TriMesh &mesh) : mesh_(mesh) {}
    MeshEdit(const MeshEdit &) = delete;
    MeshEdit &operator=(const MeshEdit &) = delete;

    const TriMesh &mesh() const { return mesh_; }

    // Listeners hear every change in the order they were attached. A listener must stay
    // alive while attached.
    void attach(EditListener &listener);
    void detach(EditListener &listener);

    void begin_changes();
    // Splits h's edge with a new vertex at `position` (split_edge); returns the vertex.
    int32_t split(int32_t h, const Vec3 &position);
    // Contracts h = (gone -> keep) with keep at `position` (collapse_edge); dead elements
    // stay until compact().
    void collapse(int32_t h, const Vec3 &position);
    // Flips h's edge (flip_edge).
    void flip(int32_t h);
    // Moves every vertex v to positions[v]; on return `positions` holds the old positions.
    void move(std::vector<Vec3> &positions);
    // Moves every vertex v to positions[v] off the surface (EditListener::offset); on
    // return `positions` holds the old positions.
    void offset(std::vector<Vec3> &positions);
    // Removes dead elements, the survivors in their order (compact()).
    void compact();
    // Renumbers vertices and triangles for locality (order_for_locality()).
    void order_for_locality();

private:
    void renumbered(const Renumbering &renumbering);

    TriMesh &mesh_;
    std::vector<EditListener *> listeners_;
    bool interpolating_ = false;
    std::vector<int32_t> fans_;      // of the last change; reused
    std::vector<Stencil> stencils_;  // of the last move; reused
};

// Attaches a listener for the lifetime of this object (a pass's own marks, say).
class Attached {
public:
    Attached(MeshEdit &edit, EditListener &listener) : edit_(edit), listener_(listener) { edit_.attach(listener_); }
    ~Attached() { edit_.detach(listener_); }
    Attached(const Attached &) = delete;
    Attached &operator=(const Attached &) = delete;

private:
    MeshEdit &edit_;
    EditListener &listener_;
};

} // namespace sfa
