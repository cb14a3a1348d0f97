// SPDX-License-Identifier: BSD-3-Clause
// surfadapt enright and surfadapt vortex: the paper's flow experiments (§5.2).
#include "cli.hpp"
#include "commands.hpp"
#include "flow_run.hpp"
#include "flows.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace {

// The options both commands share; false (after a message) on a bad one.
bool read_flow_options(int argc, char **argv, int first, FlowRun &run, const char *command)
{
    int steps = -1;
    for (int i = first; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--resolution"))
            run.frequency = int_option(argc, argv, i, 1, 2000);
        else if (!std::strcmp(argv[i], "--dt"))
            run.dt = positive_option(argc, argv, i);
        else if (!std::strcmp(argv[i], "--steps"))
            steps = int_option(argc, argv, i, 0, 100000000);
        else if (!std::strcmp(argv[i], "--adapt-every"))
            run.adapt_every = int_option(argc, argv, i, 0, 1000000);
        else if (!std::strcmp(argv[i], "--report-every"))
            run.report_every = int_option(argc, argv, i, 1, 1000000);
        else if (!std::strcmp(argv[i], "--isotropic"))
            run.isotropic = true;
        else if (!std::strcmp(argv[i], "--no-crossing-guard"))
            run.crossing_guard = false;
        else if (!std::strcmp(argv[i], "--collision-safe"))
            run.collision_safe = true;
        else if (!std::strcmp(argv[i], "--topology-change"))
            run.topology_change = true;
        else if (!std::strcmp(argv[i], "--no-smoothing"))
            run.smoothing = false;
        else if (!std::strcmp(argv[i], "--no-volume-correction"))
            run.volume_correction = false;
        else if (!std::strcmp(argv[i], "--denoise"))
            run.denoise = fraction_option(argc, argv, i);
        else if (!std::strcmp(argv[i], "--thin-sheet-ratio"))
            run.thin_sheet_edge_ratio = positive_fraction_option(argc, argv, i);
        else if (!std::strcmp(argv[i], "--json"))
            run.json = true;
        else if (!std::strcmp(argv[i], "--out") && i + 1 < argc)
            run.out_dir = argv[++i];
        else if (!std::strcmp(argv[i], "--checkpoints") && i + 1 < argc)
            run.checkpoint_dir = argv[++i];
        else if (!std::strcmp(argv[i], "--resume") && i + 1 < argc)
            run.resume_from = argv[++i];
        else if (!std::strcmp(argv[i], "--period") && !std::strcmp(command, "vortex"))
            ++i; // read by the caller
        else {
            std::fprintf(stderr, "surfadapt %s: unknown option '%s'\n", command, argv[i]);
            print_synopsis(command);
            return false;
        }
    }
    // A whole period unless told otherwise.
    run.steps = steps >= 0 ? steps : static_cast<int>(std::lround(run.period / run.dt));
    return true;
}

int execute(const FlowRun &run)
{
    FlowResult result;
    return run_flow(run, result);
}

} // namespace

FlowRun enright_setup()
{
    // §5.2.2: radius 0.15 at (0.35, 0.35, 0.35), T = 3, dt = 0.015 (200 steps), adaptation
    // every 4 steps; 23,042 vertices (the paper's mesh had 23,238).
    return FlowRun{"Enright flow", "enright", enright_velocity, 3.0, 0.015, 200, {0.35, 0.35, 0.35}, 0.15, 48, 4, false, "", "", 20};
}

int enright_command(int argc, char **argv)
{
    FlowRun run = enright_setup();
    if (!read_flow_options(argc, argv, 2, run, "enright"))
        return 2;
    return execute(run);
}

int vortex_command(int argc, char **argv)
{
    // §5.2.1 (T = 2: dt = 0.01, 10,784 vertices in the paper, 10,892 here) and §5.2.3
    // (T = 6: dt = 0.015, the Enright test's mesh): radius 0.15 at (0.5, 0.75, 0.5).
    int period = 2;
    for (int i = 2; i < argc; ++i)
        if (!std::strcmp(argv[i], "--period")) {
            period = int_option(argc, argv, i, 1, 1000);
            if (period != 2 && period != 6) {
                std::fprintf(stderr, "surfadapt vortex: --period must be 2 or 6 (the paper's runs), got %d\n", period);
                return 2;
            }
        }
    FlowRun run{period == 2 ? "Vortex flow, T = 2" : "Vortex flow, T = 6",
                "vortex",
                vortex_velocity,
                double(period),
                period == 2 ? 0.01 : 0.015,
                0,
                {0.5, 0.75, 0.5},
                0.15,
                period == 2 ? 33 : 48,
                4,
                false,
                "",
                "",
                20};
    if (!read_flow_options(argc, argv, 2, run, "vortex"))
        return 2;
    return execute(run);
}
