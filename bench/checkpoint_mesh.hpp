// SPDX-License-Identifier: BSD-3-Clause
// A flow run's checkpoint (apps/surfadapt/checkpoint.hpp) as the library's own mesh, with
// the flow's velocity at its vertices at the checkpoint's time: the benchmarks that link
// the library's internals time their searches on the meshes the paper's flows make (thin
// sheets facing each other, graded and stretched triangles), not only on spheres.
#pragma once

#include "checkpoint.hpp"
#include "flows.hpp"
#include "mesh/validate.hpp"

extern "C" {
#include "obj_io.h"
}

#include <cstdio>
#include <string>
#include <vector>

struct CheckpointMesh {
    std::string name; // the flow and the time, as "enright_t1.5"
    sfa::TriMesh mesh;
    std::vector<sfa::Vec3> velocity;
};

// False, with the reason on standard error, if `path` is not a readable checkpoint of a
// known flow or its mesh is not one sfa_set_mesh accepts.
inline bool read_checkpoint_mesh(const char *path, CheckpointMesh &out)
{
    Checkpoint info;
    std::string error;
    if (!read_checkpoint_header(path, info, error)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return false;
    }
    const sfa_velocity_fn velocity = checkpoint_velocity(info);
    if (!velocity) {
        std::fprintf(stderr, "%s: unknown flow '%s'\n", path, info.flow.c_str());
        return false;
    }
    sfa_mesh_data data{};
    char message[512];
    if (mesh_read(path, &data, message, sizeof message) != 0) {
        std::fprintf(stderr, "%s\n", message);
        return false;
    }
    try {
        out.mesh = sfa::validated_mesh(sfa::MeshInput{data.nverts, data.xyz, data.ntris, data.tris, 0, false});
    } catch (const std::exception &e) {
        std::fprintf(stderr, "%s: %s\n", path, e.what());
        mesh_free(&data);
        return false;
    }
    std::vector<double> v(3 * static_cast<size_t>(data.nverts));
    FlowPeriod period{info.period};
    velocity(&period, data.nverts, data.xyz, info.time, v.data());
    mesh_free(&data);
    out.velocity.resize(out.mesh.pos.size());
    for (size_t k = 0; k < out.velocity.size(); ++k)
        out.velocity[k] = sfa::Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
    char name[64];
    std::snprintf(name, sizeof name, "%s_t%g", info.flow.c_str(), info.time);
    out.name = name;
    return true;
}
