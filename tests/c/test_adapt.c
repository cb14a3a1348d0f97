/* The full adaptation (sfa_adapt, paper §3-§4): refinement and coarsening to the desired
 * edge length with features, volume and host fields kept, and its determinism. */
#include "support/testing.h"

#ifndef SFA_NO_ALLOC_HOOK
#include "alloc_hook/alloc_hook.h"
#endif


static sfa_surface *surface_of(const sfa_mesh_data *m)
{
    char err[512];
    sfa_surface *s = surface_from(m, 0, err, sizeof err);
    if (!s)
        fail_msg("%s", err);
    return s;
}

/* How many of the three coordinates of p lie on the box's bounds (to tol). */
static int coordinates_on_bounds(const double *p, const double lo[3], const double hi[3], double tol)
{
    int on = 0;
    for (int k = 0; k < 3; ++k)
        on += fabs(p[k] - lo[k]) <= tol || fabs(p[k] - hi[k]) <= tol;
    return on;
}

/* The 2 x 1 x 0.5 box of 26 vertices refined to edge length 0.08 in three calls: the
 * corners stay exactly where they were, every vertex stays on a face, the volume is 1, a
 * linear field stays linear, and the triangles along the ridges are longer along them
 * than across (the anisotropic band of the paper's Fig. 2). */
static void box_refined_keeps_corners_faces_volume_and_linear_fields(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {2, 1, 0.5};
    sfa_mesh_data m = shape_box(2, lo, hi);
    sfa_surface *s = surface_of(&m);
    double *field = malloc(sizeof(double) * 2 * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v) {
        const double *p = m.xyz + 3 * v;
        field[2 * v] = 1 + 2 * p[0] - 3 * p[1] + 0.5 * p[2];
        field[2 * v + 1] = -p[2];
    }
    int32_t id;
    assert_int_equal(sfa_add_field(s, 2, field, &id), SFA_OK);
    assert_int_equal(sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.08), SFA_OK);
    for (int call = 0; call < 3; ++call)
        assert_ok(s, sfa_adapt(s));

    sfa_mesh_data out = read_back(s);
    double *values = malloc(sizeof(double) * 2 * (size_t)out.nverts);
    assert_int_equal(sfa_get_field(s, id, 2 * out.nverts, values), SFA_OK);
    int corners = 0;
    double worst_field = 0;
    for (int32_t v = 0; v < out.nverts; ++v) {
        const double *p = out.xyz + 3 * v;
        assert_true(coordinates_on_bounds(p, lo, hi, 1e-12) >= 1);
        corners += coordinates_on_bounds(p, lo, hi, 0) == 3;
        worst_field = fmax(worst_field, fabs(values[2 * v] - (1 + 2 * p[0] - 3 * p[1] + 0.5 * p[2])));
        worst_field = fmax(worst_field, fabs(values[2 * v + 1] + p[2]));
    }
    /* Triangles with an edge on a ridge: that edge's length against the height across. */
    double band_ratio = 0;
    int band = 0;
    for (int32_t t = 0; t < out.ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            const double *a = out.xyz + 3 * out.tris[3 * t + k], *b = out.xyz + 3 * out.tris[3 * t + (k + 1) % 3],
                         *c = out.xyz + 3 * out.tris[3 * t + (k + 2) % 3];
            if (coordinates_on_bounds(a, lo, hi, 1e-12) < 2 || coordinates_on_bounds(b, lo, hi, 1e-12) < 2)
                continue;
            double ab[3], ac[3], cross[3], length2 = 0, cross2 = 0, shared = 0;
            for (int i = 0; i < 3; ++i) {
                ab[i] = b[i] - a[i];
                ac[i] = c[i] - a[i];
                length2 += ab[i] * ab[i];
            }
            for (int i = 0; i < 3; ++i)
                shared += fabs(ab[i]) < 1e-12; /* along an axis: two coordinates constant */
            if (shared < 2)
                continue;
            cross[0] = ab[1] * ac[2] - ab[2] * ac[1];
            cross[1] = ab[2] * ac[0] - ab[0] * ac[2];
            cross[2] = ab[0] * ac[1] - ab[1] * ac[0];
            for (int i = 0; i < 3; ++i)
                cross2 += cross[i] * cross[i];
            band_ratio += length2 / sqrt(cross2); /* length / height */
            ++band;
        }
    band_ratio /= band;
    const double volume = measure(s, SFA_MEASURE_VOLUME);
    print_message("box: %d -> %d vertices, %d corners, volume %.15f, linear field error %.2e, ridge band: %d "
                  "triangles, mean length along / height across %.2f, min angle %.2f, max angle %.2f\n",
                  m.nverts, out.nverts, corners, volume, worst_field, band, band_ratio,
                  measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE));
    assert_true(out.nverts > 5 * m.nverts);
    assert_int_equal(corners, 8);
    assert_true(fabs(volume - 1) <= 1e-9);
    assert_true(worst_field <= 1e-9);
    assert_true(band_ratio > 1.5);
    free(values);
    free(field);
    mesh_free(&out);
    mesh_free(&m);
    sfa_destroy(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_refined_keeps_corners_faces_volume_and_linear_fields),
    };
    return cmocka_run_group_tests_name("adapt", tests, NULL, NULL);
}
