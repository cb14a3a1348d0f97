/* SPDX-License-Identifier: BSD-3-Clause */
/* STL, ASCII and binary. An STL file lists every triangle with its own three corners;
 * corners with bitwise-equal coordinates are made one vertex, since nothing else in the
 * file says which corners are shared (and a tolerance would join what the author kept
 * apart). Vertices are numbered in the order of first appearance. */
#include "format_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Open addressing from a corner's coordinates to its vertex: slots hold vertex + 1. */
typedef struct {
    int32_t *slot;
    uint64_t mask;
} corner_map;

static uint64_t hash_point(const double p[3])
{
    uint64_t bits[3], h = 0x9e3779b97f4a7c15u;
    memcpy(bits, p, sizeof bits);
    for (int k = 0; k < 3; ++k) {
        h ^= bits[k] + 0x9e3779b97f4a7c15u + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdu;
    }
    return h ^ (h >> 33);
}

static int map_grow(corner_map *m, const mesh_builder *b)
{
    const uint64_t size = m->slot ? 2 * (m->mask + 1) : 4096;
    if (size > (uint64_t)SIZE_MAX / sizeof(int32_t))
        return -1;
    int32_t *slot = calloc((size_t)size, sizeof(int32_t));
    if (!slot)
        return -1;
    free(m->slot);
    m->slot = slot;
    m->mask = size - 1;
    for (int64_t v = 0; v < b->nverts; ++v) {
        uint64_t i = hash_point(b->xyz + 3 * v) & m->mask;
        while (m->slot[i])
            i = (i + 1) & m->mask;
        m->slot[i] = (int32_t)(v + 1);
    }
    return 0;
}

/* The vertex at p, added if no earlier corner had exactly these coordinates; -1 if memory
 * or the int32_t count runs out. */
static int32_t corner_vertex(corner_map *m, mesh_builder *b, const double p[3])
{
    if (!m->slot || (uint64_t)b->nverts + 1 > (m->mask + 1) / 2)
        if (map_grow(m, b) != 0)
            return -1;
    uint64_t i = hash_point(p) & m->mask;
    /* The table is at most half full, so the probe ends. */
    while (m->slot[i]) {
        if (memcmp(b->xyz + 3 * (int64_t)(m->slot[i] - 1), p, 3 * sizeof(double)) == 0)
            return m->slot[i] - 1;
        i = (i + 1) & m->mask;
    }
    if (builder_add_vertex(b, p) != 0)
        return -1;
    m->slot[i] = (int32_t)b->nverts;
    return (int32_t)(b->nverts - 1);
}

static int stl_binary(const unsigned char *data, uint32_t n, mesh_builder *b, read_context *c)
{
    corner_map map = {NULL, 0};
    int rc = 0;
    for (uint32_t t = 0; t < n && rc == 0; ++t) {
        const unsigned char *facet = data + 84 + 50 * (size_t)t;
        c->offset = 84 + 50 * (long long)t;
        int32_t corner[3];
        for (int k = 0; k < 3 && rc == 0; ++k) {
            const double p[3] = {load_f32(facet + 12 + 12 * k, 0), load_f32(facet + 16 + 12 * k, 0),
                                 load_f32(facet + 20 + 12 * k, 0)};
            corner[k] = corner_vertex(&map, b, p);
            if (corner[k] < 0)
                rc = read_fail(c, "triangle %u: too many vertices or out of memory", t);
        }
        if (rc == 0 && builder_add_triangle(b, corner[0], corner[1], corner[2]) != 0)
            rc = read_fail(c, "triangle %u: too many triangles or out of memory", t);
    }
    free(map.slot);
    return rc;
}

/* Reads the expected keyword, or fails naming it and what was there instead. */
static int expect(const char **p, read_context *c, const char *keyword)
{
    char word[32];
    if (text_word(p, c, 0, word, sizeof word) != 0)
        return read_fail(c, "expected '%s', found the end of the file", keyword);
    if (!same_word(word, keyword))
        return read_fail(c, "expected '%s', found '%s'", keyword, word);
    return 0;
}

/* One facet after its "facet" keyword: "normal n n n outer loop (vertex x y z)... endloop
 * endfacet". More than three vertices make a polygon, fan-triangulated. */
