/* SPDX-License-Identifier: BSD-3-Clause */
/* The contract every fuzz harness checks after each call of the library (README,
 * "Reliability"): the status is one the header defines and never SFA_ERR_INTERNAL (a
 * bug); a failed call has a message and left the surface exactly as it was (every getter
 * gives the same bits); a successful one has an empty message and leaves a valid mesh
 * (indices in range, finite coordinates). A violation aborts, which libFuzzer reports
 * with the input that caused it. */
#ifndef SURFADAPT_FUZZ_CONTRACT_H
#define SURFADAPT_FUZZ_CONTRACT_H

#include "support/shapes.h"
#include "surfadapt.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define FUZZ_REQUIRE(cond, ...)                                                                                        \
    do {                                                                                                               \
        if (!(cond)) {                                                                                                 \
            fprintf(stderr, "contract violated at %s:%d: ", __FILE__, __LINE__);                                     \
            fprintf(stderr, __VA_ARGS__);                                                                              \
            fprintf(stderr, "\n");                                                                                     \
            abort();                                                                                                   \
        }                                                                                                              \
    } while (0)

/* The mesh the surface holds, if any, is valid. */
static inline void fuzz_check_mesh(const sfa_surface *s)
{
    int32_t nv = 0, nt = 0;
    FUZZ_REQUIRE(sfa_get_counts(s, &nv, &nt) == SFA_OK, "sfa_get_counts: %s", sfa_last_error(s));
    FUZZ_REQUIRE(nv >= 0 && nt >= 0, "counts %d %d", nv, nt);
    if (nv == 0 && nt == 0)
        return; /* no mesh yet */
    double *xyz = malloc(sizeof(double) * 3 * (size_t)(nv + 1));
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)(nt + 1));
    FUZZ_REQUIRE(sfa_get_mesh(s, nv, xyz, nt, tris, 0) == SFA_OK, "sfa_get_mesh after sfa_get_counts: %s",
                 sfa_last_error(s));
    for (int32_t i = 0; i < 3 * nv; ++i)
        FUZZ_REQUIRE(isfinite(xyz[i]), "coordinate %d is %g", i, xyz[i]);
    for (int32_t i = 0; i < 3 * nt; ++i)
        FUZZ_REQUIRE(tris[i] >= 0 && tris[i] < nv, "triangle corner %d is %d of %d vertices", i, tris[i], nv);
    free(xyz);
    free(tris);
}

/* The status is one the header defines, not SFA_ERR_INTERNAL, and the message fits it. */
static inline void fuzz_check_status(const sfa_surface *s, int rc, const char *what)
{
    FUZZ_REQUIRE(rc >= SFA_OK && rc <= SFA_ERR_INTERNAL, "%s returned %d, not a status", what, rc);
    FUZZ_REQUIRE(rc != SFA_ERR_INTERNAL, "%s: internal error: %s", what, sfa_last_error(s));
    const char *message = sfa_last_error(s);
    FUZZ_REQUIRE(message != NULL, "%s: sfa_last_error is NULL", what);
    if (rc == SFA_OK)
        FUZZ_REQUIRE(message[0] == '\0', "%s: SFA_OK with the message \"%s\"", what, message);
    else
        FUZZ_REQUIRE(message[0] != '\0', "%s: status %d with no message", what, rc);
}

/* Checks the call that returned `rc`, given a snapshot taken just before it. */
static inline void fuzz_check_call(const sfa_surface *s, int rc, const snapshot *before, const char *what)
{
    fuzz_check_status(s, rc, what);
    if (rc != SFA_OK) {
        snapshot after;
        char why[256];
        snapshot_take(s, &after);
        FUZZ_REQUIRE(snapshot_equal(before, &after, why, sizeof why), "%s failed (%d) and changed the surface: %s",
                     what, rc, why);
        snapshot_free(&after);
    }
    fuzz_check_mesh(s);
}

