/* SPDX-License-Identifier: BSD-3-Clause */
/* Fuzzes smoothing and adaptation of arbitrary meshes (mesh_input.h) that the library
 * accepts: sfa_smooth, then sfa_adapt at the input's edge length (bounded so that the
 * result has at most a few hundred vertices), again with topology change, then every query; the contract (contract.h)
 * is checked after every call, and a surface that did not cross itself must not cross
 * itself after a call that succeeded. */
#include "mesh_input.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_input in = {data, size, 0};
    fuzz_mesh m = fuzz_mesh_read(&in);
    sfa_surface *s = fuzz_mesh_surface(&m);
    int32_t held = 0;
    sfa_get_counts(s, &held, NULL);
    if (held > 0) {
        FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, m.edge_length));
        FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, 2));
        FUZZ_REMESH(s, sfa_smooth(s, 1));
        double area = 0, mean_edge = 0;
        sfa_measure(s, SFA_MEASURE_AREA, &area);
        sfa_measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH, &mean_edge);
        const double l = m.edge_length > 0 ? m.edge_length : mean_edge;
        if (l > 0 && area / (l * l) < 400) {
            FUZZ_REMESH(s, sfa_adapt(s));
            /* Again with topology change, at a merge distance of two edges so that events
             * happen: merges, pinches and removals must keep the contract too. */
            FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_TOPOLOGY_CHANGE, 1));
            FUZZ_CALL(s, sfa_set_param(s, SFA_PARAM_MERGE_DISTANCE, 2));
            FUZZ_REMESH(s, sfa_adapt(s));
        }
        fuzz_query_everything(s);
    }
    sfa_destroy(s);
    fuzz_mesh_free(&m);
    return 0;
}
