// SPDX-License-Identifier: BSD-3-Clause
#include "repair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

namespace {

using Tri = std::array<int32_t, 3>;
using Point = std::array<double, 3>;

Point point(const std::vector<double> &xyz, int32_t v) { return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}; }

Point minus(const Point &a, const Point &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

Point cross(const Point &a, const Point &b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

double dot(const Point &a, const Point &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The library's own rule (sfa_set_mesh): twice the area no more than a few ulps of the
// squared longest edge. NaN counts as zero area, as there.
bool zero_area(const std::vector<double> &xyz, const Tri &t)
{
    const Point a = point(xyz, t[0]), b = point(xyz, t[1]), c = point(xyz, t[2]);
    const Point ab = minus(b, a), bc = minus(c, b), ca = minus(a, c);
    const double longest2 = std::max({dot(ab, ab), dot(bc, bc), dot(ca, ca)});
    const Point n = cross(ab, minus(c, a));
    return !(std::sqrt(dot(n, n)) > 4 * std::numeric_limits<double>::epsilon() * longest2);
}

// ------------------------------------------------------------------ ear clipping

using Point2 = std::array<double, 2>;

double turn(const Point2 &a, const Point2 &b, const Point2 &c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// p in the closed triangle abc (counter-clockwise), but not at one of its corners.
bool inside_or_on(const Point2 &p, const Point2 &a, const Point2 &b, const Point2 &c)
{
    if (p == a || p == b || p == c)
        return false;
    return turn(a, b, p) >= 0 && turn(b, c, p) >= 0 && turn(c, a, p) >= 0;
}

// Polygons this large are fanned: ear clipping is quadratic in the corners.
constexpr int32_t most_clipped_corners = 4096;

// Cuts the polygon into triangles in its corners' order (so the orientation is kept), in
// the plane its Newell normal is most nearly perpendicular to. The fan from the first
// corner, which is how every reader of the tool takes a polygon, is kept where it is sound
// (every triangle turns the polygon's way, none has zero area): repair changes only what is
// wrong, and two polygons that share a diagonal's ends keep the file's choice. Otherwise
// ears are clipped; `clipped` is then true. A polygon that crosses itself (no ear can be
// cut) is fanned from where clipping stopped; `simple` is then false.
void triangulate(const std::vector<double> &xyz, const int32_t *corner, int32_t n, std::vector<Tri> &out,
                 bool &clipped, bool &simple)
{
    simple = true;
    clipped = false;
    Point normal{0, 0, 0};
    for (int32_t i = 0; i < n; ++i) {
        const Point p = point(xyz, corner[i]), q = point(xyz, corner[(i + 1) % n]);
        normal = {normal[0] + (p[1] - q[1]) * (p[2] + q[2]), normal[1] + (p[2] - q[2]) * (p[0] + q[0]),
                  normal[2] + (p[0] - q[0]) * (p[1] + q[1])};
    }
    // Drop the axis of the largest normal component; the other two, taken cyclically, see
    // the polygon counter-clockwise when that component is positive, else mirrored.
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(normal[k]) > std::fabs(normal[drop]))
            drop = k;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double mirror = normal[drop] < 0 ? -1 : 1;
    std::vector<Point2> p(static_cast<size_t>(n));
    for (int32_t i = 0; i < n; ++i)
        p[i] = {xyz[3 * corner[i] + u], mirror * xyz[3 * corner[i] + v]};

    bool fan_sound = true;
    for (int32_t i = 1; i + 1 < n && fan_sound; ++i)
        fan_sound = turn(p[0], p[i], p[i + 1]) > 0 && !zero_area(xyz, {corner[0], corner[i], corner[i + 1]});
    if (fan_sound) {
        for (int32_t i = 1; i + 1 < n; ++i)
            out.push_back({corner[0], corner[i], corner[i + 1]});
        return;
    }
    clipped = true;
    std::vector<int32_t> left(static_cast<size_t>(n));
    std::iota(left.begin(), left.end(), 0);
    while (left.size() > 3 && n <= most_clipped_corners) {
        const auto m = static_cast<int32_t>(left.size());
        bool cut = false;
        for (int32_t i = 0; i < m && !cut; ++i) {
            const int32_t a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
            if (!(turn(p[a], p[b], p[c]) > 0))
                continue; // a reflex or flat corner is no ear
            bool empty = true;
            for (int32_t j = 0; j < m && empty; ++j) {
                const int32_t w = left[j];
                empty = w == a || w == b || w == c || !inside_or_on(p[w], p[a], p[b], p[c]);
            }
            if (empty) {
                out.push_back({corner[a], corner[b], corner[c]});
                left.erase(left.begin() + i);
                cut = true;
            }
        }
        if (!cut)
            break;
    }
    if (left.size() > 3)
        simple = false;
    for (size_t i = 1; i + 1 < left.size(); ++i)
        out.push_back({corner[left[0]], corner[left[i]], corner[left[i + 1]]});
}

// ------------------------------------------------------------------ connectivity

// Each triangle side as (smaller, larger vertex, triangle, side), sorted: the sides of one
// edge are adjacent.
struct Side {
    int32_t lo, hi, tri, k;
    bool operator<(const Side &o) const { return std::tie(lo, hi, tri, k) < std::tie(o.lo, o.hi, o.tri, o.k); }
};

std::vector<Side> sorted_sides(const std::vector<Tri> &tris)
{
    std::vector<Side> sides;
    sides.reserve(3 * tris.size());
    for (size_t t = 0; t < tris.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
            sides.push_back({std::min(a, b), std::max(a, b), static_cast<int32_t>(t), k});
        }
    std::sort(sides.begin(), sides.end());
    return sides;
}

// The triangles across each side that has exactly one other triangle (-1 elsewhere), and
// the count of edges with three or more.
std::vector<Tri> neighbours(const std::vector<Tri> &tris, int32_t &edges_with_many)
{
    std::vector<Tri> across(tris.size(), Tri{-1, -1, -1});
    const std::vector<Side> sides = sorted_sides(tris);
    edges_with_many = 0;
    for (size_t i = 0; i < sides.size();) {
        size_t j = i + 1;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi)
            ++j;
        if (j - i == 2) {
            across[sides[i].tri][sides[i].k] = sides[i + 1].tri;
            across[sides[i + 1].tri][sides[i + 1].k] = sides[i].tri;
        } else if (j - i > 2) {
            ++edges_with_many;
        }
        i = j;
    }
    return across;
}

// Whether triangle t runs from a to b (rather than from b to a).
bool runs(const Tri &t, int32_t a, int32_t b)
{
    for (int k = 0; k < 3; ++k)
        if (t[k] == a && t[(k + 1) % 3] == b)
            return true;
    return false;
}

void turn_round(Tri &t) { std::swap(t[1], t[2]); }

// The components (triangles joined across two-triangle edges), by a search from each
// unvisited triangle: component[t] and their count.
int32_t components(const std::vector<Tri> &across, std::vector<int32_t> &component)
{
    component.assign(across.size(), -1);
    int32_t count = 0;
    std::vector<int32_t> stack;
    for (size_t seed = 0; seed < across.size(); ++seed) {
        if (component[seed] >= 0)
            continue;
        component[seed] = count;
        stack.assign(1, static_cast<int32_t>(seed));
        while (!stack.empty()) {
            const int32_t t = stack.back();
            stack.pop_back();
            for (const int32_t o : across[t])
                if (o >= 0 && component[o] < 0) {
                    component[o] = count;
                    stack.push_back(o);
                }
        }
        ++count;
    }
    return count;
}

// Orients each component like its first triangle, flipping neighbours that traverse a
// shared edge in the same direction; where that is impossible the component is counted as
// non-orientable and left as the search made it. Of the two orientations the one that
// turns fewer triangles is kept.
void orient(std::vector<Tri> &tris, std::vector<Tri> &original, const std::vector<Tri> &across, RepairReport &report)
{
    std::vector<int32_t> component;
    const int32_t count = components(across, component);
    std::vector<std::vector<int32_t>> members(static_cast<size_t>(count));
    for (size_t t = 0; t < tris.size(); ++t)
        members[component[t]].push_back(static_cast<int32_t>(t));
    std::vector<signed char> flip(tris.size(), -1); // -1 not reached, 0 keep, 1 turn
    std::vector<int32_t> stack;
    for (const std::vector<int32_t> &member : members) {
        bool orientable = true;
        flip[member[0]] = 0;
        stack.assign(1, member[0]);
        while (!stack.empty()) {
            const int32_t t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const int32_t o = across[t][k];
                if (o < 0)
                    continue;
                // As t will be: its side k runs a -> b; o must then run b -> a.
                int32_t a = tris[t][k], b = tris[t][(k + 1) % 3];
                if (flip[t])
                    std::swap(a, b);
                const signed char wanted = runs(tris[o], a, b) ? 1 : 0;
                if (flip[o] < 0) {
                    flip[o] = wanted;
                    stack.push_back(o);
                } else if (flip[o] != wanted) {
                    orientable = false;
                }
            }
        }
        const auto turned = std::count_if(member.begin(), member.end(), [&](int32_t t) { return flip[t] == 1; });
        const bool invert = 2 * turned > static_cast<long>(member.size());
        for (const int32_t t : member)
            if ((flip[t] == 1) != invert) {
                turn_round(tris[t]);
                turn_round(original[t]);
                ++report.triangles_flipped;
            }
        if (!orientable)
            ++report.non_orientable_components;
    }
}

// Gives each fan around a vertex (triangles that meet there but are not joined through the
// vertex's edges) a vertex of its own. A fan takes, if it can, the vertex the file gave its
// corner (`original`, before the merge of coincident vertices): a merged vertex whose fans
// come apart again was two vertices that only touched, so each gets its own number back and
// neither the merge nor the split is reported. A fan no file vertex is left for gets a copy.
void split_bowties(std::vector<double> &xyz, std::vector<Tri> &tris, const std::vector<Tri> &original,
                   const std::vector<Tri> &across, RepairReport &report)
{
    const auto nverts = static_cast<int32_t>(xyz.size() / 3);
    // Corners of each vertex: (triangle, position in it), grouped by vertex.
    std::vector<int32_t> start(static_cast<size_t>(nverts) + 1, 0);
    for (const Tri &t : tris)
        for (const int32_t v : t)
            ++start[v + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::pair<int32_t, int>> corners(static_cast<size_t>(start[nverts]));
    std::vector<int32_t> fill(start.begin(), start.end() - 1);
    for (size_t t = 0; t < tris.size(); ++t)
        for (int k = 0; k < 3; ++k)
            corners[fill[tris[t][k]]++] = {static_cast<int32_t>(t), k};

    std::vector<int32_t> fan(tris.size(), -1), stack, claimed;
    for (int32_t v = 0; v < nverts; ++v) {
        int32_t fans = 0;
        claimed.clear();
        const auto claim = [&claimed](int32_t w) {
            if (std::find(claimed.begin(), claimed.end(), w) != claimed.end())
                return false;
            claimed.push_back(w);
            return true;
        };
        // First the fans, found by a search from each triangle not yet in one.
        for (int32_t c = start[v]; c < start[v + 1]; ++c) {
            const int32_t seed = corners[c].first;
            if (fan[seed] >= 0)
                continue;
            // This fan's triangles: joined across the two sides at v (sides k and k + 2).
            fan[seed] = fans;
            stack.assign(1, seed);
            while (!stack.empty()) {
                const int32_t t = stack.back();
                stack.pop_back();
                const int k = static_cast<int>(std::find(tris[t].begin(), tris[t].end(), v) - tris[t].begin());
                for (const int side : {k, (k + 2) % 3}) {
                    const int32_t o = across[t][side];
                    if (o >= 0 && fan[o] < 0 && std::find(tris[o].begin(), tris[o].end(), v) != tris[o].end()) {
                        fan[o] = fans;
                        stack.push_back(o);
                    }
                }
            }
            ++fans;
        }
        // Then each fan is numbered: the file's vertex at its seed corner if still free, else v,
        // else a new copy. Renamed after all searches, which look for v in the triangles.
        std::vector<int32_t> number(static_cast<size_t>(fans), -1);
        for (int32_t c = start[v]; c < start[v + 1] && fans > 1; ++c) {
            const int32_t f = fan[corners[c].first];
            if (number[f] < 0 && claim(original[corners[c].first][corners[c].second]))
                number[f] = original[corners[c].first][corners[c].second];
        }
        for (int32_t f = 0; f < fans && fans > 1; ++f) {
            if (number[f] >= 0) {
                if (number[f] != v)
                    --report.vertices_merged; // a merge undone
                continue;
            }
            if (claim(v)) {
                number[f] = v;
                continue;
            }
            number[f] = static_cast<int32_t>(xyz.size() / 3);
            xyz.insert(xyz.end(), {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]});
            ++report.bowties_split;
        }
        for (int32_t c = start[v]; c < start[v + 1]; ++c) {
            const auto [t, k] = corners[c];
            if (fans > 1)
                tris[t][k] = number[fan[t]];
            fan[t] = -1;
        }
    }
}

// Turns closed components with negative enclosed volume (computed about a point of the
// component, so that far from the origin it does not cancel).
void turn_outward(const std::vector<double> &xyz, std::vector<Tri> &tris, const std::vector<Tri> &across,
                  RepairReport &report)
{
    std::vector<int32_t> component;
    const int32_t count = components(across, component);
    std::vector<char> closed(static_cast<size_t>(count), 1);
    std::vector<double> volume(static_cast<size_t>(count), 0);
    std::vector<int32_t> reference(static_cast<size_t>(count), -1);
    for (size_t t = 0; t < tris.size(); ++t) {
        const int32_t c = component[t];
        if (across[t][0] < 0 || across[t][1] < 0 || across[t][2] < 0)
            closed[c] = 0;
        if (reference[c] < 0)
            reference[c] = tris[t][0];
        const Point o = point(xyz, reference[c]);
        const Point a = minus(point(xyz, tris[t][0]), o), b = minus(point(xyz, tris[t][1]), o),
                    d = minus(point(xyz, tris[t][2]), o);
        volume[c] += dot(a, cross(b, d)) / 6;
    }
    for (int32_t c = 0; c < count; ++c)
        if (closed[c] && volume[c] < 0)
            ++report.components_turned_outward;
    for (size_t t = 0; t < tris.size(); ++t)
        if (closed[component[t]] && volume[component[t]] < 0)
            turn_round(tris[t]);
}

} // namespace

