/* SPDX-License-Identifier: BSD-3-Clause */
#include "format_io.h"

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* A growing array of `count` items of `item` bytes with room for one more: `array` itself
 * while it has room, else reallocated to twice its capacity (`*cap` updated). Counts stay
 * within int32_t, the library's. NULL when it cannot grow (the array is then unchanged). */
static void *with_room(void *array, int64_t count, int64_t *cap, size_t item)
{
    if (count >= INT32_MAX)
        return NULL;
    if (count < *cap)
        return array;
    const int64_t grown_cap = *cap ? 2 * *cap : 1024;
    void *grown = realloc(array, item * (size_t)grown_cap);
    if (grown)
        *cap = grown_cap;
    return grown;
}

int builder_add_vertex(mesh_builder *b, const double p[3])
{
    double *xyz = with_room(b->xyz, b->nverts, &b->vcap, 3 * sizeof(double));
    if (!xyz)
        return -1;
    b->xyz = xyz;
    memcpy(b->xyz + 3 * b->nverts, p, sizeof(double) * 3);
    ++b->nverts;
    return 0;
}

int builder_add_triangle(mesh_builder *b, int32_t i, int32_t j, int32_t k)
{
    int32_t *tris = with_room(b->tris, b->ntris, &b->tcap, 3 * sizeof(int32_t));
    if (!tris)
        return -1;
    b->tris = tris;
    int32_t *t = b->tris + 3 * b->ntris;
    t[0] = i;
    t[1] = j;
    t[2] = k;
    ++b->ntris;
    return 0;
}

int builder_begin_face(mesh_builder *b)
{
    if (!b->record_faces)
        return 0;
    int32_t *first = with_room(b->face_first, b->nfaces, &b->fcap, sizeof(int32_t));
    if (!first)
        return -1;
    b->face_first = first;
    b->face_first[b->nfaces++] = (int32_t)b->ntris;
    return 0;
}

void builder_free(mesh_builder *b)
{
    free(b->xyz);
    free(b->tris);
    free(b->face_first);
    memset(b, 0, sizeof *b);
}

int read_fail(const read_context *c, const char *fmt, ...)
{
    if (!c->err || !c->err_len)
        return -1;
    int n;
    if (c->line > 0)
        n = snprintf(c->err, c->err_len, "%s:%ld: ", c->path, c->line);
    else if (c->offset >= 0)
        n = snprintf(c->err, c->err_len, "%s: byte %lld: ", c->path, c->offset);
    else
        n = snprintf(c->err, c->err_len, "%s: ", c->path);
    if (n < 0)
        n = 0;
    if ((size_t)n < c->err_len) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(c->err + n, c->err_len - (size_t)n, fmt, ap);
        va_end(ap);
    }
    return -1;
}

const char *text_skip(const char *p, read_context *c, char comment)
{
    for (;;) {
        while (*p && isspace((unsigned char)*p)) {
            if (*p == '\n')
                ++c->line;
            ++p;
        }
        if (!comment || *p != comment)
            return p;
        p = text_line_end(p);
    }
}

const char *text_line_end(const char *p)
{
    while (*p && *p != '\n')
        ++p;
    return p;
}

/* A number must end where its token ends: "1x" is not a number. */
static int token_ends(const char *p) { return *p == '\0' || isspace((unsigned char)*p); }

int text_double(const char **p, read_context *c, char comment, double *v)
{
    const char *s = text_skip(*p, c, comment);
    char *end;
    *p = s;
    *v = strtod(s, &end);
    /* Overflow gives +-HUGE_VAL: kept, because judging coordinates is the library's job. */
    if (end == s || !token_ends(end))
        return -1;
    *p = end;
    return 0;
}

int text_long(const char **p, read_context *c, char comment, long long *v)
{
    const char *s = text_skip(*p, c, comment);
    char *end;
    *p = s;
    errno = 0;
    *v = strtoll(s, &end, 10);
    if (end == s || errno == ERANGE || !token_ends(end))
        return -1;
    *p = end;
    return 0;
}

int text_word(const char **p, read_context *c, char comment, char *word, size_t n)
{
    const char *s = text_skip(*p, c, comment);
    size_t len = 0;
    while (s[len] && !isspace((unsigned char)s[len]))
        ++len;
    *p = s + len;
    if (len == 0)
        return -1;
    const size_t kept = len < n - 1 ? len : n - 1;
    memcpy(word, s, kept);
    word[kept] = '\0';
    return 0;
}

int same_word(const char *a, const char *b)
{
    for (; *a && *b; ++a, ++b)
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
            return 0;
    return *a == *b;
}

uint64_t load_u64(const unsigned char *p, int big_endian)
{
    uint64_t v = 0;
    for (int k = 0; k < 8; ++k)
        v |= (uint64_t)p[big_endian ? 7 - k : k] << (8 * k);
    return v;
}

uint32_t load_u32(const unsigned char *p, int big_endian)
{
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k)
        v |= (uint32_t)p[big_endian ? 3 - k : k] << (8 * k);
    return v;
}

double load_f64(const unsigned char *p, int big_endian)
{
    const uint64_t bits = load_u64(p, big_endian);
    double v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

float load_f32(const unsigned char *p, int big_endian)
{
    const uint32_t bits = load_u32(p, big_endian);
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

char *read_whole_file(const char *path, size_t *size, const read_context *c)
{
    *size = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        read_fail(c, "cannot open: %s", strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, len = 0;
    char *buf = malloc(cap);
    while (buf) {
        if (len + 1 >= cap) {
            char *grown = cap <= SIZE_MAX / 2 ? realloc(buf, cap * 2) : NULL;
            if (!grown) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = grown;
            cap *= 2;
        }
        const size_t got = fread(buf + len, 1, cap - 1 - len, f);
        len += got;
        if (got == 0)
            break;
    }
    if (!buf)
        read_fail(c, "out of memory");
    else if (ferror(f)) {
        read_fail(c, "read error");
        free(buf);
        buf = NULL;
    } else {
        buf[len] = '\0';
        *size = len;
    }
    fclose(f);
    return buf;
}
