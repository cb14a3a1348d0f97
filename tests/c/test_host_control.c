/* SPDX-License-Identifier: BSD-3-Clause */
/* What a coupled solver controls: a size field (the edge length follows the host's local
 * grid spacing; finer where a sheet is thinner than an edge, if asked), fixed vertices and
 * required edges (kept bit for bit), and the checked variants of the functions that read
 * one value per vertex (a stale array is refused). */
#include "support/testing.h"

/* Mean length of the edges whose both ends have coordinate `axis` in (low, high), and
 * their number in *count_out (if not NULL). */
static double mean_edge_length_between(const sfa_mesh_data *m, int axis, double low, double high, int32_t *count_out)
{
    int32_t count = 0, n = 0;
    int32_t *edges = mesh_edges(m, &count);
    double sum = 0;
    for (int32_t e = 0; e < count; ++e) {
        const double *a = m->xyz + 3 * edges[2 * e], *b = m->xyz + 3 * edges[2 * e + 1];
        if (!(a[axis] > low && a[axis] < high && b[axis] > low && b[axis] < high))
            continue;
        sum += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        ++n;
    }
    free(edges);
    if (count_out)
        *count_out = n;
    return n ? sum / n : NAN;
}

/* 0.05 on the upper half of the unit sphere, 0.2 on the lower: what an AMR grid one level
 * finer above the equator than below asks for. */
static double *two_level_sizes(const sfa_surface *s)
{
    sfa_mesh_data m = read_back(s);
    double *size = malloc(sizeof(double) * (size_t)m.nverts);
    for (int32_t v = 0; v < m.nverts; ++v)
        size[v] = m.xyz[3 * v + 2] > 0 ? 0.05 : 0.2;
    mesh_free(&m);
    return size;
}

static void edge_lengths_follow_the_size_field(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(4, 1.0);
    sfa_surface *s = make_surface(&sphere, 0);
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.1));
    double *size = two_level_sizes(s);
    assert_ok(s, sfa_set_size_field_checked(s, sphere.nverts, size));
    free(size);
    for (int call = 0; call < 4; ++call) /* set once: carried through every call */
        assert_ok(s, sfa_adapt(s));
    sfa_mesh_data m = read_back(s);
    int32_t fine_edges = 0, coarse_edges = 0;
    const double fine = mean_edge_length_between(&m, 2, 0.5, INFINITY, &fine_edges);
    const double coarse = mean_edge_length_between(&m, 2, -INFINITY, -0.5, &coarse_edges);
    print_message("size field: mean edge %.4f over %d edges (asked 0.05), %.4f over %d (asked 0.2)\n", fine,
                  fine_edges, coarse, coarse_edges);
    assert_true(fabs(fine - 0.05) < 0.3 * 0.05);
    assert_true(fabs(coarse - 0.2) < 0.3 * 0.2);

    /* A smooth transition: along the meridians the mean edge length grows steadily from
     * the fine side to the coarse one, band by band, without a jump of more than the
     * gradation allows between neighbouring bands. */
    double last = 0;
    for (int band = 0; band < 8; ++band) {
        const double hi = 0.5 - 0.125 * band, lo = hi - 0.125;
        int32_t count = 0, n = 0;
        int32_t *edges = mesh_edges(&m, &count);
        double sum = 0;
        for (int32_t e = 0; e < count; ++e) {
            const double *a = m.xyz + 3 * edges[2 * e], *b = m.xyz + 3 * edges[2 * e + 1];
            const double z = (a[2] + b[2]) / 2;
            if (z <= lo || z > hi)
                continue;
            sum += sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
            ++n;
        }
        free(edges);
        const double mean = sum / n;
        print_message("  band z in (%.3f, %.3f]: mean edge %.4f\n", lo, hi, mean);
        if (band > 0) {
            assert_true(mean > 0.9 * last);
            assert_true(mean < 2.0 * last);
        }
        last = mean;
    }
    mesh_free(&m);

    /* Cleared: the global length again, on both halves. */
    assert_ok(s, sfa_set_size_field(s, NULL));
    for (int call = 0; call < 4; ++call)
        assert_ok(s, sfa_adapt(s));
    m = read_back(s);
    const double upper = mean_edge_length_between(&m, 2, 0.5, INFINITY, NULL),
                 lower = mean_edge_length_between(&m, 2, -INFINITY, -0.5, NULL);
    print_message("cleared: mean edge %.4f above, %.4f below (global 0.1)\n", upper, lower);
    assert_true(fabs(upper - 0.1) < 0.3 * 0.1);
    assert_true(fabs(lower - 0.1) < 0.3 * 0.1);
    mesh_free(&m);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* A bubble (a unit sphere) and, 3 to the right, a film: the same sphere pressed to a lens
 * 0.04 thick, its two sides nearer than an edge all over. The host asks for 0.1
 * everywhere by its size field. */
