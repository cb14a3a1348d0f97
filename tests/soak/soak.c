/* SPDX-License-Identifier: BSD-3-Clause */
/* The soak (issue 18): random valid surfaces through random sequences of motion,
 * smoothing and adaptation, for a given time, checking after every call what the header
 * promises.
 *
 *   soak --seconds N [--seed S] [--iterations K] [--call-limit SECONDS]
 *   soak --seed S --replay
 *   soak --seeds FILE
 *
 * Each iteration (one surface and its calls) is drawn from its own seed and runs in a
 * child process: a crash or a hang in the library then costs that iteration alone, and is
 * reported with the seed that replays it (`--seed S --replay` runs that one iteration in
 * this process, printing every call). The parent never calls the library, so forking
 * does not meet OpenMP's thread pool. `--seeds FILE` runs the iterations of the seeds in
 * FILE (tests/soak/fixed_seeds: the findings since mended, which `make check` replays).
 *
 * What is checked after every call, and where the header promises it:
 *  - the contract (tests/fuzz/contract.h, as the fuzzers check it): a status the header
 *    defines and never SFA_ERR_INTERNAL; a message exactly when it failed; after a failure
 *    every getter gives the same bits as before; after success a finite, in-range mesh;
 *  - the statuses each call documents: motion may refuse a step (SFA_ERR_NUMERIC), which
 *    is counted, not a finding; smoothing and adaptation of a valid surface must succeed;
 *  - the mesh read back is accepted by sfa_set_mesh on a fresh handle (valid, manifold,
 *    oriented, no zero-area triangle);
 *  - motion and smoothing keep the connectivity; dt_taken lies in [1e-12 dt, dt];
 *  - no new self-intersections from sfa_smooth/sfa_adapt with SFA_PARAM_CROSSING_GUARD on,
 *    nor from motion with SFA_PARAM_COLLISION_SAFE_MOTION or SFA_PARAM_TOPOLOGY_CHANGE on,
 *    on a surface that did not cross itself; crossings where the host switched the
 *    protection off are counted as observations;
 *  - sfa_smooth/sfa_adapt keep every closed component's volume (volume correction on):
 *    without topology events the components are the same (matched through
 *    sfa_get_vertex_origins) and each keeps its volume to round-off; with events the total
 *    changes by at most what SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE reports;
 *  - a call that takes longer than the call limit (30 s) is a hang.
 * Volume drift under divergence-free motion is the time integration's error, reported as
 * an observation. */
#define _POSIX_C_SOURCE 200809L
#include "contract.h"
#include "surfaces.h"

#include <errno.h>
#include <inttypes.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void *xmalloc(size_t n)
{
    void *p = malloc(n ? n : 1);
    FUZZ_REQUIRE(p != NULL, "out of memory (%zu bytes)", n);
    return p;
}

/* =========================================================== one iteration (child) */

/* Lines the child writes for the parent start with '@': "@call N OP ARGS" before a call,
 * "@done N OP STATUS SECONDS" after it, "@count KEY N" and "@max KEY VALUE" for
 * observations, "@finding KIND MESSAGE" for a broken promise (then the child exits 3).
 * Anything else (contract.h's message before it aborts) is kept for the report. */
#define SOAK_FIND(kind, ...)                                                                                           \
    do {                                                                                                               \
        printf("@finding %s ", kind);                                                                                  \
        printf(__VA_ARGS__);                                                                                           \
        printf("\n");                                                                                                  \
        fflush(stdout);                                                                                                \
        exit(3);                                                                                                       \
    } while (0)

/* The tolerance of "to round-off" for a volume: 1e-9 relative, or more where the
 * coordinates themselves resolve the shape less finely: a component of area A and volume V
 * whose coordinates are as large as M can be moved by eps M per vertex by rounding alone,
 * which changes V by about eps M A. */
static double volume_tolerance(double volume, double area, double maxabs)
{
    return 1e-9 + 1e3 * 2.2e-16 * maxabs * area / fabs(volume);
}

/* One component of the mesh as the public API shows it. */
typedef struct component {
    int closed;
    double volume, area, maxabs;
} component;

/* The mesh, its components and their measures, read through the public API. */
typedef struct view {
    sfa_mesh_data m;
    int32_t ncomp;
    int32_t *vertex_component;
    component *c;
    int all_closed;
} view;

static int compare_u64(const void *a, const void *b)
{
    const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return x < y ? -1 : x > y;
}

