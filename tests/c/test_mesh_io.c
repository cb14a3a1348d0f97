/* SPDX-License-Identifier: BSD-3-Clause */
/* The mesh readers and writers of the command-line tool, tests and benchmarks (obj_io.h,
 * mesh_formats.h): they must hand the library exactly what the file says, 0-based, without
 * judging it, and write what reads back the same. */
#define _XOPEN_SOURCE 700 /* mkstemp, close, unlink, P_tmpdir */

#include "support/testing.h"

#include "mesh_formats.h"

#include <unistd.h>

/* Writes `text` to a new temporary file; its name goes to `path`. */
static void write_temp(const char *text, const char *suffix, char *path, size_t len)
{
    const char *dir = getenv("TMPDIR");
    char templ[512];
    snprintf(templ, sizeof templ, "%s/surfadapt-mesh-XXXXXX", dir && *dir ? dir : P_tmpdir);
    const int fd = mkstemp(templ);
    assert_true(fd >= 0);
    close(fd);
    snprintf(path, len, "%s%s", templ, suffix);
    if (suffix[0])
        assert_int_equal(rename(templ, path), 0);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
}

/* Reads `text` as a file with the given suffix; returns mesh_read's status. */
static int read_text(const char *text, const char *suffix, sfa_mesh_data *m, char *err, size_t err_len)
{
    char path[600];
    write_temp(text, suffix, path, sizeof path);
    const int rc = mesh_read(path, m, err, err_len);
    unlink(path);
    return rc;
}

static void assert_triangles(const sfa_mesh_data *m, const int32_t *expected, int32_t ntris)
{
    assert_int_equal(m->ntris, ntris);
    for (int32_t i = 0; i < 3 * ntris; ++i)
        if (m->tris[i] != expected[i])
            fail_msg("corner %d of triangle %d: %d, expected %d", (int)(i % 3), (int)(i / 3), (int)m->tris[i],
                     (int)expected[i]);
}

static void obj_plain(void **state)
{
    (void)state;
    const char *text = "# a comment\n"
                       "o cube\n"
                       "v 0 0 0\n"
                       "v 1.5 0 0\n"
                       "v 0 -2.25 0\n"
                       "v 0 0 1e-3 1.0\n" /* optional w */
                       "vn 0 0 1\n"
                       "vt 0.5 0.5\n"
                       "s off\n"
                       "usemtl red\n"
                       "f 1 2 3\n"
                       "g side\n"
                       "f 1 3 4 # trailing comment\n";
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text(text, ".obj", &m, err, sizeof err), 0);
    assert_int_equal(m.nverts, 4);
    const double xyz[12] = {0, 0, 0, 1.5, 0, 0, 0, -2.25, 0, 0, 0, 1e-3};
    assert_memory_equal(m.xyz, xyz, sizeof xyz);
    const int32_t tris[6] = {0, 1, 2, 0, 2, 3};
    assert_triangles(&m, tris, 2);
    mesh_free(&m);
}

static void obj_corner_forms_and_negative_indices(void **state)
{
    (void)state;
    const char *text = "v 0 0 0\r\n"
                       "v 1 0 0\r\n"
                       "v 1 1 0\r\n"
                       "v 0 1 0\r\n"
                       "f 1/1/1 2/2/2 3/3/3\r\n"
                       "f 1//4 3//4 4//4\r\n"
                       "f 1/7 2/8 4/9\r\n"
                       "f -4 -3 -1\r\n"  /* relative: 1 2 4 */
                       "v 5 5 5\r\n"
                       "f -1 -5/2/3 -2\r\n"; /* 5 1 4 */
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text(text, ".obj", &m, err, sizeof err), 0);
    assert_int_equal(m.nverts, 5);
    assert_true(m.xyz[3 * 4] == 5 && m.xyz[3 * 4 + 2] == 5);
    const int32_t tris[15] = {0, 1, 2, 0, 2, 3, 0, 1, 3, 0, 1, 3, 4, 0, 3};
    assert_triangles(&m, tris, 5);
    mesh_free(&m);
}

