/* SPDX-License-Identifier: BSD-3-Clause */
/* Stanford PLY: ASCII, binary_little_endian and binary_big_endian. From element "vertex"
 * the properties x, y, z (any numeric type) are read, from element "face" the list
 * "vertex_indices" (or "vertex_index", as some writers name it) of any integer types;
 * polygons are fan-triangulated. Every other property and element is read past. */
#include "format_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

enum { max_elements = 64, max_properties = 64 };

typedef enum { T_NONE = 0, T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 } ply_type;

typedef struct {
    ply_type type, count_type; /* count_type != T_NONE: a list */
    int role;                  /* 0 other, 1..3 x y z, 4 the vertex indices */
} ply_property;

typedef struct {
    char name[32];
    long long count;
    int nprops, is_vertex, is_face;
    ply_property prop[max_properties];
} ply_element;

typedef struct {
    int format; /* 0 ascii, 1 little-endian, 2 big-endian */
    int nelements;
    ply_element element[max_elements];
} ply_header;

static ply_type type_named(const char *name)
{
    static const struct {
        const char *name;
        ply_type type;
    } names[] = {{"char", T_I8},    {"int8", T_I8},    {"uchar", T_U8},   {"uint8", T_U8},     {"short", T_I16},
                 {"int16", T_I16},  {"ushort", T_U16}, {"uint16", T_U16}, {"int", T_I32},      {"int32", T_I32},
                 {"uint", T_U32},   {"uint32", T_U32}, {"float", T_F32},  {"float32", T_F32},  {"double", T_F64},
                 {"float64", T_F64}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; ++i)
        if (strcmp(name, names[i].name) == 0)
            return names[i].type;
    return T_NONE;
}

static size_t type_size(ply_type t)
{
    static const size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
    return sizes[t];
}

static int is_integer(ply_type t) { return t != T_F32 && t != T_F64 && t != T_NONE; }

/* The words of a header line (up to its newline), separated by blanks. */
static int header_words(const char *line, char words[][32], int max)
{
    int n = 0;
    while (*line && *line != '\n' && n < max) {
        while (*line == ' ' || *line == '\t' || *line == '\r')
            ++line;
        size_t len = 0;
        while (line[len] && line[len] != ' ' && line[len] != '\t' && line[len] != '\r' && line[len] != '\n')
            ++len;
        if (len == 0)
            break;
        const size_t kept = len < 31 ? len : 31;
        memcpy(words[n], line, kept);
        words[n][kept] = '\0';
        ++n;
        line += len;
    }
    return n;
}