static view view_take(const sfa_surface *s)
{
    view v;
    memset(&v, 0, sizeof v);
    FUZZ_REQUIRE(sfa_get_counts(s, &v.m.nverts, &v.m.ntris) == SFA_OK, "sfa_get_counts: %s", sfa_last_error(s));
    v.m.xyz = xmalloc(sizeof(double) * 3 * (size_t)v.m.nverts);
    v.m.tris = xmalloc(sizeof(int32_t) * 3 * (size_t)v.m.ntris);
    FUZZ_REQUIRE(sfa_get_mesh(s, v.m.nverts, v.m.xyz, v.m.ntris, v.m.tris, 0) == SFA_OK, "sfa_get_mesh: %s",
                 sfa_last_error(s));
    FUZZ_REQUIRE(sfa_get_component_count(s, &v.ncomp) == SFA_OK, "sfa_get_component_count: %s", sfa_last_error(s));
    v.vertex_component = xmalloc(sizeof(int32_t) * (size_t)v.m.nverts);
    FUZZ_REQUIRE(sfa_get_components(s, v.m.nverts, v.vertex_component) == SFA_OK, "sfa_get_components: %s",
                 sfa_last_error(s));
    v.c = xmalloc(sizeof(component) * (size_t)v.ncomp);
    for (int32_t c = 0; c < v.ncomp; ++c) {
        v.c[c].closed = 1;
        v.c[c].maxabs = 0;
        FUZZ_REQUIRE(sfa_measure_component(s, c, SFA_MEASURE_VOLUME, &v.c[c].volume) == SFA_OK,
                     "sfa_measure_component: %s", sfa_last_error(s));
        FUZZ_REQUIRE(sfa_measure_component(s, c, SFA_MEASURE_AREA, &v.c[c].area) == SFA_OK,
                     "sfa_measure_component: %s", sfa_last_error(s));
    }
    for (int32_t i = 0; i < v.m.nverts; ++i) {
        const int32_t c = v.vertex_component[i];
        FUZZ_REQUIRE(c >= 0 && c < v.ncomp, "vertex %d is in component %d of %d", (int)i, (int)c, (int)v.ncomp);
        for (int k = 0; k < 3; ++k)
            v.c[c].maxabs = fmax(v.c[c].maxabs, fabs(v.m.xyz[3 * i + k]));
    }
    /* An edge used by one triangle only is on a boundary: its component is open. */
    const size_t ne = 3 * (size_t)v.m.ntris;
    uint64_t *edges = xmalloc(sizeof(uint64_t) * ne);
    for (int32_t t = 0; t < v.m.ntris; ++t)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = (uint32_t)v.m.tris[3 * t + k], b = (uint32_t)v.m.tris[3 * t + (k + 1) % 3];
            edges[3 * (size_t)t + (size_t)k] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
        }
    qsort(edges, ne, sizeof *edges, compare_u64);
    for (size_t i = 0; i < ne;) {
        size_t j = i + 1;
        while (j < ne && edges[j] == edges[i])
            ++j;
        if (j - i == 1)
            v.c[v.vertex_component[edges[i] >> 32]].closed = 0;
        i = j;
    }
    free(edges);
    v.all_closed = 1;
    for (int32_t c = 0; c < v.ncomp; ++c)
        v.all_closed &= v.c[c].closed;
    return v;
}

static void view_free(view *v)
{
    mesh_free(&v->m);
    free(v->vertex_component);
    free(v->c);
    memset(v, 0, sizeof *v);
}

static double crossings(const sfa_surface *s)
{
    double n = -1;
    FUZZ_REQUIRE(sfa_measure(s, SFA_MEASURE_SELF_INTERSECTIONS, &n) == SFA_OK, "sfa_measure: %s", sfa_last_error(s));
    return n;
}

static double measure(const sfa_surface *s, int q)
{
    double value = 0;
    FUZZ_REQUIRE(sfa_measure(s, q, &value) == SFA_OK, "sfa_measure(%d): %s", q, sfa_last_error(s));
    return value;
}

static double param(const sfa_surface *s, int key)
{
    double value = 0;
    FUZZ_REQUIRE(sfa_get_param(s, key, &value) == SFA_OK, "sfa_get_param(%d): %s", key, sfa_last_error(s));
    return value;
}

/* The state of one iteration. */
typedef struct run {
    sfa_surface *s;
    shapes_rng rng;
    soak_surface surface;
    int calls;
    double time;          /* of the periodic flows */
    double call_limit;    /* seconds */
    const char *dump;     /* replay: write the mesh before each call to DUMP-N.obj, velocities to DUMP-N.vel */
    /* What was true just before the current call. */
    snapshot snap;
    view before;
    double crossings_before;
    double t0;
    char op[16];
} run;

/* Logs the call and records what the checks after it compare against. */
static void call_begin(run *r, const char *op, const char *fmt, ...)
{
    char args[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(args, sizeof args, fmt, ap);
    va_end(ap);
    snprintf(r->op, sizeof r->op, "%s", op);
    printf("@call %d %s %s\n", r->calls, op, args);
    fflush(stdout);
    snapshot_take(r->s, &r->snap);
    r->before = view_take(r->s);
    if (r->dump) {
        char path[1024], err[256];
        snprintf(path, sizeof path, "%s-%d.obj", r->dump, r->calls);
        if (mesh_write_obj(path, &r->before.m, args, err, sizeof err) != 0)
            fprintf(stderr, "soak: %s\n", err);
    }
    r->crossings_before = crossings(r->s);
    r->t0 = now();
}

/* Replay with --dump: the velocities a "velocities" call sets, to DUMP-N.vel (one vertex's
 * x y z per line), beside the mesh in DUMP-N.obj. */
static void dump_velocities(const run *r, int32_t nv, const double *vel)
{
    if (!r->dump)
        return;
    char path[1024];
    snprintf(path, sizeof path, "%s-%d.vel", r->dump, r->calls);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "soak: cannot write %s\n", path);
        return;
    }
    for (int32_t v = 0; v < nv; ++v)
        fprintf(f, "%.17g %.17g %.17g\n", vel[3 * v], vel[3 * v + 1], vel[3 * v + 2]);
    fclose(f);
}

/* The contract (contract.h), the statuses the call documents, the time it took and the
 * validity of the mesh it leaves. Returns the status. */