static void obj_polygons_are_fanned(void **state)
{
    (void)state;
    const char *text = "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\n"
                       "f 1 2 3 4\n"
                       "f 1 2 3 4 5\n";
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text(text, ".obj", &m, err, sizeof err), 0);
    const int32_t tris[15] = {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3, 0, 3, 4};
    assert_triangles(&m, tris, 5);
    mesh_free(&m);
}

static void obj_bad_indices_passed_on(void **state)
{
    (void)state;
    /* Out of range and repeated indices are for the library to judge ... */
    const char *text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                       "f 1 2 99\n"
                       "f 3 1 1\n";
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text(text, ".obj", &m, err, sizeof err), 0);
    const int32_t tris[6] = {0, 1, 98, 2, 0, 0};
    assert_triangles(&m, tris, 2);
    /* ... and the library names the first problem, in OBJ's numbers when given them. */
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    assert_error(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0), SFA_ERR_MESH, "triangle 0", "vertex 98");
    for (int i = 0; i < 3 * m.ntris; ++i)
        ++m.tris[i];
    assert_error(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 1), SFA_ERR_MESH, "triangle 1", "vertex 99");
    sfa_destroy(s);
    mesh_free(&m);
}

/* Indices that name no vertex in OBJ's own numbering cannot be passed on in it: an error
 * naming the line. */
