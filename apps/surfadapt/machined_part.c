/* SPDX-License-Identifier: BSD-3-Clause */
#include "machined_part.h"

#include <math.h>
#include <stddef.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* The dimensions of machined_part.h, in one place. */
static const double length = 4, width = 3, height = 1;
static const double hole_x = 1.5, hole_y = 1.5, hole_r = 0.6;
static const double chamfer = 0.6, fillet = 1;

/* The outline, counter-clockwise seen from +z, as the corners of its pieces: P0 (0, 0),
 * P1 (the chamfer's start), P2 (its end), P3 and P4 (where the fillet starts and ends),
 * P5 (0, width). The fillet turns about (length - fillet, width - fillet). */
static void outline_point(int k, double p[2])
{
    const double points[6][2] = {{0, 0},
                                 {length - chamfer, 0},
                                 {length, chamfer},
                                 {length, width - fillet},
                                 {length - fillet, width},
                                 {0, width}};
    p[0] = points[k][0];
    p[1] = points[k][1];
}

/* Pieces of the outline: straight from P0 to P1 (the front), P1 to P2 (the chamfer), P2 to
 * P3 (the right), the fillet's arc P3 to P4, straight P4 to P5 (the back), P5 to P0 (the
 * left). Straight pieces are cut into segments about three hole segments long: a CAD
 * program would not cut them at all, but then the top's triangles would have to reach
 * round the hole, and these fans already are as thin as an export's. */
static int straight_segments(double len, int resolution)
{
    const double segment = 3 * 2 * PI * hole_r / resolution;
    const int k = (int)lround(len / segment);
    return k < 1 ? 1 : k;
}

static double distance2(const double a[2], const double b[2]) { return hypot(a[0] - b[0], a[1] - b[1]); }

/* Appends the outline's points (without repeating a piece's last point) to out (2 per
 * point); returns how many. out may be NULL to count only. */
static int outline(int resolution, double *out)
{
    int n = 0;
    for (int piece = 0; piece < 6; ++piece) {
        double a[2], b[2];
        outline_point(piece, a);
        outline_point((piece + 1) % 6, b);
        if (piece == 3) { /* the fillet's arc, from angle 0 to pi / 2 */
            const int k = resolution / 4;
            for (int i = 0; i < k; ++i, ++n)
                if (out) {
                    const double t = 0.5 * PI * i / k;
                    out[2 * n] = length - fillet + fillet * cos(t);
                    out[2 * n + 1] = width - fillet + fillet * sin(t);
                }
            continue;
        }
        const int k = straight_segments(distance2(a, b), resolution);
        for (int i = 0; i < k; ++i, ++n)
            if (out) {
                const double t = (double)i / k;
                out[2 * n] = a[0] + t * (b[0] - a[0]);
                out[2 * n + 1] = a[1] + t * (b[1] - a[1]);
            }
    }
    return n;
}

static double angle_about_hole(const double p[2])
{
    const double a = atan2(p[1] - hole_y, p[0] - hole_x);
    return a < 0 ? a + 2 * PI : a;
}

static double cross2(const double a[2], const double b[2], const double c[2])
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