static int call_end(run *r, int rc, int numeric_allowed)
{
    const double seconds = now() - r->t0;
    char message[512];
    snprintf(message, sizeof message, "%s", sfa_last_error(r->s));
    fuzz_check_call(r->s, rc, &r->snap, r->op);
    printf("@done %d %s %d %.6f\n", r->calls, r->op, rc, seconds);
    if (rc != SFA_OK)
        printf("@note %s: %s: %s\n", r->op, sfa_status_string(rc), message);
    fflush(stdout);
    ++r->calls;
    if (seconds > r->call_limit)
        SOAK_FIND("hang", "%s took %.1f s (limit %.0f s) on %d vertices", r->op, seconds, r->call_limit,
                  (int)r->before.m.nverts);
    /* Motion may refuse a step it cannot take without folding, colliding or leaving the
     * coordinate range; an allocation may fail anywhere. Nothing else is expected here,
     * where every argument is valid. */
    if (rc != SFA_OK && !(rc == SFA_ERR_NUMERIC && numeric_allowed) && rc != SFA_ERR_MEMORY)
        SOAK_FIND("status", "%s returned %s on a valid surface: %s", r->op, sfa_status_string(rc), message);
    if (rc == SFA_OK) {
        view after = view_take(r->s);
        sfa_surface *fresh = NULL;
        FUZZ_REQUIRE(sfa_create(&fresh) == SFA_OK, "sfa_create failed");
        const int accepted = sfa_set_mesh(fresh, after.m.nverts, after.m.xyz, after.m.ntris, after.m.tris, 0);
        if (accepted != SFA_OK)
            SOAK_FIND("invalid_mesh", "%s returned SFA_OK, but a fresh handle rejects the mesh it left (%d vertices): %s",
                      r->op, (int)after.m.nverts, sfa_last_error(fresh));
        sfa_destroy(fresh);
        printf("@max vertices %d\n", (int)after.m.nverts);
        view_free(&after);
    }
    return rc;
}

static void call_release(run *r)
{
    snapshot_free(&r->snap);
    view_free(&r->before);
}

static void require_same_connectivity(const run *r, const view *after)
{
    if (after->m.nverts != r->before.m.nverts || after->m.ntris != r->before.m.ntris ||
        memcmp(after->m.tris, r->before.m.tris, sizeof(int32_t) * 3 * (size_t)after->m.ntris) != 0)
        SOAK_FIND("connectivity", "%s changed the connectivity (%d/%d vertices/triangles before, %d/%d after)", r->op,
                  (int)r->before.m.nverts, (int)r->before.m.ntris, (int)after->m.nverts, (int)after->m.ntris);
}

/* Crossings after a call: a finding where the call promises none, else an observation. */
static void check_crossings(const run *r, int promised, const char *observation)
{
    const double after = crossings(r->s);
    if (r->crossings_before == 0 && after > 0) {
        if (promised)
            SOAK_FIND("crossing", "%s returned SFA_OK and left %.0f pairs of triangles crossing, none before", r->op,
                      after);
        printf("@count %s 1\n", observation);
    }
}

/* Component c of the view before the call kept its volume as component d after it. */
static void check_volume(const run *r, const view *after, int32_t c, int32_t d)
{
    const component *o = &r->before.c[c], *n = &after->c[d];
    if (!o->closed || !n->closed)
        return;
    const double rel = fabs(n->volume - o->volume) / fabs(o->volume);
    const double tol = volume_tolerance(o->volume, o->area, fmax(o->maxabs, n->maxabs));
    /* The header lets the correction be withheld (a component it would fold or carry
     * through another sheet, or one with no smooth vertex) if SFA_MEASURE_VOLUME_LEFT says
     * so: counted, not a finding, when the change is no more than what it reports. */
    const double left = measure(r->s, SFA_MEASURE_VOLUME_LEFT);
    if (!(rel <= tol) && rel <= left * (1 + 1e-6) + tol) {
        printf("@count volume_withheld_and_reported 1\n");
        printf("@max volume_withheld %.3e\n", rel);
        return;
    }
    /* Far above round-off the correction was not made at all (SFA_MEASURE_VOLUME_CORRECTION
     * then reports the same change); told apart so that a long run shows both kinds. */
    if (!(rel <= tol) && rel > 1e-6)
        SOAK_FIND("volume_uncorrected", "%s changed the volume of closed component %d (%d after) from %.17g to %.17g: "
                  "relative %.3e; the operations alone moved a volume by %.3e (SFA_MEASURE_VOLUME_CORRECTION)",
                  r->op, (int)c, (int)d, o->volume, n->volume, rel, measure(r->s, SFA_MEASURE_VOLUME_CORRECTION));
    if (!(rel <= tol))
        SOAK_FIND("volume", "%s changed the volume of closed component %d (%d after) from %.17g to %.17g: relative %.3e, "
                  "tolerance %.3e",
                  r->op, (int)c, (int)d, o->volume, n->volume, rel, tol);
    /* The figures of the checks that passed: how close to round-off the volumes are kept. */
    printf("@max remesh_volume_error %.3e\n", rel);
    printf("@max remesh_volume_error_per_tolerance %.3e\n", rel / tol);
}

/* ------------------------------------------------------------------ the operations */