static int ascii_facet(const char **p, corner_map *map, mesh_builder *b, read_context *c)
{
    double normal;
    if (expect(p, c, "normal") != 0)
        return -1;
    for (int k = 0; k < 3; ++k)
        if (text_double(p, c, 0, &normal) != 0)
            return read_fail(c, "expected three numbers for the facet's normal");
    if (expect(p, c, "outer") != 0 || expect(p, c, "loop") != 0)
        return -1;
    int32_t first = 0, prev = 0;
    int corners = 0;
    char word[32];
    for (;;) {
        if (text_word(p, c, 0, word, sizeof word) != 0)
            return read_fail(c, "expected 'vertex' or 'endloop', found the end of the file");
        if (same_word(word, "endloop"))
            break;
        if (!same_word(word, "vertex"))
            return read_fail(c, "expected 'vertex' or 'endloop', found '%s'", word);
        double xyz[3];
        for (int k = 0; k < 3; ++k)
            if (text_double(p, c, 0, &xyz[k]) != 0)
                return read_fail(c, "expected three coordinates after 'vertex'");
        const int32_t v = corner_vertex(map, b, xyz);
        if (v < 0)
            return read_fail(c, "too many vertices or out of memory");
        if (corners >= 2 && builder_add_triangle(b, first, prev, v) != 0)
            return read_fail(c, "too many triangles or out of memory");
        if (corners == 0)
            first = v;
        prev = v;
        ++corners;
    }
    if (corners < 3)
        return read_fail(c, "a facet needs at least three vertices, this one has %d", corners);
    return expect(p, c, "endfacet");
}

/* One or more "solid NAME ... endsolid NAME"; a name runs to the end of its line. */
static int stl_ascii(const char *text, mesh_builder *b, read_context *c)
{
    corner_map map = {NULL, 0};
    const char *p = text;
    char word[32];
    int rc = 0, in_solid = 0, solids = 0;
    c->line = 1;
    while (rc == 0 && text_word(&p, c, 0, word, sizeof word) == 0) {
        if (!in_solid && same_word(word, "solid")) {
            p = text_line_end(p);
            in_solid = 1;
            ++solids;
        } else if (in_solid && same_word(word, "endsolid")) {
            p = text_line_end(p);
            in_solid = 0;
        } else if (in_solid && same_word(word, "facet"))
            rc = ascii_facet(&p, &map, b, c);
        else
            rc = read_fail(c, in_solid ? "expected 'facet' or 'endsolid', found '%s'"
                                       : "expected 'solid' (an ASCII STL file), found '%s'",
                           word);
    }
    if (rc == 0 && in_solid)
        rc = read_fail(c, "the file ends inside a solid (no 'endsolid')");
    if (rc == 0 && solids == 0)
        rc = read_fail(c, "an empty file is not an STL file");
    free(map.slot);
    return rc;
}

/* Binary when the size is exactly 84 + 50 n for the count n at byte 80: ASCII files start
 * with "solid", but so do the free-text headers of many binary ones. */
int stl_parse(char *data, size_t size, mesh_builder *b, read_context *c)
{
    if (size >= 84) {
        const uint32_t n = load_u32((const unsigned char *)data + 80, 0);
        if ((size - 84) % 50 == 0 && (size - 84) / 50 == n)
            return stl_binary((const unsigned char *)data, n, b, c);
    }
    if (memchr(data, '\0', size))
        return read_fail(c, "neither ASCII STL (it has NUL bytes) nor binary STL (its size is not 84 + 50 times the "
                            "triangle count at byte 80)");
    return stl_ascii(data, b, c);
}

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; ++k)
        p[k] = (unsigned char)(v >> (8 * k));
}

static void put_f32(unsigned char *p, double v)
{
    const float f = (float)v;
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    put_u32(p, bits);
}

/* Binary STL, little-endian as the format says: compact, and what every CAD and slicing
 * tool reads; coordinates are float32 there. The facet normals are computed (unit, or
 * zero for a degenerate triangle). */
void stl_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    unsigned char header[84];
    memset(header, ' ', 80);
    const char *title = x && x->title ? x->title : "binary STL written by surfadapt";
    /* A header starting with "solid" would make some readers take the file for ASCII. */
    const char *prefix = strncmp(title, "solid", 5) == 0 ? "STL " : "";
    char text[81];
    const int n = snprintf(text, sizeof text, "%s%s", prefix, title);
    memcpy(header, text, n < 0 ? 0 : (size_t)n < 80 ? (size_t)n : 80);
    put_u32(header + 80, (uint32_t)m->ntris);
    fwrite(header, 1, sizeof header, f);
    for (int32_t t = 0; t < m->ntris; ++t) {
        unsigned char facet[50] = {0};
        const double *a = m->xyz + 3 * m->tris[3 * t], *q = m->xyz + 3 * m->tris[3 * t + 1],
                     *r = m->xyz + 3 * m->tris[3 * t + 2];
        const double u[3] = {q[0] - a[0], q[1] - a[1], q[2] - a[2]}, w[3] = {r[0] - a[0], r[1] - a[1], r[2] - a[2]};
        double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        const double len = sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        for (int k = 0; k < 3; ++k) {
            put_f32(facet + 4 * k, len > 0 ? nrm[k] / len : 0);
            put_f32(facet + 12 + 4 * k, a[k]);
            put_f32(facet + 24 + 4 * k, q[k]);
            put_f32(facet + 36 + 4 * k, r[k]);
        }
        fwrite(facet, 1, sizeof facet, f);
    }
}
