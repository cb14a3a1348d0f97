/* SPDX-License-Identifier: BSD-3-Clause */
/* INRIA Medit .mesh, ASCII (what MMG reads and writes): "MeshVersionFormatted 1|2",
 * "Dimension 3", then sections of a keyword, a count and the entries, up to "End".
 * Vertices and Triangles make the mesh; Quadrilaterals are split into two triangles each
 * (a quad-dominant surface is still a surface to remesh, and skipping them would leave
 * holes); the other sections MMG writes (Edges, Corners, Ridges, Required*, Normals,
 * Tangents, volume elements ...) are read past. An unknown keyword is an error: its entries'
 * size is unknown, so reading on could only guess. Indices are 1-based in the file and
 * passed on as they are (0-based here): the library names a bad one in the file's numbers. */
#include "format_io.h"

#include <string.h>

typedef struct {
    const char *keyword;
    int integers, reals; /* per entry, skipped */
} skipped_section;

/* Entry sizes as libMeshb defines them for ASCII files (references included). */
static const skipped_section skipped[] = {
    {"Edges", 3, 0},           {"Corners", 1, 0},           {"Ridges", 1, 0},
    {"RequiredVertices", 1, 0}, {"RequiredEdges", 1, 0},     {"RequiredTriangles", 1, 0},
    {"RequiredQuadrilaterals", 1, 0}, {"Tetrahedra", 5, 0},  {"Prisms", 7, 0},
    {"Pyramids", 6, 0},        {"Hexahedra", 9, 0},         {"Normals", 0, 3},
    {"NormalAtVertices", 2, 0}, {"NormalAtTriangleVertices", 3, 0}, {"Tangents", 0, 3},
    {"TangentAtVertices", 2, 0}, {"TangentAtEdgeVertices", 3, 0},
};

/* A 1-based index from the file, 0-based; -1 if it is no integer or not an int32_t then. */
static int medit_index(const char **p, read_context *c, int32_t *index)
{
    long long v;
    if (text_long(p, c, '#', &v) != 0 || v <= INT32_MIN || v > INT32_MAX)
        return -1;
    *index = (int32_t)(v - 1);
    return 0;
}

static int read_elements(const char **p, read_context *c, long long count, int corners, mesh_builder *b)
{
    for (long long e = 0; e < count; ++e) {
        int32_t v[4];
        long long ref;
        for (int k = 0; k < corners; ++k)
            if (medit_index(p, c, &v[k]) != 0)
                return read_fail(c, "%s %lld: expected %d vertex numbers and a reference",
                                 corners == 3 ? "triangle" : "quadrilateral", e + 1, corners);
        if (text_long(p, c, '#', &ref) != 0)
            return read_fail(c, "%s %lld: expected a reference after the vertices",
                             corners == 3 ? "triangle" : "quadrilateral", e + 1);
        if (builder_begin_face(b) != 0 || builder_add_triangle(b, v[0], v[1], v[2]) != 0 ||
            (corners == 4 && builder_add_triangle(b, v[0], v[2], v[3]) != 0))
            return read_fail(c, "too many triangles or out of memory");
    }
    return 0;
}

int medit_parse(char *data, mesh_builder *b, read_context *c)
{
    const char *p = data;
    char word[64];
    long long version = 0, dimension = 0;
    c->line = 1;
    for (;;) {
        if (text_word(&p, c, '#', word, sizeof word) != 0)
            return read_fail(c, "the file ends without 'End'");
        if (same_word(word, "End"))
            break;
        if (same_word(word, "MeshVersionFormatted")) {
            if (text_long(&p, c, '#', &version) != 0 || version < 1 || version > 2)
                return read_fail(c, "MeshVersionFormatted must be 1 or 2");
            continue;
        }
        if (!version)
            return read_fail(c, "not a Medit mesh: expected 'MeshVersionFormatted', found '%s'", word);
        if (same_word(word, "Dimension")) {
            if (text_long(&p, c, '#', &dimension) != 0 || dimension != 3)
                return read_fail(c, "Dimension must be 3 (a surface in space)");
            continue;
        }
        if (dimension != 3)
            return read_fail(c, "expected 'Dimension 3' before '%s'", word);
        long long count;
        if (text_long(&p, c, '#', &count) != 0 || count < 0)
            return read_fail(c, "%s: expected a count", word);
        if (same_word(word, "Vertices")) {
            if (count > INT32_MAX - b->nverts)
                return read_fail(c, "too many vertices");
            for (long long v = 0; v < count; ++v) {
                double xyz[3];
                long long ref;
                for (int k = 0; k < 3; ++k)
                    if (text_double(&p, c, '#', &xyz[k]) != 0)
                        return read_fail(c, "vertex %lld: expected three coordinates and a reference",
                                         (long long)b->nverts + 1);
                if (text_long(&p, c, '#', &ref) != 0)
                    return read_fail(c, "vertex %lld: expected a reference after the coordinates", (long long)b->nverts + 1);
                if (builder_add_vertex(b, xyz) != 0)
                    return read_fail(c, "out of memory");
            }
        } else if (same_word(word, "Triangles") || same_word(word, "Quadrilaterals")) {
            if (read_elements(&p, c, count, same_word(word, "Triangles") ? 3 : 4, b) != 0)
                return -1;
        } else {
            const skipped_section *s = NULL;
            for (size_t i = 0; i < sizeof skipped / sizeof skipped[0] && !s; ++i)
                if (same_word(word, skipped[i].keyword))
                    s = &skipped[i];
            if (!s)
                return read_fail(c, "unknown keyword '%s'", word);
            /* Each value consumes a token or fails at the end, so the loops are bounded by
             * the text; a section of empty entries has nothing to read. */
            for (long long e = 0; e < count && s->integers + s->reals > 0; ++e) {
                for (int k = 0; k < s->integers; ++k) {
                    long long v;
                    if (text_long(&p, c, '#', &v) != 0)
                        return read_fail(c, "%s %lld: expected %d integers", s->keyword, e + 1, s->integers);
                }
                for (int k = 0; k < s->reals; ++k) {
                    double v;
                    if (text_double(&p, c, '#', &v) != 0)
                        return read_fail(c, "%s %lld: expected %d numbers", s->keyword, e + 1, s->reals);
                }
            }
        }
    }
    return 0;
}

/* Version 2: double precision, so coordinates are written in full (%.17g). */
void medit_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    if (x && x->title && !strpbrk(x->title, "\r\n"))
        fprintf(f, "# %s\n", x->title);
    fprintf(f, "MeshVersionFormatted 2\n\nDimension 3\n\nVertices\n%d\n", m->nverts);
    for (int32_t i = 0; i < m->nverts; ++i)
        fprintf(f, "%.17g %.17g %.17g 0\n", m->xyz[3 * i], m->xyz[3 * i + 1], m->xyz[3 * i + 2]);
    fprintf(f, "\nTriangles\n%d\n", m->ntris);
    for (int32_t t = 0; t < m->ntris; ++t)
        fprintf(f, "%d %d %d 0\n", m->tris[3 * t] + 1, m->tris[3 * t + 1] + 1, m->tris[3 * t + 2] + 1);
    fputs("\nEnd\n", f);
}
