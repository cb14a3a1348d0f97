/* SPDX-License-Identifier: BSD-3-Clause */
/* The VTK time series of the command-line tool (vtu_series.h) and the .vtu writer's point
 * and cell data (mesh_file_write_vtu): the mesh must read back bit for bit through the
 * tool's own reader, and every array must be in the XML header under its name, type and
 * component count, with exactly the values the library (or the velocity field) gives, in
 * the raw appended data, little-endian whatever the machine. The header is parsed here
 * by hand rather than with the reader under test: it reads no point or cell data. */
#define _XOPEN_SOURCE 700 /* mkdtemp, rmdir, unlink, P_tmpdir */

#include "support/testing.h"

#include "mesh_formats.h"
#include "vtu_series.h"

#include <unistd.h>

/* A rigid rotation about z at angular speed omega * t, plus a rise: the file must hold the
 * field at the step's time, not at any other. */
static void spin(void *ctx, int32_t n, const double *xyz, double t, double *vel)
{
    const double w = *(const double *)ctx * t;
    for (int32_t i = 0; i < n; ++i) {
        vel[3 * i] = -w * xyz[3 * i + 1];
        vel[3 * i + 1] = w * xyz[3 * i];
        vel[3 * i + 2] = 0.5;
    }
}

static char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        fail_msg("cannot open %s", path);
    assert_int_equal(fseek(f, 0, SEEK_END), 0);
    const long n = ftell(f);
    assert_true(n >= 0);
    rewind(f);
    char *data = malloc((size_t)n + 1);
    assert_non_null(data);
    assert_int_equal(fread(data, 1, (size_t)n, f), (size_t)n);
    data[n] = '\0';
    fclose(f);
    *size = (size_t)n;
    return data;
}

static uint64_t le64(const unsigned char *p)
{
    uint64_t v = 0;
    for (int k = 7; k >= 0; --k)
        v = v << 8 | p[k];
    return v;
}

/* A written .vtu: the XML part (cut off at the AppendedData element) and the raw bytes. */
typedef struct {
    char *data;
    const char *xml_end;
    const unsigned char *raw;
    size_t raw_size;
} vtu_text;

static vtu_text open_vtu(const char *path)
{
    vtu_text v;
    size_t size = 0;
    v.data = slurp(path, &size);
    const char *appended = strstr(v.data, "<AppendedData encoding=\"raw\">");
    assert_non_null(appended);
    const char *underscore = strchr(appended, '_');
    assert_non_null(underscore);
    v.xml_end = appended;
    v.raw = (const unsigned char *)underscore + 1;
    v.raw_size = size - (size_t)(v.raw - (const unsigned char *)v.data);
    /* Little-endian bytes, 8-byte block sizes: what the raw data below is decoded as. */
    const char *file = strstr(v.data, "<VTKFile ");
    assert_non_null(file);
    assert_true(strstr(file, "byte_order=\"LittleEndian\"") && strstr(file, "header_type=\"UInt64\""));
    assert_null(strstr(v.data, "format=\"ascii\""));
    return v;
}

/* Finds the DataArray `name` inside `element` (PointData or CellData), checks its type and
 * component count, and returns its `count` values' bytes after checking the block size. */
static const unsigned char *array_bytes(const vtu_text *v, const char *element, const char *name, const char *type,
                                        int ncomp, uint64_t count)
{
    char open[64], close[64], key[128], attr[64];
    snprintf(open, sizeof open, "<%s>", element);
    snprintf(close, sizeof close, "</%s>", element);
    snprintf(key, sizeof key, "Name=\"%s\"", name);
    const char *begin = strstr(v->data, open), *end = begin ? strstr(begin, close) : NULL;
    if (!begin || !end || end > v->xml_end)
        fail_msg("no %s element in the header", element);
    const char *at = strstr(begin, key);
    if (!at || at > end)
        fail_msg("no array '%s' in %s", name, element);
    const char *tag = at;
    while (tag > begin && strncmp(tag, "<DataArray", 10) != 0)
        --tag;
    const char *tag_end = strstr(at, "/>");
    assert_non_null(tag_end);
    const size_t len = (size_t)(tag_end - tag);
    char text[512];
    assert_true(len < sizeof text);
    memcpy(text, tag, len);
    text[len] = '\0';
    snprintf(attr, sizeof attr, "type=\"%s\"", type);
    if (!strstr(text, attr))
        fail_msg("array '%s': not %s: %s", name, attr, text);
    snprintf(attr, sizeof attr, "NumberOfComponents=\"%d\"", ncomp);
    if (!strstr(text, attr))
        fail_msg("array '%s': not %s: %s", name, attr, text);
    assert_non_null(strstr(text, "format=\"appended\""));
    const char *offset_text = strstr(text, "offset=\"");
    assert_non_null(offset_text);
    const unsigned long long offset = strtoull(offset_text + 8, NULL, 10);
    const uint64_t size = strcmp(type, "Float64") == 0 ? 8 : 4, bytes = count * (uint64_t)ncomp * size;
    assert_true(offset + 8 + bytes <= v->raw_size);
    const uint64_t block = le64(v->raw + offset);
    if (block != bytes)
        fail_msg("array '%s': a block of %llu bytes, expected %llu", name, (unsigned long long)block,
                 (unsigned long long)bytes);
    return v->raw + offset + 8;
}

