// SPDX-License-Identifier: BSD-3-Clause
// Unit directions sorted into classes, and which two classes may hold directions more than a
// given angle apart. Where a search wants only pairs of nearly opposite normals (two sheets
// facing each other), most pairs of one smooth sheet have normals of one class or of two
// neighbouring ones, and are passed over by their classes alone (box_pairs.hpp).
//
// The classes are the six faces of the cube, each cut into divisions x divisions squares of
// its central projection (a direction n with largest component on axis a lands at
// n / |n_a|): each square is a convex region of the sphere bounded by great circles, so the
// direction farthest from its centre is one of its four corners.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <vector>

namespace sfa {

class DirectionClasses {
public:
    static constexpr int divisions = 4;
    static constexpr int count = 6 * divisions * divisions;

    // Classes for pairs of directions whose dot product is below `cosine`.
    explicit DirectionClasses(double cosine);

    // The class of a vector's direction (its length does not matter); any class for a zero
    // or NaN one (whose dot product with anything is below no cosine).
    int of(const Vec3 &n) const;
    // False where every direction of class a and every one of class b have a dot product of
    // at least the cosine (within a degree's margin, for rounding at the squares' edges).
    bool may_pair(int a, int b) const { return may_pair_[static_cast<size_t>(a * count + b)] != 0; }

private:
    std::vector<char> may_pair_; // count x count
};

} // namespace sfa