int machined_part(int resolution, int32_t *nverts_out, double **xyz_out, int32_t *ntris_out, int32_t **tris_out)
{
    if (resolution < 8 || resolution > 4096 || resolution % 4)
        return -1;
    const int no = outline(resolution, NULL), nh = resolution;
    const int ring = no + nh, nverts = 2 * ring;
    /* top and bottom: one triangle per outline and per hole point; walls: two per segment */
    const int ntris = 2 * ring + 2 * (no + nh);
    double *plane = malloc(sizeof(double) * 2 * (size_t)ring);
    double *xyz = malloc(sizeof(double) * 3 * (size_t)nverts);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)ntris);
    if (!plane || !xyz || !tris)
        goto fail;

    /* The plane's points: the outline from its point with the smallest angle about the
     * hole's axis (it is star-shaped about the axis: each angle once), then the hole's,
     * both counter-clockwise. */
    outline(resolution, xyz); /* xyz as scratch: it has room for 3 ring points */
    int first = 0;
    for (int i = 1; i < no; ++i)
        if (angle_about_hole(xyz + 2 * i) < angle_about_hole(xyz + 2 * first))
            first = i;
    for (int i = 0; i < no; ++i) {
        plane[2 * i] = xyz[2 * ((first + i) % no)];
        plane[2 * i + 1] = xyz[2 * ((first + i) % no) + 1];
    }
    for (int j = 0; j < nh; ++j) {
        const double t = 2 * PI * j / nh;
        plane[2 * (no + j)] = hole_x + hole_r * cos(t);
        plane[2 * (no + j) + 1] = hole_y + hole_r * sin(t);
    }
    for (int v = 0; v < ring; ++v)
        for (int level = 0; level < 2; ++level) {
            double *p = xyz + 3 * (v + level * ring);
            p[0] = plane[2 * v];
            p[1] = plane[2 * v + 1];
            p[2] = level == 0 ? height : 0; /* the top first, then the bottom */
        }

    /* The top: the outline and the hole zipped by their angle about the axis, each step
     * advancing the loop whose next point comes first (angles unwrapped: the outline's grow
     * from a0 to a0 + 2 pi, the hole's from that of its last point not past a0). From
     * outline point i and hole point j, the triangle (i, i + 1, j) or (i, j + 1, j),
     * counter-clockwise seen from +z; the bottom has the same triangles reversed. Whatever
     * the triangles, their signed areas add up to the area within the two loops; so if every
     * one is counter-clockwise, none overlaps another: the zip is a triangulation. */
    int32_t *t = tris;
    const double a0 = angle_about_hole(plane);
    const int j0 = (int)floor(a0 / (2 * PI / nh));
    for (int i = 0, j = 0; i < no || j < nh;) {
        const double next_o = i + 1 < no ? angle_about_hole(plane + 2 * (i + 1)) : i + 1 == no ? a0 + 2 * PI : INFINITY;
        const double next_h = j < nh ? 2 * PI * (j0 + j + 1) / nh : INFINITY;
        const int32_t o = i % no, h = no + (j0 + j) % nh;
        const int32_t b = next_o <= next_h ? (i + 1) % no : no + (j0 + j + 1) % nh;
        if (next_o <= next_h)
            ++i;
        else
            ++j;
        if (!(cross2(plane + 2 * o, plane + 2 * b, plane + 2 * h) > 0))
            goto fail;
        *t++ = o, *t++ = b, *t++ = h;
        *t++ = ring + o, *t++ = ring + h, *t++ = ring + b;
    }
    /* The walls, one strip as tall as the part per segment: the outline's facing out, the
     * hole's facing its axis (away from the material). */
    for (int i = 0; i < no; ++i) {
        const int32_t a = i, b = (i + 1) % no;
        *t++ = ring + a, *t++ = ring + b, *t++ = b;
        *t++ = ring + a, *t++ = b, *t++ = a;
    }
    for (int j = 0; j < nh; ++j) {
        const int32_t a = no + j, b = no + (j + 1) % nh;
        *t++ = ring + b, *t++ = ring + a, *t++ = a;
        *t++ = ring + b, *t++ = a, *t++ = b;
    }
    if (t != tris + 3 * ntris)
        goto fail;
    free(plane);
    *nverts_out = nverts;
    *ntris_out = ntris;
    *xyz_out = xyz;
    *tris_out = tris;
    return 0;
fail:
    free(plane);
    free(xyz);
    free(tris);
    return -1;
}

double machined_part_volume(void)
{
    return height * (length * width - PI * hole_r * hole_r - 0.5 * chamfer * chamfer - (1 - PI / 4) * fillet * fillet);
}

