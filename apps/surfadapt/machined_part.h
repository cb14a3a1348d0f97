/* SPDX-License-Identifier: BSD-3-Clause */
/* A generated machined part: the demo's static input and a test's, so that a fresh clone
 * shows real sharp features and curved patches without any data beside the project.
 *
 * The part is a 4 x 3 x 1 plate, [0, 4] x [0, 3] x [0, 1], with
 *   - a hole of radius 0.6 drilled through it along z, its axis at (1.5, 1.5);
 *   - the vertical edge at (4, 0) chamfered: a planar 45-degree bevel 0.6 wide on each face,
 *     from (3.4, 0) to (4, 0.6), so two sharp edges instead of one;
 *   - the vertical edge at (4, 3) filleted: a quarter cylinder of radius 1 about (3, 2),
 *     tangent to both faces it joins, so no sharp edge at all.
 * Its sharp features: 8 corners, where the 4 vertical edges (at x = 0 and the chamfer's)
 * meet the top and the bottom; 14 ridge curves between them (see machined_part_ridge_name):
 * the 4 pieces of the top outline and the 4 of the bottom (one of each runs round the fillet
 * without a corner), the 4 vertical edges and the hole's 2 rims. The fillet's and the hole's
 * walls are smooth, and so are the lines where the fillet meets the flat faces.
 *
 * The mesh is tessellated as a CAD program exports it (an STL file): the walls are single
 * strips of triangles as tall as the part, the top and the bottom are fans of long thin
 * triangles between the outline and the hole. A remesher has everything to improve. */
#ifndef SURFADAPT_APP_MACHINED_PART_H
#define SURFADAPT_APP_MACHINED_PART_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MACHINED_PART_CORNERS 8
#define MACHINED_PART_RIDGES 14

/* The part with `resolution` segments round the hole (a multiple of 4 in [8, 4096]): the
 * fillet's quarter circle has resolution / 4, the straight edges of the outline pieces about
 * three hole segments long. Closed, manifold, of genus 1, outward and counter-clockwise,
 * 0-based; the arrays are malloc'ed (free them). Returns 0, or -1 if out of memory or the
 * resolution is not accepted. */
int machined_part(int resolution, int32_t *nverts, double **xyz, int32_t *ntris, int32_t **tris);

/* The exact volume of the part: 4 * 3 * 1 minus the hole (0.36 pi), the chamfer's prism
 * (0.18) and what the fillet takes off (1 - pi / 4). */
double machined_part_volume(void);

/* How far the volume of machined_part(resolution) may be from machined_part_volume(): the
 * mesh is exact but for its circular arcs, whose chords (inscribed, angle t apart) take off
 * r^2 / 2 (t - sin t) <= r^2 t^3 / 12 each. So the hole's polygon is smaller than the hole
 * by at most pi r^2 t^2 / 6 (per unit height; making the part larger) and the fillet's
 * polygon cuts off at most pi f^2 t^2 / 24 (making it smaller). The two have opposite signs,
 * so the larger one bounds the difference. */
double machined_part_volume_bound(int resolution);

/* Which of the part's 8 corners p is within `tol` of (0 to 7), or -1. */
int machined_part_corner(const double p[3], double tol);

/* Which of the part's 14 ridge curves p is within `tol` of (0 to 13; the first found where
 * curves meet, at a corner), or -1. */
int machined_part_ridge(const double p[3], double tol);

/* Which ridge curve the straight edge (a, b) runs along: the curve both its ends and its
 * midpoint are within `tol` of, or -1. */
int machined_part_ridge_edge(const double a[3], const double b[3], double tol);

/* The length of ridge curve `ridge` (of the exact part), and its name ("the hole's top
 * rim"); 0 and NULL if there is no such curve. */
double machined_part_ridge_length(int ridge);
const char *machined_part_ridge_name(int ridge);

/* What of the part p lies on, within `tol`, away (by more than tol) from the ridges that
 * bound the patch: 1 the hole's wall, 2 the fillet (its tangent lines included), 0 anything
 * else. Ridges found there are spurious. */
int machined_part_curved_patch(const double p[3], double tol);

/* What a feature detection found of the part, from the mesh (nverts points xyz), each
 * vertex's rank (2 a corner; as sfa_get_feature_ranks gives them) and the ridge edges
 * (nridges pairs of 0-based vertex indices; as sfa_get_ridge_edges gives them). A point
 * within `tol` of a corner or a ridge curve counts as on it. */
typedef struct machined_part_features {
    int corners_found;     /* of the 8 corners, those with a corner vertex there */
    int corners_elsewhere; /* corner vertices at none of them */
    int ridges_found;      /* of the 14 ridge curves, those found (machined_part_ridge_found) */
    int32_t ridge_edges;   /* along the 14 curves */
    int32_t edges_on[MACHINED_PART_RIDGES];
    double covered[MACHINED_PART_RIDGES]; /* the length of the ridge edges along each curve */
    int32_t ridge_edges_elsewhere; /* along none of them: spurious ridges */
    int32_t on_hole_wall, on_fillet; /* of those, the ones on the smooth curved patches */
} machined_part_features;

void machined_part_features_of(int32_t nverts, const double *xyz, const int32_t *ranks, int32_t nridges,
                               const int32_t *ridges, double tol, machined_part_features *found);

/* Whether ridge curve `ridge` was found whole: its ridge edges cover 98 % of its length
 * (the chords of an arc are shorter than the arc, by 0.3 % at 24 segments round the hole). */
int machined_part_ridge_found(const machined_part_features *found, int ridge);

#ifdef __cplusplus
}
#endif

#endif