/* Parses the header; returns the offset of the body, or 0 after read_fail. */
static size_t read_header(const char *data, size_t size, ply_header *h, read_context *c)
{
    const char *line = data;
    c->line = 0;
    for (;;) {
        if ((size_t)(line - data) >= size)
            return read_fail(c, "the header has no end_header line"), 0;
        const char *next = memchr(line, '\n', size - (size_t)(line - data));
        if (!next)
            return read_fail(c, "the header has no end_header line"), 0;
        ++c->line;
        char w[6][32];
        const int n = header_words(line, w, 6);
        line = next + 1;
        if (c->line == 1) {
            if (n != 1 || strcmp(w[0], "ply") != 0)
                return read_fail(c, "not a PLY file (the first line is not 'ply')"), 0;
            continue;
        }
        if (n == 0 || strcmp(w[0], "comment") == 0 || strcmp(w[0], "obj_info") == 0)
            continue;
        if (strcmp(w[0], "end_header") == 0)
            break;
        if (strcmp(w[0], "format") == 0) {
            if (n < 3 || strcmp(w[2], "1.0") != 0)
                return read_fail(c, "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'"), 0;
            if (strcmp(w[1], "ascii") == 0)
                h->format = 0;
            else if (strcmp(w[1], "binary_little_endian") == 0)
                h->format = 1;
            else if (strcmp(w[1], "binary_big_endian") == 0)
                h->format = 2;
            else
                return read_fail(c, "unknown PLY format '%s'", w[1]), 0;
        } else if (strcmp(w[0], "element") == 0) {
            char *end;
            if (n != 3)
                return read_fail(c, "expected 'element NAME COUNT'"), 0;
            if (h->nelements == max_elements)
                return read_fail(c, "more than %d elements", max_elements), 0;
            ply_element *e = &h->element[h->nelements++];
            memset(e, 0, sizeof *e);
            memcpy(e->name, w[1], sizeof e->name);
            e->count = strtoll(w[2], &end, 10);
            if (*end || e->count < 0 || e->count > INT32_MAX)
                return read_fail(c, "element %s: bad count '%s'", e->name, w[2]), 0;
            e->is_vertex = strcmp(e->name, "vertex") == 0;
            e->is_face = strcmp(e->name, "face") == 0;
        } else if (strcmp(w[0], "property") == 0) {
            if (h->nelements == 0)
                return read_fail(c, "a property before any element"), 0;
            ply_element *e = &h->element[h->nelements - 1];
            if (e->nprops == max_properties)
                return read_fail(c, "element %s: more than %d properties", e->name, max_properties), 0;
            ply_property *p = &e->prop[e->nprops];
            const char *name;
            if (n == 5 && strcmp(w[1], "list") == 0) {
                p->count_type = type_named(w[2]);
                p->type = type_named(w[3]);
                name = w[4];
                if (!is_integer(p->count_type) || p->type == T_NONE)
                    return read_fail(c, "bad list types '%s %s'", w[2], w[3]), 0;
                if (e->is_face && (strcmp(name, "vertex_indices") == 0 || strcmp(name, "vertex_index") == 0)) {
                    if (!is_integer(p->type))
                        return read_fail(c, "vertex indices of type '%s': they must be integers", w[3]), 0;
                    p->role = 4;
                }
            } else if (n == 3) {
                p->count_type = T_NONE;
                p->type = type_named(w[1]);
                name = w[2];
                if (p->type == T_NONE)
                    return read_fail(c, "unknown property type '%s'", w[1]), 0;
                if (e->is_vertex && name[0] >= 'x' && name[0] <= 'z' && name[1] == '\0')
                    p->role = 1 + name[0] - 'x';
            } else
                return read_fail(c, "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'"), 0;
            for (int k = 0; k < e->nprops; ++k)
                if (p->role && e->prop[k].role == p->role)
                    return read_fail(c, "element %s: property '%s' twice", e->name, name), 0;
            ++e->nprops;
        } else
            return read_fail(c, "unknown header line '%s'", w[0]), 0;
    }
    for (int i = 0; i < h->nelements; ++i) {
        const ply_element *e = &h->element[i];
        if (e->is_vertex) {
            int roles = 0;
            for (int k = 0; k < e->nprops; ++k)
                roles |= e->prop[k].role >= 1 && e->prop[k].role <= 3 ? 1 << e->prop[k].role : 0;
            if (roles != 14)
                return read_fail(c, "element vertex needs the properties x, y and z"), 0;
        }
    }
    return (size_t)(line - data);
}

/* Reading values one after the other, from text or binary data. */
typedef struct {
    const char *text; /* ASCII: the current place */
    const unsigned char *data;
    size_t pos, size;
    int big_endian, binary;
    read_context *c;
} ply_reader;

/* One value of type t; integers are exact in a double. 0, or -1 at the end of the data or
 * on a token that is no number. */
static int read_value(ply_reader *r, ply_type t, double *v)
{
    if (!r->binary) {
        if (is_integer(t)) {
            long long i;
            if (text_long(&r->text, r->c, 0, &i) != 0)
                return -1;
            *v = (double)i;
            return 0;
        }
        return text_double(&r->text, r->c, 0, v);
    }
    const size_t n = type_size(t);
    if (r->size - r->pos < n)
        return -1;
    const unsigned char *p = r->data + r->pos;
    r->pos += n;
    switch (t) {
    case T_I8: *v = (signed char)p[0]; break;
    case T_U8: *v = p[0]; break;
    case T_I16: {
        const uint16_t u = (uint16_t)(r->big_endian ? (p[0] << 8 | p[1]) : (p[1] << 8 | p[0]));
        *v = (int16_t)u;
        break;
    }
    case T_U16: *v = r->big_endian ? (p[0] << 8 | p[1]) : (p[1] << 8 | p[0]); break;
    case T_I32: *v = (int32_t)load_u32(p, r->big_endian); break;
    case T_U32: *v = load_u32(p, r->big_endian); break;
    case T_F32: *v = load_f32(p, r->big_endian); break;
    case T_F64: *v = load_f64(p, r->big_endian); break;
    case T_NONE: return -1;
    }
    return 0;
}

