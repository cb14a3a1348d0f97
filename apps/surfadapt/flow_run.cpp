// SPDX-License-Identifier: BSD-3-Clause
#include "flow_run.hpp"

#include "checkpoint.hpp"
#include "cli.hpp"
#include "flows.hpp"
#include "icosphere.h"
#include "obj_io.h"
#include "progress.hpp"
#include "vtu_series.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The start of a run: the geodesic sphere at t = 0, or the checkpoint run.resume_from and
// its time. Returns the surface, or null after a message.
sfa_surface *start_surface(const FlowRun &run, double &t)
{
    sfa_mesh_data mesh{};
    char message[512];
    t = 0;
    if (run.resume_from.empty()) {
        if (geodesic_sphere(run.frequency, run.radius, run.centre, &mesh.nverts, &mesh.xyz, &mesh.ntris, &mesh.tris) != 0) {
            std::fprintf(stderr, "surfadapt: out of memory\n");
            return nullptr;
        }
    } else {
        Checkpoint info;
        std::string error;
        if (!read_checkpoint_header(run.resume_from, info, error)) {
            std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
            return nullptr;
        }
        if (info.flow != run.flow || info.period != run.period) {
            std::fprintf(stderr, "surfadapt: %s is a checkpoint of %s with T = %g, not of this run (%s, T = %g)\n",
                         run.resume_from.c_str(), info.flow.c_str(), info.period, run.flow, run.period);
            return nullptr;
        }
        if (mesh_read(run.resume_from.c_str(), &mesh, message, sizeof message) != 0) {
            std::fprintf(stderr, "surfadapt: %s\n", message);
            return nullptr;
        }
        t = info.time;
    }
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK) {
        mesh_free(&mesh);
        return nullptr;
    }
    const int rc = sfa_set_mesh(s, mesh.nverts, mesh.xyz, mesh.ntris, mesh.tris, 0);
    mesh_free(&mesh);
    if (rc != SFA_OK) {
        fail(s, "sfa_set_mesh");
        return nullptr;
    }
    return s;
}

} // namespace