static void op_motion(run *r, int advect)
{
    soak_flow f = soak_random_flow(&r->rng, &r->surface);
    const double span = 0.02 + 0.4 * rng_uniform(&r->rng);
    const int protected_motion = param(r->s, SFA_PARAM_COLLISION_SAFE_MOTION) != 0 ||
                                 param(r->s, SFA_PARAM_TOPOLOGY_CHANGE) != 0;
    double left = span;
    for (int step = 0; step < 6 && left > 1e-9 * span; ++step) {
        const char *op = advect ? "advect" : "move";
        double taken = 0;
        int rc;
        if (advect) {
            call_begin(r, op, "flow=%s t=%.17g dt=%.17g", soak_flow_name(f.kind), r->time, left);
            rc = sfa_advect(r->s, soak_flow_eval, &f, r->time, left, &taken);
        } else {
            /* The host's explicit step: velocities at the vertices, then sfa_move. */
            int32_t nv = 0, nt = 0;
            sfa_get_counts(r->s, &nv, &nt);
            double *xyz = xmalloc(sizeof(double) * 3 * (size_t)nv), *vel = xmalloc(sizeof(double) * 3 * (size_t)nv);
            int32_t *tris = xmalloc(sizeof(int32_t) * 3 * (size_t)nt);
            FUZZ_REQUIRE(sfa_get_mesh(r->s, nv, xyz, nt, tris, 0) == SFA_OK, "sfa_get_mesh: %s", sfa_last_error(r->s));
            free(tris);
            soak_flow_eval(&f, nv, xyz, r->time, vel);
            call_begin(r, "velocities", "flow=%s t=%.17g", soak_flow_name(f.kind), r->time);
            dump_velocities(r, nv, vel);
            call_end(r, sfa_set_velocities_checked(r->s, nv, vel), 0);
            call_release(r);
            free(xyz);
            free(vel);
            call_begin(r, op, "dt=%.17g", left);
            rc = sfa_move(r->s, left, &taken);
        }
        rc = call_end(r, rc, 1);
        if (rc == SFA_OK) {
            view after = view_take(r->s);
            require_same_connectivity(r, &after);
            if (!(taken >= 1e-12 * left && taken <= left))
                SOAK_FIND("contract", "%s: dt_taken %.17g outside [1e-12 dt, dt], dt %.17g", op, taken, left);
            check_crossings(r, protected_motion, "motion_crossings_unprotected");
            if (soak_flow_divergence_free(f.kind))
                for (int32_t c = 0; c < after.ncomp; ++c)
                    if (r->before.c[c].closed)
                        printf("@max motion_volume_drift %.3e\n",
                               fabs(after.c[c].volume - r->before.c[c].volume) / fabs(r->before.c[c].volume));
            view_free(&after);
            left -= taken;
            r->time += taken;
        } else {
            printf("@count motion_refused 1\n");
        }
        call_release(r);
        if (rc != SFA_OK)
            break;
    }
}

static void op_smooth(run *r)
{
    const int iterations = 1 + (int)(rng_next(&r->rng) % 3);
    call_begin(r, "smooth", "iterations=%d", iterations);
    const int rc = call_end(r, sfa_smooth(r->s, iterations), 0);
    if (rc == SFA_OK) {
        view after = view_take(r->s);
        require_same_connectivity(r, &after);
        check_crossings(r, param(r->s, SFA_PARAM_CROSSING_GUARD) != 0, "remesh_crossings_unguarded");
        if (param(r->s, SFA_PARAM_VOLUME_CORRECTION) != 0)
            for (int32_t c = 0; c < after.ncomp; ++c) /* numbering unchanged with the vertex order */
                check_volume(r, &after, c, c);
        view_free(&after);
    }
    call_release(r);
}

static void op_adapt(run *r)
{
    int32_t nv = 0;
    sfa_get_counts(r->s, &nv, NULL);
    if (nv > 40000) /* keeps an iteration bounded when the edge length asked for is small */
        return;
    call_begin(r, "adapt", "");
    const int rc = call_end(r, sfa_adapt(r->s), 0);
    if (rc == SFA_OK) {
        view after = view_take(r->s);
        check_crossings(r, param(r->s, SFA_PARAM_CROSSING_GUARD) != 0, "remesh_crossings_unguarded");
        const double merges = measure(r->s, SFA_MEASURE_MERGES), pinches = measure(r->s, SFA_MEASURE_PINCHES),
                     drops = measure(r->s, SFA_MEASURE_DROPS_REMOVED);
        const double topo_change = measure(r->s, SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE);
        printf("@note adapt: %d -> %d vertices, %d -> %d components, operations moved a volume by %.3e before the "
               "correction (%.3e left), %.0f merges, %.0f pinches, %.0f drops removed\n",
               (int)r->before.m.nverts, (int)after.m.nverts, (int)r->before.ncomp, (int)after.ncomp,
               measure(r->s, SFA_MEASURE_VOLUME_CORRECTION), measure(r->s, SFA_MEASURE_VOLUME_LEFT), merges, pinches,
               drops);
        if (merges + pinches + drops > 0) {
            printf("@count merges %.0f\n@count pinches %.0f\n@count drops_removed %.0f\n", merges, pinches, drops);
            if (param(r->s, SFA_PARAM_TOPOLOGY_CHANGE) == 0)
                SOAK_FIND("components", "adapt made %.0f merges, %.0f pinches, removed %.0f drops without topology change",
                          merges, pinches, drops);
            /* The events change the volume by at most what they report; the rest keeps it. */
            if (r->before.all_closed && after.all_closed && param(r->s, SFA_PARAM_VOLUME_CORRECTION) != 0) {
                double vo = 0, vn = 0, area = 0, maxabs = 0;
                for (int32_t c = 0; c < r->before.ncomp; ++c) {
                    vo += r->before.c[c].volume;
                    area += r->before.c[c].area;
                    maxabs = fmax(maxabs, r->before.c[c].maxabs);
                }
                double magnitude = 0; /* of the volumes after: what VOLUME_LEFT is relative to */
                for (int32_t c = 0; c < after.ncomp; ++c) {
                    vn += after.c[c].volume;
                    magnitude += fabs(after.c[c].volume);
                }
                const double excess = fabs(vn - vo) - topo_change;
                const double tolerance = volume_tolerance(vo, area, maxabs) * fabs(vo);
                /* A correction withheld after the events, as check_volume allows it: no
                 * component's volume V is more than SFA_MEASURE_VOLUME_LEFT = l of its target
                 * V0 away from it, and |V0| <= |V| / (1 - l). */
                const double l = measure(r->s, SFA_MEASURE_VOLUME_LEFT);
                const double left = l < 1 ? l / (1 - l) * (1 + 1e-6) * magnitude : INFINITY;
                if (!(excess <= tolerance) && excess <= left + tolerance) {
                    printf("@count volume_withheld_and_reported 1\n");
                    printf("@max volume_withheld %.3e\n", l);
                } else if (!(excess <= tolerance))
                    SOAK_FIND("volume", "adapt with topology events changed the total volume from %.17g to %.17g, "
                              "%.3e more than the %.3e its events report",
                              vo, vn, excess, topo_change);
            }
        } else {
            /* Same components: match each new one to the old one its first vertex came from. */
            if (after.ncomp != r->before.ncomp)
                SOAK_FIND("components", "adapt changed the number of components from %d to %d without topology events",
                          (int)r->before.ncomp, (int)after.ncomp);
            int32_t *triangle = xmalloc(sizeof(int32_t) * (size_t)after.m.nverts);
            double *bary = xmalloc(sizeof(double) * 3 * (size_t)after.m.nverts);
            FUZZ_REQUIRE(sfa_get_vertex_origins(r->s, after.m.nverts, triangle, bary, 0) == SFA_OK,
                         "sfa_get_vertex_origins: %s", sfa_last_error(r->s));
            int32_t *old_of = xmalloc(sizeof(int32_t) * (size_t)after.ncomp), *seen = xmalloc(sizeof(int32_t) * (size_t)after.ncomp);
            for (int32_t c = 0; c < after.ncomp; ++c)
                old_of[c] = -1, seen[c] = 0;
            for (int32_t v = 0; v < after.m.nverts; ++v) {
                const int32_t c = after.vertex_component[v], t = triangle[v];
                FUZZ_REQUIRE(t >= 0 && t < r->before.m.ntris, "vertex %d comes from triangle %d of %d", (int)v, (int)t,
                             (int)r->before.m.ntris);
                if (old_of[c] < 0)
                    old_of[c] = r->before.vertex_component[r->before.m.tris[3 * t]];
            }
            for (int32_t c = 0; c < after.ncomp; ++c) {
                if (old_of[c] < 0 || seen[old_of[c]]++)
                    SOAK_FIND("components", "adapt: component %d after it comes from component %d before, which another "
                              "component also comes from", (int)c, (int)old_of[c]);
                if (param(r->s, SFA_PARAM_VOLUME_CORRECTION) != 0)
                    check_volume(r, &after, old_of[c], c);
            }
            free(triangle);
            free(bary);
            free(old_of);
            free(seen);
        }
        view_free(&after);
    }
    call_release(r);
}