double machined_part_volume_bound(int resolution)
{
    const double t = 2 * PI / resolution; /* the angle of a segment, of the hole and the fillet alike */
    const double hole = PI * hole_r * hole_r * t * t / 6, rounding = PI * fillet * fillet * t * t / 24;
    return height * (hole > rounding ? hole : rounding);
}

/* ------------------------------------------------------------------ features */

static double distance3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static double to_segment(const double p[3], const double a[3], const double b[3])
{
    double d[3], q[3], dd = 0, t = 0;
    for (int c = 0; c < 3; ++c) {
        d[c] = b[c] - a[c];
        dd += d[c] * d[c];
        t += (p[c] - a[c]) * d[c];
    }
    t = dd > 0 ? t / dd : 0;
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (int c = 0; c < 3; ++c)
        q[c] = a[c] + t * d[c];
    return distance3(p, q);
}

/* To the arc of radius r about (cx, cy) at height z, angles from t0 to t1 (t0 < t1). */
static double to_arc(const double p[3], double cx, double cy, double z, double r, double t0, double t1)
{
    double t = atan2(p[1] - cy, p[0] - cx);
    if (t < t0 - 1e-12 && t + 2 * PI <= t1)
        t += 2 * PI;
    if (t < t0 || t > t1) {
        const double a[3] = {cx + r * cos(t0), cy + r * sin(t0), z}, b[3] = {cx + r * cos(t1), cy + r * sin(t1), z};
        const double da = distance3(p, a), db = distance3(p, b);
        return da < db ? da : db;
    }
    return hypot(hypot(p[0] - cx, p[1] - cy) - r, p[2] - z);
}

/* The corners' places: the outline points P0, P1, P2, P5 at the top (0 to 3), then at the
 * bottom (4 to 7). */
static void corner_point(int corner, double p[3])
{
    static const int at[4] = {0, 1, 2, 5};
    outline_point(at[corner % 4], p);
    p[2] = corner < 4 ? height : 0;
}

int machined_part_corner(const double p[3], double tol)
{
    for (int k = 0; k < MACHINED_PART_CORNERS; ++k) {
        double c[3];
        corner_point(k, c);
        if (distance3(p, c) <= tol)
            return k;
    }
    return -1;
}

static double to_ridge(const double p[3], int ridge)
{
    if (ridge < 8) { /* the outline's pieces between corners, at the top then the bottom */
        const double z = ridge < 4 ? height : 0;
        double a[3] = {0, 0, z}, b[3] = {0, 0, z};
        switch (ridge % 4) {
        case 0:
        case 1:
            outline_point(ridge % 4, a);
            outline_point(ridge % 4 + 1, b);
            return to_segment(p, a, b);
        case 2: { /* P2 to P3, the fillet's arc, P4 to P5 */
            double d = INFINITY;
            outline_point(2, a);
            outline_point(3, b);
            d = fmin(d, to_segment(p, a, b));
            d = fmin(d, to_arc(p, length - fillet, width - fillet, z, fillet, 0, 0.5 * PI));
            outline_point(4, a);
            outline_point(5, b);
            return fmin(d, to_segment(p, a, b));
        }
        default:
            outline_point(5, a);
            outline_point(0, b);
            return to_segment(p, a, b);
        }
    }
    if (ridge < 12) { /* the vertical edges: at P0, P1, P2, P5 */
        double a[3], b[3];
        corner_point(ridge - 8, a);
        corner_point(ridge - 4, b);
        return to_segment(p, a, b);
    }
    if (ridge < 14)
        return to_arc(p, hole_x, hole_y, ridge == 12 ? height : 0, hole_r, 0, 2 * PI);
    return INFINITY;
}

int machined_part_ridge(const double p[3], double tol)
{
    for (int k = 0; k < MACHINED_PART_RIDGES; ++k)
        if (to_ridge(p, k) <= tol)
            return k;
    return -1;
}