static sfa_surface *bubble_and_film(void)
{
    sfa_mesh_data bubble = shape_icosphere(3, 1.0), film = shape_icosphere(3, 1.0);
    for (int32_t v = 0; v < film.nverts; ++v) {
        film.xyz[3 * v] += 3;
        film.xyz[3 * v + 2] *= 0.02;
    }
    mesh_append(&bubble, &film);
    sfa_surface *s = make_surface(&bubble, 0);
    double *size = malloc(sizeof(double) * (size_t)bubble.nverts);
    for (int32_t v = 0; v < bubble.nverts; ++v)
        size[v] = 0.1;
    assert_ok(s, sfa_set_size_field_checked(s, bubble.nverts, size));
    free(size);
    mesh_free(&film);
    mesh_free(&bubble);
    return s;
}

static void thin_sheets_get_finer_edges_and_the_size_field_stays(void **state)
{
    (void)state;
    sfa_surface *plain = bubble_and_film(), *s = bubble_and_film();
    assert_ok(s, sfa_set_param(s, SFA_PARAM_THIN_SHEET_EDGE_RATIO, 0.5));
    for (int call = 0; call < 4; ++call) {
        assert_ok(plain, sfa_adapt(plain));
        assert_ok(s, sfa_adapt(s));
    }
    sfa_mesh_data a = read_back(plain), b = read_back(s);
    /* The bubble lies at x < 1.5, the film beyond. */
    const double bubble_plain = mean_edge_length_between(&a, 0, -INFINITY, 1.5, NULL),
                 film_plain = mean_edge_length_between(&a, 0, 1.5, INFINITY, NULL);
    const double bubble = mean_edge_length_between(&b, 0, -INFINITY, 1.5, NULL),
                 film = mean_edge_length_between(&b, 0, 1.5, INFINITY, NULL);
    print_message("thin sheets at 0.5 l: bubble %.4f (without %.4f), film %.4f (without %.4f)\n", bubble, bubble_plain,
                  film, film_plain);
    /* The film's edges about halve (once: the sizes asked are the host's times the ratio
     * at every call, not the last call's); the bubble, thick everywhere, is meshed as
     * without. */
    assert_true(film > 0.35 * film_plain && film < 0.65 * film_plain);
    assert_true(fabs(bubble - bubble_plain) < 0.02 * bubble_plain);
    mesh_free(&a);
    mesh_free(&b);

    /* The film blown up into a sphere again (its heights stretched 25 times): nothing is
     * thin any more, and its edges keep to the host's 0.1, which the finer sizes asked for
     * while it was thin did not replace. (Had they replaced it, each call would have
     * halved the sizes again: 0.007 after these calls.) */
    double done = 0;
    for (int move = 0; move < 100 && done < 1 - 1e-12; ++move) {
        b = read_back(s);
        double *velocity = calloc(3 * (size_t)b.nverts, sizeof(double));
        for (int32_t v = 0; v < b.nverts; ++v)
            if (b.xyz[3 * v] > 1.5)
                velocity[3 * v + 2] = 24 * b.xyz[3 * v + 2] / (1 + 24 * done);
        assert_ok(s, sfa_set_velocities_checked(s, b.nverts, velocity));
        double taken = 0;
        assert_ok(s, sfa_move(s, 1 - done, &taken));
        done += taken;
        free(velocity);
        mesh_free(&b);
    }
    assert_true(done > 1 - 1e-9);
    for (int call = 0; call < 4; ++call)
        assert_ok(s, sfa_adapt(s));
    b = read_back(s);
    const double blown_up = mean_edge_length_between(&b, 0, 1.5, INFINITY, NULL);
    print_message("blown up into a sphere: film %.4f\n", blown_up);
    assert_true(blown_up > 0.7 * film_plain && blown_up < 1.3 * film_plain);
    mesh_free(&b);
    sfa_destroy(plain);
    sfa_destroy(s);
}

