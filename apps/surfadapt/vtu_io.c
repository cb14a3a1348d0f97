/* SPDX-License-Identifier: BSD-3-Clause */
/* VTK XML UnstructuredGrid (.vtu) of one Piece: the Points array and the Cells arrays
 * connectivity, offsets and types, each inline ASCII, inline base64 binary (meshio's and
 * ParaView's default) or appended raw binary (header_type UInt32 or UInt64, either byte
 * order). Triangles (cell type 5) make the mesh, polygons (7) and quads (9) are
 * fan-triangulated, vertices and lines (1 to 4) are read past, any other cell is an
 * error; point and cell data are not read (the writer writes them for ParaView; the mesh
 * is what the tool reads back). Compressed data and base64 appended data are not read (an
 * error says so): the tool never writes them. Only the tags that matter are looked for,
 * not a general XML parse: the files are machine-written. */
#include "format_io.h"

#include <stdlib.h>
#include <string.h>

typedef enum { V_NONE = 0, V_I8, V_U8, V_I16, V_U16, V_I32, V_U32, V_I64, V_U64, V_F32, V_F64 } vtu_type;

static vtu_type type_named(const char *name)
{
    static const char *const names[] = {"",       "Int8",   "UInt8",  "Int16",   "UInt16", "Int32",
                                        "UInt32", "Int64",  "UInt64", "Float32", "Float64"};
    for (int i = 1; i < (int)(sizeof names / sizeof names[0]); ++i)
        if (strcmp(name, names[i]) == 0)
            return (vtu_type)i;
    return V_NONE;
}

static size_t type_size(vtu_type t)
{
    static const size_t sizes[] = {0, 1, 1, 2, 2, 4, 4, 8, 8, 4, 8};
    return sizes[t];
}

typedef struct {
    char *data;        /* the whole file; the XML part ends at a NUL put where AppendedData starts */
    const char *raw;   /* the appended bytes, after the '_' (NULL if none) */
    size_t raw_size;
    int big_endian, header64;
    read_context *c;
} vtu_file;

/* The line of position p, for messages about the XML part. */
static void at(const vtu_file *f, const char *p)
{
    long line = 1;
    for (const char *q = f->data; q < p && *q; ++q)
        line += *q == '\n';
    f->c->line = line;
    f->c->offset = -1;
}

/* The value of attribute `name` of the tag starting at `tag` (up to its '>'), copied to
 * value; 0 if found. */
static int attribute(const char *tag, const char *name, char *value, size_t n)
{
    const char *end = strchr(tag, '>');
    const size_t len = strlen(name);
    for (const char *p = tag; p && (!end || p < end); p = strchr(p + 1, ' ')) {
        const char *q = p + 1;
        while (*q == ' ' || *q == '\n' || *q == '\r' || *q == '\t')
            ++q;
        if (end && q >= end)
            break;
        if (strncmp(q, name, len) == 0 && q[len] == '=' && (q[len + 1] == '"' || q[len + 1] == '\'')) {
            const char quote = q[len + 1];
            const char *v = q + len + 2, *close = strchr(v, quote);
            if (!close)
                return -1;
            const size_t vlen = (size_t)(close - v) < n - 1 ? (size_t)(close - v) : n - 1;
            memcpy(value, v, vlen);
            value[vlen] = '\0';
            return 0;
        }
    }
    return -1;
}

/* The first tag `<name` (followed by a space, '>' or '/') in [from, to) or NULL. */
static const char *find_tag(const char *from, const char *to, const char *name)
{
    const size_t len = strlen(name);
    for (const char *p = strstr(from, name); p && (!to || p < to); p = strstr(p + 1, name))
        if (p > from && p[-1] == '<' && (p[len] == ' ' || p[len] == '>' || p[len] == '/' || p[len] == '\n' ||
                                         p[len] == '\r' || p[len] == '\t'))
            return p - 1;
    return NULL;
}

typedef struct {
    long long count; /* values */
    double *real;    /* points */
    long long *integer;
} vtu_array;

