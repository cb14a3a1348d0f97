/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzzes the command-line tool's mesh reader (OBJ and OFF) with arbitrary text, and hands
 * what it reads to sfa_set_mesh: the reader must fail with a message naming a line or
 * return arrays of the counts it states; the library must then keep its contract.
 *
 * Input: one byte choosing the file name (".obj" or ".off"), then the file's text. */
#include "contract.h"
#include "obj_io.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    const char *name = (data[0] & 1) ? "fuzz.off" : "fuzz.obj";
    char *text = malloc(size);
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    sfa_mesh_data m;
    char err[256];
    if (mesh_parse(name, text, &m, err, sizeof err) != 0) {
        FUZZ_REQUIRE(strncmp(err, name, strlen(name)) == 0, "a reader error that names no file: \"%s\"", err);
        FUZZ_REQUIRE(m.nverts == 0 && m.ntris == 0 && !m.xyz && !m.tris, "a failed read left a mesh behind");
    } else {
        FUZZ_REQUIRE(m.nverts >= 0 && m.ntris >= 0, "counts %d %d", m.nverts, m.ntris);
        if (m.nverts <= 4096 && m.ntris <= 8192) {
            sfa_surface *s = NULL;
            FUZZ_REQUIRE(sfa_create(&s) == SFA_OK, "sfa_create failed");
            FUZZ_CALL(s, sfa_set_mesh(s, m.nverts, m.xyz, m.ntris, m.tris, 0));
            sfa_destroy(s);
        }
        mesh_free(&m);
    }
    free(text);
    return 0;
}