static void assert_doubles(const unsigned char *p, const double *expected, uint64_t n, const char *name)
{
    for (uint64_t i = 0; i < n; ++i) {
        const uint64_t bits = le64(p + 8 * i);
        double value;
        memcpy(&value, &bits, sizeof value);
        if (memcmp(&value, &expected[i], sizeof value) != 0)
            fail_msg("%s[%llu] = %.17g, expected %.17g", name, (unsigned long long)i, value, expected[i]);
    }
}

static void assert_ints(const unsigned char *p, const int32_t *expected, uint64_t n, const char *name)
{
    for (uint64_t i = 0; i < n; ++i) {
        const int32_t value = (int32_t)((uint32_t)p[4 * i] | (uint32_t)p[4 * i + 1] << 8 |
                                        (uint32_t)p[4 * i + 2] << 16 | (uint32_t)p[4 * i + 3] << 24);
        if (value != expected[i])
            fail_msg("%s[%llu] = %d, expected %d", name, (unsigned long long)i, (int)value, (int)expected[i]);
    }
}

typedef struct {
    char dir[512];
    int files;
} temp_dir;

static temp_dir make_temp_dir(void)
{
    temp_dir d;
    const char *tmp = getenv("TMPDIR");
    snprintf(d.dir, sizeof d.dir, "%s/surfadapt-series-XXXXXX", tmp && *tmp ? tmp : P_tmpdir);
    assert_non_null(mkdtemp(d.dir));
    d.files = 0;
    return d;
}

static void remove_temp_dir(const temp_dir *d, const char *name, int steps)
{
    char path[700];
    for (int i = 0; i < steps; ++i) {
        snprintf(path, sizeof path, "%s/%s_%04d.vtu", d->dir, name, i);
        unlink(path);
    }
    snprintf(path, sizeof path, "%s/%s.pvd", d->dir, name);
    unlink(path);
    assert_int_equal(rmdir(d->dir), 0);
}