/* Room for `count` reals or integers in *out. */
static int out_alloc(vtu_array *out, long long count, int reals)
{
    out->count = count;
    void *values = malloc((reals ? sizeof(double) : sizeof(long long)) * (size_t)(count > 0 ? count : 1));
    if (reals)
        out->real = values;
    else
        out->integer = values;
    return values != NULL;
}

/* `count` values of type t from binary data (enough of it checked) into *out. */
static int binary_values(const vtu_file *f, const unsigned char *bytes, vtu_type type, long long count, int reals,
                         vtu_array *out)
{
    if (!out_alloc(out, count, reals))
        return read_fail(f->c, "out of memory");
    const size_t size = type_size(type);
    for (long long i = 0; i < count; ++i) {
        const unsigned char *p = bytes + (size_t)i * size;
        double r = 0;
        long long n = 0;
        switch (type) {
        case V_I8: n = (signed char)p[0]; break;
        case V_U8: n = p[0]; break;
        case V_I16: n = (int16_t)(uint16_t)(f->big_endian ? (p[0] << 8 | p[1]) : (p[1] << 8 | p[0])); break;
        case V_U16: n = f->big_endian ? (p[0] << 8 | p[1]) : (p[1] << 8 | p[0]); break;
        case V_I32: n = (int32_t)load_u32(p, f->big_endian); break;
        case V_U32: n = load_u32(p, f->big_endian); break;
        case V_I64: n = (long long)load_u64(p, f->big_endian); break;
        case V_U64: {
            const uint64_t u = load_u64(p, f->big_endian);
            n = u > INT64_MAX ? -1 : (long long)u; /* out of range either way */
            break;
        }
        case V_F32: r = load_f32(p, f->big_endian); break;
        case V_F64: r = load_f64(p, f->big_endian); break;
        case V_NONE: break;
        }
        if (reals)
            out->real[i] = type == V_F32 || type == V_F64 ? r : (double)n;
        else
            out->integer[i] = n;
    }
    return 0;
}

/* Base64 up to the next '<' (white space skipped). Each group of four characters is
 * decoded on its own, so that streams padded with '=' and put one after the other (VTK
 * encodes the header and the data apart) decode as one. NULL if out of memory. */
static unsigned char *base64_decode(const char *text, uint64_t *len)
{
    const char *end = strchr(text, '<');
    const size_t n = end ? (size_t)(end - text) : strlen(text);
    unsigned char *out = malloc(n / 4 * 3 + 3);
    if (!out)
        return NULL;
    uint64_t used = 0;
    unsigned group = 0, chars = 0, pad = 0;
    for (size_t i = 0; i < n; ++i) {
        const char ch = text[i];
        int v;
        if (ch >= 'A' && ch <= 'Z')
            v = ch - 'A';
        else if (ch >= 'a' && ch <= 'z')
            v = ch - 'a' + 26;
        else if (ch >= '0' && ch <= '9')
            v = ch - '0' + 52;
        else if (ch == '+' || ch == '/')
            v = ch == '+' ? 62 : 63;
        else if (ch == '=')
            v = 0, ++pad;
        else
            continue; /* white space (and anything else) between groups */
        group = group << 6 | (unsigned)v;
        if (++chars == 4) {
            const unsigned bytes = pad < 3 ? 3 - pad : 0;
            for (unsigned k = 0; k < bytes; ++k)
                out[used++] = (unsigned char)(group >> (16 - 8 * k));
            group = chars = pad = 0;
        }
    }
    *len = used;
    return out;
}