/* Runs `call` (an expression using s) and checks it against the contract. */
#define FUZZ_CALL(s, call)                                                                                             \
    do {                                                                                                               \
        snapshot before_;                                                                                              \
        snapshot_take((s), &before_);                                                                                  \
        const int rc_ = (call);                                                                                        \
        fuzz_check_call((s), rc_, &before_, #call);                                                                    \
        snapshot_free(&before_);                                                                                       \
    } while (0)

/* The number of pairs of triangles that cross (SFA_MEASURE_SELF_INTERSECTIONS). */
static inline double fuzz_crossings(const sfa_surface *s)
{
    double count = 0;
    FUZZ_REQUIRE(sfa_measure(s, SFA_MEASURE_SELF_INTERSECTIONS, &count) == SFA_OK, "sfa_measure: %s",
                 sfa_last_error(s));
    return count;
}

/* Runs `call`, a smoothing or adaptation, checks it, and, if it succeeded on a surface
 * that did not cross itself, that it does not now: no operation may return SFA_OK with a
 * surface passing through itself that did not before (unless the host switched off the
 * check that keeps it so, SFA_PARAM_CROSSING_GUARD). */
#define FUZZ_REMESH(s, call)                                                                                           \
    do {                                                                                                               \
        double guard_ = 1;                                                                                             \
        sfa_get_param((s), SFA_PARAM_CROSSING_GUARD, &guard_);                                                         \
        const double crossings_before_ = guard_ != 0 ? fuzz_crossings(s) : -1;                                         \
        snapshot before_;                                                                                              \
        snapshot_take((s), &before_);                                                                                  \
        const int rc_ = (call);                                                                                        \
        fuzz_check_call((s), rc_, &before_, #call);                                                                    \
        snapshot_free(&before_);                                                                                       \
        if (rc_ == SFA_OK && crossings_before_ == 0)                                                                   \
            FUZZ_REQUIRE(fuzz_crossings(s) == 0, "%s returned SFA_OK and left the surface crossing itself", #call); \
    } while (0)

/* Runs a read-only query (the surface is const to it) and checks its status and message.
 * That it changed nothing, failed or not, is checked once for the whole batch of queries
 * (fuzz_query_everything): a snapshot per query, each reading every getter, cost most of
 * a fuzzing run. */
#define FUZZ_QUERY(s, call)                                                                                            \
    do {                                                                                                               \
        const int rc_ = (call);                                                                                        \
        fuzz_check_status((s), rc_, #call);                                                                            \
    } while (0)

/* Every read-only query of a surface, each checked; the surface is the same after them all. */
static inline void fuzz_query_everything(sfa_surface *s)
{
    snapshot before, after;
    char why[256];
    snapshot_take(s, &before);
    int32_t nv = 0, nt = 0;
    FUZZ_QUERY(s, sfa_get_counts(s, &nv, &nt));
    const size_t n = (size_t)(nv > 0 ? nv : 1), m = (size_t)(nt > 0 ? nt : 1);
    double value = 0, *d3 = malloc(sizeof(double) * 3 * n), *e3 = malloc(sizeof(double) * 3 * n);
    double *s2 = malloc(sizeof(double) * 2 * n), *b3 = malloc(sizeof(double) * 3 * n);
    int32_t *i1 = malloc(sizeof(int32_t) * n), *edges = malloc(sizeof(int32_t) * 6 * m), count = 0;
    for (int q = 0; q <= SFA_MEASURE_MIN_ANGLE_RESOLVED; ++q) {
        FUZZ_QUERY(s, sfa_measure(s, q, &value));
        FUZZ_QUERY(s, sfa_measure_component(s, 0, q, &value));
    }
    FUZZ_QUERY(s, sfa_get_component_count(s, &count));
    FUZZ_QUERY(s, sfa_get_components(s, nv, i1));
    FUZZ_QUERY(s, sfa_get_feature_ranks(s, nv, i1));
    FUZZ_QUERY(s, sfa_get_vertex_frames(s, nv, d3, e3, s2));
    FUZZ_QUERY(s, sfa_get_ridge_edges(s, 3 * nt, edges, &count, 0));
    FUZZ_QUERY(s, sfa_get_vertex_origins(s, nv, i1, b3, 0));
    free(d3);
    free(e3);
    free(s2);
    free(b3);
    free(i1);
    free(edges);
    snapshot_take(s, &after);
    FUZZ_REQUIRE(snapshot_equal(&before, &after, why, sizeof why), "the queries changed the surface: %s", why);
    fuzz_check_mesh(s);
    snapshot_free(&before);
    snapshot_free(&after);
}

/* Reads little bytes from a fuzzer's input, zeros once it runs out. */
typedef struct fuzz_input {
    const uint8_t *data;
    size_t size, at;
} fuzz_input;

static inline uint8_t fuzz_byte(fuzz_input *in) { return in->at < in->size ? in->data[in->at++] : 0; }
static inline int fuzz_more(const fuzz_input *in) { return in->at < in->size; }
static inline double fuzz_raw_double(fuzz_input *in)
{
    uint64_t bits = 0;
    for (int k = 0; k < 8; ++k)
        bits = bits << 8 | fuzz_byte(in);
    double x;
    memcpy(&x, &bits, sizeof x);
    return x;
}
/* A small coordinate on a 1/64 grid in [-2, 2): most inputs are then meshes of sensible
 * size, with exact coincidences and collinearities among them. */
static inline double fuzz_small(fuzz_input *in) { return ((int)fuzz_byte(in) - 128) / 64.0; }

#endif
