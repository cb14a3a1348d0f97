/* SPDX-License-Identifier: BSD-3-Clause */
/* How a coupling library carries data of its own through sfa_adapt: it keeps its values on
 * the vertices of the mesh it last read, and after the call maps them onto the new
 * vertices with sfa_get_vertex_origins (each new vertex: an old triangle and barycentric
 * coordinates there). Here the data is a temperature on a flat, jittered patch; the mesh is
 * refined to half its edge length, and the carried values are compared with the old
 * mesh's own linear interpolant (they agree to round-off: the patch is flat) and with the
 * exact temperature (they differ by the interpolation error of the old mesh).
 * Build: cc coupler_host.c $(pkg-config --cflags --libs surfadapt) -lm */
#include <surfadapt.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define N 16 /* vertices per side of the patch */

static double temperature(const double *p) { return sin(3 * p[0]) * cos(2 * p[1]); }

static int check(sfa_surface *s, int rc, const char *what)
{
    if (rc != SFA_OK)
        fprintf(stderr, "%s: %s\n", what, sfa_last_error(s));
    return rc == SFA_OK;
}

int main(void)
{
    /* The patch [0, 1]^2 at z = 0, the interior vertices jittered. */
    double xyz[3 * N * N];
    int32_t tris[3 * 2 * (N - 1) * (N - 1)];
    unsigned seed = 7;
    for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
            double *p = xyz + 3 * (j * N + i);
            const int inside = i > 0 && i < N - 1 && j > 0 && j < N - 1;
            seed = seed * 1103515245u + 12345u;
            p[0] = (i + (inside ? 0.3 * ((seed >> 16) / 65536.0 - 0.5) : 0)) / (N - 1);
            seed = seed * 1103515245u + 12345u;
            p[1] = (j + (inside ? 0.3 * ((seed >> 16) / 65536.0 - 0.5) : 0)) / (N - 1);
            p[2] = 0;
        }
    int32_t ntris = 0;
    for (int j = 0; j + 1 < N; ++j)
        for (int i = 0; i + 1 < N; ++i) {
            const int32_t a = j * N + i, b = a + 1, c = a + N + 1, d = a + N;
            const int32_t quad[6] = {a, b, c, a, c, d};
            for (int k = 0; k < 6; ++k)
                tris[3 * ntris + k] = quad[k];
            ntris += 2;
        }

    sfa_surface *s = NULL;
    if (sfa_create(&s) != SFA_OK)
        return 1;
    int ok = check(s, sfa_set_mesh(s, N * N, xyz, ntris, tris, 0), "sfa_set_mesh");
    /* The coupler's own data, on the mesh as it read it. */
    double old_value[N * N];
    for (int v = 0; v < N * N; ++v)
        old_value[v] = temperature(xyz + 3 * v);

    ok = ok && check(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.5 / (N - 1)), "sfa_set_param");
    ok = ok && check(s, sfa_adapt(s), "sfa_adapt");
    int32_t nverts = 0, new_ntris = 0;
    ok = ok && check(s, sfa_get_counts(s, &nverts, &new_ntris), "sfa_get_counts");
    double *new_xyz = malloc(sizeof(double) * 3 * (size_t)nverts);
    double *weights = malloc(sizeof(double) * 3 * (size_t)nverts);
    int32_t *new_tris = malloc(sizeof(int32_t) * 3 * (size_t)new_ntris);
    int32_t *origin = malloc(sizeof(int32_t) * (size_t)nverts);
    ok = ok && new_xyz && weights && new_tris && origin;
    ok = ok && check(s, sfa_get_mesh(s, nverts, new_xyz, new_ntris, new_tris, 0), "sfa_get_mesh");
    ok = ok && check(s, sfa_get_vertex_origins(s, nverts, origin, weights, 0), "sfa_get_vertex_origins");

    /* Carry: the old values at the corners of each vertex's old triangle, weighted. */
    double worst_position = 0, worst_exact = 0;
    for (int32_t v = 0; ok && v < nverts; ++v) {
        const int32_t *t = tris + 3 * origin[v];
        double carried = 0, at[3] = {0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            carried += weights[3 * v + k] * old_value[t[k]];
            for (int c = 0; c < 3; ++c)
                at[c] += weights[3 * v + k] * xyz[3 * t[k] + c];
        }
        for (int c = 0; c < 3; ++c)
            worst_position = fmax(worst_position, fabs(at[c] - new_xyz[3 * v + c]));
        worst_exact = fmax(worst_exact, fabs(carried - temperature(new_xyz + 3 * v)));
    }
    if (ok) {
        printf("sfa_adapt: %d -> %d vertices; each new vertex is where its origin says to %.1e,\n", N * N, nverts,
               worst_position);
        printf("and the temperature carried there differs from the exact one by at most %.2e\n", worst_exact);
        printf("(the old mesh's interpolation error, edge length %.3f)\n", 1.0 / (N - 1));
        ok = worst_position < 1e-12 && worst_exact < 0.05;
    }
    free(new_xyz);
    free(weights);
    free(new_tris);
    free(origin);
    sfa_destroy(s);
    printf("coupler-host: %d passed, %d failed\n", ok, !ok);
    return ok ? 0 : 1;
}