int machined_part_ridge_edge(const double a[3], const double b[3], double tol)
{
    const double m[3] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
    for (int k = 0; k < MACHINED_PART_RIDGES; ++k)
        if (to_ridge(a, k) <= tol && to_ridge(b, k) <= tol && to_ridge(m, k) <= tol)
            return k;
    return -1;
}

double machined_part_ridge_length(int ridge)
{
    if (ridge < 0 || ridge >= MACHINED_PART_RIDGES)
        return 0;
    if (ridge >= 12)
        return 2 * PI * hole_r;
    if (ridge >= 8)
        return height;
    double a[2], b[2];
    switch (ridge % 4) {
    case 0:
    case 1:
        outline_point(ridge % 4, a);
        outline_point(ridge % 4 + 1, b);
        return distance2(a, b);
    case 2:
        return (width - fillet - chamfer) + 0.5 * PI * fillet + (length - fillet);
    default:
        return width;
    }
}

const char *machined_part_ridge_name(int ridge)
{
    static const char *const names[MACHINED_PART_RIDGES] = {
        "the top's front edge",
        "the chamfer's top edge",
        "the top's right and back edges, round the fillet",
        "the top's left edge",
        "the bottom's front edge",
        "the chamfer's bottom edge",
        "the bottom's right and back edges, round the fillet",
        "the bottom's left edge",
        "the vertical edge at (0, 0)",
        "the chamfer's front edge",
        "the chamfer's right edge",
        "the vertical edge at (0, 3)",
        "the hole's top rim",
        "the hole's bottom rim",
    };
    return ridge >= 0 && ridge < MACHINED_PART_RIDGES ? names[ridge] : NULL;
}

int machined_part_curved_patch(const double p[3], double tol)
{
    if (p[2] <= tol || p[2] >= height - tol)
        return 0;
    if (fabs(hypot(p[0] - hole_x, p[1] - hole_y) - hole_r) <= tol)
        return 1;
    const double cx = length - fillet, cy = width - fillet;
    if (p[0] >= cx - tol && p[1] >= cy - tol && fabs(hypot(p[0] - cx, p[1] - cy) - fillet) <= tol)
        return 2;
    return 0;
}

void machined_part_features_of(int32_t nverts, const double *xyz, const int32_t *ranks, int32_t nridges,
                               const int32_t *ridges, double tol, machined_part_features *found)
{
    machined_part_features f = {0};
    int has_corner[MACHINED_PART_CORNERS] = {0};
    for (int32_t v = 0; v < nverts; ++v)
        if (ranks[v] == 2) {
            const int k = machined_part_corner(xyz + 3 * v, tol);
            if (k >= 0)
                has_corner[k] = 1;
            else
                ++f.corners_elsewhere;
        }
    for (int k = 0; k < MACHINED_PART_CORNERS; ++k)
        f.corners_found += has_corner[k];
    for (int32_t e = 0; e < nridges; ++e) {
        const double *a = xyz + 3 * ridges[2 * e], *b = xyz + 3 * ridges[2 * e + 1];
        const int k = machined_part_ridge_edge(a, b, tol);
        if (k >= 0) {
            ++f.edges_on[k];
            ++f.ridge_edges;
            f.covered[k] += distance3(a, b);
            continue;
        }
        ++f.ridge_edges_elsewhere;
        const double m[3] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
        const int patch = machined_part_curved_patch(m, tol);
        f.on_hole_wall += patch == 1;
        f.on_fillet += patch == 2;
    }
    for (int k = 0; k < MACHINED_PART_RIDGES; ++k)
        f.ridges_found += machined_part_ridge_found(&f, k);
    *found = f;
}

int machined_part_ridge_found(const machined_part_features *found, int ridge)
{
    return ridge >= 0 && ridge < MACHINED_PART_RIDGES &&
           found->covered[ridge] >= 0.98 * machined_part_ridge_length(ridge);
}