static void obj_index_zero_and_before_the_first(void **state)
{
    (void)state;
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", ".obj", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, ":4: index 0: OBJ indices start at 1"));
    assert_null(m.tris);
    assert_int_equal(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf -7 1 2\n", ".obj", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, ":5: relative index -7"));
    assert_int_equal(read_text("v 0 0 0\nf 1 1 2147483648\n", ".obj", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, ":2:"));
}

static void obj_errors(void **state)
{
    (void)state;
    sfa_mesh_data m = {7, 7, NULL, NULL};
    char err[256];
    assert_int_equal(read_text("v 1 2\n", ".obj", &m, err, sizeof err), -1);
    assert_int_equal(m.nverts, 0);
    assert_null(m.xyz);
    assert_non_null(strstr(err, ":1:"));
    assert_int_equal(read_text("v 0 0 0\nv 1 0 0\nf 1 2\n", ".obj", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, ":3:"));
    assert_int_equal(read_text("v 0 0 0\nf 1 x 2\n", ".obj", &m, err, sizeof err), -1);
    assert_int_equal(read_text("v 0 0 0\nf 1 2 99999999999\n", ".obj", &m, err, sizeof err), -1);
    assert_int_equal(mesh_read("no/such/file.obj", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "no/such/file.obj"));
    /* A tiny error buffer is respected, and none at all is fine. */
    char tiny[4] = "abc";
    assert_int_equal(mesh_read("no/such/file.obj", &m, tiny, sizeof tiny), -1);
    assert_int_equal(tiny[3], '\0');
    assert_int_equal(mesh_read("no/such/file.obj", &m, NULL, 0), -1);
}

static void obj_empty_file(void **state)
{
    (void)state;
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(read_text("# nothing\n", ".obj", &m, err, sizeof err), 0);
    assert_int_equal(m.nverts, 0);
    assert_int_equal(m.ntris, 0);
    mesh_free(&m);
}

static void off_files(void **state)
{
    (void)state;
    const char *text = "OFF\n"
                       "# a square and a triangle\n"
                       "5 2 0\n"
                       "0 0 0\n"
                       "1 0 0\n"
                       "1 1 0 # comment\n"
                       "0 1 0\n"
                       "2 2 2\n"
                       "4 0 1 2 3 255 0 0\n"
                       "3 1 4 2\n";
    sfa_mesh_data m;
    char err[256];
    /* Recognised by its header whatever the name, and by its name. */
    const char *suffixes[2] = {"", ".off"};
    for (int i = 0; i < 2; ++i) {
        assert_int_equal(read_text(text, suffixes[i], &m, err, sizeof err), 0);
        assert_int_equal(m.nverts, 5);
        const double last[3] = {2, 2, 2};
        assert_memory_equal(m.xyz + 12, last, sizeof last);
        const int32_t tris[9] = {0, 1, 2, 0, 2, 3, 1, 4, 2};
        assert_triangles(&m, tris, 3);
        mesh_free(&m);
    }
    assert_int_equal(read_text("OFF\n3 1 0\n0 0 0\n1 0 0\n", ".off", &m, err, sizeof err), -1);
    assert_int_equal(read_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", ".off", &m, err, sizeof err), -1);
    assert_int_equal(read_text("PLY\n", ".off", &m, err, sizeof err), -1);
}

/* Writes m as `suffix`, reads it back. */
static sfa_mesh_data round_trip(const sfa_mesh_data *m, const char *suffix, int *base)
{
    char path[600], err[512];
    write_temp("", suffix, path, sizeof path);
    if (mesh_file_write(path, m, "a jittered sphere", NULL, err, sizeof err) != 0)
        fail_msg("writing %s: %s", suffix, err);
    sfa_mesh_data back;
    const int rc = mesh_file_read(path, &back, base, err, sizeof err);
    unlink(path);
    if (rc != 0)
        fail_msg("reading %s back: %s", suffix, err);
    return back;
}

/* Every format reads back what was written, bit for bit (STL: as float32), in the
 * vertex order written; STL numbers vertices in order of first appearance instead. */
static void every_format_round_trips(void **state)
{
    (void)state;
    sfa_mesh_data m = shape_jittered_icosphere(2, 1.0, 0.25, 3);
    const char *exact[] = {".obj", ".OFF", ".ply", ".mesh", ".vtk", ".Vtu"};
    const int bases[] = {1, 0, 0, 1, 0, 0};
    for (int i = 0; i < 6; ++i) {
        int base = -1;
        sfa_mesh_data back = round_trip(&m, exact[i], &base);
        assert_int_equal(base, bases[i]);
        assert_int_equal(back.nverts, m.nverts);
        assert_memory_equal(back.xyz, m.xyz, sizeof(double) * 3 * (size_t)m.nverts);
        assert_triangles(&back, m.tris, m.ntris);
        mesh_free(&back);
    }
    sfa_mesh_data back = round_trip(&m, ".stl", NULL);
    assert_int_equal(back.nverts, m.nverts);
    assert_int_equal(back.ntris, m.ntris);
    for (int32_t t = 0; t < m.ntris; ++t)
        for (int k = 0; k < 3; ++k)
            for (int d = 0; d < 3; ++d)
                assert_true(back.xyz[3 * back.tris[3 * t + k] + d] == (float)m.xyz[3 * m.tris[3 * t + k] + d]);
    mesh_free(&back);
    mesh_free(&m);
}

static void formats_by_extension(void **state)
{
    (void)state;
    assert_int_equal(mesh_format_of("a/b.c/mesh.STL"), MESH_FORMAT_STL);
    assert_int_equal(mesh_format_of("x.mesh"), MESH_FORMAT_MEDIT);
    assert_int_equal(mesh_format_of("x.meshb"), MESH_FORMAT_UNKNOWN);
    assert_int_equal(mesh_format_of("dir.obj/file"), MESH_FORMAT_UNKNOWN);
    assert_int_equal(mesh_format_of("obj"), MESH_FORMAT_UNKNOWN);
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(mesh_file_read("x.stp", &m, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "x.stp: unknown mesh format"));
    assert_non_null(strstr(err, ".obj, .off, .stl, .ply, .mesh, .vtk, .vtu"));
    assert_int_equal(mesh_file_read("no/such/file.ply", &m, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, "no/such/file.ply"));
    const sfa_mesh_data cube = shape_unit_cube();
    assert_int_equal(mesh_file_write("x.step", &cube, NULL, NULL, err, sizeof err), -1);
    assert_non_null(strstr(err, ".vtu"));
    sfa_mesh_data c = cube;
    mesh_free(&c);
}

/* Parses `text` as a file named `name`: 0 or -1 as mesh_file_parse. */
static int parse_text(const char *name, const char *text, sfa_mesh_data *m, char *err, size_t err_len)
{
    const size_t n = strlen(text);
    char *copy = malloc(n + 1);
    memcpy(copy, text, n + 1);
    const int rc = mesh_file_parse(name, copy, n, m, NULL, err, err_len);
    free(copy);
    return rc;
}

static void ply_binary_big_endian(void **state)
{
    (void)state;
    /* float coordinates, a short to skip, char counts and uint indices named vertex_index. */
    static const char header[] = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\n"
                                 "property float y\nproperty float z\nproperty short s\nelement face 1\n"
                                 "property list char uint vertex_index\nend_header\n";
    unsigned char data[sizeof header - 1 + 3 * 14 + 13 + 1] = {0};
    memcpy(data, header, sizeof header - 1);
    unsigned char *p = data + sizeof header - 1;
    p[4 + 14] = 0x3f, p[5 + 14] = 0x80;   /* vertex 1: y = 1.0f */
    p[8 + 28] = 0xc0;                     /* vertex 2: z = -2.0f */
    p[42] = 3, p[42 + 8] = 1, p[42 + 12] = 2; /* face 0 1 2 */
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(mesh_file_parse("t.ply", (char *)data, sizeof data - 1, &m, NULL, err, sizeof err), 0);
    assert_int_equal(m.nverts, 3);
    const double xyz[9] = {0, 0, 0, 0, 1, 0, 0, 0, -2};
    assert_memory_equal(m.xyz, xyz, sizeof xyz);
    const int32_t tris[3] = {0, 1, 2};
    assert_triangles(&m, tris, 1);
    mesh_free(&m);
    /* Cut short: the byte where it ends. */
    assert_int_equal(mesh_file_parse("t.ply", (char *)data, sizeof data - 3, &m, NULL, err, sizeof err), -1);
    if (!strstr(err, "t.ply: byte "))
        fail_msg("%s", err);
}

static void text_formats_name_lines(void **state)
{
    (void)state;
    sfa_mesh_data m;
    char err[256];
    assert_int_equal(parse_text("a.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                         "vertex 0 1 0\nendloop\nendfacet\nendsolid\n",
                                &m, err, sizeof err),
                     0);
    assert_int_equal(m.nverts, 3);
    mesh_free(&m);
    assert_int_equal(parse_text("a.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                                         "endloop\nendfacet\nendsolid\n",
                                &m, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "a.stl:6: a facet needs at least three vertices"));
    assert_int_equal(parse_text("a.mesh", "MeshVersionFormatted 2\nDimension 3\nVertices 1\n0 0 0 0\nFoo 1\nEnd\n",
                                &m, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "a.mesh:5: unknown keyword 'Foo'"));
    assert_int_equal(parse_text("a.mesh", "MeshVersionFormatted 2\nDimension 2\n", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "a.mesh:2: Dimension must be 3"));
    assert_int_equal(parse_text("a.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n",
                                &m, err, sizeof err),
                     -1);
    assert_non_null(strstr(err, "needs the properties x, y and z"));
    assert_int_equal(parse_text("a.vtk", "# vtk DataFile Version 3.0\nt\nBINARY\n", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "a.vtk:3: only ASCII"));
    assert_int_equal(parse_text("a.vtu", "<VTKFile type=\"PolyData\">\n", &m, err, sizeof err), -1);
    assert_non_null(strstr(err, "a.vtu:1: only VTKFile type"));
}

static void free_is_safe(void **state)
{
    (void)state;
    sfa_mesh_data zero = {0, 0, NULL, NULL};
    mesh_free(&zero);
    mesh_free(NULL);
    sfa_mesh_data cube = shape_unit_cube();
    mesh_free(&cube);
    assert_null(cube.xyz);
    assert_null(cube.tris);
    assert_int_equal(cube.nverts, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(obj_plain),
        cmocka_unit_test(obj_corner_forms_and_negative_indices),
        cmocka_unit_test(obj_polygons_are_fanned),
        cmocka_unit_test(obj_bad_indices_passed_on),
        cmocka_unit_test(obj_index_zero_and_before_the_first),
        cmocka_unit_test(obj_errors),
        cmocka_unit_test(obj_empty_file),
        cmocka_unit_test(off_files),
        cmocka_unit_test(every_format_round_trips),
        cmocka_unit_test(formats_by_extension),
        cmocka_unit_test(ply_binary_big_endian),
        cmocka_unit_test(text_formats_name_lines),
        cmocka_unit_test(free_is_safe),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