static void bad_sizes_are_refused_by_vertex(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(2, 1.0);
    sfa_surface *s = make_surface(&sphere, 1);
    double *size = malloc(sizeof(double) * (size_t)sphere.nverts);
    for (int32_t v = 0; v < sphere.nverts; ++v)
        size[v] = 0.3;
    assert_ok(s, sfa_set_size_field(s, size));
    /* Out of range (<= 0): SFA_ERR_ARGUMENT; not finite: SFA_ERR_NUMERIC, as for every field. */
    const double bad[] = {0, -0.1, NAN, INFINITY};
    const int status[] = {SFA_ERR_ARGUMENT, SFA_ERR_ARGUMENT, SFA_ERR_NUMERIC, SFA_ERR_NUMERIC};
    for (int k = 0; k < 4; ++k) {
        double *wrong = malloc(sizeof(double) * (size_t)sphere.nverts);
        for (int32_t v = 0; v < sphere.nverts; ++v)
            wrong[v] = 0.05;
        wrong[17] = bad[k];
        /* Vertex 17 counted from 0 is vertex 18 in the host's numbering (base 1). */
        assert_error(s, sfa_set_size_field(s, wrong), status[k], "vertex 18", "> 0");
        free(wrong);
    }
    /* Nothing changed: the size field of 0.3 still rules. */
    assert_ok(s, sfa_adapt(s));
    sfa_surface *twin = make_surface(&sphere, 1);
    assert_ok(twin, sfa_set_size_field(twin, size));
    assert_ok(twin, sfa_adapt(twin));
    snapshot a, b;
    snapshot_take(s, &a);
    snapshot_take(twin, &b);
    assert_same_snapshot(&a, &b);
    snapshot_free(&a);
    snapshot_free(&b);
    free(size);
    sfa_destroy(twin);
    sfa_destroy(s);
    mesh_free(&sphere);
}

/* The index of the vertex of m at exactly the position p, or -1. */
static int32_t vertex_at(const sfa_mesh_data *m, const double p[3])
{
    for (int32_t v = 0; v < m->nverts; ++v)
        if (memcmp(m->xyz + 3 * v, p, 3 * sizeof(double)) == 0)
            return v;
    return -1;
}

static int has_edge(const sfa_mesh_data *m, int32_t a, int32_t b)
{
    for (int32_t t = 0; t < m->ntris; ++t)
        for (int k = 0; k < 3; ++k)
            if (m->tris[3 * t + k] == a && m->tris[3 * t + (k + 1) % 3] == b)
                return 1;
    return 0;
}

/* Every 9th vertex fixed, and a chain of required edges running along the sphere: after
 * refining, smoothing and coarsening calls each fixed vertex is still there bit for bit,
 * and each required edge still joins its two vertices. */
