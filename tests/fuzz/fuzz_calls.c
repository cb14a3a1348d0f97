/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzzes sequences of API calls on one surface: parameters (any key, any value), velocities
 * (of the right or a stale length), motion, advection through a few flows, smoothing,
 * adaptation, vertex and face fields, size fields, fixed vertices and required edges, and
 * every query; the contract (contract.h) is checked after every call.
 *
 * Input: a byte choosing the starting shape, then per call an opcode byte and the bytes
 * its arguments take, read in the order the arguments are written (each into a variable
 * first: C leaves the order in which a call's arguments are evaluated to the compiler, and
 * an input must mean the same calls to gcc and clang). At most 24 calls, and adaptation
 * only while the mesh is small and with at most three passes (adapt_bounded), so that each
 * input runs in milliseconds. */
#include "contract.h"

static const double interesting[] = {0,    1,      -1,    0.5,      2,     1e-3,     1e3,      0.05,
                                     0.25, 1e-300, 1e300, INFINITY, -0.0,  NAN,      0.999999, 0.3};
enum { N_INTERESTING = sizeof interesting / sizeof interesting[0] };

static double pick_value(fuzz_input *in) { return interesting[fuzz_byte(in) % N_INTERESTING]; }

static sfa_mesh_data shape(uint8_t which)
{
    switch (which % 7) {
    case 0: return shape_icosphere(1, 0.5);
    case 1: return shape_unit_cube();
    case 2: return shape_grid(4, 3, 0.25); /* open */
    case 3: return shape_capped_cylinder(0.3, 1.0, 8, 3);
    case 4: return shape_spherical_cap(0.5, 1.0, 8, 3); /* open */
    case 5: {
        sfa_mesh_data a = shape_icosphere(1, 0.3), b = shape_icosahedron(0.2);
        const double shift[3] = {0.55, 0, 0};
        mesh_translate(&b, shift);
        mesh_append(&a, &b);
        mesh_free(&b);
        return a;
    }
    default: return shape_ellipsoid(1, 1.0, 0.3, 0.05);
    }
}

/* Flows for sfa_advect, chosen by ctx: a rotation, a shear, a collapse to the origin, none. */
static void flow(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    const int kind = *(const int *)ctx;
    for (int32_t v = 0; v < n; ++v) {
        const double x = xyz[3 * v], y = xyz[3 * v + 1], z = xyz[3 * v + 2];
        double *u = vel + 3 * v;
        switch (kind % 4) {
        case 0: u[0] = -y; u[1] = x; u[2] = 0; break;
        case 1: u[0] = sin(3 * z + t); u[1] = 0; u[2] = 0; break;
        case 2: u[0] = -x; u[1] = -y; u[2] = -z; break;
        default: u[0] = u[1] = u[2] = 0; break;
        }
    }
}

/* sfa_adapt, checked, with at most three passes: each pass may more than double the
 * vertices where the metric asks for far shorter edges than the mesh has, so that eight
 * took a 34-vertex disc flattened to 1e10 times its thickness to 26,000 vertices in one
 * call, for several seconds (tests/fuzz/open/README.md). What passes four to eight do is what the
 * first three do again. */
static void adapt_bounded(sfa_surface *s)
{
    double passes = 0;
    FUZZ_CALL(s, sfa_get_param(s, SFA_PARAM_ADAPT_PASSES, &passes));
    if (passes > 3)
        FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, 3));
    FUZZ_REMESH(s, sfa_adapt(s));
    if (passes > 3)
        FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, passes));
}

