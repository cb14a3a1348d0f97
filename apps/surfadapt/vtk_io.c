/* SPDX-License-Identifier: BSD-3-Clause */
/* Legacy VTK, ASCII POLYDATA: what the tool writes (vtk_writer.cpp, vtk_write below) and
 * what ParaView saves as legacy. POINTS and POLYGONS make the mesh (polygons are
 * fan-triangulated), TRIANGLE_STRIPS are split into triangles, VERTICES and LINES (the
 * ridges the tool writes) are read past, and the point and cell data after them are not
 * read at all. Both cell layouts are read: "n size" with a count before each cell (files
 * of version < 5) and the OFFSETS / CONNECTIVITY arrays of version 5.1. */
#include "format_io.h"

#include <stdlib.h>
#include <string.h>

/* Adds cell `cell` of `section` with its n vertices v[]. */
static int add_cell(const char *section, long long cell, const long long *v, long long n, mesh_builder *b,
                    read_context *c)
{
    const int polygons = strcmp(section, "POLYGONS") == 0, strips = strcmp(section, "TRIANGLE_STRIPS") == 0;
    if (!polygons && !strips)
        return 0;
    if (n < 3)
        return read_fail(c, "%s cell %lld has %lld vertices, a surface cell needs at least three", section, cell, n);
    for (long long k = 0; k < n; ++k)
        if (v[k] < INT32_MIN || v[k] > INT32_MAX)
            return read_fail(c, "%s cell %lld: vertex index %lld out of range", section, cell, v[k]);
    if (polygons && builder_begin_face(b) != 0)
        return read_fail(c, "out of memory");
    for (long long k = 2; k < n; ++k) {
        if (!polygons && builder_begin_face(b) != 0) /* a strip's triangles are no fan */
            return read_fail(c, "out of memory");
        int32_t t[3] = {(int32_t)v[polygons ? 0 : k - 2], (int32_t)v[k - 1], (int32_t)v[k]};
        if (strips && k % 2 == 1) { /* every other triangle of a strip turns the other way */
            t[0] = (int32_t)v[k - 1];
            t[1] = (int32_t)v[k - 2];
        }
        if (builder_add_triangle(b, t[0], t[1], t[2]) != 0)
            return read_fail(c, "too many triangles or out of memory");
    }
    return 0;
}

/* "SECTION ncells size" and the cells with their counts (versions before 5). */
static int classic_cells(const char **p, read_context *c, const char *section, long long ncells, long long size,
                         mesh_builder *b)
{
    long long *v = NULL;
    long long cap = 0, used = 0;
    int rc = 0;
    for (long long cell = 0; cell < ncells && rc == 0; ++cell) {
        long long n;
        if (text_long(p, c, 0, &n) != 0 || n < 0 || n > size - used - 1 || n > (long long)strlen(*p))
            rc = read_fail(c, "%s cell %lld: expected its vertex count (within the section's size %lld)", section,
                           cell, size);
        if (rc == 0 && n > cap) {
            long long *grown = realloc(v, sizeof(long long) * (size_t)n);
            if (!grown)
                rc = read_fail(c, "out of memory");
            else {
                v = grown;
                cap = n;
            }
        }
        for (long long k = 0; k < n && rc == 0; ++k)
            if (text_long(p, c, 0, &v[k]) != 0)
                rc = read_fail(c, "%s cell %lld: expected %lld vertex indices", section, cell, n);
        if (rc == 0)
            rc = add_cell(section, cell, v, n, b, c);
        used += rc == 0 ? n + 1 : 0; /* n is not checked after a failure */
    }
    free(v);
    return rc;
}

/* Reads "NAME type" and then n integers into a new array (*out). */
static int int_array(const char **p, read_context *c, const char *name, long long n, long long **out)
{
    char word[64];
    if (text_word(p, c, 0, word, sizeof word) != 0 || strcmp(word, name) != 0)
        return read_fail(c, "expected '%s'", name);
    if (text_word(p, c, 0, word, sizeof word) != 0)
        return read_fail(c, "%s: expected a type", name);
    /* Every integer takes at least two characters: a larger count cannot be right, and is
     * not allocated. */
    if (n > (long long)strlen(*p) / 2 + 1)
        return read_fail(c, "%s: %lld integers, more than the rest of the file holds", name, n);
    *out = malloc(sizeof(long long) * (size_t)(n > 0 ? n : 1));
    if (!*out)
        return read_fail(c, "out of memory");
    for (long long i = 0; i < n; ++i)
        if (text_long(p, c, 0, &(*out)[i]) != 0)
            return read_fail(c, "%s: expected %lld integers", name, n);
    return 0;
}

