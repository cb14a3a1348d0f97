/* SPDX-License-Identifier: BSD-3-Clause */
/* mkdir() is POSIX, not C11. */
#define _POSIX_C_SOURCE 200809L

#include "vtu_series.h"

#include "mesh_formats.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

void vtu_series_init(vtu_series *ts, const char *directory, const char *name)
{
    memset(ts, 0, sizeof *ts);
    ts->directory = directory;
    ts->name = name;
}

void vtu_series_free(vtu_series *ts)
{
    free(ts->times);
    ts->times = NULL;
    ts->steps = ts->capacity = 0;
}

static int library_fail(const sfa_surface *s, const char *what, char *err, size_t err_len)
{
    snprintf(err, err_len, "%s: %s", what, sfa_last_error(s));
    return -1;
}

/* A host field's values, `count` tuples of field->ncomp. The library writes as many values
 * as the field really has; they are finite, so a NaN left at the end says the caller gave
 * more components than the field has (fewer is refused by the library: capacity). */
static double *host_field(const sfa_surface *s, const vtu_series_field *field, int faces, int64_t count, char *err,
                          size_t err_len)
{
    const int64_t n = count * (int64_t)field->ncomp;
    if (field->ncomp < 1 || n > INT32_MAX) {
        snprintf(err, err_len, "%s field '%s': %d components", faces ? "face" : "vertex", field->name,
                 (int)field->ncomp);
        return NULL;
    }
    double *values = malloc(sizeof(double) * (size_t)(n > 0 ? n : 1));
    if (!values) {
        snprintf(err, err_len, "out of memory");
        return NULL;
    }
    if (n > 0)
        values[n - 1] = NAN;
    const int rc = faces ? sfa_get_face_field(s, field->id, (int32_t)n, values)
                         : sfa_get_field(s, field->id, (int32_t)n, values);
    if (rc != SFA_OK || (n > 0 && isnan(values[n - 1]))) {
        if (rc != SFA_OK)
            library_fail(s, faces ? "sfa_get_face_field" : "sfa_get_field", err, err_len);
        else
            snprintf(err, err_len, "%s field '%s' (id %d) has fewer than %d components", faces ? "face" : "vertex",
                     field->name, (int)field->id, (int)field->ncomp);
        free(values);
        return NULL;
    }
    return values;
}

static int write_collection(const vtu_series *ts, char *err, size_t err_len)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s.pvd", ts->directory, ts->name);
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, err_len, "cannot write %s: %s", path, strerror(errno));
        return -1;
    }
    fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n", f);
    for (int i = 0; i < ts->steps; ++i)
        fprintf(f, "<DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s_%04d.vtu\"/>\n", ts->times[i],
                ts->name, i);
    fputs("</Collection>\n</VTKFile>\n", f);
    const int failed = ferror(f);
    if (fclose(f) != 0 || failed) {
        snprintf(err, err_len, "cannot write %s: %s", path, strerror(errno ? errno : EIO));
        return -1;
    }
    return 0;
}

int vtu_series_save(vtu_series *ts, const sfa_surface *s, double t, char *err, size_t err_len)
{
    if (mkdir(ts->directory, 0777) != 0 && errno != EEXIST) {
        snprintf(err, err_len, "cannot write %s: %s", ts->directory, strerror(errno));
        return -1;
    }
    if (ts->steps == ts->capacity) {
        const int capacity = ts->capacity ? 2 * ts->capacity : 16;
        double *times = realloc(ts->times, sizeof(double) * (size_t)capacity);
        if (!times) {
            snprintf(err, err_len, "out of memory");
            return -1;
        }
        ts->times = times;
        ts->capacity = capacity;
    }
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    const int nfixed = ts->velocity ? 3 : 2, npoint = nfixed + ts->nvertex_fields, ncell = ts->nface_fields;
    mesh_data_array *arrays = calloc((size_t)(npoint + ncell), sizeof *arrays);
    sfa_mesh_data m = {nverts, ntris, malloc(sizeof(double) * 3 * (size_t)(nverts ? nverts : 1)),
                       malloc(sizeof(int32_t) * 3 * (size_t)(ntris ? ntris : 1))};
    int32_t *rank = malloc(sizeof(int32_t) * (size_t)(nverts ? nverts : 1));
    int32_t *component = malloc(sizeof(int32_t) * (size_t)(nverts ? nverts : 1));
    double *velocity = ts->velocity ? malloc(sizeof(double) * 3 * (size_t)(nverts ? nverts : 1)) : NULL;
    int rc = 0;
    if (!arrays || !m.xyz || !m.tris || !rank || !component || (ts->velocity && !velocity))
        rc = (snprintf(err, err_len, "out of memory"), -1);
    else if (sfa_get_mesh(s, nverts, m.xyz, ntris, m.tris, 0) != SFA_OK)
        rc = library_fail(s, "sfa_get_mesh", err, err_len);
    else if (sfa_get_feature_ranks(s, nverts, rank) != SFA_OK)
        rc = library_fail(s, "sfa_get_feature_ranks", err, err_len);
    else if (sfa_get_components(s, nverts, component) != SFA_OK)
        rc = library_fail(s, "sfa_get_components", err, err_len);
    if (rc == 0) {
        arrays[0] = (mesh_data_array){"rank", MESH_ARRAY_INT32, 1, rank};
        arrays[1] = (mesh_data_array){"component", MESH_ARRAY_INT32, 1, component};
        if (velocity) {
            ts->velocity(ts->velocity_ctx, nverts, m.xyz, t, velocity);
            arrays[2] = (mesh_data_array){"velocity", MESH_ARRAY_FLOAT64, 3, velocity};
        }
    }
    /* The host's fields; the values of each are freed with `arrays` below. */
    for (int i = 0; i < ts->nvertex_fields + ts->nface_fields && rc == 0; ++i) {
        const int faces = i >= ts->nvertex_fields;
        const vtu_series_field *field = faces ? &ts->face_fields[i - ts->nvertex_fields] : &ts->vertex_fields[i];
        double *values = host_field(s, field, faces, faces ? ntris : nverts, err, err_len);
        if (!values)
            rc = -1;
        else
            arrays[nfixed + i] = (mesh_data_array){field->name, MESH_ARRAY_FLOAT64, field->ncomp, values};
    }
    if (rc == 0) {
        char path[4096], title[128];
        snprintf(path, sizeof path, "%s/%s_%04d.vtu", ts->directory, ts->name, ts->steps);
        snprintf(title, sizeof title, "surfadapt time series, step %d, t = %.17g", ts->steps, t);
        rc = mesh_file_write_vtu(path, &m, title, arrays, npoint, arrays + npoint, ncell, err, err_len);
    }
    if (rc == 0) {
        ts->times[ts->steps++] = t;
        rc = write_collection(ts, err, err_len);
    }
    for (int i = nfixed; arrays && i < npoint + ncell; ++i)
        free((void *)arrays[i].values);
    free(arrays);
    free(velocity);
    free(component);
    free(rank);
    mesh_free(&m);
    return rc;
}