/* Reads the `count` values of the DataArray at `tag` as reals or integers. */
static int read_array(const vtu_file *f, const char *tag, const char *name, long long count, int reals,
                      vtu_array *out)
{
    char value[64];
    at(f, tag);
    if (attribute(tag, "type", value, sizeof value) != 0)
        return read_fail(f->c, "DataArray %s has no type", name);
    const vtu_type type = type_named(value);
    if (type == V_NONE)
        return read_fail(f->c, "DataArray %s: unknown type '%s'", name, value);
    if (!reals && (type == V_F32 || type == V_F64))
        return read_fail(f->c, "DataArray %s: integers expected, not %s", name, value);
    char format[16] = "ascii";
    attribute(tag, "format", format, sizeof format);
    const size_t size = type_size(type);
    const char *text = NULL;
    unsigned char *decoded = NULL; /* inline base64, decoded */
    const unsigned char *block = NULL;
    uint64_t avail = 0;
    if (strcmp(format, "appended") == 0) {
        char *end;
        if (!f->raw || attribute(tag, "offset", value, sizeof value) != 0)
            return read_fail(f->c, "DataArray %s: appended, but no raw AppendedData or no offset", name);
        const unsigned long long offset = strtoull(value, &end, 10);
        if (*end || value[0] == '-' || offset > f->raw_size)
            return read_fail(f->c, "DataArray %s: offset %s outside the appended data", name, value);
        block = (const unsigned char *)f->raw + offset;
        avail = f->raw_size - offset;
        f->c->line = 0;
        f->c->offset = (long long)(f->raw - f->data) + (long long)offset;
    } else if (strcmp(format, "binary") == 0) {
        const char *close = strchr(tag, '>');
        if (!close || close[-1] == '/')
            return read_fail(f->c, "DataArray %s: no values", name);
        decoded = base64_decode(close + 1, &avail);
        if (!decoded)
            return read_fail(f->c, "DataArray %s: out of memory", name);
        block = decoded;
    }
    if (block) {
        const size_t header = f->header64 ? 8 : 4;
        const uint64_t nbytes = avail < header ? 0
                                : f->header64 ? load_u64(block, f->big_endian)
                                              : load_u32(block, f->big_endian);
        int rc = 0;
        if (avail < header || nbytes > avail - header)
            rc = read_fail(f->c, "DataArray %s: %llu bytes, more than the file holds", name, (unsigned long long)nbytes);
        else if ((uint64_t)count > nbytes / size)
            rc = read_fail(f->c, "DataArray %s: %llu bytes hold fewer than %lld values", name,
                           (unsigned long long)nbytes, count);
        else
            rc = binary_values(f, block + header, type, count, reals, out);
        free(decoded);
        return rc;
    } else if (strcmp(format, "ascii") == 0) {
        const char *close = strchr(tag, '>');
        if (!close || close[-1] == '/')
            return read_fail(f->c, "DataArray %s: no values", name);
        text = close + 1;
        const char *stop = strstr(text, "</DataArray");
        const long long chars = stop ? (long long)(stop - text) : (long long)strlen(text);
        /* Every value takes at least two characters (a digit and a separator). */
        if (count > chars / 2 + 1)
            return read_fail(f->c, "DataArray %s: %lld values cannot fit in its text", name, count);
    } else
        return read_fail(f->c, "DataArray %s: format '%s' is not read (only ascii, binary and raw appended)", name, format);
    if (!out_alloc(out, count, reals))
        return read_fail(f->c, "out of memory");
    /* The tag's line is counted on from here as the values are read. */
    for (long long i = 0; i < count; ++i) {
        if (reals ? text_double(&text, f->c, 0, &out->real[i]) != 0 : text_long(&text, f->c, 0, &out->integer[i]) != 0)
            return read_fail(f->c, "DataArray %s: value %lld is no %s", name, i, reals ? "number" : "integer");
    }
    return 0;
}

/* The DataArray named `name` inside the element at [from, to), or NULL. */
static const char *named_array(const char *from, const char *to, const char *name)
{
    char value[64];
    for (const char *tag = find_tag(from, to, "DataArray"); tag; tag = find_tag(tag + 1, to, "DataArray"))
        if (attribute(tag, "Name", value, sizeof value) == 0 && strcmp(value, name) == 0)
            return tag;
    return NULL;
}

/* A whole-number attribute of a tag within [0, max]; -1 if missing or bad. */
static long long count_attribute(const char *tag, const char *name, long long max)
{
    char value[32], *end;
    if (attribute(tag, name, value, sizeof value) != 0)
        return -1;
    const long long n = strtoll(value, &end, 10);
    return *end || end == value || n < 0 || n > max ? -1 : n;
}

