/* SPDX-License-Identifier: BSD-3-Clause */
/* Mesh files of every format the command-line tool knows, chosen by the file name's
 * extension (any case) both ways: reading .obj .off .stl .ply .mesh .vtk .vtu, writing the
 * same. Readers only parse: whether the mesh is acceptable is for sfa_set_mesh() to say,
 * in the file's own numbering (mesh_file_read gives its index base for that). */
#ifndef SURFADAPT_APP_MESH_FORMATS_H
#define SURFADAPT_APP_MESH_FORMATS_H

#include "obj_io.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
    MESH_FORMAT_UNKNOWN = 0,
    MESH_FORMAT_OBJ,   /* Wavefront OBJ: v / f lines, 1-based */
    MESH_FORMAT_OFF,   /* Object File Format, 0-based */
    MESH_FORMAT_STL,   /* stereolithography, ASCII or binary; written binary (float32) */
    MESH_FORMAT_PLY,   /* Stanford PLY, ASCII or binary; written binary little-endian */
    MESH_FORMAT_MEDIT, /* INRIA Medit .mesh (MMG's), ASCII, 1-based */
    MESH_FORMAT_VTK,   /* legacy VTK POLYDATA, ASCII */
    MESH_FORMAT_VTU    /* VTK XML UnstructuredGrid; written binary appended raw */
} mesh_format;

/* The format named by the path's extension, or MESH_FORMAT_UNKNOWN. */
mesh_format mesh_format_of(const char *path);

/* The supported extensions, for messages: ".obj, .off, .stl, .ply, .mesh, .vtk, .vtu". */
const char *mesh_format_extensions(void);

/* The base of the vertex numbers a format's files use (OBJ and Medit 1, the others 0). */
int mesh_format_index_base(mesh_format format);

/* Reads `path` in the format of its extension into `out` (0-based triangles, malloc'ed);
 * `*index_base` (if not NULL) receives the file's own base. Returns 0, or -1 with `*out`
 * zeroed and a message in `err` naming the file and the line (text formats) or the byte
 * offset (binary data), or the supported extensions for an unknown one. */
int mesh_file_read(const char *path, sfa_mesh_data *out, int *index_base, char *err, size_t err_len);

/* The faces of a file as it has them, for `surfadapt repair`, which triangulates polygons
 * itself: face f became triangles first_triangle[f] up to first_triangle[f + 1] (or the
 * last triangle) of the mesh read, fanned from its first corner, so its corners are the
 * first triangle's three and the third of each further one. Formats of triangles only
 * (STL) give one face per triangle. */
typedef struct {
    int32_t nfaces;
    int32_t *first_triangle;
} mesh_faces;

/* mesh_file_read, and the faces (`faces` zeroed on failure); free them with mesh_faces_free. */
int mesh_file_read_faces(const char *path, sfa_mesh_data *out, mesh_faces *faces, int *index_base, char *err,
                         size_t err_len);
void mesh_faces_free(mesh_faces *faces);

/* mesh_file_read for contents in memory: `data` has `size` bytes followed by a NUL (it may
 * be modified); `name` chooses the format and names it in messages. */
int mesh_file_parse(const char *name, char *data, size_t size, sfa_mesh_data *out, int *index_base, char *err,
                    size_t err_len);

/* Writes `m` (0-based) to `path` in the format of its extension, every coordinate to full
 * double precision where the format allows (binary STL holds float32). `title` (or NULL)
 * goes where the format has room for one line of text; `rank` (or NULL: nverts values)
 * is written as point data "rank" to .vtu and ignored by the other formats. Returns 0, or
 * -1 with a message in `err`. */
int mesh_file_write(const char *path, const sfa_mesh_data *m, const char *title, const int32_t *rank, char *err,
                    size_t err_len);

/* A named array of point data (one tuple per vertex) or cell data (one per triangle) for
 * .vtu files: `ncomp` values per tuple, `values[ncomp*i+c]`, of the given type. */
typedef enum { MESH_ARRAY_FLOAT64, MESH_ARRAY_INT32 } mesh_array_type;
typedef struct {
    const char *name; /* unique among the point (or cell) arrays; no '"', '<', '>', '&' */
    mesh_array_type type;
    int32_t ncomp;    /* >= 1 */
    const void *values; /* double or int32_t, ncomp*nverts (or ncomp*ntris) of them */
} mesh_data_array;

/* mesh_file_write to a .vtu with any number of point and cell data arrays (the format
 * that carries them; a path of another extension is an error). Returns 0, or -1 with a
 * message in `err` (a bad or repeated array name, ncomp < 1, or the system's reason). */
int mesh_file_write_vtu(const char *path, const sfa_mesh_data *m, const char *title, const mesh_data_array *point_data,
                        int npoint_data, const mesh_data_array *cell_data, int ncell_data, char *err, size_t err_len);

#ifdef __cplusplus
}
#endif

#endif
