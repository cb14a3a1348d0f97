/* SPDX-License-Identifier: BSD-3-Clause */
/* The OBJ/OFF reader of the command-line tool, tests and benchmarks (apps/surfadapt/obj_io.c):
 * it must hand the library exactly what the file says, 0-based, without judging it. */
#define _XOPEN_SOURCE 700 /* mkstemp, close, unlink, P_tmpdir */

#include "support/testing.h"

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
        cmocka_unit_test(free_is_safe),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
