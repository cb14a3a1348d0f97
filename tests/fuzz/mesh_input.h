/* SPDX-License-Identifier: BSD-3-Clause */
/* Decodes a fuzzer's input into arrays for sfa_set_mesh, for fuzz_mesh and fuzz_adapt.
 *
 * Input: a flags byte (bit 0: index base 1; bit 1: drop unreferenced vertices; bit 2:
 * raw 8-byte coordinates instead of small grid ones), the vertex and triangle counts (a
 * byte each: at most 64 and 96), an edge length byte, then the coordinates and the corner
 * indices (a byte each: -1 to nverts, so that out-of-range indices occur). */
#ifndef SURFADAPT_FUZZ_MESH_INPUT_H
#define SURFADAPT_FUZZ_MESH_INPUT_H

#include "contract.h"

typedef struct fuzz_mesh {
    int32_t base, nverts, ntris;
    int drop_unreferenced;
    double edge_length; /* 0: the mesh's mean edge */
    double *xyz;
    int32_t *tris;
} fuzz_mesh;

static inline fuzz_mesh fuzz_mesh_read(fuzz_input *in)
{
    fuzz_mesh m;
    const uint8_t flags = fuzz_byte(in);
    m.base = flags & 1;
    m.drop_unreferenced = (flags & 2) != 0;
    m.nverts = fuzz_byte(in) % 65;
    m.ntris = fuzz_byte(in) % 97;
    m.edge_length = fuzz_byte(in) / 64.0;
    m.xyz = malloc(sizeof(double) * 3 * (size_t)(m.nverts + 1));
    m.tris = malloc(sizeof(int32_t) * 3 * (size_t)(m.ntris + 1));
    for (int32_t i = 0; i < 3 * m.nverts; ++i)
        m.xyz[i] = (flags & 4) ? fuzz_raw_double(in) : fuzz_small(in);
    for (int32_t i = 0; i < 3 * m.ntris; ++i)
        m.tris[i] = (int32_t)(fuzz_byte(in) % (m.nverts + 2)) - 1 + m.base;
    return m;
}

/* A surface holding the decoded mesh if the library accepts it (checked either way). */
static inline sfa_surface *fuzz_mesh_surface(const fuzz_mesh *m)
{
    sfa_surface *s = NULL;
    FUZZ_REQUIRE(sfa_create(&s) == SFA_OK, "sfa_create failed");
    FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_THREADS, 1));
    FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, m->drop_unreferenced));
    FUZZ_CALL(s, sfa_set_mesh(s, m->nverts, m->xyz, m->ntris, m->tris, m->base));
    return s;
}

static inline void fuzz_mesh_free(fuzz_mesh *m)
{
    free(m->xyz);
    free(m->tris);
}

#endif