/* Sets a parameter, logged and checked like any call (the soak's values are all valid). */
static void set_param(run *r, int key, double value)
{
    call_begin(r, "param", "key=%d value=%.17g", key, value);
    call_end(r, sfa_set_param(r->s, key, value), 0);
    call_release(r);
}

static void run_iteration(uint64_t seed, double call_limit, const char *dump)
{
    run r;
    memset(&r, 0, sizeof r);
    r.dump = dump;
    r.rng = rng_seed(seed);
    r.call_limit = call_limit;
    r.surface = soak_random_surface(&r.rng);
    printf("@surface %s\n", r.surface.what);
    FUZZ_REQUIRE(sfa_create(&r.s) == SFA_OK, "sfa_create failed");
    const sfa_mesh_data *m = &r.surface.mesh;
    const int rc = sfa_set_mesh(r.s, m->nverts, m->xyz, m->ntris, m->tris, 0);
    if (rc != SFA_OK)
        SOAK_FIND("harness", "the generated surface (%s) is rejected: %s", r.surface.what, sfa_last_error(r.s));
    if (crossings(r.s) != 0)
        SOAK_FIND("harness", "the generated surface (%s) crosses itself", r.surface.what);
    const double mean_edge = measure(r.s, SFA_MEASURE_MEAN_EDGE_LENGTH);

    /* Random parameters, within the ranges the header gives. */
    shapes_rng *g = &r.rng;
    set_param(&r, SFA_PARAM_ANISOTROPIC, rng_uniform(g) < 0.7);
    if (rng_uniform(g) < 0.5)
        set_param(&r, SFA_PARAM_EDGE_LENGTH, mean_edge * pow(10, -0.2 + 0.5 * rng_uniform(g)));
    set_param(&r, SFA_PARAM_CROSSING_GUARD, rng_uniform(g) < 0.85);
    set_param(&r, SFA_PARAM_VOLUME_CORRECTION, rng_uniform(g) < 0.9);
    set_param(&r, SFA_PARAM_COLLISION_SAFE_MOTION, rng_uniform(g) < 0.3);
    if (rng_uniform(g) < 0.2) {
        set_param(&r, SFA_PARAM_TOPOLOGY_CHANGE, 1);
        set_param(&r, SFA_PARAM_MERGE_DISTANCE, 0.2 + rng_uniform(g));
    }
    if (rng_uniform(g) < 0.2)
        set_param(&r, SFA_PARAM_DENOISE, 0.5 * rng_uniform(g));
    set_param(&r, SFA_PARAM_ADAPT_PASSES, 1 + (double)(rng_next(g) % 8));
    if (rng_uniform(g) < 0.5)
        set_param(&r, SFA_PARAM_FOLD_SAFETY, 0.2 + 0.8 * rng_uniform(g));
    /* Keys added later draw from a stream of their own, and only for runs started after
     * they were (an iteration's seed is its run's seed times a million plus its number), so
     * that every seed recorded before (FINDINGS.md, fixed_seeds) replays as it did. */
    shapes_rng later = rng_seed(seed ^ 0x6c61746572ULL);
    if (seed / 1000000 > 20261210 && rng_uniform(&later) < 0.3)
        set_param(&r, SFA_PARAM_THIN_SHEET_EDGE_RATIO, 0.3 + 0.7 * rng_uniform(&later));

    /* Host data that must follow every call (and be unchanged by a failed one). */
    if (rng_uniform(g) < 0.5) {
        const int ncomp = 1 + (int)(rng_next(g) % 3);
        double *values = xmalloc(sizeof(double) * (size_t)ncomp * (size_t)m->nverts);
        for (int32_t v = 0; v < m->nverts; ++v)
            for (int c = 0; c < ncomp; ++c)
                values[ncomp * v + c] = (m->xyz[3 * v + c] - r.surface.centre[c]) / r.surface.size + c;
        int32_t id = -1;
        call_begin(&r, "field", "ncomp=%d", ncomp);
        call_end(&r, sfa_add_field_checked(r.s, m->nverts, ncomp, values, &id), 0);
        call_release(&r);
        free(values);
    }
    if (rng_uniform(g) < 0.15) {
        /* A size field varying by a factor of three over the surface. */
        const double base = mean_edge * pow(10, -0.1 + 0.4 * rng_uniform(g));
        double *sizes = xmalloc(sizeof(double) * (size_t)m->nverts);
        for (int32_t v = 0; v < m->nverts; ++v)
            sizes[v] = base * (1 + 0.5 * sin(3 * (m->xyz[3 * v] - r.surface.centre[0]) / r.surface.size));
        call_begin(&r, "size_field", "base=%.17g", base);
        call_end(&r, sfa_set_size_field_checked(r.s, m->nverts, sizes), 0);
        call_release(&r);
        free(sizes);
    }

    const int ops = 4 + (int)(rng_next(g) % 11);
    for (int k = 0; k < ops; ++k) {
        const double u = rng_uniform(g);
        if (u < 0.3)
            op_motion(&r, 0);
        else if (u < 0.55)
            op_motion(&r, 1);
        else if (u < 0.75)
            op_smooth(&r);
        else
            op_adapt(&r);
    }
    sfa_destroy(r.s);
    mesh_free(&r.surface.mesh);
    printf("@end\n");
    fflush(stdout);
}