static void fixed_vertices_and_required_edges_are_kept_bit_for_bit(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_jittered_icosphere(3, 1.0, 0.2, 7);
    sfa_surface *s = make_surface(&sphere, 1);
    int32_t nfixed = 0, fixed[200];
    for (int32_t v = 0; v < sphere.nverts && nfixed < 200; v += 9)
        fixed[nfixed++] = v + 1;
    /* A chain of edges: from vertex 0, each step to the neighbour with the largest x. */
    int32_t nedges = 0, chain[2 * 12];
    int32_t count = 0, *edges = mesh_edges(&sphere, &count), at = 0;
    for (int step = 0; step < 12; ++step) {
        int32_t best = -1;
        for (int32_t e = 0; e < count; ++e)
            for (int k = 0; k < 2; ++k)
                if (edges[2 * e + k] == at) {
                    const int32_t w = edges[2 * e + 1 - k];
                    int used = 0;
                    for (int32_t i = 0; i < 2 * nedges; ++i)
                        used = used || chain[i] == w;
                    if (!used && (best < 0 || sphere.xyz[3 * w] > sphere.xyz[3 * best]))
                        best = w;
                }
        chain[2 * nedges] = at + 1;
        chain[2 * nedges + 1] = best + 1;
        ++nedges;
        at = best;
    }
    free(edges);
    assert_ok(s, sfa_set_fixed_vertices(s, nfixed, fixed, 1));
    assert_ok(s, sfa_set_required_edges(s, nedges, chain, 1));

    const double lengths[3] = {0.05, 0, 0.4}; /* refine, smooth only, coarsen */
    for (int round = 0; round < 3; ++round) {
        if (lengths[round] > 0) {
            assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, lengths[round]));
            assert_ok(s, sfa_adapt(s));
            assert_ok(s, sfa_adapt(s));
        } else {
            assert_ok(s, sfa_smooth(s, 3));
        }
        sfa_mesh_data m = read_back(s);
        for (int32_t i = 0; i < nfixed; ++i)
            if (vertex_at(&m, sphere.xyz + 3 * (fixed[i] - 1)) < 0)
                fail_msg("round %d: fixed vertex %d has moved or gone", round, fixed[i]);
        for (int32_t i = 0; i < nedges; ++i) {
            const int32_t a = vertex_at(&m, sphere.xyz + 3 * (chain[2 * i] - 1));
            const int32_t b = vertex_at(&m, sphere.xyz + 3 * (chain[2 * i + 1] - 1));
            if (a < 0 || b < 0 || !(has_edge(&m, a, b) || has_edge(&m, b, a)))
                fail_msg("round %d: required edge (%d, %d) is gone", round, chain[2 * i], chain[2 * i + 1]);
        }
        print_message("round %d: %d vertices, every fixed vertex and required edge in place\n", round, m.nverts);
        if (round == 0)
            assert_true(m.nverts > 4 * sphere.nverts); /* it did refine */
        if (round == 2)
            assert_true(m.nverts < sphere.nverts);     /* and coarsen */
        mesh_free(&m);
    }
    /* Cleared: the vertices may move again. */
    assert_ok(s, sfa_set_fixed_vertices(s, 0, NULL, 1));
    assert_ok(s, sfa_set_required_edges(s, 0, NULL, 1));
    assert_ok(s, sfa_smooth(s, 2));
    sfa_mesh_data m = read_back(s);
    int32_t still = 0;
    for (int32_t i = 0; i < nfixed; ++i)
        still += vertex_at(&m, sphere.xyz + 3 * (fixed[i] - 1)) >= 0;
    assert_true(still < nfixed / 2);
    mesh_free(&m);
    sfa_destroy(s);
    mesh_free(&sphere);
}

