// SPDX-License-Identifier: BSD-3-Clause
#include "adapt/constraints.hpp"

#include <algorithm>

namespace sfa {

CarriedConstraints::CarriedConstraints(const TriMesh &mesh, const Constraints &constraints)
    : host_fixed_(constraints.fixed)
{
    if (constraints.empty())
        return;
    fixed_ = host_fixed_;
    fixed_.resize(mesh.pos.size(), 0);
    if (constraints.required.empty())
        return;
    std::vector<char> flags(mesh.opp.size(), 0);
    for (const std::array<int32_t, 2> &edge : constraints.required) {
        for (int32_t v : edge)
            fixed_[v] = 1;
        for (int32_t h : {mesh.halfedge(edge[0], edge[1]), mesh.halfedge(edge[1], edge[0])})
            if (h >= 0)
                flags[h] = 1;
    }
    required_ = HalfedgeFlags(std::move(flags));
}

void CarriedConstraints::impose_on(std::vector<int8_t> &rank) const
{
    for (size_t v = 0; v < fixed_.size(); ++v)
        if (fixed_[v])
            rank[v] = 2;
}

Constraints CarriedConstraints::as_host(const TriMesh &mesh) const
{
    Constraints out;
    out.fixed = host_fixed_;
    for (int32_t h = 0; h < static_cast<int32_t>(required_.flags().size()); ++h)
        if (required_[h] && (mesh.opp[h] < 0 || mesh.opp[h] > h)) {
            const int32_t a = mesh.tail(h), b = mesh.head(h);
            out.required.push_back({std::min(a, b), std::max(a, b)});
        }
    std::sort(out.required.begin(), out.required.end());
    return out;
}

void CarriedConstraints::split(const TriMesh &mesh, const SplitChange &change)
{
    if (!host_fixed_.empty())
        host_fixed_.push_back(0);
    if (!fixed_.empty())
        fixed_.push_back(0);
    if (!required_.flags().empty())
        required_.split(mesh, change);
}

void CarriedConstraints::collapse(const TriMesh &mesh, const CollapseChange &change)
{
    // The contraction pass keeps a fixed end and never contracts two (contract.cpp): the
    // gone vertex was free. Two edges of a contracted triangle become one, which is
    // required if either was.
    if (!required_.flags().empty())
        required_.collapse(mesh, change);
}

void CarriedConstraints::flip(const TriMesh &mesh, const FlipChange &change)
{
    if (!required_.flags().empty())
        required_.flip(mesh, change);
}

void CarriedConstraints::renumber(const Renumbering &renumbering)
{
    if (!host_fixed_.empty())
        renumbering.apply_to_vertices(host_fixed_);
    if (!fixed_.empty())
        renumbering.apply_to_vertices(fixed_);
    if (!required_.flags().empty())
        required_.renumber(renumbering);
}

} // namespace sfa