/* ============================================================ the driver (parent) */

enum { KIND_CONTRACT, KIND_STATUS, KIND_INVALID_MESH, KIND_CONNECTIVITY, KIND_CROSSING, KIND_VOLUME,
       KIND_VOLUME_UNCORRECTED, KIND_COMPONENTS, KIND_HANG, KIND_CRASH, KIND_HARNESS, KINDS };
static const char *kind_names[KINDS] = {"contract", "status",     "invalid_mesh", "connectivity",
                                        "crossing", "volume",     "volume_uncorrected",
                                        "components", "hang",     "crash",        "harness"};

enum { OPS = 7 };
static const char *op_names[OPS] = {"param", "field", "size_field", "velocities", "move", "advect", "smooth"};

typedef struct totals {
    long executions, calls, refused, calls_by_op[OPS + 1];
    long failures[KINDS];
    double slowest;
    char slowest_op[32];
    uint64_t slowest_seed;
    /* observations */
    double remesh_volume_error, remesh_volume_error_per_tolerance, motion_volume_drift, largest, volume_withheld;
    long motion_crossings_unprotected, remesh_crossings_unguarded, merges, pinches, drops_removed,
        volume_withheld_and_reported;
    uint64_t withheld_seed[16];
    int nfindings;
    uint64_t finding_seed[64];
    int finding_kind[64];
} totals;

static int op_index(const char *op)
{
    for (int k = 0; k < OPS; ++k)
        if (strcmp(op, op_names[k]) == 0)
            return k;
    return OPS; /* adapt */
}

/* The child's output, kept whole for the report of a finding (bounded). */
typedef struct transcript {
    char *text;
    size_t len, cap;
} transcript;

static void transcript_add(transcript *t, const char *data, size_t n)
{
    if (t->len + n + 1 > t->cap) {
        if (t->len + n + 1 > ((size_t)64 << 20))
            return; /* a runaway child: what came before is enough */
        t->cap = 2 * (t->len + n + 1);
        t->text = realloc(t->text, t->cap);
        FUZZ_REQUIRE(t->text != NULL, "out of memory");
    }
    memcpy(t->text + t->len, data, n);
    t->len += n;
    t->text[t->len] = '\0';
}

/* Adds up one finished line of the child. */
static void account_line(totals *tot, const char *line, uint64_t seed, int *open_call, double *call_start,
                         int *finding_kind, char *finding_text, size_t finding_len)
{
    char op[32], key[64];
    int n = 0, status = 0;
    double value = 0;
    if (sscanf(line, "@call %d %31s", &n, op) == 2) {
        *open_call = 1;
        *call_start = now();
    } else if (sscanf(line, "@done %d %31s %d %lf", &n, op, &status, &value) == 4) {
        *open_call = 0;
        ++tot->calls;
        ++tot->calls_by_op[op_index(op)];
        if (status != SFA_OK)
            ++tot->refused;
        if (value > tot->slowest) {
            tot->slowest = value;
            snprintf(tot->slowest_op, sizeof tot->slowest_op, "%s", op);
            tot->slowest_seed = seed;
        }
    } else if (sscanf(line, "@count %63s %lf", key, &value) == 2) {
        if (strcmp(key, "motion_crossings_unprotected") == 0)
            tot->motion_crossings_unprotected += (long)value;
        else if (strcmp(key, "remesh_crossings_unguarded") == 0)
            tot->remesh_crossings_unguarded += (long)value;
        else if (strcmp(key, "merges") == 0)
            tot->merges += (long)value;
        else if (strcmp(key, "pinches") == 0)
            tot->pinches += (long)value;
        else if (strcmp(key, "drops_removed") == 0)
            tot->drops_removed += (long)value;
        else if (strcmp(key, "volume_withheld_and_reported") == 0) {
            /* The seeds of the first few, to look at what the correction still leaves. */
            if (tot->volume_withheld_and_reported < 16)
                tot->withheld_seed[tot->volume_withheld_and_reported] = seed;
            tot->volume_withheld_and_reported += (long)value;
        }
    } else if (sscanf(line, "@max %63s %lf", key, &value) == 2) {
        double *slot = strcmp(key, "remesh_volume_error") == 0                 ? &tot->remesh_volume_error
                       : strcmp(key, "remesh_volume_error_per_tolerance") == 0 ? &tot->remesh_volume_error_per_tolerance
                       : strcmp(key, "motion_volume_drift") == 0               ? &tot->motion_volume_drift
                       : strcmp(key, "vertices") == 0                          ? &tot->largest
                       : strcmp(key, "volume_withheld") == 0                   ? &tot->volume_withheld
                                                                                : NULL;
        if (slot && value > *slot)
            *slot = value;
    } else if (strncmp(line, "@finding ", 9) == 0) {
        for (int k = 0; k < KINDS; ++k)
            if (strncmp(line + 9, kind_names[k], strlen(kind_names[k])) == 0 && line[9 + strlen(kind_names[k])] == ' ')
                *finding_kind = k;
        snprintf(finding_text, finding_len, "%s", line + 9);
    } else if (strncmp(line, "contract violated", 17) == 0 && *finding_kind < 0) {
        *finding_kind = KIND_CONTRACT;
        snprintf(finding_text, finding_len, "%s", line);
    }
}

