/* SPDX-License-Identifier: BSD-3-Clause */
/* Face fields (densities per unit area, conserved through smoothing and adaptation by a
 * remap by overlap) and vertex origins (where each vertex came from, so that a host
 * carries data of its own through a call). */
#include "support/testing.h"

static double triangle_area(const sfa_mesh_data *m, int32_t t)
{
    const double *a = m->xyz + 3 * m->tris[3 * t], *b = m->xyz + 3 * m->tris[3 * t + 1],
                 *c = m->xyz + 3 * m->tris[3 * t + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    return 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

/* The integral of component c of a face field over the triangles whose first corner is in
 * component `part` of `of` (every triangle when `of` is NULL). */
static double integral(const sfa_mesh_data *m, const double *density, int ncomp, int c, const int32_t *of, int32_t part)
{
    double sum = 0;
    for (int32_t t = 0; t < m->ntris; ++t)
        if (!of || of[m->tris[3 * t]] == part)
            sum += density[ncomp * t + c] * triangle_area(m, t);
    return sum;
}

/* Two spheres in one surface: a jittered one of radius 1 (jitter seed `seed`) and a small
 * one of radius 0.4 three units away. */
static sfa_mesh_data two_spheres(uint64_t seed)
{
    sfa_mesh_data m = shape_jittered_icosphere(3, 1.0, 0.2, seed);
    sfa_mesh_data small = shape_icosphere(2, 0.4);
    const double shift[3] = {3, 0, 0};
    mesh_translate(&small, shift);
    mesh_append(&m, &small);
    mesh_free(&small);
    return m;
}

static double *read_face_field(const sfa_surface *s, int32_t id, int ncomp)
{
    int32_t nv = 0, nt = 0;
    assert_ok(s, sfa_get_counts(s, &nv, &nt));
    double *values = malloc(sizeof(double) * (size_t)ncomp * (size_t)nt);
    assert_ok(s, sfa_get_face_field(s, id, ncomp * nt, values));
    return values;
}

/* Two spheres in one surface, a constant and a linear density on each: through refining,
 * smoothing and coarsening calls the integral of each over each sphere is kept to 1e-12,
 * and the constant stays nearly constant: every density within 1 % of their mean after
 * refining and smoothing, within 2 % after coarsening to ten times fewer triangles in one
 * call (measured: 0.84 %, 0.83 %, 1.6 %). Each contraction keeps its own fan's integral
 * while the fan's area shrinks a little where the surface is curved, so the constant
 * drifts a little, fan by fan. */
static void face_field_integrals_are_kept_per_component(void **state)
{
    (void)state;
    sfa_mesh_data m = two_spheres(3);
    sfa_surface *s = make_surface(&m, 0);
    double *density = malloc(sizeof(double) * 2 * (size_t)m.ntris);
    for (int32_t t = 0; t < m.ntris; ++t) {
        const double *a = m.xyz + 3 * m.tris[3 * t];
        density[2 * t] = 2.5;
        density[2 * t + 1] = 1 + a[0] + 2 * a[1]; /* varies, of both signs */
    }
    int32_t id = -1;
    assert_ok(s, sfa_add_face_field_checked(s, m.ntris, 2, density, &id));
    assert_int_equal(id, 0);
    int32_t *of = malloc(sizeof(int32_t) * (size_t)m.nverts);
    assert_ok(s, sfa_get_components(s, m.nverts, of));
    double before[2][2];
    for (int part = 0; part < 2; ++part)
        for (int c = 0; c < 2; ++c)
            before[part][c] = integral(&m, density, 2, c, of, part);
    free(of);
    free(density);

    const double lengths[4] = {0.06, 0, 0.3, 0.3}; /* refine, smooth, coarsen twice */
    for (int round = 0; round < 4; ++round) {
        if (lengths[round] > 0) {
            assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, lengths[round]));
            assert_ok(s, sfa_adapt(s));
        } else {
            assert_ok(s, sfa_smooth(s, 3));
        }
        sfa_mesh_data now = read_back(s);
        double *d = read_face_field(s, id, 2);
        int32_t *parts = malloc(sizeof(int32_t) * (size_t)now.nverts);
        assert_ok(s, sfa_get_components(s, now.nverts, parts));
        double total = 0, area = 0, worst_constant = 0;
        for (int32_t t = 0; t < now.ntris; ++t) {
            total += d[2 * t] * triangle_area(&now, t);
            area += triangle_area(&now, t);
        }
        const double mean = total / area;
        for (int32_t t = 0; t < now.ntris; ++t)
            worst_constant = fmax(worst_constant, fabs(d[2 * t] / mean - 1));
        for (int part = 0; part < 2; ++part)
            for (int c = 0; c < 2; ++c) {
                const double after = integral(&now, d, 2, c, parts, part);
                if (!(fabs(after - before[part][c]) <= 1e-12 * fabs(before[part][c])))
                    fail_msg("round %d, sphere %d, component %d: integral %.17g, was %.17g", round, part, c, after,
                             before[part][c]);
            }
        print_message("round %d: %d triangles, integrals kept; the constant's mean %.5f, every value within %.2e "
                      "of it\n", round, now.ntris, mean, worst_constant);
        assert_true(worst_constant < (round < 2 ? 0.01 : 0.02));
        free(parts);
        free(d);
        mesh_free(&now);
    }
    sfa_destroy(s);
    mesh_free(&m);
}

