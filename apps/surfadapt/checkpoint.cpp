// SPDX-License-Identifier: BSD-3-Clause
#include "checkpoint.hpp"
#include "flows.hpp"

#include "obj_io.h"

#include <cstdio>
#include <vector>

namespace {
const char *const header_format = "surfadapt checkpoint: flow %15s period %lf time %lf centre %lf %lf %lf radius %lf";
}

bool save_checkpoint(const sfa_surface *s, const Checkpoint &info, const std::string &path, std::string &error)
{
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::vector<double> xyz(3 * static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris));
    if (sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0) != SFA_OK) {
        error = std::string("sfa_get_mesh: ") + sfa_last_error(s);
        return false;
    }
    char comment[256];
    std::snprintf(comment, sizeof comment,
                  "surfadapt checkpoint: flow %s period %.17g time %.17g centre %.17g %.17g %.17g radius %.17g",
                  info.flow.c_str(), info.period, info.time, info.centre[0], info.centre[1], info.centre[2],
                  info.radius);
    const sfa_mesh_data mesh{nverts, ntris, xyz.data(), tris.data()};
    char message[512];
    if (mesh_write_obj(path.c_str(), &mesh, comment, message, sizeof message) != 0) {
        error = message;
        return false;
    }
    return true;
}

bool read_checkpoint_header(const std::string &path, Checkpoint &info, std::string &error)
{
    FILE *f = std::fopen(path.c_str(), "r");
    if (!f) {
        error = path + ": cannot open";
        return false;
    }
    char flow[16] = "";
    const int read = std::fscanf(f, "# ") == 0 ? std::fscanf(f, header_format, flow, &info.period, &info.time,
                                                            &info.centre[0], &info.centre[1], &info.centre[2],
                                                            &info.radius)
                                               : 0;
    std::fclose(f);
    if (read != 7) {
        error = path + ": the first line is not a surfadapt checkpoint header (a flow's --checkpoints file)";
        return false;
    }
    info.flow = flow;
    return true;
}

sfa_velocity_fn checkpoint_velocity(const Checkpoint &info)
{
    return info.flow == "enright" ? enright_velocity : info.flow == "vortex" ? vortex_velocity : nullptr;
}