/* Runs one iteration in a child; returns the kind of its finding, or -1. */
static int run_child(totals *tot, uint64_t seed, double call_limit, const char *self)
{
    int fds[2];
    FUZZ_REQUIRE(pipe(fds) == 0, "pipe: %s", strerror(errno));
    fflush(stdout);
    fflush(stderr);
    const pid_t pid = fork();
    FUZZ_REQUIRE(pid >= 0, "fork: %s", strerror(errno));
    if (pid == 0) {
        close(fds[0]);
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[1]);
        const struct rlimit no_core = {0, 0};
        setrlimit(RLIMIT_CORE, &no_core); /* contract.h aborts: no core file per finding */
        setvbuf(stdout, NULL, _IOLBF, 0);
        run_iteration(seed, call_limit, NULL);
        exit(0);
    }
    close(fds[1]);
    transcript t = {NULL, 0, 0};
    size_t line_start = 0;
    int open_call = 0, finding = -1, killed = 0, ended = 0;
    double call_start = now();
    char finding_text[1024] = "";
    /* Bounded: each pass either reads output, or waits at most a second; a call that does
     * not end within twice the limit (plus a margin) is killed. */
    for (long pass = 0; pass < 100000000L; ++pass) {
        struct pollfd p = {fds[0], POLLIN, 0};
        const int ready = poll(&p, 1, 1000);
        if (ready > 0) {
            char buf[65536];
            const ssize_t n = read(fds[0], buf, sizeof buf);
            if (n <= 0)
                break;
            transcript_add(&t, buf, (size_t)n);
            for (char *nl; t.text && (nl = memchr(t.text + line_start, '\n', t.len - line_start)) != NULL;) {
                *nl = '\0';
                const char *line = t.text + line_start;
                if (strcmp(line, "@end") == 0)
                    ended = 1;
                account_line(tot, line, seed, &open_call, &call_start, &finding, finding_text, sizeof finding_text);
                *nl = '\n';
                line_start = (size_t)(nl - t.text) + 1;
            }
        } else if (ready < 0 && errno != EINTR)
            break;
        if (open_call && now() - call_start > 2 * call_limit + 30) {
            kill(pid, SIGKILL);
            killed = 1;
            finding = KIND_HANG;
            snprintf(finding_text, sizeof finding_text, "hang: a call did not return in %.0f s; killed",
                     2 * call_limit + 30);
            break;
        }
    }
    close(fds[0]);
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (finding < 0 && !killed && (!ended || !WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0)) {
        finding = WIFSIGNALED(wstatus) && WTERMSIG(wstatus) != SIGABRT ? KIND_CRASH : KIND_CONTRACT;
        snprintf(finding_text, sizeof finding_text, "the child %s %d without a finding of its own",
                 WIFSIGNALED(wstatus) ? "died of signal" : "exited with", WIFSIGNALED(wstatus) ? WTERMSIG(wstatus)
                                                                                               : WEXITSTATUS(wstatus));
    }
    if (finding >= 0) {
        ++tot->failures[finding];
        if (tot->nfindings < 64) {
            tot->finding_seed[tot->nfindings] = seed;
            tot->finding_kind[tot->nfindings] = finding;
            ++tot->nfindings;
        }
        fprintf(stderr, "soak: finding (%s) with seed %" PRIu64 ": %s\n  replay: %s --seed %" PRIu64 " --replay\n",
                kind_names[finding], seed, finding_text, self, seed);
        /* The whole transcript for the first few findings of a kind; later ones (often the
         * same defect again) by their seed alone, so that a long run's report stays readable. */
        if (tot->failures[finding] > 3) {
            free(t.text);
            ++tot->executions;
            return finding;
        }
        fprintf(stderr, "  the iteration's calls and messages:\n");
        /* The transcript without the observations: the calls, their statuses, the messages. */
        const char *line = t.text ? t.text : "";
        for (int k = 0; k < 1000000 && *line; ++k) {
            const char *end = strchr(line, '\n');
            const size_t n = end ? (size_t)(end - line) : strlen(line);
            if (strncmp(line, "@max", 4) != 0 && strncmp(line, "@count", 6) != 0)
                fprintf(stderr, "    %.*s\n", (int)n, line);
            line += n + (end != NULL);
        }
    }
    free(t.text);
    ++tot->executions;
    return finding;
}