static void bad_face_fields_are_refused(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = make_surface(&cube, 1);
    double values[12];
    for (int t = 0; t < 12; ++t)
        values[t] = t;
    int32_t id = -1;
    values[4] = NAN;
    expect_unchanged(s, sfa_add_face_field(s, 1, values, &id), SFA_ERR_NUMERIC, "triangle 5");
    values[4] = 4;
    expect_unchanged(s, sfa_add_face_field_checked(s, 10, 1, values, &id), SFA_ERR_ARGUMENT,
                     "the mesh has 12 triangles since the last sfa_set_mesh", "the array given has 10");
    expect_unchanged(s, sfa_add_face_field(s, 0, values, &id), SFA_ERR_ARGUMENT, "ncomp");
    assert_ok(s, sfa_add_face_field(s, 1, values, &id));
    double back[12];
    expect_unchanged(s, sfa_get_face_field(s, 1, 12, back), SFA_ERR_ARGUMENT, "unknown face field id 1");
    expect_unchanged(s, sfa_get_face_field(s, id, 11, back), SFA_ERR_ARGUMENT, "capacity");
    assert_ok(s, sfa_get_face_field(s, id, 12, back));
    assert_memory_equal(back, values, sizeof values);
    sfa_destroy(s);
    mesh_free(&cube);
}

/* sfa_set_face_field: a host that has advanced its densities over a step (a surfactant
 * produced on one bubble) replaces them, and from then on sfa_adapt() keeps the new
 * integrals, sphere by sphere, to 1e-12. A bad replacement names what is wrong and leaves
 * the field as it was. */
