/* SPDX-License-Identifier: BSD-3-Clause */
/* Benchmarks of the quadric analysis: feature detection (sfa_get_feature_ranks) and the
 * per-vertex metric frames (sfa_get_vertex_frames) on icospheres of growing size. One JSON
 * line per case: the median of several runs, in seconds and nanoseconds per vertex. The
 * largest sphere (level 9, 2.6 million vertices) is measured only if one run is quick
 * enough that the whole case stays within a time budget; otherwise its line says why not. */
#define _POSIX_C_SOURCE 199309L
#include "icosphere.h"
#include "timing.h"

#include "surfadapt.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { runs = 5 };

/* Seconds one case (all its runs) may take before the largest level is left out. */
static const double budget_s = 20.0;

static void report(const char *name, int32_t nverts, int32_t ntris, double seconds)
{
    printf("{\"bench\":\"%s\",\"vertices\":%d,\"triangles\":%d,\"median_s\":%.6f,\"ns_per_vertex\":%.2f,"
           "\"runs\":%d}\n",
           name, nverts, ntris, seconds, 1e9 * seconds / nverts, runs);
    fflush(stdout);
}

static void skipped(const char *name, int32_t nverts, int32_t ntris, double one_s)
{
    printf("{\"bench\":\"%s\",\"vertices\":%d,\"triangles\":%d,\"skipped\":\"one run took %.2f s; %d runs "
           "exceed the %.0f s budget\"}\n",
           name, nverts, ntris, one_s, runs, budget_s);
    fflush(stdout);
}

/* The two calls benchmarked, with their outputs. */
typedef struct outputs {
    int32_t *ranks;
    double *normals, *long_directions, *aspect_ratios;
} outputs;

static int ranks_call(const sfa_surface *s, int32_t nverts, outputs *o)
{
    return sfa_get_feature_ranks(s, nverts, o->ranks);
}

static int frames_call(const sfa_surface *s, int32_t nverts, outputs *o)
{
    return sfa_get_vertex_frames(s, nverts, o->normals, o->long_directions, o->aspect_ratios);
}

/* Runs one case; returns 0, or 1 if a call failed. */
static int run_case(const char *name, int (*call)(const sfa_surface *, int32_t, outputs *), const sfa_surface *s,
                    int32_t nverts, int32_t ntris, outputs *o, int guarded)
{
    double samples[runs];
    /* One run first, not counted: it touches the output pages for the first time. Its time
     * decides whether a guarded case fits in the budget. */
    for (int r = -1; r < runs; ++r) {
        const double t0 = now();
        if (call(s, nverts, o) != SFA_OK) {
            fprintf(stderr, "%s: %s\n", name, sfa_last_error(s));
            return 1;
        }
        const double seconds = now() - t0;
        if (r < 0 && guarded && seconds * runs > budget_s) {
            skipped(name, nverts, ntris, seconds);
            return 0;
        }
        if (r >= 0)
            samples[r] = seconds;
    }
    report(name, nverts, ntris, median(samples, runs));
    return 0;
}

int main(void)
{
    const double center[3] = {0, 0, 0};
    const int levels[] = {5, 7, 8, 9};
    for (size_t i = 0; i < sizeof levels / sizeof levels[0]; ++i) {
        const int level = levels[i], guarded = level >= 9;
        int32_t nverts, ntris;
        double *xyz;
        int32_t *tris;
        if (icosphere(level, 1.0, center, &nverts, &xyz, &ntris, &tris) != 0) {
            if (guarded) { /* not enough memory for the optional largest case */
                printf("{\"bench\":\"analysis\",\"level\":%d,\"skipped\":\"out of memory\"}\n", level);
                break;
            }
            return 1;
        }
        sfa_surface *s;
        if (sfa_create(&s) != SFA_OK)
            return 1;
        const int rc = sfa_set_mesh(s, nverts, xyz, ntris, tris, 0);
        free(xyz);
        free(tris);
        if (rc != SFA_OK) {
            fprintf(stderr, "sfa_set_mesh: %s\n", sfa_last_error(s));
            return 1;
        }
        outputs o;
        o.ranks = malloc(sizeof(int32_t) * (size_t)nverts);
        o.normals = malloc(sizeof(double) * 3 * (size_t)nverts);
        o.long_directions = malloc(sizeof(double) * 3 * (size_t)nverts);
        o.aspect_ratios = malloc(sizeof(double) * (size_t)nverts);
        if (!o.ranks || !o.normals || !o.long_directions || !o.aspect_ratios)
            return 1;
        if (run_case("feature_ranks", ranks_call, s, nverts, ntris, &o, guarded) ||
            run_case("vertex_frames", frames_call, s, nverts, ntris, &o, guarded))
            return 1;
        free(o.ranks);
        free(o.normals);
        free(o.long_directions);
        free(o.aspect_ratios);
        sfa_destroy(s);
    }
    return 0;
}
