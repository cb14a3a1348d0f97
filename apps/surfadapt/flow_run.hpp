// SPDX-License-Identifier: BSD-3-Clause
// Tracking a sphere through one of the paper's flows with the schedule a host follows
// (README, "Dynamic surfaces"): every step, RK4 advection (sfa_advect, sub-stepping while
// the fold control cuts the step) then one smoothing sweep; a full sfa_adapt every k steps,
// or at once after a step the fold control had to cut to less than half.
#pragma once

#include "surfadapt.h"

#include <string>

struct FlowRun {
    const char *title;
    const char *flow;     // "enright" or "vortex": the velocity's name in checkpoints
    sfa_velocity_fn velocity;
    double period;
    double dt;
    int steps;
    double centre[3];
    double radius;
    int frequency;        // initial geodesic sphere: 10 n^2 + 2 vertices
    int adapt_every;      // 0: never adapt
    bool isotropic;
    std::string out_dir;  // empty: no files
    // Empty: none. Otherwise the mesh at t = 0, T/4, T/2, 3T/4 and T (checkpoint.hpp), as
    // DIR/t<time>.obj, for bench/fidelity.
    std::string checkpoint_dir;
    int report_every;     // table rows (and saved steps)
    bool json = false;    // also print the summary as one JSON line (for benchmarks)
    double denoise = 0;   // SFA_PARAM_DENOISE
    double thin_sheet_edge_ratio = 1; // SFA_PARAM_THIN_SHEET_EDGE_RATIO
    bool crossing_guard = true; // SFA_PARAM_CROSSING_GUARD
    bool collision_safe = false; // SFA_PARAM_COLLISION_SAFE_MOTION
    bool topology_change = false; // SFA_PARAM_TOPOLOGY_CHANGE
    bool volume_correction = true; // SFA_PARAM_VOLUME_CORRECTION
    bool smoothing = true;  // false: a step that is not adapted is not smoothed either
    // Empty: start from the sphere at t = 0. Otherwise a checkpoint of the same flow, period
    // and time step: the run goes on from its mesh and time (to look at a late stage of a
    // long run without running all of it; parameters and size field are the defaults, so
    // the run differs from the one that wrote the checkpoint from there on).
    std::string resume_from = "";
};

struct FlowResult {
    double volume_error = 0;       // at the end, relative
    double worst_volume_error = 0; // over the run, relative, largest magnitude
    double max_area_ratio = 1;
    double max_normal_turn = 0;    // degrees, over every step: near 180 at a fold or a cusp
    int max_self_intersections = 0; // at the table's rows: pairs of triangles that cross
    int max_vertices = 0;
    int merges = 0, pinches = 0, drops_removed = 0; // topology changes, summed over the run
    int advect_calls = 0, adapt_calls = 0;
    // The largest SFA_MEASURE_VOLUME_CORRECTION of any sfa_smooth or sfa_adapt call: how far
    // the operations of one call alone moved the volume.
    double max_volume_correction = 0;
    double seconds = 0, advect_seconds = 0, smooth_seconds = 0, adapt_seconds = 0; // per call
    // Inside sfa_smooth and sfa_adapt, per phase (SFA_MEASURE_SECONDS_*).
    double analysis_seconds = 0, smoothing_seconds = 0, flipping_seconds = 0, repair_seconds = 0;
};

// The paper's Enright test (§5.2.2).
FlowRun enright_setup();

// Runs and prints the table; returns the exit status.
int run_flow(const FlowRun &run, FlowResult &result);