/* Step `step` of the series in `dir` holds the surface as it is now, at time t. */
static void check_step(const char *dir, int step, const sfa_surface *s, double t, double omega, int32_t field_a,
                       int32_t field_b, int32_t face_field)
{
    char path[700], err[512];
    snprintf(path, sizeof path, "%s/surface_%04d.vtu", dir, step);
    int32_t nv = 0, nt = 0;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    double *xyz = malloc(sizeof(double) * 3 * (size_t)nv), *vel = malloc(sizeof(double) * 3 * (size_t)nv);
    double *a = malloc(sizeof(double) * (size_t)nv), *b = malloc(sizeof(double) * 3 * (size_t)nv);
    double *c = malloc(sizeof(double) * 2 * (size_t)nt);
    int32_t *tris = malloc(sizeof(int32_t) * 3 * (size_t)nt), *rank = malloc(sizeof(int32_t) * (size_t)nv),
            *component = malloc(sizeof(int32_t) * (size_t)nv);
    assert_true(xyz && vel && a && b && c && tris && rank && component);
    assert_int_equal(sfa_get_mesh(s, nv, xyz, nt, tris, 0), SFA_OK);
    assert_int_equal(sfa_get_feature_ranks(s, nv, rank), SFA_OK);
    assert_int_equal(sfa_get_components(s, nv, component), SFA_OK);
    assert_int_equal(sfa_get_field(s, field_a, nv, a), SFA_OK);
    assert_int_equal(sfa_get_field(s, field_b, 3 * nv, b), SFA_OK);
    assert_int_equal(sfa_get_face_field(s, face_field, 2 * nt, c), SFA_OK);
    spin(&omega, nv, xyz, t, vel);

    /* The mesh, through the tool's reader. */
    sfa_mesh_data back;
    if (mesh_file_read(path, &back, NULL, err, sizeof err) != 0)
        fail_msg("reading %s back: %s", path, err);
    assert_int_equal(back.nverts, nv);
    assert_int_equal(back.ntris, nt);
    assert_memory_equal(back.xyz, xyz, sizeof(double) * 3 * (size_t)nv);
    assert_memory_equal(back.tris, tris, sizeof(int32_t) * 3 * (size_t)nt);
    mesh_free(&back);

    /* The arrays, by name. */
    vtu_text v = open_vtu(path);
    char piece[128];
    snprintf(piece, sizeof piece, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">", (int)nv, (int)nt);
    assert_non_null(strstr(v.data, piece));
    assert_ints(array_bytes(&v, "PointData", "rank", "Int32", 1, (uint64_t)nv), rank, (uint64_t)nv, "rank");
    assert_ints(array_bytes(&v, "PointData", "component", "Int32", 1, (uint64_t)nv), component, (uint64_t)nv,
                "component");
    assert_doubles(array_bytes(&v, "PointData", "velocity", "Float64", 3, (uint64_t)nv), vel, 3 * (uint64_t)nv,
                   "velocity");
    assert_doubles(array_bytes(&v, "PointData", "temperature", "Float64", 1, (uint64_t)nv), a, (uint64_t)nv,
                   "temperature");
    assert_doubles(array_bytes(&v, "PointData", "displacement", "Float64", 3, (uint64_t)nv), b, 3 * (uint64_t)nv,
                   "displacement");
    assert_doubles(array_bytes(&v, "CellData", "concentration", "Float64", 2, (uint64_t)nt), c, 2 * (uint64_t)nt,
                   "concentration");
    free(v.data);
    free(xyz), free(vel), free(a), free(b), free(c), free(tris), free(rank), free(component);
}

/* A box (corners and ridges: ranks 0 to 2) and a sphere beside it (two components), with
 * two vertex fields and a face field; saved, adapted, saved again. */
