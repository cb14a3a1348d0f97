/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A plugin host: loads the library with dlopen, resolves only sfa_get_api and does
 * everything else through the function table. This is how hosts that must not link
 * surfadapt at build time use it, so the test is built without -lsurfadapt: the
 * header is included for its types and macros only.
 *
 * Usage: test_plugin /absolute/path/to/libsurfadapt.so.1
 * Prints one line per check and finally "plugin: N passed, M failed".
 */
#define _POSIX_C_SOURCE 200809L
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "surfadapt.h"

static int passed = 0;
static int failed = 0;

static int check(int ok, const char *what)
{
    printf("%s - %s\n", ok ? "ok" : "FAIL", what);
    if (ok)
        passed++;
    else
        failed++;
    return ok;
}

static int finish(void)
{
    printf("plugin: %d passed, %d failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

typedef const sfa_api *(*get_api_fn)(uint32_t);

/* Unit cube [0,1]^3; every triangle counter-clockwise seen from outside. */
static const double cube_xyz[8 * 3] = {
    0, 0, 0,  1, 0, 0,  1, 1, 0,  0, 1, 0,
    0, 0, 1,  1, 0, 1,  1, 1, 1,  0, 1, 1,
};
static const int32_t cube_tris[12 * 3] = {
    0, 2, 1,  0, 3, 2, /* z = 0, normal -z */
    4, 5, 6,  4, 6, 7, /* z = 1, normal +z */
    0, 1, 5,  0, 5, 4, /* y = 0, normal -y */
    3, 7, 6,  3, 6, 2, /* y = 1, normal +y */
    0, 4, 7,  0, 7, 3, /* x = 0, normal -x */
    1, 2, 6,  1, 6, 5, /* x = 1, normal +x */
};

static int same_mesh(const sfa_api *api, const sfa_surface *s, const double *want_xyz)
{
    double xyz[8 * 3];
    int32_t tris[12 * 3];
    int32_t nv = -1, nt = -1;
    if (api->get_counts(s, &nv, &nt) != SFA_OK || nv != 8 || nt != 12)
        return 0;
    if (api->get_mesh(s, 8, xyz, 12, tris, 0) != SFA_OK)
        return 0;
    return memcmp(xyz, want_xyz, sizeof xyz) == 0 && memcmp(tris, cube_tris, sizeof tris) == 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: %s /path/to/libsurfadapt.so.1\n", argv[0]);
        return 2;
    }

    void *lib = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!check(lib != NULL, "dlopen the library")) {
        printf("  %s\n", dlerror());
        return finish();
    }

    /* ISO C has no conversion from void * to a function pointer; POSIX guarantees the
       representation is the same, so copy the bytes. */
    void *sym = dlsym(lib, "sfa_get_api");
    get_api_fn get_api = NULL;
    if (sym)
        memcpy(&get_api, &sym, sizeof get_api);
    if (!check(get_api != NULL, "dlsym sfa_get_api")) {
        dlclose(lib);
        return finish();
    }

    const sfa_api *api = get_api(SFA_ABI_VERSION);
    if (!check(api != NULL, "get_api(1) is not NULL")) {
        dlclose(lib);
        return finish();
    }
    check(get_api(0) == NULL, "get_api(0) is NULL");
    check(get_api(SFA_ABI_VERSION + 1) == NULL, "get_api(2) is NULL");
    check(api->struct_size >= sizeof(sfa_api), "struct_size >= sizeof(sfa_api) of this header");
    check(api->abi == SFA_ABI_VERSION, "abi == 1");

    /* Members are listed by name, not walked as an array: function pointers and
       object pointers need not share a representation. */
    int all_set = 1;
#define MEMBER_SET(m)                                                   \
    if (api->m == NULL) {                                               \
        printf("  member %s is NULL\n", #m);                            \
        all_set = 0;                                                    \
    }
    MEMBER_SET(version_string)
    MEMBER_SET(abi_version)
    MEMBER_SET(status_string)
    MEMBER_SET(create)
    MEMBER_SET(destroy)
    MEMBER_SET(last_error)
    MEMBER_SET(set_mesh)
    MEMBER_SET(get_counts)
    MEMBER_SET(get_mesh)
    MEMBER_SET(set_param)
    MEMBER_SET(get_param)
    MEMBER_SET(set_velocities)
    MEMBER_SET(move)
    MEMBER_SET(advect)
    MEMBER_SET(smooth)
    MEMBER_SET(adapt)
    MEMBER_SET(get_feature_ranks)
    MEMBER_SET(measure)
    MEMBER_SET(add_field)
    MEMBER_SET(get_field)
    MEMBER_SET(get_vertex_frames)
    MEMBER_SET(get_ridge_edges)
    MEMBER_SET(get_param_bounds)
    MEMBER_SET(version_number)
    MEMBER_SET(get_component_count)
    MEMBER_SET(get_components)
    MEMBER_SET(measure_component)
    MEMBER_SET(set_velocities_checked)
    MEMBER_SET(add_field_checked)
    MEMBER_SET(set_size_field)
    MEMBER_SET(set_size_field_checked)
    MEMBER_SET(set_fixed_vertices)
    MEMBER_SET(set_required_edges)
    MEMBER_SET(add_face_field)
    MEMBER_SET(add_face_field_checked)
    MEMBER_SET(get_face_field)
    MEMBER_SET(get_vertex_origins)
    MEMBER_SET(set_field)
    MEMBER_SET(set_face_field)
#undef MEMBER_SET
    if (!check(all_set, "every member of the table is set")) {
        /* Calling through a NULL member would crash instead of reporting. */
        dlclose(lib);
        return finish();
    }

    char want_version[64];
    snprintf(want_version, sizeof want_version, "%d.%d.%d", SFA_VERSION_MAJOR, SFA_VERSION_MINOR,
             SFA_VERSION_PATCH);
    const char *version = api->version_string();
    if (!check(version != NULL && strcmp(version, want_version) == 0,
               "version_string() matches the header's version macros"))
        printf("  library \"%s\", header \"%s\"\n", version ? version : "(null)", want_version);
    check(api->abi_version() == SFA_ABI_VERSION, "abi_version() == 1");
    const int want_number = SFA_VERSION_MAJOR * 10000 + SFA_VERSION_MINOR * 100 + SFA_VERSION_PATCH;
    if (!check(api->version_number() == want_number, "version_number() is MAJOR * 10000 + MINOR * 100 + PATCH"))
        printf("  library %d, header %d\n", api->version_number(), want_number);

    /* Bounds need no surface: (0, 180) for an angle, [0, infinity) for the edge length. */
    double lowest = -1, highest = -1;
    int bounds_rc = api->get_param_bounds(SFA_PARAM_RIDGE_ANGLE, &lowest, &highest);
    if (!check(bounds_rc == SFA_OK && lowest == 0 && highest == 180, "get_param_bounds(ridge angle) is 0, 180"))
        printf("  status %d, [%g, %g]\n", bounds_rc, lowest, highest);
    bounds_rc = api->get_param_bounds(SFA_PARAM_EDGE_LENGTH, &lowest, &highest);
    if (!check(bounds_rc == SFA_OK && lowest == 0 && isinf(highest) && highest > 0,
               "get_param_bounds(edge length) is 0, infinity"))
        printf("  status %d, [%g, %g]\n", bounds_rc, lowest, highest);
    check(api->get_param_bounds(-1, &lowest, &highest) == SFA_ERR_ARGUMENT,
          "get_param_bounds of an unknown key gives SFA_ERR_ARGUMENT");
    check(api->status_string(SFA_ERR_MESH) != NULL, "status_string() is not NULL");

    sfa_surface *s = NULL;
    if (!check(api->create(&s) == SFA_OK && s != NULL, "create")) {
        dlclose(lib);
        return finish();
    }

    check(api->set_mesh(s, 8, cube_xyz, 12, cube_tris, 0) == SFA_OK, "set_mesh unit cube");

    double volume = 0.0;
    /* Exact: with 0/1 coordinates every term a.(b x c) is a small integer. */
    int rc = api->measure(s, SFA_MEASURE_VOLUME, &volume);
    if (!check(rc == SFA_OK && volume == 1.0, "measure volume == 1 exactly"))
        printf("  status %d, volume %.17g\n", rc, volume);

    check(same_mesh(api, s, cube_xyz), "get_mesh returns the cube as set");

    const double v[3] = {0.25, -0.5, 0.125};
    double vel[8 * 3];
    for (int i = 0; i < 8; i++)
        memcpy(&vel[3 * i], v, sizeof v);
    check(api->set_velocities(s, vel) == SFA_OK, "set_velocities of a rigid translation");

    /* A translation never turns a normal over, so the whole step is taken. */
    const double dt = 0.5;
    double dt_taken = 0.0;
    rc = api->move(s, dt, &dt_taken);
    if (!check(rc == SFA_OK && dt_taken == dt, "move takes the whole step (dt_taken == dt)"))
        printf("  status %d, dt_taken %.17g\n", rc, dt_taken);

    double moved[8 * 3];
    for (int i = 0; i < 8 * 3; i++)
        moved[i] = cube_xyz[i] + dt * v[i % 3];
    /* dt and v are powers of two, so x + dt*v is exact. */
    check(same_mesh(api, s, moved), "vertices translated by dt*v");

    /* Vertex 8 does not exist: the mesh must be refused and the cube kept. */
    static const int32_t bad_tris[12 * 3] = {
        0, 2, 1,  0, 3, 2,  4, 5, 6,  4, 6, 7,  0, 1, 5,  0, 5, 4,
        3, 7, 6,  3, 6, 2,  0, 4, 7,  0, 7, 3,  1, 2, 6,  1, 6, 8,
    };
    rc = api->set_mesh(s, 8, cube_xyz, 12, bad_tris, 0);
    if (!check(rc == SFA_ERR_MESH, "set_mesh with an index out of range gives SFA_ERR_MESH"))
        printf("  status %d\n", rc);
    const char *message = api->last_error(s);
    if (check(message != NULL && message[0] != '\0', "last_error explains the refusal"))
        printf("  \"%s\"\n", message);
    check(same_mesh(api, s, moved), "the cube survives the refused mesh");
    rc = api->measure(s, SFA_MEASURE_VOLUME, &volume);
    if (!check(rc == SFA_OK && fabs(volume - 1.0) < 1e-12, "volume is still 1"))
        printf("  status %d, volume %.17g\n", rc, volume);

    /* The members appended for feature detection work through the table too: the cube
       has its 12 edges as ridges and every vertex is a corner. */
    int32_t nridges = -1, ranks[8] = {0};
    rc = api->get_ridge_edges(s, 0, NULL, &nridges, 0);
    if (!check(rc == SFA_OK && nridges == 12, "get_ridge_edges counts the 12 cube edges"))
        printf("  status %d, count %d\n", rc, (int)nridges);
    rc = api->get_feature_ranks(s, 8, ranks);
    int corners = 0;
    for (int i = 0; i < 8; i++)
        corners += ranks[i] == 2;
    if (!check(rc == SFA_OK && corners == 8, "get_feature_ranks: 8 corners"))
        printf("  status %d, %d corners\n", rc, corners);
    double aspect[8];
    check(api->get_vertex_frames(s, 8, NULL, NULL, aspect) == SFA_OK, "get_vertex_frames");

    /* Adaptation through the table: refined to edge length 0.3, read back with the new
       counts, same volume. */
    double volume_before = 0, volume_after = 0;
    api->measure(s, SFA_MEASURE_VOLUME, &volume_before);
    check(api->set_param(s, SFA_PARAM_EDGE_LENGTH, 0.3) == SFA_OK, "set_param edge length 0.3");
    rc = api->adapt(s);
    if (!check(rc == SFA_OK, "adapt"))
        printf("  status %d: %s\n", rc, api->last_error(s));
    int32_t nv = 0, nt = 0;
    check(api->get_counts(s, &nv, &nt) == SFA_OK && nv > 8 && nt == 2 * nv - 4, "adapted counts: more vertices, closed");
    double *xyz = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)(nt > 0 ? nt : 1));
    int in_range = xyz && tris && api->get_mesh(s, nv, xyz, nt, tris, 0) == SFA_OK;
    for (int32_t i = 0; in_range && i < 3 * nt; i++)
        in_range = tris[i] >= 0 && tris[i] < nv;
    check(in_range, "get_mesh reads the adapted mesh back");
    free(xyz);
    free(tris);
    api->measure(s, SFA_MEASURE_VOLUME, &volume_after);
    if (!check(fabs(volume_after - volume_before) <= 1e-9, "adapt kept the volume"))
        printf("  %.17g -> %.17g\n", volume_before, volume_after);

    /* Host control through the table: a stale array is refused by the checked variants;
       a fixed vertex survives a coarsening with a size field, bit for bit. */
    check(api->set_velocities_checked(s, 8, vel) == SFA_ERR_ARGUMENT, "set_velocities_checked refuses a stale array");
    double *sizes = malloc(sizeof(double) * (size_t)(nv > 0 ? nv : 1));
    double *before_xyz = malloc(sizeof(double) * 3 * (size_t)(nv > 0 ? nv : 1));
    int32_t *before_tris = malloc(sizeof(int32_t) * 3 * (size_t)(nt > 0 ? nt : 1));
    if (sizes && before_xyz && before_tris && api->get_mesh(s, nv, before_xyz, nt, before_tris, 0) == SFA_OK) {
        for (int32_t i = 0; i < nv; i++)
            sizes[i] = 0.6;
        int32_t field_id = -1;
        check(api->add_field_checked(s, nv, 1, sizes, &field_id) == SFA_OK, "add_field_checked");
        check(api->set_size_field_checked(s, nv, sizes) == SFA_OK, "set_size_field_checked");
        const int32_t fixed[1] = {before_tris[0]};
        const int32_t edge[2] = {before_tris[0], before_tris[1]};
        check(api->set_fixed_vertices(s, 1, fixed, 0) == SFA_OK, "set_fixed_vertices");
        const int32_t not_an_edge[2] = {before_tris[0], before_tris[0]};
        check(api->set_required_edges(s, 1, not_an_edge, 0) == SFA_ERR_ARGUMENT, "set_required_edges refuses a loop");
        check(api->set_required_edges(s, 1, edge, 0) == SFA_OK, "set_required_edges");
        rc = api->adapt(s);
        if (!check(rc == SFA_OK, "adapt with a size field and constraints"))
            printf("  status %d: %s\n", rc, api->last_error(s));
        int32_t nv2 = 0, nt2 = 0;
        api->get_counts(s, &nv2, &nt2);
        double *after_xyz = malloc(sizeof(double) * 3 * (size_t)(nv2 > 0 ? nv2 : 1));
        int32_t *after_tris = malloc(sizeof(int32_t) * 3 * (size_t)(nt2 > 0 ? nt2 : 1));
        int kept = 0;
        if (after_xyz && after_tris && api->get_mesh(s, nv2, after_xyz, nt2, after_tris, 0) == SFA_OK)
            for (int32_t i = 0; i < nv2; i++)
                kept += memcmp(after_xyz + 3 * i, before_xyz + 3 * fixed[0], 3 * sizeof(double)) == 0;
        if (!check(nv2 < nv && kept == 1, "coarsened to the size field, the fixed vertex in place"))
            printf("  %d -> %d vertices, fixed vertex found %d times\n", nv, nv2, kept);
        check(api->set_size_field(s, NULL) == SFA_OK, "set_size_field(NULL) clears");
        /* Every vertex's origin is a triangle of the mesh before the call. */
        int32_t *origin = malloc(sizeof(int32_t) * (size_t)(nv2 > 0 ? nv2 : 1));
        double *weights = malloc(sizeof(double) * 3 * (size_t)(nv2 > 0 ? nv2 : 1));
        int origins_ok = origin && weights && api->get_vertex_origins(s, nv2, origin, weights, 0) == SFA_OK;
        for (int32_t i = 0; origins_ok && i < nv2; i++)
            origins_ok = origin[i] >= 0 && origin[i] < nt;
        check(origins_ok, "get_vertex_origins names a triangle of the mesh before sfa_adapt for every vertex");
        free(origin);
        free(weights);
        double *density = malloc(sizeof(double) * (size_t)(nt2 > 0 ? nt2 : 1));
        for (int32_t i = 0; density && i < nt2; i++)
            density[i] = 1.5;
        int32_t face_id = -1;
        check(density && api->add_face_field_checked(s, nt2, 1, density, &face_id) == SFA_OK && face_id == 0,
              "add_face_field_checked");
        check(density && api->add_face_field(s, 1, density, &face_id) == SFA_OK && face_id == 1, "add_face_field");
        check(density && api->get_face_field(s, 0, nt2, density) == SFA_OK && density[0] == 1.5, "get_face_field");
        free(density);
        free(after_xyz);
        free(after_tris);
    }
    free(sizes);
    free(before_xyz);
    free(before_tris);

    api->destroy(s);
    check(1, "destroy");

    check(dlclose(lib) == 0, "dlclose");
    return finish();
}
