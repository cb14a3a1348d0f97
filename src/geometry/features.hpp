// SPDX-License-Identifier: BSD-3-Clause
// Feature detection (§2.2, §3.1, after Jiao's quadric-based detection): feature ranks
// 0/1/2 (smooth/ridge/corner) from the quadric's eigenvalue ratios, made exact on clean
// input and stable on noisy input by safeguards that make ridge vertices form curves.
#pragma once

#include "geometry/quadric.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace sfa {

struct FeatureThresholds {
    double ridge_angle;  // radians: chi_c = tan^2(angle/2) on lambda2/lambda1, and the dihedral of a ridge edge
    double corner_angle; // radians: chi_r = tan^2(angle/2) on lambda3/lambda1
    double turn_angle;   // radians: a ridge curve turning more than this at a vertex makes it a corner
};

struct Features {
    std::vector<int8_t> rank;                       // per vertex: 0 smooth, 1 ridge, 2 corner
    std::vector<char> ridge_halfedge;               // per half-edge, both halves of a ridge edge set
    std::vector<std::array<int32_t, 2>> ridge_edges; // (a, b) with a < b, sorted
};

Features detect_features(const TriMesh &mesh, const std::vector<QuadricEigen> &eigen,
                         const std::vector<Vec3> &area_vectors, const FeatureThresholds &thresholds);

} // namespace sfa