int32_t RepairReport::changes() const
{
    return faces_out_of_range + vertices_merged + polygons_clipped + degenerate_dropped + duplicates_dropped +
           triangles_flipped + components_turned_outward + edges_with_many_faces + bowties_split +
           unreferenced_dropped;
}

std::vector<std::string> RepairReport::lines() const
{
    std::vector<std::string> out;
    // `one` and `many` have a '#' where the count goes.
    const auto say = [&out](int32_t n, const char *one, const char *many, const char *why) {
        if (n <= 0)
            return;
        std::string line = n == 1 ? one : many;
        line.replace(line.find('#'), 1, std::to_string(n));
        out.push_back(line + why);
    };
    say(faces_out_of_range, "dropped # face that uses a vertex the file does not have",
        "dropped # faces that use vertices the file does not have", "");
    say(vertices_merged, "merged # vertex into an earlier one at exactly its position",
        "merged # vertices into earlier ones at exactly their positions", "");
    say(polygons_clipped, "triangulated # polygon by ear clipping", "triangulated # polygons by ear clipping",
        " (fanned from the first corner, as read, they fold over or have a zero-area triangle)");
    say(polygons_not_simple, "fanned # polygon that crosses itself", "fanned # polygons that cross themselves",
        " (no ear clipping can cut them; check them)");
    say(degenerate_dropped, "dropped # degenerate triangle", "dropped # degenerate triangles",
        " (a repeated corner, or collinear corners)");
    say(duplicates_dropped, "dropped # duplicate triangle", "dropped # duplicate triangles",
        " (the same three vertices as an earlier one)");
    say(triangles_flipped, "turned # triangle round", "turned # triangles round",
        " to agree with their neighbours' orientation");
    say(components_turned_outward, "turned # closed component outward", "turned # closed components outward",
        " (it was inside-out: negative volume)");
    say(edges_with_many_faces, "separated the triangles at # edge of three or more",
        "separated the triangles at # edges of three or more",
        " (each sheet through it gets its own copy of the edge: its ends are split as bow-ties)");
    say(bowties_split, "split # bow-tie vertex", "split # bow-tie vertices",
        " (fans that touched only there get a vertex each)");
    say(unreferenced_dropped, "dropped # vertex no triangle uses", "dropped # vertices no triangle uses", "");
    say(non_orientable_components, "left # component that cannot be oriented",
        "left # components that cannot be oriented", " (like a Moebius strip; the library refuses them)");
    say(edges_with_many_faces_left, "left # edge of three or more triangles", "left # edges of three or more triangles",
        " (their sheets also meet elsewhere, so splitting its ends does not part them)");
    return out;
}

