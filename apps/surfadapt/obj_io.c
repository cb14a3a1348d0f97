/* SPDX-License-Identifier: BSD-3-Clause */
#include "obj_io.h"

#include "format_io.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *skip_blanks(const char *p)
{
    while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\f' || *p == '\v')
        ++p;
    return p;
}

static int parse_double(const char **p, double *v)
{
    char *end;
    const char *s = skip_blanks(*p);
    errno = 0;
    *v = strtod(s, &end);
    if (end == s)
        return -1;
    /* Overflow gives +-HUGE_VAL: kept, because judging coordinates is the library's job;
     * underflow to a denormal or zero is harmless. */
    *p = end;
    return 0;
}

static int parse_long(const char **p, long long *v)
{
    char *end;
    const char *s = skip_blanks(*p);
    errno = 0;
    *v = strtoll(s, &end, 10);
    if (end == s || errno == ERANGE)
        return -1;
    *p = end;
    return 0;
}

/* One OBJ face corner `a`, `a/t`, `a//n` or `a/t/n`: the position index, made 0-based
 * (negative indices count back from the last vertex read so far). An index that names no
 * vertex in OBJ's own numbering (0, or a relative one before the first vertex) is an
 * error here: passed on, the library could only name it in another numbering. A positive
 * index past the last vertex is passed on, for the library to name as the file does. */
static int obj_corner(const char **p, int64_t nverts, int64_t face, int32_t *index, read_context *c)
{
    long long a;
    if (parse_long(p, &a) != 0)
        return read_fail(c, "face %lld: bad vertex index", (long long)face);
    while (**p && !isspace((unsigned char)**p))
        ++*p; /* the texture and normal indices are not needed */
    if (a == 0)
        return read_fail(c, "index 0: OBJ indices start at 1");
    if (a < -nverts)
        return read_fail(c, "relative index %lld: only %lld vertices come before it", a, (long long)nverts);
    /* 1-based, the index must stay an int32_t: the tool passes the file's own numbers. */
    if (a > INT32_MAX)
        return read_fail(c, "index %lld: too large", a);
    *index = (int32_t)(a < 0 ? nverts + a : a - 1);
    return 0;
}

int obj_parse_text(char *text, mesh_builder *b, read_context *c)
{
    char *line = text;
    while (line) {
        char *next = strchr(line, '\n');
        if (next)
            *next++ = '\0';
        ++c->line;
        const char *p = skip_blanks(line);
        if (p[0] == 'v' && (p[1] == ' ' || p[1] == '\t')) {
            double v[3];
            ++p;
            for (int k = 0; k < 3; ++k)
                if (parse_double(&p, &v[k]) != 0)
                    return read_fail(c, "vertex %lld: expected three coordinates", (long long)b->nverts + 1);
            if (builder_add_vertex(b, v) != 0)
                return read_fail(c, "too many vertices or out of memory");
        } else if (p[0] == 'f' && (p[1] == ' ' || p[1] == '\t')) {
            int32_t first = 0, prev = 0, cur = 0;
            int corners = 0;
            ++p;
            if (builder_begin_face(b) != 0)
                return read_fail(c, "out of memory");
            for (;;) {
                p = skip_blanks(p);
                if (*p == '\0' || *p == '#')
                    break;
                if (obj_corner(&p, b->nverts, b->ntris + 1, &cur, c) != 0)
                    return -1;
                if (corners == 0)
                    first = cur;
                else if (corners >= 2 && builder_add_triangle(b, first, prev, cur) != 0)
                    return read_fail(c, "too many triangles or out of memory");
                prev = cur;
                ++corners;
            }
            if (corners < 3)
                return read_fail(c, "a face needs at least three vertices, this one has %d", corners);
        }
        line = next;
    }
    return 0;
}

/* The next token of an OFF file, skipping comments to the end of their line. */
static const char *off_token(const char *p, read_context *c)
{
    for (;;) {
        while (*p && isspace((unsigned char)*p)) {
            if (*p == '\n')
                ++c->line;
            ++p;
        }
        if (*p != '#')
            return p;
        while (*p && *p != '\n')
            ++p;
    }
}

