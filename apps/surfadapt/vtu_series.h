/* SPDX-License-Identifier: BSD-3-Clause */
/* A VTK time series for ParaView: one XML unstructured-grid file (.vtu, binary appended,
 * mesh_formats.h's writer) per saved step and a .pvd collection that lists them with their
 * times. Each step carries what a viewer colours by: point data "rank" (feature rank) and
 * "component" (connected component), "velocity" when the caller gives the velocity field,
 * and the host's vertex fields; cell data: the host's face fields. C, so that the C tests
 * write series as the tool does. */
#ifndef SURFADAPT_APP_VTU_SERIES_H
#define SURFADAPT_APP_VTU_SERIES_H

#include "surfadapt.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A host field to write: the library cannot list a surface's fields or name them, so the
 * host that added them says which, under what name and with how many components. */
typedef struct {
    const char *name; /* the array's name in the files: not "rank", "component" or "velocity" */
    int32_t id;       /* from sfa_add_field() (vertex fields) or sfa_add_face_field() (face fields) */
    int32_t ncomp;    /* as the field was added with */
} vtu_series_field;

typedef struct {
    /* Set by vtu_series_init; the strings must outlive the series. */
    const char *directory, *name;
    /* Optional, set before the first save: the velocity field, evaluated at the vertices at
     * the step's time as point data "velocity" (NULL: none), and the host's fields. */
    sfa_velocity_fn velocity;
    void *velocity_ctx;
    const vtu_series_field *vertex_fields, *face_fields;
    int nvertex_fields, nface_fields;
    /* The saved steps' times; step i is NAME_iiii.vtu. */
    double *times;
    int steps, capacity;
} vtu_series;

/* Files go to `directory` (created if missing, not its parents) as NAME_0000.vtu ... and
 * NAME.pvd. */
void vtu_series_init(vtu_series *ts, const char *directory, const char *name);

/* Writes the surface as it is at time t and rewrites the collection, so that it is complete
 * even if the run stops early. Returns 0, or -1 with the reason in `err`. */
int vtu_series_save(vtu_series *ts, const sfa_surface *s, double t, char *err, size_t err_len);

/* Frees the list of times; the files stay. */
void vtu_series_free(vtu_series *ts);

#ifdef __cplusplus
}
#endif

#endif