RepairReport repair_mesh(const PolygonMesh &in, TriangleSoup &out)
{
    RepairReport report;
    const auto nverts = static_cast<int32_t>(in.xyz.size() / 3);
    out.xyz = in.xyz;

    // Vertices at bitwise the same finite position are one (STL-like exports, seams).
    std::vector<int32_t> same(static_cast<size_t>(nverts));
    std::iota(same.begin(), same.end(), 0);
    {
        std::vector<int32_t> order;
        for (int32_t v = 0; v < nverts; ++v)
            if (std::isfinite(in.xyz[3 * v]) && std::isfinite(in.xyz[3 * v + 1]) && std::isfinite(in.xyz[3 * v + 2]))
                order.push_back(v);
        const auto key = [&in](int32_t v) { return std::tie(in.xyz[3 * v], in.xyz[3 * v + 1], in.xyz[3 * v + 2]); };
        std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) { return key(a) < key(b); });
        for (size_t i = 1; i < order.size(); ++i)
            if (key(order[i]) == key(order[i - 1])) {
                same[order[i]] = same[order[i - 1]];
                ++report.vertices_merged;
            }
    }

    // Triangles on the file's vertices; `tris` below are the same on the merged ones.
    std::vector<Tri> original;
    std::vector<int32_t> corner;
    for (int32_t f = 0; f < in.faces(); ++f) {
        const int32_t begin = in.face_start[f], end = in.face_start[f + 1];
        corner.clear();
        bool in_range = true;
        for (int32_t i = begin; i < end; ++i) {
            in_range = in_range && in.indices[i] >= 0 && in.indices[i] < nverts;
            if (in_range)
                corner.push_back(in.indices[i]);
        }
        if (!in_range) {
            ++report.faces_out_of_range;
            continue;
        }
        if (corner.size() < 3) {
            ++report.degenerate_dropped;
            continue;
        }
        if (corner.size() == 3) {
            original.push_back({corner[0], corner[1], corner[2]});
            continue;
        }
        bool clipped = false, simple = true;
        triangulate(out.xyz, corner.data(), static_cast<int32_t>(corner.size()), original, clipped, simple);
        report.polygons_clipped += clipped ? 1 : 0;
        report.polygons_not_simple += simple ? 0 : 1;
    }

    // Degenerate and duplicate triangles, on the merged vertices.
    std::vector<Tri> tris;
    {
        std::vector<Tri> kept, kept_original;
        std::vector<std::pair<Tri, int32_t>> sorted;
        for (const Tri &o : original) {
            const Tri t{same[o[0]], same[o[1]], same[o[2]]};
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || zero_area(out.xyz, t)) {
                ++report.degenerate_dropped;
                continue;
            }
            Tri key = t;
            std::sort(key.begin(), key.end());
            sorted.emplace_back(key, static_cast<int32_t>(kept.size()));
            kept.push_back(t);
            kept_original.push_back(o);
        }
        std::sort(sorted.begin(), sorted.end());
        std::vector<char> drop(kept.size(), 0);
        for (size_t i = 1; i < sorted.size(); ++i)
            if (sorted[i].first == sorted[i - 1].first) {
                drop[sorted[i].second] = 1;
                ++report.duplicates_dropped;
            }
        original.clear();
        for (size_t t = 0; t < kept.size(); ++t)
            if (!drop[t]) {
                tris.push_back(kept[t]);
                original.push_back(kept_original[t]);
            }
    }

    std::vector<Tri> across = neighbours(tris, report.edges_with_many_faces);
    orient(tris, original, across, report);
    int32_t same_edges_with_many = 0;
    across = neighbours(tris, same_edges_with_many); // turning a triangle round renumbers its sides
    split_bowties(out.xyz, tris, original, across, report);
    across = neighbours(tris, report.edges_with_many_faces_left);
    report.edges_with_many_faces -= report.edges_with_many_faces_left;
    turn_outward(out.xyz, tris, across, report);

    // Drop the vertices nothing uses any more (merged ones among them), in order.
    const auto total = static_cast<int32_t>(out.xyz.size() / 3);
    std::vector<int32_t> renumber(static_cast<size_t>(total), -1);
    for (const Tri &t : tris)
        for (const int32_t v : t)
            renumber[v] = 0;
    int32_t kept = 0;
    for (int32_t v = 0; v < total; ++v) {
        if (renumber[v] < 0) {
            const bool merged = v < nverts && same[v] != v; // counted as merged already
            if (!merged)
                ++report.unreferenced_dropped;
            continue;
        }
        renumber[v] = kept;
        std::copy_n(out.xyz.begin() + 3 * v, 3, out.xyz.begin() + 3 * kept);
        ++kept;
    }
    out.xyz.resize(3 * static_cast<size_t>(kept));
    out.tris.clear();
    for (const Tri &t : tris)
        for (const int32_t v : t)
            out.tris.push_back(renumber[v]);
    return report;
}
