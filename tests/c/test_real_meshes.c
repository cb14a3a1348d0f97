/* SPDX-License-Identifier: BSD-3-Clause */
/* The real meshes of the data directory ($SFA_DATA_DIR, default ../shared/data): what
 * the library makes of them. Each test skips when its file is absent. */
#include "support/testing.h"

static sfa_surface *empty_surface(void)
{
    sfa_surface *s = NULL;
    assert_int_equal(sfa_create(&s), SFA_OK);
    return s;
}

/* Accepted as it is: the counts are the file's and the volume is positive. */
static void accepted(const char *name, int32_t nverts, int32_t ntris)
{
    sfa_mesh_data m;
    read_data_or_skip(name, &m);
    assert_int_equal(m.nverts, nverts);
    assert_int_equal(m.ntris, ntris);
    sfa_surface *s = empty_surface();
    assert_ok(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0));
    int32_t nv = -1, nt = -1;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_int_equal(nv, nverts);
    assert_int_equal(nt, ntris);
    sfa_mesh_data back = read_back(s);
    assert_memory_equal(back.xyz, m.xyz, sizeof(double) * 3 * (size_t)nv);
    assert_memory_equal(back.tris, m.tris, sizeof(int32_t) * 3 * (size_t)nt);
    const double volume = measure(s, SFA_MEASURE_VOLUME);
    print_message("%s: %d vertices, %d triangles, volume %.9g, area %.9g, angles %.3f to %.3f\n", name, (int)nv,
                  (int)nt, volume, measure(s, SFA_MEASURE_AREA), measure(s, SFA_MEASURE_MIN_ANGLE),
                  measure(s, SFA_MEASURE_MAX_ANGLE));
    assert_true(volume > 0);
    mesh_free(&back);
    mesh_free(&m);
    sfa_destroy(s);
}

static void fandisk(void **state)
{
    (void)state;
    accepted("fandisk.obj", 6475, 12946);
}

static void spot(void **state)
{
    (void)state;
    accepted("spot.obj", 2930, 5856);
}

static void teapot_rejected(void **state)
{
    (void)state;
    sfa_mesh_data m;
    read_data_or_skip("teapot.obj", &m);
    sfa_surface *s = empty_surface();
    const int rc = sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0);
    const char *msg = sfa_last_error(s);
    print_message("teapot.obj: %s\n", msg);
    assert_error(s, rc, SFA_ERR_MESH, "");
    /* Whatever rule it breaks first, the message points at a vertex or an edge. */
    assert_true(strstr(msg, "vertex ") != NULL || strstr(msg, "edge (") != NULL);
    int32_t nv = -1, nt = -1;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_int_equal(nv, 0);
    assert_int_equal(nt, 0);
    mesh_free(&m);
    sfa_destroy(s);
}

static void bunny_has_unreferenced_vertices(void **state)
{
    (void)state;
    sfa_mesh_data m;
    read_data_or_skip("stanford-bunny.obj", &m);
    sfa_surface *s = empty_surface();
    const int rc = sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0);
    print_message("stanford-bunny.obj: %s\n", sfa_last_error(s));
    assert_error(s, rc, SFA_ERR_MESH, "unreferenced", "vertex ");

    assert_int_equal(sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, 1), SFA_OK);
    assert_ok(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0));
    int32_t nv = -1, nt = -1;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    print_message("stanford-bunny.obj with unreferenced vertices dropped: %d of %d vertices, %d triangles\n",
                  (int)nv, (int)m.nverts, (int)nt);
    assert_true(nv > 0 && nv < m.nverts);
    assert_int_equal(nt, m.ntris);
    /* The vertices kept are the referenced ones, in their order. */
    char *used = calloc((size_t)m.nverts, 1);
    assert_non_null(used);
    for (int32_t i = 0; i < 3 * m.ntris; ++i)
        used[m.tris[i]] = 1;
    sfa_mesh_data back = read_back(s);
    int32_t k = 0;
    for (int32_t v = 0; v < m.nverts; ++v)
        if (used[v]) {
            assert_true(k < back.nverts);
            assert_memory_equal(back.xyz + 3 * k, m.xyz + 3 * v, sizeof(double) * 3);
            ++k;
        }
    assert_int_equal(k, nv);
    free(used);
    mesh_free(&back);
    mesh_free(&m);
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fandisk),
        cmocka_unit_test(spot),
        cmocka_unit_test(teapot_rejected),
        cmocka_unit_test(bunny_has_unreferenced_vertices),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
