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

/* Number of parameter keys of the API (SFA_PARAM_EDGE_LENGTH .. SFA_PARAM_DROP_UNREFERENCED). */
#define SHAPES_NPARAMS 15

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

/* An open, flat patch in the plane z = 0 with nx x ny square cells of side h, normals +z.
 * Vertex (i, j) (0 <= i <= nx, 0 <= j <= ny) is number j*(nx+1) + i, at (i h, j h, 0). */
sfa_mesh_data shape_grid(int nx, int ny, double h);

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
     * fixed byte pattern: the whole buffer is compared, so the field's size counts too. */
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

#endif