static void series_with_arrays(void **state)
{
    (void)state;
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1}, shift[3] = {3, 0, 0};
    sfa_mesh_data m = shape_box(4, lo, hi), ball = shape_icosphere(2, 0.5);
    mesh_translate(&ball, shift);
    mesh_append(&m, &ball);
    mesh_free(&ball);
    sfa_surface *s = make_surface(&m, 0);
    double *a = malloc(sizeof(double) * (size_t)m.nverts), *b = malloc(sizeof(double) * 3 * (size_t)m.nverts);
    double *c = malloc(sizeof(double) * 2 * (size_t)m.ntris);
    assert_true(a && b && c);
    for (int32_t i = 0; i < m.nverts; ++i) {
        a[i] = m.xyz[3 * i] + 0.1 * m.xyz[3 * i + 2];
        for (int k = 0; k < 3; ++k)
            b[3 * i + k] = m.xyz[3 * i + k] * (k + 1);
    }
    for (int32_t t = 0; t < m.ntris; ++t)
        c[2 * t] = 1, c[2 * t + 1] = t % 7;
    int32_t field_a = -1, field_b = -1, face_field = -1;
    assert_int_equal(sfa_add_field(s, 1, a, &field_a), SFA_OK);
    assert_int_equal(sfa_add_field(s, 3, b, &field_b), SFA_OK);
    assert_int_equal(sfa_add_face_field(s, 2, c, &face_field), SFA_OK);
    free(a), free(b), free(c);

    temp_dir d = make_temp_dir();
    const vtu_series_field vertex_fields[] = {{"temperature", field_a, 1}, {"displacement", field_b, 3}};
    const vtu_series_field face_fields[] = {{"concentration", face_field, 2}};
    double omega = 2;
    vtu_series ts;
    vtu_series_init(&ts, d.dir, "surface");
    ts.velocity = spin;
    ts.velocity_ctx = &omega;
    ts.vertex_fields = vertex_fields;
    ts.nvertex_fields = 2;
    ts.face_fields = face_fields;
    ts.nface_fields = 1;
    char err[512];
    if (vtu_series_save(&ts, s, 0, err, sizeof err) != 0)
        fail_msg("saving step 0: %s", err);
    check_step(d.dir, 0, s, 0, omega, field_a, field_b, face_field);

    /* Ranks as the library finds them: the box's corners and ridges are in the file. */
    int32_t *rank = malloc(sizeof(int32_t) * (size_t)m.nverts), *component = malloc(sizeof(int32_t) * (size_t)m.nverts);
    assert_true(rank && component);
    assert_int_equal(sfa_get_feature_ranks(s, m.nverts, rank), SFA_OK);
    assert_int_equal(sfa_get_components(s, m.nverts, component), SFA_OK);
    int seen_rank[3] = {0, 0, 0}, seen_component[2] = {0, 0};
    for (int32_t i = 0; i < m.nverts; ++i) {
        assert_true(rank[i] >= 0 && rank[i] <= 2 && component[i] >= 0 && component[i] <= 1);
        seen_rank[rank[i]] = seen_component[component[i]] = 1;
    }
    assert_true(seen_rank[0] && seen_rank[1] && seen_rank[2] && seen_component[0] && seen_component[1]);
    free(rank), free(component);

    sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, 0.5 * mesh_mean_edge_length(&m));
    assert_int_equal(sfa_adapt(s), SFA_OK);
    int32_t nv = 0, nt = 0;
    assert_int_equal(sfa_get_counts(s, &nv, &nt), SFA_OK);
    assert_true(nv != m.nverts); /* the second step is not the first written again */
    if (vtu_series_save(&ts, s, 0.25, err, sizeof err) != 0)
        fail_msg("saving step 1: %s", err);
    check_step(d.dir, 1, s, 0.25, omega, field_a, field_b, face_field);

    /* The collection lists both, in order, with their times. */
    char path[700];
    size_t size = 0;
    snprintf(path, sizeof path, "%s/surface.pvd", d.dir);
    char *pvd = slurp(path, &size);
    const char *first = strstr(pvd, "<DataSet timestep=\"0\" group=\"\" part=\"0\" file=\"surface_0000.vtu\"/>");
    const char *second = strstr(pvd, "<DataSet timestep=\"0.25\" group=\"\" part=\"0\" file=\"surface_0001.vtu\"/>");
    assert_true(first && second && first < second);
    assert_null(strstr(second + 1, "<DataSet"));
    free(pvd);

    /* A field said to have more components than it has, or named like a built-in array, is
     * refused with a reason; no step is counted and the collection stays as it was. */
    const vtu_series_field too_many[] = {{"displacement", field_b, 4}};
    ts.vertex_fields = too_many;
    ts.nvertex_fields = 1;
    assert_int_equal(vtu_series_save(&ts, s, 0.5, err, sizeof err), -1);
    assert_non_null(strstr(err, "fewer than 4 components"));
    const vtu_series_field named_rank[] = {{"rank", field_a, 1}};
    ts.vertex_fields = named_rank;
    assert_int_equal(vtu_series_save(&ts, s, 0.5, err, sizeof err), -1);
    assert_non_null(strstr(err, "two point data arrays named 'rank'"));
    assert_int_equal(ts.steps, 2);
    snprintf(path, sizeof path, "%s/surface_0002.vtu", d.dir);
    assert_int_equal(access(path, F_OK), -1); /* checked before the file is opened */

    vtu_series_free(&ts);
    remove_temp_dir(&d, "surface", 2);
    sfa_destroy(s);
    mesh_free(&m);
}

/* mesh_file_write_vtu checks what goes into the header. */
static void bad_arrays_are_refused(void **state)
{
    (void)state;
    sfa_mesh_data cube = shape_unit_cube();
    const int32_t ones[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    char err[512];
    const mesh_data_array quote = {"a\"b", MESH_ARRAY_INT32, 1, ones};
    const mesh_data_array twice[2] = {{"x", MESH_ARRAY_INT32, 1, ones}, {"x", MESH_ARRAY_INT32, 1, ones}};
    const mesh_data_array no_components = {"x", MESH_ARRAY_INT32, 0, ones};
    assert_int_equal(mesh_file_write_vtu("never.vtu", &cube, NULL, &quote, 1, NULL, 0, err, sizeof err), -1);
    assert_int_equal(mesh_file_write_vtu("never.vtu", &cube, NULL, twice, 2, NULL, 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "two point data arrays named 'x'"));
    assert_int_equal(mesh_file_write_vtu("never.vtu", &cube, NULL, NULL, 0, &no_components, 1, err, sizeof err), -1);
    assert_int_equal(mesh_file_write_vtu("never.obj", &cube, NULL, NULL, 0, NULL, 0, err, sizeof err), -1);
    assert_int_equal(access("never.vtu", F_OK), -1);
    mesh_free(&cube);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(series_with_arrays),
        cmocka_unit_test(bad_arrays_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
