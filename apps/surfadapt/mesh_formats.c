/* SPDX-License-Identifier: BSD-3-Clause */
#include "mesh_formats.h"

#include "format_io.h"

#include <ctype.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    mesh_format format;
    const char *extension;
    int index_base;
} format_entry;

static const format_entry formats[] = {
    {MESH_FORMAT_OBJ, "obj", 1},  {MESH_FORMAT_OFF, "off", 0},   {MESH_FORMAT_STL, "stl", 0},
    {MESH_FORMAT_PLY, "ply", 0},  {MESH_FORMAT_MEDIT, "mesh", 1}, {MESH_FORMAT_VTK, "vtk", 0},
    {MESH_FORMAT_VTU, "vtu", 0},
};
enum { format_count = sizeof formats / sizeof formats[0] };

mesh_format mesh_format_of(const char *path)
{
    if (!path)
        return MESH_FORMAT_UNKNOWN;
    const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
    if (!dot || (slash && slash > dot))
        return MESH_FORMAT_UNKNOWN;
    for (int i = 0; i < format_count; ++i)
        if (same_word(dot + 1, formats[i].extension))
            return formats[i].format;
    return MESH_FORMAT_UNKNOWN;
}

const char *mesh_format_extensions(void) { return ".obj, .off, .stl, .ply, .mesh, .vtk, .vtu"; }

int mesh_format_index_base(mesh_format format)
{
    for (int i = 0; i < format_count; ++i)
        if (formats[i].format == format)
            return formats[i].index_base;
    return 0;
}

static int parse_as(mesh_format format, char *data, size_t size, mesh_builder *b, read_context *c)
{
    switch (format) {
    case MESH_FORMAT_OBJ: return obj_parse_text(data, b, c);
    case MESH_FORMAT_OFF: return off_parse_text(data, b, c);
    case MESH_FORMAT_STL: return stl_parse(data, size, b, c);
    case MESH_FORMAT_PLY: return ply_parse(data, size, b, c);
    case MESH_FORMAT_MEDIT: return medit_parse(data, b, c);
    case MESH_FORMAT_VTK: return vtk_parse(data, b, c);
    case MESH_FORMAT_VTU: return vtu_parse(data, size, b, c);
    case MESH_FORMAT_UNKNOWN: break;
    }
    return read_fail(c, "unknown mesh format: the extension must be one of %s", mesh_format_extensions());
}

/* mesh_file_parse, and with `faces` not NULL the faces as mesh_file_read_faces gives them. */
static int parse_file(const char *name, char *data, size_t size, sfa_mesh_data *out, mesh_faces *faces,
                      int *index_base, char *err, size_t err_len)
{
    read_context c = {name ? name : "(null)", err, err_len, 0, -1};
    if (err && err_len)
        err[0] = '\0';
    if (faces)
        memset(faces, 0, sizeof *faces);
    if (!out)
        return read_fail(&c, "no output given");
    memset(out, 0, sizeof *out);
    if (!name || !data)
        return read_fail(&c, "no name or no data given");
    const mesh_format format = mesh_format_of(name);
    if (index_base)
        *index_base = mesh_format_index_base(format);
    mesh_builder b = {0};
    b.record_faces = faces != NULL;
    if (parse_as(format, data, size, &b, &c) != 0) {
        builder_free(&b);
        return -1;
    }
    if (faces && b.nfaces == 0) /* a format of triangles only: each is a face */
        for (int64_t t = 0; t < b.ntris; ++t)
            if (builder_begin_face(&b) != 0) {
                builder_free(&b);
                return read_fail(&c, "out of memory");
            }
    if (faces) {
        faces->nfaces = (int32_t)b.nfaces;
        faces->first_triangle = b.face_first;
        b.face_first = NULL;
    }
    out->nverts = (int32_t)b.nverts;
    out->ntris = (int32_t)b.ntris;
    out->xyz = b.xyz;
    out->tris = b.tris;
    return 0;
}

int mesh_file_parse(const char *name, char *data, size_t size, sfa_mesh_data *out, int *index_base, char *err,
                    size_t err_len)
{
    return parse_file(name, data, size, out, NULL, index_base, err, err_len);
}

static int read_file(const char *path, sfa_mesh_data *out, mesh_faces *faces, int *index_base, char *err,
                     size_t err_len)
{
    read_context c = {path ? path : "(null)", err, err_len, 0, -1};
    if (!path || !out || mesh_format_of(path) == MESH_FORMAT_UNKNOWN) /* parse_file says why */
        return parse_file(path, path ? "" : NULL, 0, out, faces, index_base, err, err_len);
    size_t size;
    char *data = read_whole_file(path, &size, &c);
    if (!data) {
        memset(out, 0, sizeof *out);
        if (faces)
            memset(faces, 0, sizeof *faces);
        return -1;
    }
    const int rc = parse_file(path, data, size, out, faces, index_base, err, err_len);
    free(data);
    return rc;
}