static void replaced_face_field_is_what_is_kept(void **state)
{
    (void)state;
    sfa_mesh_data m = two_spheres(5);
    sfa_surface *s = make_surface(&m, 1);
    double *density = malloc(sizeof(double) * (size_t)m.ntris);
    for (int32_t t = 0; t < m.ntris; ++t)
        density[t] = 1;
    int32_t id = -1;
    assert_ok(s, sfa_add_face_field_checked(s, m.ntris, 1, density, &id));
    int32_t *of = malloc(sizeof(int32_t) * (size_t)m.nverts);
    assert_ok(s, sfa_get_components(s, m.nverts, of));
    for (int32_t t = 0; t < m.ntris; ++t)
        density[t] = of[m.tris[3 * t]] == 0 ? 2 + m.xyz[3 * m.tris[3 * t]] : 5;
    assert_ok(s, sfa_set_face_field(s, id, m.ntris, density));
    const double kept[2] = {integral(&m, density, 1, 0, of, 0), integral(&m, density, 1, 0, of, 1)};

    density[7] = INFINITY;
    assert_error(s, sfa_set_face_field(s, id, m.ntris, density), SFA_ERR_NUMERIC, "triangle 8", "non-finite");
    density[7] = 1;
    assert_error(s, sfa_set_face_field(s, id, m.ntris - 1, density), SFA_ERR_ARGUMENT, "the array given has");
    assert_error(s, sfa_set_face_field(s, id + 1, m.ntris, density), SFA_ERR_ARGUMENT, "unknown face field id 1");
    assert_error(s, sfa_set_face_field(s, id, m.ntris, NULL), SFA_ERR_ARGUMENT, "values is NULL");
    double *back = read_face_field(s, id, 1);
    for (int32_t t = 0; t < m.ntris; ++t)
        density[t] = of[m.tris[3 * t]] == 0 ? 2 + m.xyz[3 * m.tris[3 * t]] : 5;
    assert_memory_equal(back, density, sizeof(double) * (size_t)m.ntris);
    free(back);

    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.08));
    assert_ok(s, sfa_adapt(s));
    sfa_mesh_data now = read_back(s);
    double *d = read_face_field(s, id, 1);
    int32_t *parts = malloc(sizeof(int32_t) * (size_t)now.nverts);
    assert_ok(s, sfa_get_components(s, now.nverts, parts));
    assert_true(now.ntris > m.ntris);
    for (int part = 0; part < 2; ++part) {
        const double after = integral(&now, d, 1, 0, parts, part);
        if (!(fabs(after - kept[part]) <= 1e-12 * fabs(kept[part])))
            fail_msg("sphere %d: integral %.17g after sfa_adapt, %.17g when set", part, after, kept[part]);
    }
    free(parts);
    free(d);
    mesh_free(&now);
    free(of);
    free(density);
    sfa_destroy(s);
    mesh_free(&m);
}

/* A flat square with jittered vertices (z = 0.25), refined and smoothed: every vertex of the
 * result is reproduced from its origin, the old triangle's corners weighted by the
 * barycentric coordinates, to 1e-12. */
static void origins_reproduce_every_vertex_on_a_plane(void **state)
{
    (void)state;
    sfa_mesh_data plane = shape_grid(12, 12, 0.1);
    shapes_rng rng = rng_seed(11);
    for (int32_t v = 0; v < plane.nverts; ++v) {
        double *p = plane.xyz + 3 * v;
        const int interior = p[0] > 1e-9 && p[0] < 1.2 - 1e-9 && p[1] > 1e-9 && p[1] < 1.2 - 1e-9;
        if (interior) {
            p[0] += 0.03 * (rng_uniform(&rng) - 0.5);
            p[1] += 0.03 * (rng_uniform(&rng) - 0.5);
        }
        p[2] = 0.25;
    }
    sfa_surface *s = make_surface(&plane, 1);
    int32_t triangle[1];
    double weights[3];
    expect_unchanged(s, sfa_get_vertex_origins(s, 1, triangle, weights, 1), SFA_ERR_STATE, "no sfa_smooth");
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.05));
    for (int call = 0; call < 3; ++call) {
        sfa_mesh_data old = read_back(s);
        assert_ok(s, call == 1 ? sfa_smooth(s, 2) : sfa_adapt(s));
        sfa_mesh_data now = read_back(s);
        int32_t *tri = malloc(sizeof(int32_t) * (size_t)now.nverts);
        double *w = malloc(sizeof(double) * 3 * (size_t)now.nverts);
        expect_unchanged(s, sfa_get_vertex_origins(s, now.nverts - 1, tri, w, 1), SFA_ERR_ARGUMENT, "capacity");
        assert_ok(s, sfa_get_vertex_origins(s, now.nverts, tri, w, 1));
        double worst = 0;
        for (int32_t v = 0; v < now.nverts; ++v) {
            assert_in_range(tri[v], 1, old.ntris);
            double sum = 0;
            for (int k = 0; k < 3; ++k) {
                assert_true(w[3 * v + k] >= 0 && w[3 * v + k] <= 1);
                sum += w[3 * v + k];
            }
            assert_true(fabs(sum - 1) < 1e-15);
            for (int c = 0; c < 3; ++c) {
                double x = 0;
                for (int k = 0; k < 3; ++k)
                    x += w[3 * v + k] * old.xyz[3 * old.tris[3 * (tri[v] - 1) + k] + c];
                worst = fmax(worst, fabs(x - now.xyz[3 * v + c]));
            }
        }
        print_message("call %d: %d -> %d vertices, origins reproduce them to %.1e\n", call, old.nverts, now.nverts,
                      worst);
        assert_true(worst < 1e-12);
        free(tri);
        free(w);
        mesh_free(&old);
        mesh_free(&now);
    }
    /* A new mesh has no origins until it is smoothed or adapted. */
    assert_ok(s, sfa_set_mesh(s, plane.nverts, plane.xyz, plane.ntris, plane.tris, 0));
    expect_unchanged(s, sfa_get_vertex_origins(s, 1, triangle, weights, 1), SFA_ERR_STATE, "no sfa_smooth");
    sfa_destroy(s);
    mesh_free(&plane);
}