static void print_json(const totals *tot, uint64_t seed, double seconds)
{
    printf("{\"soak\":\"surfadapt\",\"seed\":%" PRIu64 ",\"seconds\":%.1f,\"executions\":%ld,\"calls\":%ld,", seed,
           seconds, tot->executions, tot->calls);
    printf("\"calls_by_op\":{");
    for (int k = 0; k <= OPS; ++k)
        printf("%s\"%s\":%ld", k ? "," : "", k < OPS ? op_names[k] : "adapt", tot->calls_by_op[k]);
    printf("},\"refused\":%ld,\"failures\":{", tot->refused);
    long total = 0;
    for (int k = 0; k < KINDS; ++k) {
        printf("%s\"%s\":%ld", k ? "," : "", kind_names[k], tot->failures[k]);
        total += tot->failures[k];
    }
    printf("},\"findings\":%ld,\"finding_seeds\":[", total);
    for (int k = 0; k < tot->nfindings; ++k)
        printf("%s{\"seed\":%" PRIu64 ",\"kind\":\"%s\"}", k ? "," : "", tot->finding_seed[k],
               kind_names[tot->finding_kind[k]]);
    printf("],\"slowest_call\":{\"op\":\"%s\",\"seconds\":%.3f,\"seed\":%" PRIu64 "},", tot->slowest_op, tot->slowest,
           tot->slowest_seed);
    printf("\"largest_mesh\":%.0f,\"remesh_volume_error_max\":%.3e,\"remesh_volume_error_per_tolerance_max\":%.3e,"
           "\"motion_volume_drift_max\":%.3e,\"motion_crossings_unprotected\":%ld,\"remesh_crossings_unguarded\":%ld,"
           "\"merges\":%ld,\"pinches\":%ld,\"drops_removed\":%ld,\"volume_withheld_and_reported\":%ld,"
           "\"volume_withheld_max\":%.3e,\"volume_withheld_seeds\":[",
           tot->largest, tot->remesh_volume_error, tot->remesh_volume_error_per_tolerance, tot->motion_volume_drift,
           tot->motion_crossings_unprotected, tot->remesh_crossings_unguarded, tot->merges, tot->pinches,
           tot->drops_removed, tot->volume_withheld_and_reported, tot->volume_withheld);
    for (long k = 0; k < tot->volume_withheld_and_reported && k < 16; ++k)
        printf("%s%" PRIu64, k ? "," : "", tot->withheld_seed[k]);
    printf("]}\n");
    fflush(stdout);
}

static int usage(const char *self)
{
    fprintf(stderr,
            "usage: %s --seconds N [--seed S] [--iterations K] [--call-limit SECONDS]\n"
            "       %s --seed S --replay [--dump PREFIX]   (PREFIX-N.obj: the mesh before call N;\n"
            "                                            PREFIX-N.vel: the velocities call N sets)\n"
            "       %s --seeds FILE   (the iterations whose seeds begin FILE's lines, each checked)\n",
            self, self, self);
    return 2;
}

int main(int argc, char **argv)
{
    double seconds = 60, call_limit = 30;
    uint64_t seed = 1;
    long iterations = -1;
    int replay = 0;
    const char *dump = NULL, *seeds_file = NULL;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--seconds") == 0 && i + 1 < argc)
            seconds = atof(argv[++i]);
        else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc)
            seed = strtoull(argv[++i], NULL, 10);
        else if (strcmp(argv[i], "--iterations") == 0 && i + 1 < argc)
            iterations = atol(argv[++i]);
        else if (strcmp(argv[i], "--call-limit") == 0 && i + 1 < argc)
            call_limit = atof(argv[++i]);
        else if (strcmp(argv[i], "--dump") == 0 && i + 1 < argc)
            dump = argv[++i];
        else if (strcmp(argv[i], "--replay") == 0)
            replay = 1;
        else if (strcmp(argv[i], "--seeds") == 0 && i + 1 < argc)
            seeds_file = argv[++i];
        else
            return usage(argv[0]);
    }
    if (replay) {
        /* In this process, so that a debugger sees it; the transcript goes to stdout. */
        run_iteration(seed, call_limit, dump);
        return 0;
    }
    totals tot;
    memset(&tot, 0, sizeof tot);
    const double start = now();
    if (seeds_file) {
        /* The iterations of these seeds, each as the run that found it ran it. Read before
         * the first fork: a child's exit would move the shared file offset under the
         * parent's buffered reading. */
        FILE *f = fopen(seeds_file, "r");
        FUZZ_REQUIRE(f != NULL, "cannot read %s", seeds_file);
        uint64_t listed[256];
        int count = 0;
        char line[512];
        while (fgets(line, sizeof line, f)) {
            char *end;
            const uint64_t s = strtoull(line, &end, 10);
            if (end == line)
                continue;
            FUZZ_REQUIRE(count < 256, "%s lists more than 256 seeds", seeds_file);
            listed[count++] = s;
        }
        fclose(f);
        for (int k = 0; k < count; ++k)
            run_child(&tot, listed[k], call_limit, argv[0]);
    } else {
        /* Iteration k of the run with seed S has its own seed, S * 10^6 + k: what a
         * finding prints and --replay takes. */
        for (long k = 0; k < 100000000L && (iterations < 0 || k < iterations); ++k) {
            if (iterations < 0 && now() - start >= seconds)
                break;
            run_child(&tot, seed * 1000000u + (uint64_t)k, call_limit, argv[0]);
        }
    }
    print_json(&tot, seed, now() - start);
    long total = 0;
    for (int k = 0; k < KINDS; ++k)
        total += tot.failures[k];
    return total ? 1 : 0;
}
