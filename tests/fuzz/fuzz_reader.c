/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzzes the command-line tool's mesh readers (mesh_formats.h: OBJ, OFF, STL, PLY, Medit,
 * legacy VTK, VTU) with arbitrary bytes, and hands what they read to sfa_set_mesh: a
 * reader must fail with a message naming the file or return arrays of the counts it
 * states; the library must then keep its contract.
 *
 * Input: one byte choosing the file name (its value modulo 7: .obj .off .stl .ply .mesh
 * .vtk .vtu), then the file's bytes as they are (binary STL, PLY and VTU included); the
 * reader sees them with a NUL after them, as mesh_file_read gives them.
 *
 * FUZZ_READER=off (or obj, stl, ply, mesh, vtk, vtu) in the environment gives every input
 * to that one reader, whatever its first byte: the goal is counted reader by reader, and
 * libFuzzer otherwise spends its time on the readers whose inputs find new coverage. */
#include "contract.h"
#include "mesh_formats.h"

static const char *const names[7] = {"fuzz.obj", "fuzz.off", "fuzz.stl", "fuzz.ply",
                                     "fuzz.mesh", "fuzz.vtk", "fuzz.vtu"};
/* Inputs per reader, printed when the run ends: the goal is counted reader by reader. */
static unsigned long long inputs_of[7];

__attribute__((destructor)) static void print_inputs_per_reader(void)
{
    fprintf(stderr, "fuzz_reader: inputs per reader:");
    for (int k = 0; k < 7; ++k)
        fprintf(stderr, " %s %llu", names[k] + 5, inputs_of[k]);
    fprintf(stderr, "\n");
}

/* The reader FUZZ_READER names, or -1 for the one each input's first byte chooses. */
static int forced_reader(void)
{
    static int forced = -2;
    if (forced == -2) {
        const char *want = getenv("FUZZ_READER");
        forced = -1;
        for (int k = 0; want && *want && k < 7; ++k)
            if (strcmp(want, names[k] + 5) == 0)
                forced = k;
        if (want && *want && forced < 0) {
            fprintf(stderr, "fuzz_reader: FUZZ_READER=%s names no reader (obj off stl ply mesh vtk vtu)\n", want);
            abort();
        }
    }
    return forced;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const int forced = forced_reader(), reader = forced >= 0 ? forced : data[0] % 7;
    const char *name = names[reader];
    ++inputs_of[reader];
    char *bytes = malloc(size);
    memcpy(bytes, data + 1, size - 1);
    bytes[size - 1] = '\0';
    sfa_mesh_data m;
    int base = -1;
    char err[256];
    if (mesh_file_parse(name, bytes, size - 1, &m, &base, err, sizeof err) != 0) {
        FUZZ_REQUIRE(strncmp(err, name, strlen(name)) == 0, "a reader error that names no file: \"%s\"", err);
        FUZZ_REQUIRE(m.nverts == 0 && m.ntris == 0 && !m.xyz && !m.tris, "a failed read left a mesh behind");
    } else {
        FUZZ_REQUIRE(m.nverts >= 0 && m.ntris >= 0, "counts %d %d", m.nverts, m.ntris);
        FUZZ_REQUIRE(base == 0 || base == 1, "index base %d", base);
        if (m.nverts <= 4096 && m.ntris <= 8192) {
            /* As the tool passes them: in the file's own base, which must fit. */
            for (int64_t i = 0; i < 3 * (int64_t)m.ntris; ++i) {
                FUZZ_REQUIRE(base == 0 || m.tris[i] < INT32_MAX, "index %d cannot be made 1-based", m.tris[i]);
                m.tris[i] += base;
            }
            sfa_surface *s = NULL;
            FUZZ_REQUIRE(sfa_create(&s) == SFA_OK, "sfa_create failed");
            FUZZ_CALL(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, base));
            sfa_destroy(s);
        }
        mesh_free(&m);
    }
    free(bytes);
    return 0;
}