int run_flow(const FlowRun &run, FlowResult &result)
{
    double t_start = 0;
    sfa_surface *s = start_surface(run, t_start);
    if (!s)
        return 1;
    // A resumed run takes the steps after its checkpoint's time.
    const int first_step = static_cast<int>(std::lround(t_start / run.dt));
    int32_t nverts = 0;
    sfa_get_counts(s, &nverts, nullptr);
    if (run.isotropic)
        sfa_set_param(s, SFA_PARAM_ANISOTROPIC, 0);
    sfa_set_param(s, SFA_PARAM_DENOISE, run.denoise);
    sfa_set_param(s, SFA_PARAM_THIN_SHEET_EDGE_RATIO, run.thin_sheet_edge_ratio);
    sfa_set_param(s, SFA_PARAM_CROSSING_GUARD, run.crossing_guard ? 1 : 0);
    sfa_set_param(s, SFA_PARAM_COLLISION_SAFE_MOTION, run.collision_safe ? 1 : 0);
    sfa_set_param(s, SFA_PARAM_TOPOLOGY_CHANGE, run.topology_change ? 1 : 0);
    sfa_set_param(s, SFA_PARAM_VOLUME_CORRECTION, run.volume_correction ? 1 : 0);
    // Adapted every few steps: one pass per call, the next call picks up what it leaves.
    sfa_set_param(s, SFA_PARAM_ADAPT_PASSES, 1);

    const double volume0 = measure(s, SFA_MEASURE_VOLUME), area0 = measure(s, SFA_MEASURE_AREA);
    char thin_sheets[80] = "";
    if (run.thin_sheet_edge_ratio < 1)
        std::snprintf(thin_sheets, sizeof thin_sheets, ", edges of %g l where a sheet is thinner than an edge",
                      run.thin_sheet_edge_ratio);
    std::printf("%s: sphere of radius %g at (%g, %g, %g), %d vertices; T = %g, dt = %g, %d steps; %s adaptation "
                "every %d steps, denoising %g, crossing guard %s, collision-safe motion %s, topology change %s, "
                "volume correction %s%s\n\n",
                run.title, run.radius, run.centre[0], run.centre[1], run.centre[2], nverts, run.period, run.dt,
                run.steps, run.isotropic ? "isotropic" : "anisotropic", run.adapt_every, run.denoise,
                run.crossing_guard ? "on" : "off", run.collision_safe ? "on" : "off",
                run.topology_change ? "on" : "off", run.volume_correction ? "on" : "off", thin_sheets);
    if (first_step > 0)
        std::printf("resumed from %s at t = %g (step %d); volume errors are relative to its volume\n\n",
                    run.resume_from.c_str(), t_start, first_step);
    std::printf("%5s %6s %9s %10s %13s %10s %9s %9s %9s %9s %8s\n", "step", "t", "vertices", "triangles",
                "volume err %", "area ratio", "min angle", "max angle", "max turn", "crossings", "seconds");
    FlowPeriod flow{run.period};
    // The flow's own velocity goes with each saved step: what moved the surface there.
    vtu_series series;
    vtu_series_init(&series, run.out_dir.c_str(), "surface");
    series.velocity = run.velocity;
    series.velocity_ctx = &flow;
    struct SeriesEnd {
        vtu_series &ts;
        ~SeriesEnd() { vtu_series_free(&ts); }
    } series_end{series};
    std::string error;
    const auto report = [&](int step, double t) {
        int32_t v = 0, tcount = 0;
        sfa_get_counts(s, &v, &tcount);
        const int crossings = static_cast<int>(measure(s, SFA_MEASURE_SELF_INTERSECTIONS));
        result.max_self_intersections = std::max(result.max_self_intersections, crossings);
        std::printf("%5d %6.3f %9d %10d %13.5f %10.3f %9.3f %9.3f %9.2f %9d %8.2f\n", step, t, v, tcount,
                    100 * (measure(s, SFA_MEASURE_VOLUME) - volume0) / volume0, measure(s, SFA_MEASURE_AREA) / area0,
                    measure(s, SFA_MEASURE_MIN_ANGLE), measure(s, SFA_MEASURE_MAX_ANGLE),
                    measure(s, SFA_MEASURE_MAX_NORMAL_TURN), crossings, result.seconds);
        std::fflush(stdout);
        char message[512];
        if (run.out_dir.empty() || vtu_series_save(&series, s, t, message, sizeof message) == 0)
            return true;
        error = message;
        return false;
    };
    // The surface at time t to DIR/NAME (NAME begins with '/'), where DIR is the checkpoints'.
    const auto write_checkpoint = [&](const std::string &name, double t, std::string &why) {
        if (!ensure_directory(run.checkpoint_dir)) {
            why = "cannot create " + run.checkpoint_dir;
            return false;
        }
        const Checkpoint info{run.flow, run.period, t, {run.centre[0], run.centre[1], run.centre[2]}, run.radius};
        return save_checkpoint(s, info, run.checkpoint_dir + name, why);
    };
    // At t = 0 and every quarter period, when the steps divide into quarters.
    const auto save = [&](int step, double t) {
        if (run.checkpoint_dir.empty() || (4 * step) % std::max(run.steps, 1) != 0)
            return true;
        char name[64];
        std::snprintf(name, sizeof name, "/t%g.obj", t);
        return write_checkpoint(name, t, error);
    };
    if (!report(first_step, t_start) || !save(first_step, t_start)) {
        std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
        sfa_destroy(s);
        return 1;
    }

    // A call failed: the surface is as it was before it (the library loses nothing), so it
    // goes to the checkpoints as DIR/failed-t<time>.obj, to look at or --resume from.
    const auto stop = [&](const char *what, double t) {
        if (!run.checkpoint_dir.empty()) {
            const std::string message = std::string(what) + ": " + sfa_last_error(s);
            char name[64];
            std::snprintf(name, sizeof name, "/failed-t%.6g.obj", t);
            std::string unsaved;
            if (write_checkpoint(name, t, unsaved))
                std::fprintf(stderr, "surfadapt: the surface before the failed call: %s%s\n", run.checkpoint_dir.c_str(),
                             name);
            else
                std::fprintf(stderr, "surfadapt: %s\n", unsaved.c_str());
            std::fprintf(stderr, "surfadapt: %s\n", message.c_str());
            sfa_destroy(s);
            return 1;
        }
        return fail(s, what);
    };
    Progress progress;
    // With topology change, each event as it happens.
    const auto adapt = [&](double t) {
        if (sfa_adapt(s) != SFA_OK)
            return false;
        ++result.adapt_calls;
        const int merges = static_cast<int>(measure(s, SFA_MEASURE_MERGES));
        const int pinches = static_cast<int>(measure(s, SFA_MEASURE_PINCHES));
        const int removed = static_cast<int>(measure(s, SFA_MEASURE_DROPS_REMOVED));
        if (merges + pinches + removed > 0) {
            progress.clear();
            int32_t components = 0;
            sfa_get_component_count(s, &components);
            std::printf("      t = %.4f: %d merge(s), %d pinch(es), %d drop(s) removed; %d component(s); volume "
                        "change %.3g\n",
                        t, merges, pinches, removed, components, measure(s, SFA_MEASURE_TOPOLOGY_VOLUME_CHANGE));
        }
        result.merges += merges;
        result.pinches += pinches;
        result.drops_removed += removed;
        return true;
    };
    const auto start = Clock::now();
    double t = t_start;
    for (int step = first_step + 1; step <= run.steps; ++step) {
        const double t_end = step * run.dt;
        int substeps = 0;
        auto phase = Clock::now();
        while (t < t_end - 1e-12 * run.dt) {
            double taken = 0;
            if (sfa_advect(s, run.velocity, &flow, t, t_end - t, &taken) != SFA_OK)
                return stop("sfa_advect", t);
            t += taken;
            ++substeps;
            ++result.advect_calls;
            // Collision-safe motion cuts the step where two sheets close in: adapting lets
            // them merge, instead of creeping toward each other in ever smaller steps.
            if (run.topology_change && taken < 0.5 * (t_end - t + taken) && !adapt(t))
                return stop("sfa_adapt", t);
        }
        t = t_end;
        result.advect_seconds += since(phase);
        phase = Clock::now();
        // More than two sub-steps: the fold control cut the step to less than half. The
        // adaptation smooths too (sfa_adapt's sweeps), so a step adapted is not smoothed again.
        if (run.adapt_every > 0 && (step % run.adapt_every == 0 || substeps > 2)) {
            if (!adapt(t))
                return stop("sfa_adapt", t);
            result.adapt_seconds += since(phase);
        } else if (run.smoothing) {
            if (sfa_smooth(s, 1) != SFA_OK)
                return stop("sfa_smooth", t);
            result.smooth_seconds += since(phase);
        }
        result.seconds = since(start);
        result.max_volume_correction = std::max(result.max_volume_correction, measure(s, SFA_MEASURE_VOLUME_CORRECTION));

        const double volume_error = (measure(s, SFA_MEASURE_VOLUME) - volume0) / volume0;
        if (std::abs(volume_error) > std::abs(result.worst_volume_error))
            result.worst_volume_error = volume_error;
        result.volume_error = volume_error;
        result.max_area_ratio = std::max(result.max_area_ratio, measure(s, SFA_MEASURE_AREA) / area0);
        result.max_normal_turn = std::max(result.max_normal_turn, measure(s, SFA_MEASURE_MAX_NORMAL_TURN));
        int32_t v = 0, tcount = 0;
        sfa_get_counts(s, &v, &tcount);
        result.max_vertices = std::max(result.max_vertices, static_cast<int>(v));
        const bool row = step % run.report_every == 0 || step == run.steps;
        if (row)
            progress.clear();
        else
            progress.show("step %d of %d, t = %.3f, %d vertices", step, run.steps, t, v);
        if ((row && !report(step, t)) || !save(step, t)) {
            std::fprintf(stderr, "surfadapt: %s\n", error.c_str());
            sfa_destroy(s);
            return 1;
        }
    }
    result.analysis_seconds = measure(s, SFA_MEASURE_SECONDS_ANALYSIS);
    result.smoothing_seconds = measure(s, SFA_MEASURE_SECONDS_SMOOTHING);
    result.flipping_seconds = measure(s, SFA_MEASURE_SECONDS_FLIPPING);
    result.repair_seconds = measure(s, SFA_MEASURE_SECONDS_REPAIR);
    std::printf("\nvolume error at the end %.4f %% (worst %.4f %%), area up to x%.2f, up to %d vertices, largest "
                "normal turn %.1f deg, self-intersections at most %d\n%.1f s: advection %.1f s, sfa_smooth %.1f s, sfa_adapt %.1f s; inside "
                "these, analysis %.1f s, smoothing %.1f s, flipping %.1f s, splitting and contraction %.1f s\n",
                100 * result.volume_error, 100 * result.worst_volume_error, result.max_area_ratio, result.max_vertices,
                result.max_normal_turn, result.max_self_intersections, result.seconds, result.advect_seconds,
                result.smooth_seconds, result.adapt_seconds, result.analysis_seconds, result.smoothing_seconds, result.flipping_seconds,
                result.repair_seconds);
    std::printf("the operations of one sfa_smooth or sfa_adapt call changed the volume by at most %.2g (relative)%s\n",
                result.max_volume_correction, run.volume_correction ? "; the volume correction took it back" : "");
    if (run.topology_change)
        std::printf("topology changes: %d merge(s), %d pinch(es), %d drop(s) removed\n", result.merges, result.pinches,
                    result.drops_removed);
    std::printf("%d sfa_advect calls for %d steps, %d sfa_adapt calls\n", result.advect_calls, run.steps,
                result.adapt_calls);
    if (run.json)
        std::printf("{\"bench\":\"flow\",\"flow\":\"%s\",\"anisotropic\":%d,\"denoise\":%g,\"crossing_guard\":%d,"
                    "\"collision_safe\":%d,\"topology_change\":%d,\"merges\":%d,\"pinches\":%d,\"vertices_start\":%d,"
                    "\"vertices_max\":%d,\"steps\":%d,\"volume_error\":%.3e,\"worst_volume_error\":%.3e,"
                    "\"max_area_ratio\":%.3f,\"max_normal_turn\":%.1f,\"max_self_intersections\":%d,"
                    "\"volume_correction\":%d,\"max_volume_correction\":%.3e,\"seconds\":%.2f,\"advect_s\":%.2f,"
                    "\"smooth_s\":%.2f,\"adapt_s\":%.2f,\"analysis_s\":%.2f,\"smoothing_s\":%.2f,"
                    "\"flipping_s\":%.2f,\"split_contract_s\":%.2f,\"adaptation_over_advection\":%.1f}\n",
                    run.title, run.isotropic ? 0 : 1, run.denoise, run.crossing_guard ? 1 : 0, run.collision_safe ? 1 : 0,
                    run.topology_change ? 1 : 0, result.merges, result.pinches, nverts, result.max_vertices, run.steps, result.volume_error,
                    result.worst_volume_error, result.max_area_ratio, result.max_normal_turn,
                    result.max_self_intersections, run.volume_correction ? 1 : 0, result.max_volume_correction,
                    result.seconds,
                    result.advect_seconds, result.smooth_seconds, result.adapt_seconds, result.analysis_seconds,
                    result.smoothing_seconds, result.flipping_seconds, result.repair_seconds,
                    (result.smooth_seconds + result.adapt_seconds) / result.advect_seconds);
    if (!run.out_dir.empty())
        std::printf("time series: %s/surface.pvd\n", run.out_dir.c_str());
    if (!run.checkpoint_dir.empty())
        std::printf("checkpoints: %s/t*.obj\n", run.checkpoint_dir.c_str());
    sfa_destroy(s);
    return 0;
}