/* Finds raw appended data: its '_' marks the start; the XML part is cut off before it. */
static int find_appended(vtu_file *f, size_t size)
{
    static const char key[] = "<AppendedData";
    const size_t klen = sizeof key - 1;
    for (size_t i = 0; i + klen <= size; ++i) {
        if (memcmp(f->data + i, key, klen) != 0)
            continue;
        char *tag = f->data + i;
        char encoding[16] = "";
        at(f, tag);
        if (attribute(tag, "encoding", encoding, sizeof encoding) != 0 || strcmp(encoding, "raw") != 0)
            return read_fail(f->c, "AppendedData encoding '%s' is not read (only raw)", encoding);
        const char *underscore = strchr(tag, '>');
        if (underscore)
            underscore = strchr(underscore, '_');
        if (!underscore)
            return read_fail(f->c, "AppendedData without its '_' marker");
        f->raw = underscore + 1;
        f->raw_size = size - (size_t)(f->raw - f->data);
        *tag = '\0';
        return 0;
    }
    return 0;
}

int vtu_parse(char *data, size_t size, mesh_builder *b, read_context *c)
{
    vtu_file f = {data, NULL, 0, 0, 0, c};
    vtu_array points = {0, NULL, NULL}, conn = {0, NULL, NULL}, offsets = {0, NULL, NULL}, types = {0, NULL, NULL};
    char value[64];
    int rc = find_appended(&f, size);
    const char *file = rc == 0 ? find_tag(data, NULL, "VTKFile") : NULL;
    const char *piece = file ? find_tag(file, NULL, "Piece") : NULL;
    const char *points_tag = piece ? find_tag(piece, NULL, "Points") : NULL;
    const char *cells = piece ? find_tag(piece, NULL, "Cells") : NULL;
    const char *cells_end = cells ? strstr(cells, "</Cells") : NULL;
    long long npoints = -1, ncells = -1;
    if (rc == 0 && !file)
        rc = (c->line = 1, read_fail(c, "not a VTK XML file (no VTKFile element)"));
    if (rc == 0) {
        at(&f, file);
        if (attribute(file, "type", value, sizeof value) != 0 || strcmp(value, "UnstructuredGrid") != 0)
            rc = read_fail(c, "only VTKFile type=\"UnstructuredGrid\" is read");
        else if (attribute(file, "compressor", value, sizeof value) == 0)
            rc = read_fail(c, "compressed data (%s) is not read", value);
        else {
            f.big_endian = attribute(file, "byte_order", value, sizeof value) == 0 && strcmp(value, "BigEndian") == 0;
            f.header64 = attribute(file, "header_type", value, sizeof value) == 0 && strcmp(value, "UInt64") == 0;
        }
    }
    if (rc == 0 && (!piece || !points_tag || !cells || !cells_end))
        rc = read_fail(c, "expected a Piece with Points and Cells");
    if (rc == 0 && find_tag(piece + 1, NULL, "Piece"))
        rc = (at(&f, find_tag(piece + 1, NULL, "Piece")), read_fail(c, "more than one Piece"));
    if (rc == 0) {
        at(&f, piece);
        npoints = count_attribute(piece, "NumberOfPoints", INT32_MAX);
        ncells = count_attribute(piece, "NumberOfCells", INT64_MAX / 8);
        if (npoints < 0 || ncells < 0)
            rc = read_fail(c, "Piece needs NumberOfPoints and NumberOfCells");
    }
    const char *array = rc == 0 ? find_tag(points_tag, NULL, "DataArray") : NULL;
    if (rc == 0 && (!array || count_attribute(array, "NumberOfComponents", 3) != 3))
        rc = (at(&f, array ? array : points_tag), read_fail(c, "Points need a DataArray of 3 components"));
    if (rc == 0)
        rc = read_array(&f, array, "Points", 3 * npoints, 1, &points);
    const char *tags[3] = {NULL, NULL, NULL};
    const char *const names[3] = {"offsets", "types", "connectivity"};
    for (int k = 0; k < 3 && rc == 0; ++k)
        if (!(tags[k] = named_array(cells, cells_end, names[k])))
            rc = (at(&f, cells), read_fail(c, "Cells have no DataArray '%s'", names[k]));
    if (rc == 0)
        rc = read_array(&f, tags[0], names[0], ncells, 0, &offsets);
    if (rc == 0)
        rc = read_array(&f, tags[1], names[1], ncells, 0, &types);
    for (long long i = 0; i < ncells && rc == 0; ++i)
        if (offsets.integer[i] < (i ? offsets.integer[i - 1] : 0))
            rc = (at(&f, tags[0]), read_fail(c, "offsets: cell %lld ends before it begins", i));
    if (rc == 0)
        rc = read_array(&f, tags[2], names[2], ncells ? offsets.integer[ncells - 1] : 0, 0, &conn);
    for (int32_t v = 0; v < npoints && rc == 0; ++v)
        if (builder_add_vertex(b, points.real + 3 * (int64_t)v) != 0)
            rc = read_fail(c, "out of memory");
    for (long long i = 0; i < ncells && rc == 0; ++i) {
        const long long begin = i ? offsets.integer[i - 1] : 0, n = offsets.integer[i] - begin, type = types.integer[i];
        const long long *v = conn.integer + begin;
        if (type >= 1 && type <= 4)
            continue; /* vertices and lines */
        if (type != 5 && type != 7 && type != 9)
            rc = (at(&f, tags[1]), read_fail(c, "cell %lld: type %lld is not a surface cell (5, 7 or 9)", i, type));
        else if (n < 3 || (type == 5 && n != 3) || (type == 9 && n != 4))
            rc = (at(&f, tags[0]), read_fail(c, "cell %lld of type %lld has %lld vertices", i, type, n));
        for (long long k = 0; k < n && rc == 0; ++k)
            if (v[k] < INT32_MIN || v[k] > INT32_MAX)
                rc = (at(&f, tags[2]), read_fail(c, "cell %lld: vertex index %lld out of range", i, v[k]));
        if (rc == 0 && builder_begin_face(b) != 0)
            rc = read_fail(c, "out of memory");
        for (long long k = 2; k < n && rc == 0; ++k)
            if (builder_add_triangle(b, (int32_t)v[0], (int32_t)v[k - 1], (int32_t)v[k]) != 0)
                rc = read_fail(c, "too many triangles or out of memory");
    }
    free(points.real);
    free(offsets.integer);
    free(types.integer);
    free(conn.integer);
    return rc;
}

