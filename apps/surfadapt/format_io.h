/* SPDX-License-Identifier: BSD-3-Clause */
/* What the mesh readers and writers of mesh_formats.c share: a growing mesh, errors that
 * name the file and the line (or byte), a tokenizer for the text formats, byte-order
 * helpers for the binary ones, and each format's entry points. Internal to the tool, its
 * tests and the fuzzer; mesh_formats.h is what callers use. */
#ifndef SURFADAPT_APP_FORMAT_IO_H
#define SURFADAPT_APP_FORMAT_IO_H

#include "mesh_formats.h"

#include <stdint.h>
#include <stdio.h>

/* Growing arrays for what is read: 0-based triangles. Counts stay within int32_t because
 * the library's counts are int32_t. */
typedef struct {
    double *xyz;
    int32_t *tris;
    int64_t nverts, ntris, vcap, tcap;
    /* Kept only when record_faces is set (for `surfadapt repair`, which triangulates
     * polygons itself): face f of the file became triangles face_first[f] up to the next
     * face's first, fanned from its first corner. */
    int record_faces;
    int32_t *face_first;
    int64_t nfaces, fcap;
} mesh_builder;

int builder_add_vertex(mesh_builder *b, const double p[3]);
int builder_add_triangle(mesh_builder *b, int32_t i, int32_t j, int32_t k);
/* A reader of polygons calls this before the triangles it fans a face into (from the
 * face's first corner); a reader that never calls it gives one face per triangle. */
int builder_begin_face(mesh_builder *b);
void builder_free(mesh_builder *b);

/* Where a reader is, for its messages: "path:line: " while `line` > 0, else
 * "path: byte N: " while `offset` >= 0 (binary data), else "path: ". */
typedef struct {
    const char *path;
    char *err;
    size_t err_len;
    long line;
    long long offset;
} read_context;

/* Writes the message (printf-style) after the place; returns -1. */
int read_fail(const read_context *c, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The whole file, with a NUL after its `size` bytes (malloc'ed); NULL after read_fail. */
char *read_whole_file(const char *path, size_t *size, const read_context *c);

/* Text formats: the text is NUL-terminated. Tokens are separated by white space; `comment`
 * (e.g. '#') starts a comment to the end of the line, 0 for none. Newlines passed over are
 * counted in c->line. */
const char *text_skip(const char *p, read_context *c, char comment);
/* The next token as a number; 0, or -1 if it is not one (p is left on it). */
int text_double(const char **p, read_context *c, char comment, double *v);
int text_long(const char **p, read_context *c, char comment, long long *v);
/* Copies the next token (at most n - 1 characters) to `word`; 0, or -1 at the end. */
int text_word(const char **p, read_context *c, char comment, char *word, size_t n);
/* Moves p to the next line (not counted: the newline is left for text_skip). */
const char *text_line_end(const char *p);
/* ASCII case-insensitive equality of two NUL-terminated strings. */
int same_word(const char *a, const char *b);

/* Unaligned little- and big-endian loads from binary data. */
uint32_t load_u32(const unsigned char *p, int big_endian);
uint64_t load_u64(const unsigned char *p, int big_endian);
double load_f64(const unsigned char *p, int big_endian);
float load_f32(const unsigned char *p, int big_endian);

/* The readers: `data` holds `size` bytes and one NUL after them (text readers may modify
 * it). They fill `b` and return 0, or -1 after read_fail. */
int obj_parse_text(char *data, mesh_builder *b, read_context *c);
int off_parse_text(char *data, mesh_builder *b, read_context *c);
int stl_parse(char *data, size_t size, mesh_builder *b, read_context *c);
int ply_parse(char *data, size_t size, mesh_builder *b, read_context *c);
int medit_parse(char *data, mesh_builder *b, read_context *c);
int vtk_parse(char *data, mesh_builder *b, read_context *c);
int vtu_parse(char *data, size_t size, mesh_builder *b, read_context *c);

/* What a writer may add to the mesh: a title or comment line (NULL for none) and, for
 * .vtu, named point and cell data arrays (mesh_formats.h; checked by the caller). */
typedef struct {
    const char *title;
    const mesh_data_array *point_data, *cell_data;
    int npoint_data, ncell_data;
} mesh_write_extras;

/* The writers: `m` to the open file `f`; errors of the stream are the caller's to check. */
void obj_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void off_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void stl_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void ply_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void medit_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void vtk_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);
void vtu_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x);

#endif