static void bad_constraints_are_refused_by_name(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    sfa_surface *s = make_surface(&cube, 1);
    const int32_t fixed[] = {1, 8, 9};
    expect_unchanged(s, sfa_set_fixed_vertices(s, 3, fixed, 1), SFA_ERR_ARGUMENT, "vertices[2] = 9", "8");
    expect_unchanged(s, sfa_set_fixed_vertices(s, 2, fixed, 0), SFA_ERR_ARGUMENT, "vertices[1] = 8");
    expect_unchanged(s, sfa_set_fixed_vertices(s, -1, fixed, 1), SFA_ERR_ARGUMENT, "count");
    expect_unchanged(s, sfa_set_fixed_vertices(s, 2, NULL, 1), SFA_ERR_ARGUMENT, "NULL");
    expect_unchanged(s, sfa_set_fixed_vertices(s, 1, fixed, 2), SFA_ERR_ARGUMENT, "index_base");
    /* (1, 3) is an edge of the cube (triangle 0, 2, 1 in base 0); (1, 7) is a diagonal of no face. */
    const int32_t pairs[] = {1, 3, 1, 7};
    expect_unchanged(s, sfa_set_required_edges(s, 2, pairs, 1), SFA_ERR_ARGUMENT, "edge 1", "(1, 7)", "not an edge");
    const int32_t loop[] = {2, 2};
    expect_unchanged(s, sfa_set_required_edges(s, 1, loop, 1), SFA_ERR_ARGUMENT, "(2, 2)", "not an edge");
    const int32_t out_of_range[] = {1, 0};
    expect_unchanged(s, sfa_set_required_edges(s, 1, out_of_range, 1), SFA_ERR_ARGUMENT, "edges[1] = 0");
    assert_ok(s, sfa_set_required_edges(s, 1, pairs, 1));
    sfa_destroy(s);
    mesh_free(&cube);
}

/* After sfa_adapt grew the mesh, an array sized for the mesh before is refused by every
 * checked variant, with both counts named; arrays of the right size pass. */
static void checked_variants_reject_a_stale_array(void **state)
{
    (void)state;
    sfa_mesh_data sphere = shape_icosphere(3, 1.0);
    sfa_surface *s = make_surface(&sphere, 0);
    const int32_t before = sphere.nverts;
    double *old = calloc(3 * (size_t)before, sizeof(double));
    int32_t id = -1;
    assert_ok(s, sfa_set_velocities_checked(s, before, old));
    assert_ok(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.05));
    assert_ok(s, sfa_adapt(s));
    int32_t now = 0, ntris = 0;
    assert_ok(s, sfa_get_counts(s, &now, &ntris));
    assert_true(now > before);
    char has[64], given[64];
    snprintf(has, sizeof has, "the mesh has %d vertices since the last sfa_adapt", now);
    snprintf(given, sizeof given, "the array given has %d", before);
    expect_unchanged(s, sfa_set_velocities_checked(s, before, old), SFA_ERR_ARGUMENT, has, given);
    expect_unchanged(s, sfa_add_field_checked(s, before, 3, old, &id), SFA_ERR_ARGUMENT, has, given);
    expect_unchanged(s, sfa_set_size_field_checked(s, before, old), SFA_ERR_ARGUMENT, has, given);
    double *fresh = malloc(sizeof(double) * 3 * (size_t)now);
    for (int32_t i = 0; i < 3 * now; ++i)
        fresh[i] = 0.1;
    assert_ok(s, sfa_set_velocities_checked(s, now, fresh));
    assert_ok(s, sfa_add_field_checked(s, now, 3, fresh, &id));
    assert_ok(s, sfa_set_size_field_checked(s, now, fresh));
    free(fresh);
    free(old);
    sfa_destroy(s);
    mesh_free(&sphere);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(edge_lengths_follow_the_size_field),
        cmocka_unit_test(thin_sheets_get_finer_edges_and_the_size_field_stays),
        cmocka_unit_test(bad_sizes_are_refused_by_vertex),
        cmocka_unit_test(fixed_vertices_and_required_edges_are_kept_bit_for_bit),
        cmocka_unit_test(bad_constraints_are_refused_by_name),
        cmocka_unit_test(checked_variants_reject_a_stale_array),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