/* Little-endian bytes, gathered before fwrite: one call per value cost more than the
 * formatting of the ASCII files this replaced. Byte by byte from the value, so the file is
 * little-endian (as its byte_order says) whatever the machine's own order. */
typedef struct {
    FILE *f;
    size_t used;
    unsigned char bytes[1 << 15];
} le_out;

static void put_le(le_out *o, uint64_t bits, int n)
{
    if (o->used + 8 > sizeof o->bytes) {
        fwrite(o->bytes, 1, o->used, o->f);
        o->used = 0;
    }
    for (int k = 0; k < n; ++k)
        o->bytes[o->used++] = (unsigned char)(bits >> (8 * k));
}

static void put_f64(le_out *o, double v)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    put_le(o, bits, 8);
}

static uint64_t value_size(const mesh_data_array *a) { return a->type == MESH_ARRAY_FLOAT64 ? 8 : 4; }

/* The DataArray elements of point or cell data; `offset` runs on through the appended
 * data, each array taking its 8-byte size and `tuples` * ncomp values. */
static void data_tags(FILE *f, const char *element, const mesh_data_array *a, int n, uint64_t tuples,
                      uint64_t *offset)
{
    if (n == 0)
        return;
    fprintf(f, "      <%s>\n", element);
    for (int i = 0; i < n; ++i) {
        fprintf(f,
                "        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"appended\" "
                "offset=\"%llu\"/>\n",
                a[i].type == MESH_ARRAY_FLOAT64 ? "Float64" : "Int32", a[i].name, (int)a[i].ncomp,
                (unsigned long long)*offset);
        *offset += 8 + tuples * (uint64_t)a[i].ncomp * value_size(&a[i]);
    }
    fprintf(f, "      </%s>\n", element);
}

