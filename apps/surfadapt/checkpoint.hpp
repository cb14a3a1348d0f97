// SPDX-License-Identifier: BSD-3-Clause
// Meshes saved during a flow run for the backtrace measure of shape error (bench/fidelity):
// OBJ at full precision, with a first comment line that says which flow, period, time and
// start sphere they belong to, so that a checkpoint file is read without other knowledge.
#pragma once

#include "surfadapt.h"

#include <string>

struct Checkpoint {
    std::string flow;  // "enright" or "vortex" (flows.hpp)
    double period = 0; // T
    double time = 0;   // t at which the mesh was saved
    double centre[3] = {0, 0, 0};
    double radius = 0; // of the start sphere, which the exact surface returns to at t = T
};

// Writes the surface to `path` with `info` in its header line; false with the reason.
bool save_checkpoint(const sfa_surface *s, const Checkpoint &info, const std::string &path, std::string &error);

// Reads the header line of a file save_checkpoint wrote; false with the reason.
bool read_checkpoint_header(const std::string &path, Checkpoint &info, std::string &error);

// The velocity field of the checkpoint's flow (flows.hpp), or nullptr for a flow of
// another name.
sfa_velocity_fn checkpoint_velocity(const Checkpoint &info);