static int ended(ply_reader *r, const ply_element *e, long long i)
{
    if (r->binary)
        r->c->offset = (long long)r->pos;
    return read_fail(r->c, "element %s %lld: %s", e->name, i,
                     r->binary ? "the file ends inside it" : "expected a number");
}

static int read_element(ply_reader *r, const ply_element *e, mesh_builder *b)
{
    for (long long i = 0; i < e->count; ++i) {
        double xyz[3] = {0, 0, 0};
        if (r->binary)
            r->c->offset = (long long)r->pos;
        for (int k = 0; k < e->nprops; ++k) {
            const ply_property *p = &e->prop[k];
            double v;
            if (p->count_type == T_NONE) {
                if (read_value(r, p->type, &v) != 0)
                    return ended(r, e, i);
                if (p->role >= 1 && p->role <= 3)
                    xyz[p->role - 1] = v;
                continue;
            }
            double count;
            if (read_value(r, p->count_type, &count) != 0)
                return ended(r, e, i);
            if (count < 0)
                return read_fail(r->c, "element %s %lld: a list of %g values", e->name, i, count);
            if (p->role == 4 && count < 3)
                return read_fail(r->c, "face %lld: a face needs at least three vertices, this one has %g", i, count);
            int32_t first = 0, prev = 0;
            if (p->role == 4 && builder_begin_face(b) != 0)
                return read_fail(r->c, "out of memory");
            /* Every value read consumes data, so the loop ends with the data at the latest. */
            for (double j = 0; j < count; ++j) {
                if (read_value(r, p->type, &v) != 0)
                    return ended(r, e, i);
                if (p->role != 4)
                    continue;
                if (v < INT32_MIN || v > INT32_MAX)
                    return read_fail(r->c, "face %lld: vertex index %.0f out of range", i, v);
                const int32_t cur = (int32_t)v;
                if (j == 0)
                    first = cur;
                else if (j >= 2 && builder_add_triangle(b, first, prev, cur) != 0)
                    return read_fail(r->c, "too many triangles or out of memory");
                prev = cur;
            }
        }
        if (e->is_vertex && builder_add_vertex(b, xyz) != 0)
            return read_fail(r->c, "too many vertices or out of memory");
    }
    return 0;
}

int ply_parse(char *data, size_t size, mesh_builder *b, read_context *c)
{
    ply_header *h = calloc(1, sizeof *h);
    if (!h)
        return read_fail(c, "out of memory");
    const size_t body = read_header(data, size, h, c);
    int rc = body == 0 ? -1 : 0;
    ply_reader r = {data + body, (const unsigned char *)data, body, size, h->format == 2, h->format != 0, c};
    if (r.binary)
        c->line = 0;
    else
        ++c->line; /* the body starts on the line after end_header */
    for (int i = 0; rc == 0 && i < h->nelements; ++i)
        if (h->element[i].nprops > 0) /* an element without properties has no data */
            rc = read_element(&r, &h->element[i], b);
    free(h);
    return rc;
}

static void put_bytes(FILE *f, uint64_t bits, int n)
{
    unsigned char p[8];
    for (int k = 0; k < n; ++k)
        p[k] = (unsigned char)(bits >> (8 * k));
    fwrite(p, 1, (size_t)n, f);
}

/* Binary little-endian with double coordinates: exact, compact, and read by MeshLab,
 * ParaView, Blender and Open3D. */
void ply_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    fputs("ply\nformat binary_little_endian 1.0\n", f);
    if (x && x->title && !strpbrk(x->title, "\r\n"))
        fprintf(f, "comment %s\n", x->title);
    fprintf(f,
            "element vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
            "element face %d\nproperty list uchar int vertex_indices\nend_header\n",
            m->nverts, m->ntris);
    for (int64_t i = 0; i < 3 * (int64_t)m->nverts; ++i) {
        uint64_t bits;
        memcpy(&bits, &m->xyz[i], sizeof bits);
        put_bytes(f, bits, 8);
    }
    for (int32_t t = 0; t < m->ntris; ++t) {
        put_bytes(f, 3, 1);
        for (int k = 0; k < 3; ++k)
            put_bytes(f, (uint32_t)m->tris[3 * t + k], 4);
    }
}
