/* SPDX-License-Identifier: BSD-3-Clause */
/* Generated meshes with exact answers, and helpers shared by the C tests and benchmarks.
 *
 * Everything here uses the public API only and does not depend on CMocka, because the
 * benchmarks link these objects too; the CMocka assertions built on top live in
 * support/testing.h. Every generator returns 0-based, outward, counter-clockwise meshes
 * in malloc'ed arrays (free with mesh_free()) and aborts if out of memory. */
#ifndef SURFADAPT_TEST_SHAPES_H
#define SURFADAPT_TEST_SHAPES_H

#include "obj_io.h"
#include "surfadapt.h"

#include <stddef.h>
#include <stdint.h>

/* Number of parameter keys of the API (SFA_PARAM_EDGE_LENGTH .. SFA_PARAM_THIN_SHEET_EDGE_RATIO);
 * unit_constant_lists fails when enum sfa_param has more or fewer. */
#define SHAPES_NPARAMS 28

/* [0,1]^3: 8 vertices, 12 triangles, each face split along one diagonal. */
sfa_mesh_data shape_unit_cube(void);

/* The box [lo, hi] with n x n square cells per face, each cell split in two: watertight,
 * vertices shared between faces; 6 n^2 + 2 vertices, 12 n^2 triangles. */
sfa_mesh_data shape_box(int n, const double lo[3], const double hi[3]);

/* The regular icosahedron with circumradius r about the origin: 12 vertices, 20 triangles. */
sfa_mesh_data shape_icosahedron(double r);

/* The icosahedron subdivided k times, vertices on the sphere of radius r about the origin:
 * 10*4^k + 2 vertices, 20*4^k triangles. */
sfa_mesh_data shape_icosphere(int k, double r);

/* Two icospheres of shape_icosphere(k, r) whose centres are `distance` apart on the x axis,
 * either side of the origin: two drops. */
sfa_mesh_data shape_two_icospheres(int k, double r, double distance);

/* An open, flat patch in the plane z = 0 with nx x ny square cells of side h, normals +z.
 * Vertex (i, j) (0 <= i <= nx, 0 <= j <= ny) is number j*(nx+1) + i, at (i h, j h, 0). */
sfa_mesh_data shape_grid(int nx, int ny, double h);

/* A closed cylinder of radius r and height h about the z axis, z in [-h/2, h/2]: the side
 * has `rings` rows of `segments` quads (two triangles each), each cap is a fan around a
 * centre vertex. Watertight, outward. Vertex j*segments + i (0 <= j <= rings) is on ring j
 * at angle 2 pi i / segments and z = -h/2 + h j / rings, so rings 0 and `rings` are the
 * rims; then come the centres of the bottom and the top cap.
 * (rings + 1) segments + 2 vertices, 2 (rings + 1) segments triangles. */
sfa_mesh_data shape_capped_cylinder(double r, double h, int segments, int rings);

/* The ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1: the unit icosphere subdivided k times,
 * scaled by (a, b, c) (so the triangles are stretched where the semi-axes differ). */
sfa_mesh_data shape_ellipsoid(int k, double a, double b, double c);

/* An open spherical cap of radius r about the origin around +z, polar angles up to
 * `max_angle` (radians): a pole vertex (number 0) with a fan, then `rings` circles of
 * `segments` vertices (vertex 1 + (j-1)*segments + i at polar angle j max_angle / rings,
 * azimuth 2 pi i / segments). The last `segments` vertices form the boundary. Outward. */
sfa_mesh_data shape_spherical_cap(double r, double max_angle, int segments, int rings);

/* The icosphere of shape_icosphere(k, r) with every vertex moved along its radius by a
 * uniform random amount in [-fraction, fraction] times the mean edge length; the same
 * `seed` gives the same mesh on every platform. */
sfa_mesh_data shape_noisy_icosphere(int k, double r, double fraction, uint64_t seed);

/* The icosphere of shape_icosphere(k, r) with every vertex moved along the sphere (in a
 * random tangent direction, then back onto the sphere) by up to `fraction` of the mean
 * edge length; the same `seed` gives the same mesh on every platform. */
sfa_mesh_data shape_jittered_icosphere(int k, double r, double fraction, uint64_t seed);

/* A small deterministic random number generator (SplitMix64), so that generated meshes
 * do not depend on the C library's rand(). */
