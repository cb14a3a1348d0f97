// SPDX-License-Identifier: BSD-3-Clause
// The fan of a vertex of high valence, ordered by angle, so that the faces of the fan a
// triangle could meet are found without reading the whole fan (issue 18: a cone whose apex
// neighbours every vertex of its rim made each contraction's check read all of it).
//
// The fan's faces (w, v_i, v_i+1) are projected by a linear map L along an axis (the sum
// of the fan's area vectors). Where the projected fan is star-shaped around L(w) (every
// link vertex away from the axis, the angles of the link vertices increasing by less than
// pi each and by 2 pi in all), face i lies in the wedge of w spanned by v_i and v_i+1, and
// every point of that wedge but w projects into the sector [phi_i, phi_i+1]. A linear map
// keeps a common point common, so a triangle can meet face i only if its projection meets
// that sector: the sectors of a triangle are found by binary search and only their faces
// need the exact test. The filter is conservative: angles are padded by more than their
// rounding error, and where the projection of a triangle comes near L(w) (no angle is
// defined there) the triangle is only filtered if its distance from w keeps its common
// points with the fan away from the axis; otherwise the caller tests the whole fan.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace sfa {

class FanSectors {
public:
    // Indexes w's fan as it is now; false (and usable() false) where the fan is open, or
    // not star-shaped in projection.
    bool build(const TriMesh &mesh, int32_t w);
    // Indexes the fan the merged vertex would have if h were contracted with it at
    // `merged` (the faces around either end but the two of h's edge, as they are numbered
    // now); false where either end is on the boundary or the fan is not star-shaped.
    bool build_merged(const TriMesh &mesh, int32_t h, const Vec3 &merged);
    bool usable() const { return usable_; }
    int32_t hub() const { return hub_; }
    size_t size() const { return faces_.size(); }

    // Calls fn(f) for every face of the indexed fan (as it was built) whose sector meets
    // the projection of the triangle p (at least every face p could meet, perhaps a face
    // more than once). False, calling nothing, where the filter cannot tell: the caller
    // tests the whole fan.
    template <class Fn>
    bool for_each_candidate(const Vec3 (&p)[3], Fn &&fn) const
    {
        double from, to;
        if (!usable_ || !query_range(p, from, to))
            return false;
        const double two_pi = 2 * 3.14159265358979323846;
        if (to - from >= two_pi - 2 * pad_) { // every sector
            for (int32_t f : faces_)
                fn(f);
            return true;
        }
        // From within the turn the sectors cover, [phi_0, phi_0 + 2 pi): the range and its
        // padding may then reach past either end of it, into the turn before or after.
        const double turns = std::floor((from - phi_[0]) / two_pi);
        from -= turns * two_pi;
        to -= turns * two_pi;
        for (double shift : {-two_pi, 0.0, two_pi}) {
            const double lo = from + shift - pad_, hi = to + shift + pad_;
            // Sector i is [phi_i, phi_i+1] (padded); phi is increasing.
            size_t i = static_cast<size_t>(std::lower_bound(phi_.begin() + 1, phi_.end(), lo) - phi_.begin()) - 1;
            for (; i < faces_.size() && phi_[i] <= hi; ++i)
                fn(faces_[i]);
        }
        return true;
    }

private:
    // The angles of the projection of p seen from L(w), [from, to], padded.
    bool query_range(const Vec3 (&p)[3], double &from, double &to) const;
    // Indexes faces_ (face i between links_[i] and links_[i + 1], cyclically) around centre.
    bool index(const Vec3 &centre);

    bool usable_ = false;
    int32_t hub_ = -1;
    Vec3 centre_ = Vec3::Zero(), e1_ = Vec3::Zero(), e2_ = Vec3::Zero(); // L(x) = ((x - w).e1, (x - w).e2)
    double stretch_ = 0;        // |x - w| <= stretch_ |L(x - w)| on every face of the fan
    double pad_ = 0;            // more than the rounding error of every angle of the fan
    std::vector<double> phi_;   // the link vertices' angles, unwrapped, increasing: 2 pi in all
    std::vector<int32_t> faces_; // face i between phi_[i] and phi_[i + 1]
    std::vector<Vec3> links_;    // the link vertices' positions
};

} // namespace sfa
