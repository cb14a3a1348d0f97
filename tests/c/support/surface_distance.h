/* SPDX-License-Identifier: BSD-3-Clause */
/* Distances between two triangle meshes, for tests that compare an adapted surface with
 * its input: the largest distance from any vertex or triangle centroid of one mesh to the
 * surface of the other (a sampled one-sided Hausdorff distance), found through a uniform
 * grid of the other mesh's triangles. Public API only; aborts if out of memory. */
#ifndef SURFADAPT_TEST_SURFACE_DISTANCE_H
#define SURFADAPT_TEST_SURFACE_DISTANCE_H

#include "obj_io.h"

/* The largest distance from the vertices and triangle centroids of `from` to `to`. */
double sampled_distance(const sfa_mesh_data *from, const sfa_mesh_data *to);

/* max(sampled_distance(a, b), sampled_distance(b, a)). */
double sampled_hausdorff(const sfa_mesh_data *a, const sfa_mesh_data *b);

/* The length of the diagonal of the mesh's bounding box. */
double bounding_diagonal(const sfa_mesh_data *m);

#endif