/* The count a host believes the mesh has: mostly right, sometimes stale. */
static int32_t believed(fuzz_input *in, int32_t actual)
{
    const uint8_t b = fuzz_byte(in);
    return b < 200 ? actual : actual + (int32_t)(b % 7) - 3;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_input in = {data, size, 0};
    sfa_surface *s = NULL;
    FUZZ_REQUIRE(sfa_create(&s) == SFA_OK, "sfa_create failed");
    FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_THREADS, 1));
    sfa_mesh_data m = shape(fuzz_byte(&in));
    FUZZ_CALL(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0));
    mesh_free(&m);
    for (int call = 0; call < 24 && fuzz_more(&in); ++call) {
        int32_t nv = 0, nt = 0;
        sfa_get_counts(s, &nv, &nt);
        const int32_t n = believed(&in, nv), nf = believed(&in, nt);
        const size_t room = (size_t)(n > 0 ? n : 1) * 3, face_room = (size_t)(nf > 0 ? nf : 1) * 3;
        double *values = malloc(sizeof(double) * (room > face_room ? room : face_room));
        int32_t *indices = malloc(sizeof(int32_t) * 16), id = -1, count = fuzz_byte(&in) % 9;
        for (size_t k = 0; k < (room > face_room ? room : face_room); ++k)
            values[k] = (k % 5 == 0) ? pick_value(&in) : 0.1 * (double)(k % 7) - 0.3;
        for (int k = 0; k < 16; ++k)
            indices[k] = (int32_t)(fuzz_byte(&in) % (nv + 2)) - 1;
        const uint8_t op = fuzz_byte(&in);
        double dt_taken = 0;
        switch (op % 14) {
        case 0: {
            const int key = (int)(fuzz_byte(&in) % (SHAPES_NPARAMS + 2)) - 1;
            const double value = pick_value(&in);
            FUZZ_CALL(s, sfa_set_param(s, key, value));
            break;
        }
        case 1: FUZZ_CALL(s, sfa_set_velocities_checked(s, n, values)); break;
        case 2: FUZZ_CALL(s, sfa_move(s, pick_value(&in), &dt_taken)); break;
        case 3: {
            const int kind = fuzz_byte(&in);
            const double t = pick_value(&in), dt = pick_value(&in);
            FUZZ_CALL(s, sfa_advect(s, flow, (void *)&kind, t, dt, &dt_taken));
            break;
        }
        case 4: FUZZ_REMESH(s, sfa_smooth(s, (int32_t)(fuzz_byte(&in) % 5) - 1)); break;
        case 5:
            if (nv < 200)
                adapt_bounded(s);
            break;
        case 6: FUZZ_CALL(s, sfa_add_field_checked(s, n, 1 + fuzz_byte(&in) % 3, values, &id)); break;
        case 7: FUZZ_CALL(s, sfa_add_face_field_checked(s, nf, 1, values, &id)); break;
        case 8:
            for (size_t k = 0; k < room; ++k)
                values[k] = fabs(values[k]) + 0.02;
            if (fuzz_byte(&in) & 1)
                values[0] = pick_value(&in);
            FUZZ_CALL(s, sfa_set_size_field_checked(s, n, values));
            break;
        case 9: FUZZ_CALL(s, sfa_set_fixed_vertices(s, count, indices, 0)); break;
        case 10: FUZZ_CALL(s, sfa_set_required_edges(s, count / 2, indices, 0)); break;
        case 11: fuzz_query_everything(s); break;
        case 12: {
            double *out = malloc(sizeof(double) * 3 * (size_t)(nt + nv + 1));
            FUZZ_CALL(s, sfa_get_field(s, fuzz_byte(&in) % 4, 3 * nv, out));
            FUZZ_CALL(s, sfa_get_face_field(s, fuzz_byte(&in) % 4, nt, out));
            free(out);
            /* A host replacing what it advanced, for the count it believes. */
            FUZZ_CALL(s, sfa_set_field(s, fuzz_byte(&in) % 4, n, values));
            FUZZ_CALL(s, sfa_set_face_field(s, fuzz_byte(&in) % 4, nf, values));
            break;
        }
        default: {
            sfa_mesh_data next = shape(fuzz_byte(&in));
            FUZZ_CALL(s, sfa_set_mesh(s, next.nverts, next.xyz, next.ntris, next.tris, 0));
            mesh_free(&next);
            break;
        }
        }
        free(values);
        free(indices);
    }
    sfa_destroy(s);
    return 0;
}