typedef struct shapes_rng {
    uint64_t state;
} shapes_rng;
shapes_rng rng_seed(uint64_t seed);
uint64_t rng_next(shapes_rng *rng);
/* Uniform in [0, 1), 53 random bits. */
double rng_uniform(shapes_rng *rng);

/* Rotation matrices, row-major: y = R x is y[i] = sum_k R[3 i + k] x[k]. */
/* The rotation by `angle` radians about `axis` (any non-zero length; right-hand rule). */
void rotation_axis_angle(const double axis[3], double angle, double R[9]);
/* A rotation drawn from `rng` (uniform axis direction, angle in [0, 2 pi)). */
void rotation_random(shapes_rng *rng, double R[9]);

/* x <- scale * R x for every vertex (R row-major, as above; scale > 0 keeps the
 * orientation). */
void mesh_rotate_scale(sfa_mesh_data *m, const double R[9], double scale);

/* Renumbers the vertices and the triangles in a random order drawn from `seed`, and starts
 * each triangle at a random corner (a cyclic shift, so the orientation is kept). Vertex v
 * of the input is vertex vert_new[v] of the result and triangle t is triangle tri_new[t];
 * either array (nverts, ntris entries) may be NULL when not wanted. */
void mesh_permute(sfa_mesh_data *m, uint64_t seed, int32_t *vert_new, int32_t *tri_new);

/* Mean length of the undirected edges (each interior edge counted once). */
double mesh_mean_edge_length(const sfa_mesh_data *m);

/* The undirected edges of a mesh as sorted pairs (smaller, larger): 2*(*count) indices,
 * malloc'ed (free them). */
int32_t *mesh_edges(const sfa_mesh_data *m, int32_t *count);

/* qsort/bsearch order of (int32_t, int32_t) pairs. */
int compare_index_pairs(const void *a, const void *b);

/* A deep copy. */
sfa_mesh_data mesh_copy(const sfa_mesh_data *m);

/* Reverses the orientation of every triangle. */
void mesh_reverse(sfa_mesh_data *m);

/* Adds d to every vertex. */
void mesh_translate(sfa_mesh_data *m, const double d[3]);

/* Appends `b` to `a` (vertices and triangles of b renumbered after those of a). */
void mesh_append(sfa_mesh_data *a, const sfa_mesh_data *b);

/* A new surface holding `m`, passed with index base `base` (0 or 1; the indices are
 * converted). NULL if creating it or setting the mesh fails; then, if `err` is not NULL,
 * the library's message is copied there. */
sfa_surface *surface_from(const sfa_mesh_data *m, int base, char *err, size_t err_len);

/* Everything the public API shows of a surface, to check that a failed call changed nothing.
 * Each part records the status its getter returned, so surfaces without a mesh (or without
 * fields) compare too. Velocities have no getter; tests check them through sfa_move(). */
#define SNAPSHOT_MAX_FIELDS 8
#define SNAPSHOT_MAX_NCOMP 8
typedef struct snapshot {
    int counts_status;
    int32_t nverts, ntris;
    int mesh_status;
    double *xyz;
    int32_t *tris;
    int param_status[SHAPES_NPARAMS];
    double params[SHAPES_NPARAMS];
    /* Field id f read into a buffer of SNAPSHOT_MAX_NCOMP*nverts doubles prefilled with a
     * fixed byte pattern: the whole buffer is compared, so the field's size counts too. Ids
     * past the first that fails are not read (they fail the same way: ids are consecutive). */
    int field_status[SNAPSHOT_MAX_FIELDS];
    double *fields[SNAPSHOT_MAX_FIELDS];
} snapshot;

/* Takes a snapshot. The getters it calls reset sfa_last_error(): read the message first. */
void snapshot_take(const sfa_surface *s, snapshot *out);
void snapshot_free(snapshot *snap);
/* 1 if the two snapshots agree bit for bit, else 0 with a description of the first
 * difference in `why`. */
int snapshot_equal(const snapshot *a, const snapshot *b, char *why, size_t why_len);

/* The directory of the real meshes: $SFA_DATA_DIR, else ../shared/data (relative to the
 * repository root, where the tests run). */
const char *data_dir(void);
/* Writes data_dir()/name into buf; returns 1 if that file can be opened, else 0. */
int data_file(const char *name, char *buf, size_t len);
/* The one line a test prints when it skips because data_file() did not find `path`: what
 * is missing and why a fresh clone does not have it. scripts/run-tests.sh counts these
 * lines by their start, "skipped: needs ". */
void print_data_skip(const char *path);

#endif