int off_parse_text(char *text, mesh_builder *b, read_context *c)
{
    c->line = 1;
    const char *p = off_token(text, c);
    /* "OFF" and the variants with colours or normals, whose extra values per vertex are
     * skipped with the rest of the vertex's line. */
    if (strncmp(p, "NOFF", 4) == 0 || strncmp(p, "COFF", 4) == 0)
        p += 4;
    else if (strncmp(p, "OFF", 3) == 0)
        p += 3;
    else
        return read_fail(c, "not an OFF file (no OFF header)");
    long long nv, nf, ne;
    p = off_token(p, c);
    if (parse_long(&p, &nv) != 0 || (p = off_token(p, c), parse_long(&p, &nf)) != 0 ||
        (p = off_token(p, c), parse_long(&p, &ne)) != 0 || nv < 0 || nf < 0 || nv > INT32_MAX)
        return read_fail(c, "expected the counts of vertices, faces and edges");
    for (long long i = 0; i < nv; ++i) {
        double v[3];
        for (int k = 0; k < 3; ++k)
            if ((p = off_token(p, c), parse_double(&p, &v[k])) != 0)
                return read_fail(c, "vertex %lld: expected three coordinates", i);
        while (*p && *p != '\n')
            ++p;
        if (builder_add_vertex(b, v) != 0)
            return read_fail(c, "out of memory");
    }
    for (long long f = 0; f < nf; ++f) {
        long long n, idx[3];
        if ((p = off_token(p, c), parse_long(&p, &n)) != 0 || n < 3)
            return read_fail(c, "face %lld: expected a vertex count of at least 3", f);
        if (builder_begin_face(b) != 0)
            return read_fail(c, "out of memory");
        for (long long k = 0; k < n; ++k) {
            long long v;
            if ((p = off_token(p, c), parse_long(&p, &v)) != 0 || v < INT32_MIN || v > INT32_MAX)
                return read_fail(c, "face %lld: bad vertex index", f);
            if (k < 2)
                idx[k] = v;
            else {
                idx[2] = v;
                if (builder_add_triangle(b, (int32_t)idx[0], (int32_t)idx[1], (int32_t)idx[2]) != 0)
                    return read_fail(c, "too many triangles or out of memory");
                idx[1] = v;
            }
        }
        /* Per-face colours may follow on the same line: skip to its end. */
        while (*p && *p != '\n')
            ++p;
    }
    return 0;
}

static int is_off(const char *path, const char *text)
{
    const size_t n = strlen(path);
    if (n >= 4 && path[n - 4] == '.' && tolower((unsigned char)path[n - 3]) == 'o' &&
        tolower((unsigned char)path[n - 2]) == 'f' && tolower((unsigned char)path[n - 1]) == 'f')
        return 1;
    const char *p = text;
    while (*p && isspace((unsigned char)*p))
        ++p;
    return strncmp(p, "OFF", 3) == 0 || strncmp(p, "COFF", 4) == 0 || strncmp(p, "NOFF", 4) == 0;
}

/* Parses NUL-terminated `text` (modified in place) read from `path`. */
static int parse(const char *path, char *text, sfa_mesh_data *out, read_context *c)
{
    mesh_builder b = {0};
    const int rc = is_off(path, text) ? off_parse_text(text, &b, c) : obj_parse_text(text, &b, c);
    if (rc != 0) {
        builder_free(&b);
        return -1;
    }
    out->nverts = (int32_t)b.nverts;
    out->ntris = (int32_t)b.ntris;
    out->xyz = b.xyz;
    out->tris = b.tris;
    return 0;
}

int mesh_read(const char *path, sfa_mesh_data *out, char *err, size_t err_len)
{
    read_context c = {path ? path : "(null)", err, err_len, 0, -1};
    if (!path || !out) /* mesh_parse says which */
        return mesh_parse(path, NULL, out, err, err_len);
    size_t size;
    char *text = read_whole_file(path, &size, &c);
    if (!text) {
        memset(out, 0, sizeof *out);
        return -1;
    }
    const int rc = mesh_parse(path, text, out, err, err_len);
    free(text);
    return rc;
}

int mesh_parse(const char *name, char *text, sfa_mesh_data *out, char *err, size_t err_len)
{
    read_context c = {name ? name : "(null)", err, err_len, 0, -1};
    if (err && err_len)
        err[0] = '\0';
    if (!out)
        return read_fail(&c, "no output given");
    memset(out, 0, sizeof *out);
    if (!name || !text)
        return read_fail(&c, "no name or no text given");
    return parse(name, text, out, &c);
}

void obj_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    if (x && x->title)
        fprintf(f, "# %s\n", x->title);
    for (int32_t i = 0; i < m->nverts; ++i)
        fprintf(f, "v %.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
    for (int32_t i = 0; i < m->ntris; ++i)
        fprintf(f, "f %d %d %d\n", m->tris[3 * i] + 1, m->tris[3 * i + 1] + 1, m->tris[3 * i + 2] + 1);
}

/* OFF: counts, then the vertices and triangles, 0-based. The title goes in a comment
 * after the header line, where OFF readers allow one. */
void off_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    fputs("OFF\n", f);
    if (x && x->title)
        fprintf(f, "# %s\n", x->title);
    fprintf(f, "%d %d 0\n", m->nverts, m->ntris);
    for (int32_t i = 0; i < m->nverts; ++i)
        fprintf(f, "%.17g %.17g %.17g\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
    for (int32_t i = 0; i < m->ntris; ++i)
        fprintf(f, "3 %d %d %d\n", m->tris[3 * i], m->tris[3 * i + 1], m->tris[3 * i + 2]);
}

int mesh_write_obj(const char *path, const sfa_mesh_data *m, const char *comment, char *err, size_t err_len)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        return -1;
    }
    const mesh_write_extras x = {comment, NULL, NULL, 0, 0};
    obj_write(f, m, &x);
    const int failed = ferror(f);
    if (fclose(f) != 0 || failed) {
        snprintf(err, err_len, "%s: cannot write: %s", path, strerror(errno));
        return -1;
    }
    return 0;
}

void mesh_free(sfa_mesh_data *m)
{
    if (!m)
        return;
    free(m->xyz);
    free(m->tris);
    memset(m, 0, sizeof *m);
}
