/* SPDX-License-Identifier: BSD-3-Clause */
/* Reading triangle meshes from Wavefront OBJ and OFF files, for the command-line tool,
 * the tests and the benchmarks. Not part of the library: the reader only parses; whether
 * the mesh is acceptable is for sfa_set_mesh() to say, so nothing is dropped or checked. */
#ifndef SURFADAPT_APP_OBJ_IO_H
#define SURFADAPT_APP_OBJ_IO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A mesh as read: 3*nverts coordinates and 3*ntris 0-based vertex indices, malloc'ed. */
typedef struct sfa_mesh_data {
    int32_t nverts, ntris;
    double *xyz;
    int32_t *tris;
} sfa_mesh_data;

/* Reads `path`: OFF if the file starts with an OFF header (or is named *.off), OBJ
 * otherwise. OBJ: `v x y z` and `f a b c ...` lines (`a/t/n` and negative, relative
 * indices accepted); polygons are fan-triangulated, other lines ignored. Indices are
 * converted to 0-based and passed on as they are, even if past the last vertex; an OBJ
 * index 0, or a relative one before the first vertex, is an error naming its line.
 * (mesh_formats.h reads every format the tool knows, chosen by extension.)
 * Returns 0, or -1 with `*out` zeroed and a message in `err` (file and line). */
int mesh_read(const char *path, sfa_mesh_data *out, char *err, size_t err_len);

/* mesh_read for a file's contents already in memory: `text`, NUL-terminated, is parsed in
 * place (modified); `name` picks the format as the path does and names it in messages. */
int mesh_parse(const char *name, char *text, sfa_mesh_data *out, char *err, size_t err_len);

/* Writes `m` to `path` as OBJ: a `# comment` first line if `comment` is not NULL, `v` lines with every coordinate to full double precision
 * (%.17g: read back bit for bit), then 1-based `f` lines. Returns 0, or -1 with a message
 * in `err` (file and the system's reason). */
int mesh_write_obj(const char *path, const sfa_mesh_data *m, const char *comment, char *err, size_t err_len);

/* Frees the arrays of `m` and zeroes it; NULL and zeroed meshes are fine. */
void mesh_free(sfa_mesh_data *m);

#ifdef __cplusplus
}
#endif

#endif
