/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzzes sfa_set_mesh with arbitrary vertex and triangle arrays (mesh_input.h), then every
 * query of the surface; the contract (contract.h) is checked after every call. The cheap
 * path: fuzz_adapt takes the same inputs through smoothing and adaptation. */
#include "mesh_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_input in = {data, size, 0};
    fuzz_mesh m = fuzz_mesh_read(&in);
    sfa_surface *s = fuzz_mesh_surface(&m);
    fuzz_query_everything(s);
    sfa_destroy(s);
    fuzz_mesh_free(&m);
    return 0;
}