/* On a sphere a linear function carried by the origins differs from its exact values at
 * the new vertices by O(h^2): a vertex lies a sagitta off the old triangles. */
static void origins_carry_a_linear_function_to_second_order_on_a_sphere(void **state)
{
    (void)state;
    double errors[2];
    for (int level = 0; level < 2; ++level) {
        sfa_mesh_data sphere = shape_jittered_icosphere(3 + level, 1.0, 0.2, 5);
        sfa_surface *s = make_surface(&sphere, 0);
        const double h = mesh_mean_edge_length(&sphere);
        assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.6 * h));
        assert_ok(s, sfa_adapt(s));
        sfa_mesh_data now = read_back(s);
        int32_t *tri = malloc(sizeof(int32_t) * (size_t)now.nverts);
        double *w = malloc(sizeof(double) * 3 * (size_t)now.nverts);
        assert_ok(s, sfa_get_vertex_origins(s, now.nverts, tri, w, 0));
        double worst = 0;
        for (int32_t v = 0; v < now.nverts; ++v) {
            double carried = 0;
            for (int k = 0; k < 3; ++k) {
                const double *p = sphere.xyz + 3 * sphere.tris[3 * tri[v] + k];
                carried += w[3 * v + k] * (0.3 * p[0] - 0.7 * p[1] + 0.5 * p[2] + 2);
            }
            const double *x = now.xyz + 3 * v;
            worst = fmax(worst, fabs(carried - (0.3 * x[0] - 0.7 * x[1] + 0.5 * x[2] + 2)));
        }
        errors[level] = worst;
        print_message("h = %.4f: %d -> %d vertices, largest error %.2e = %.3f h^2\n", h, sphere.nverts, now.nverts,
                      worst, worst / (h * h));
        assert_true(worst < h * h);
        free(tri);
        free(w);
        mesh_free(&now);
        mesh_free(&sphere);
        sfa_destroy(s);
    }
    assert_true(errors[1] < errors[0] / 2.5); /* halving h takes it down by about 4 */
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(face_field_integrals_are_kept_per_component),
        cmocka_unit_test(bad_face_fields_are_refused),
        cmocka_unit_test(replaced_face_field_is_what_is_kept),
        cmocka_unit_test(origins_reproduce_every_vertex_on_a_plane),
        cmocka_unit_test(origins_carry_a_linear_function_to_second_order_on_a_sphere),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