static void data_values(le_out *o, const mesh_data_array *a, int n, uint64_t tuples)
{
    for (int i = 0; i < n; ++i) {
        const uint64_t count = tuples * (uint64_t)a[i].ncomp;
        put_le(o, count * value_size(&a[i]), 8);
        if (a[i].type == MESH_ARRAY_FLOAT64)
            for (uint64_t k = 0; k < count; ++k)
                put_f64(o, ((const double *)a[i].values)[k]);
        else
            for (uint64_t k = 0; k < count; ++k)
                put_le(o, (uint32_t)((const int32_t *)a[i].values)[k], 4);
    }
}

/* Binary appended raw, little-endian, header_type UInt64: exact doubles, compact, and
 * ParaView's own layout. Points Float64; connectivity and offsets Int32, or Int64 when the
 * offsets outgrow Int32 (more than 715 million triangles); types UInt8; then the point
 * and cell data arrays given, Float64 or Int32. */
void vtu_write(FILE *f, const sfa_mesh_data *m, const mesh_write_extras *x)
{
    static const mesh_write_extras none = {NULL, NULL, NULL, 0, 0};
    if (!x)
        x = &none;
    const uint64_t nv = (uint64_t)m->nverts, nt = (uint64_t)m->ntris;
    const int wide = 3 * nt > INT32_MAX;
    const uint64_t isize = wide ? 8 : 4;
    const uint64_t points = 0, conn = points + 8 + 24 * nv, offs = conn + 8 + 3 * isize * nt,
                   types = offs + 8 + isize * nt;
    uint64_t offset = types + 8 + nt;
    fputs("<?xml version=\"1.0\"?>\n", f);
    if (x->title && !strstr(x->title, "--") && !strpbrk(x->title, "<>&"))
        fprintf(f, "<!-- %s -->\n", x->title);
    fprintf(f,
            "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            "  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n",
            m->nverts, m->ntris);
    data_tags(f, "PointData", x->point_data, x->npoint_data, nv, &offset);
    data_tags(f, "CellData", x->cell_data, x->ncell_data, nt, &offset);
    const char *itype = wide ? "Int64" : "Int32";
    fprintf(f,
            "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"appended\" "
            "offset=\"%llu\"/>\n      </Points>\n      <Cells>\n"
            "        <DataArray type=\"%s\" Name=\"connectivity\" format=\"appended\" offset=\"%llu\"/>\n"
            "        <DataArray type=\"%s\" Name=\"offsets\" format=\"appended\" offset=\"%llu\"/>\n"
            "        <DataArray type=\"UInt8\" Name=\"types\" format=\"appended\" offset=\"%llu\"/>\n"
            "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _",
            (unsigned long long)points, itype, (unsigned long long)conn, itype, (unsigned long long)offs,
            (unsigned long long)types);
    le_out o;
    o.f = f;
    o.used = 0;
    put_le(&o, 24 * nv, 8);
    for (uint64_t i = 0; i < 3 * nv; ++i)
        put_f64(&o, m->xyz[i]);
    put_le(&o, 3 * isize * nt, 8);
    for (uint64_t i = 0; i < 3 * nt; ++i)
        put_le(&o, (uint64_t)(int64_t)m->tris[i], (int)isize);
    put_le(&o, isize * nt, 8);
    for (uint64_t t = 1; t <= nt; ++t)
        put_le(&o, 3 * t, (int)isize);
    put_le(&o, nt, 8);
    for (uint64_t t = 0; t < nt; ++t)
        put_le(&o, 5, 1); /* VTK_TRIANGLE */
    data_values(&o, x->point_data, x->npoint_data, nv);
    data_values(&o, x->cell_data, x->ncell_data, nt);
    fwrite(o.bytes, 1, o.used, f);
    fputs("\n  </AppendedData>\n</VTKFile>\n", f);
}