int mesh_file_read(const char *path, sfa_mesh_data *out, int *index_base, char *err, size_t err_len)
{
    return read_file(path, out, NULL, index_base, err, err_len);
}

int mesh_file_read_faces(const char *path, sfa_mesh_data *out, mesh_faces *faces, int *index_base, char *err,
                         size_t err_len)
{
    return read_file(path, out, faces, index_base, err, err_len);
}

void mesh_faces_free(mesh_faces *faces)
{
    if (!faces)
        return;
    free(faces->first_triangle);
    memset(faces, 0, sizeof *faces);
}

/* The arrays' names go into XML attributes as they are, and ParaView keeps one array of a
 * name: both are checked here rather than written into a file it then misreads. */
static int arrays_ok(const char *path, const char *kind, const mesh_data_array *a, int n, int32_t tuples, char *err,
                     size_t err_len)
{
    for (int i = 0; i < n; ++i) {
        const char *name = a[i].name;
        if (!name || !*name || strpbrk(name, "\"<>&") || a[i].ncomp < 1 || (!a[i].values && tuples > 0) ||
            (a[i].type != MESH_ARRAY_FLOAT64 && a[i].type != MESH_ARRAY_INT32)) {
            snprintf(err, err_len, "%s: %s array %d ('%s'): needs a name without '\"', '<', '>' or '&', a type, "
                     "values and at least one component", path, kind, i, name ? name : "(null)");
            return -1;
        }
        for (const unsigned char *c = (const unsigned char *)name; *c; ++c)
            if (*c < 0x20) {
                snprintf(err, err_len, "%s: %s array %d: a control character in its name", path, kind, i);
                return -1;
            }
        for (int j = 0; j < i; ++j)
            if (strcmp(a[j].name, name) == 0) {
                snprintf(err, err_len, "%s: two %s arrays named '%s'", path, kind, name);
                return -1;
            }
    }
    return 0;
}

static int write_file(const char *path, mesh_format format, const sfa_mesh_data *m, const mesh_write_extras *x,
                      char *err, size_t err_len)
{
    /* Binary formats need "wb" only where it matters; it is the same on POSIX. */
    FILE *f = fopen(path, "wb");
    if (!f) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        return -1;
    }
    switch (format) {
    case MESH_FORMAT_OBJ: obj_write(f, m, x); break;
    case MESH_FORMAT_OFF: off_write(f, m, x); break;
    case MESH_FORMAT_STL: stl_write(f, m, x); break;
    case MESH_FORMAT_PLY: ply_write(f, m, x); break;
    case MESH_FORMAT_MEDIT: medit_write(f, m, x); break;
    case MESH_FORMAT_VTK: vtk_write(f, m, x); break;
    case MESH_FORMAT_VTU: vtu_write(f, m, x); break;
    case MESH_FORMAT_UNKNOWN: break;
    }
    const int failed = ferror(f);
    if (fclose(f) != 0 || failed) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno ? errno : EIO));
        return -1;
    }
    return 0;
}

int mesh_file_write(const char *path, const sfa_mesh_data *m, const char *title, const int32_t *rank, char *err,
                    size_t err_len)
{
    const mesh_format format = mesh_format_of(path);
    if (format == MESH_FORMAT_UNKNOWN) {
        snprintf(err, err_len, "%s: unknown mesh format: the extension must be one of %s", path ? path : "(null)",
                 mesh_format_extensions());
        return -1;
    }
    const mesh_data_array ranks = {"rank", MESH_ARRAY_INT32, 1, rank};
    const mesh_write_extras x = {title, rank ? &ranks : NULL, NULL, rank ? 1 : 0, 0};
    return write_file(path, format, m, &x, err, err_len);
}

int mesh_file_write_vtu(const char *path, const sfa_mesh_data *m, const char *title, const mesh_data_array *point_data,
                        int npoint_data, const mesh_data_array *cell_data, int ncell_data, char *err, size_t err_len)
{
    if (mesh_format_of(path) != MESH_FORMAT_VTU) {
        snprintf(err, err_len, "%s: point and cell data are written to .vtu files only", path ? path : "(null)");
        return -1;
    }
    if (npoint_data < 0 || ncell_data < 0 || (npoint_data > 0 && !point_data) || (ncell_data > 0 && !cell_data)) {
        snprintf(err, err_len, "%s: bad list of point or cell data arrays", path);
        return -1;
    }
    if (arrays_ok(path, "point data", point_data, npoint_data, m->nverts, err, err_len) != 0 ||
        arrays_ok(path, "cell data", cell_data, ncell_data, m->ntris, err, err_len) != 0)
        return -1;
    const mesh_write_extras x = {title, point_data, cell_data, npoint_data, ncell_data};
    return write_file(path, MESH_FORMAT_VTU, m, &x, err, err_len);
}