/* Version 5.1: "SECTION noffsets nconnectivity", then OFFSETS and CONNECTIVITY arrays. */
static int offset_cells(const char **p, read_context *c, const char *section, long long noffsets, long long nconn,
                        mesh_builder *b)
{
    long long *offsets = NULL, *conn = NULL;
    int rc = int_array(p, c, "OFFSETS", noffsets, &offsets);
    if (rc == 0)
        rc = int_array(p, c, "CONNECTIVITY", nconn, &conn);
    for (long long cell = 0; cell + 1 < noffsets && rc == 0; ++cell) {
        const long long begin = offsets[cell], end = offsets[cell + 1];
        if (begin < 0 || end < begin || end > nconn)
            rc = read_fail(c, "%s cell %lld: offsets %lld to %lld outside the %lld connectivity entries", section,
                           cell, begin, end, nconn);
        else
            rc = add_cell(section, cell, conn + begin, end - begin, b, c);
    }
    free(offsets);
    free(conn);
    return rc;
}

int vtk_parse(char *data, mesh_builder *b, read_context *c)
{
    c->line = 1;
    if (strncmp(data, "# vtk DataFile", 14) != 0)
        return read_fail(c, "not a legacy VTK file (no '# vtk DataFile' line)");
    /* The first line and the title line are free text. */
    const char *p = text_line_end(data);
    if (*p)
        p = text_line_end(p + 1), ++c->line;
    char word[64];
    if (text_word(&p, c, 0, word, sizeof word) != 0 || strcmp(word, "ASCII") != 0)
        return read_fail(c, "only ASCII legacy VTK is read (write .vtu for binary)");
    if (text_word(&p, c, 0, word, sizeof word) != 0 || strcmp(word, "DATASET") != 0 ||
        text_word(&p, c, 0, word, sizeof word) != 0)
        return read_fail(c, "expected 'DATASET POLYDATA'");
    if (strcmp(word, "POLYDATA") != 0)
        return read_fail(c, "DATASET %s: only POLYDATA is read", word);
    int have_points = 0;
    while (text_word(&p, c, 0, word, sizeof word) == 0) {
        long long n, size;
        if (strcmp(word, "POINT_DATA") == 0 || strcmp(word, "CELL_DATA") == 0)
            break; /* the data of the points and cells: not needed */
        if (strcmp(word, "METADATA") == 0 || strcmp(word, "FIELD") == 0)
            return read_fail(c, "%s before the data sections is not read", word);
        if (strcmp(word, "POINTS") == 0) {
            if (have_points++)
                return read_fail(c, "POINTS twice");
            if (text_long(&p, c, 0, &n) != 0 || n < 0 || n > INT32_MAX ||
                text_word(&p, c, 0, word, sizeof word) != 0)
                return read_fail(c, "expected 'POINTS count type'");
            for (long long i = 0; i < n; ++i) {
                double xyz[3];
                for (int k = 0; k < 3; ++k)
                    if (text_double(&p, c, 0, &xyz[k]) != 0)
                        return read_fail(c, "point %lld: expected three coordinates", i);
                if (builder_add_vertex(b, xyz) != 0)
                    return read_fail(c, "out of memory");
            }
            continue;
        }
        if (strcmp(word, "VERTICES") != 0 && strcmp(word, "LINES") != 0 && strcmp(word, "POLYGONS") != 0 &&
            strcmp(word, "TRIANGLE_STRIPS") != 0)
            return read_fail(c, "unknown POLYDATA section '%s'", word);
        char section[16];
        strcpy(section, word);
        if (text_long(&p, c, 0, &n) != 0 || text_long(&p, c, 0, &size) != 0 || n < 0 || size < 0)
            return read_fail(c, "expected '%s count size'", section);
        /* Version 5.1 writes OFFSETS next; peek without consuming. */
        read_context peek = *c;
        const char *q = p;
        const int offsets = text_word(&q, &peek, 0, word, sizeof word) == 0 && strcmp(word, "OFFSETS") == 0;
        if ((offsets ? offset_cells(&p, c, section, n, size, b) : classic_cells(&p, c, section, n, size, b)) != 0)
            return -1;
    }
    return 0;
}

/* The mesh alone, for `convert` (remesh and features write vtk_writer.cpp's file with the
 * features instead). */
void vtk_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    char title[256];
    snprintf(title, sizeof title, "%s", x && x->title ? x->title : "surfadapt mesh");
    title[strcspn(title, "\r\n")] = '\0'; /* one line */
    fprintf(f, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET POLYDATA\nPOINTS %d double\n", title, m->nverts);
    for (int32_t i = 0; i < m->nverts; ++i)
        fprintf(f, "%.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
    fprintf(f, "POLYGONS %d %lld\n", m->ntris, 4LL * m->ntris);
    for (int32_t t = 0; t < m->ntris; ++t)
        fprintf(f, "3 %d %d %d\n", m->tris[3 * t], m->tris[3 * t + 1], m->tris[3 * t + 2]);
}
