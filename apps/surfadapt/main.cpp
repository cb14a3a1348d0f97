// SPDX-License-Identifier: BSD-3-Clause
// surfadapt: the command-line tool. A host of the library like any other: it uses only
// the public C interface.
//
//   surfadapt demo              remesh a machined part, then run the Enright test
//   surfadapt enright, vortex   the paper's flows with adaptation, as a table and a VTK series
//   surfadapt remesh IN OUT     remesh a mesh at a chosen edge length, write it
//   surfadapt info FILE         validate a mesh and print its measures
//   surfadapt features IN OUT   write the detected features of a mesh, e.g. as VTK for ParaView
//   surfadapt convert IN OUT    a mesh file in another format
//   surfadapt repair IN OUT     mend a mesh the library refuses, reporting each change
#include "cli.hpp"
#include "commands.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

const char *const usage =
    "usage: surfadapt COMMAND [OPTIONS]\n"
    "\n"
    "commands:\n"
    "  demo [--mesh FILE] [--out DIR] [--resolution N] [--steps S]\n"
    "        first remesh a generated machined part (a block with a drilled hole, a\n"
    "        chamfer and a fillet; written as generated to DIR/part.vtk) at edge length\n"
    "        0.08 and print its corners and ridges, expected and as detected before and\n"
    "        after; or with --mesh, FILE at half its mean edge length. The result goes to\n"
    "        DIR/remeshed.vtk (DIR defaults to .). Then run the Enright test as 'enright'\n"
    "        does, writing the time series to DIR/enright\n"
    "  enright [--resolution N] [--dt DT] [--steps S] [--adapt-every K] [--isotropic]\n"
    "          [--denoise W] [--no-crossing-guard] [--collision-safe] [--topology-change]\n"
    "          [--no-volume-correction] [--no-smoothing] [--report-every R] [--out DIR]\n"
    "          [--thin-sheet-ratio R] [--checkpoints DIR] [--resume CHECKPOINT] [--json]\n"
    "        the Enright test (paper §5.2.2): a sphere of radius 0.15 at (0.35, 0.35, 0.35)\n"
    "        of 10 N^2 + 2 vertices (N = 48: 23,042) through the deformation field of period\n"
    "        T = 3 with time step DT (0.015) for S steps (T / DT); every step RK4 advection\n"
    "        with fold control and one smoothing sweep, sfa_adapt every K steps (4; 0 never)\n"
    "        or after a step the fold control cut to less than half; --isotropic adapts with\n"
    "        the identity metric, --denoise W sets SFA_PARAM_DENOISE (0 to 1; default 0),\n"
    "        --no-crossing-guard sets SFA_PARAM_CROSSING_GUARD to 0 (no check that remeshing\n"
    "        keeps the surface from passing through itself where it is thinner than an edge),\n"
    "        --collision-safe sets SFA_PARAM_COLLISION_SAFE_MOTION to 1 (the advection never\n"
    "        lets two triangles meet; a run that brings sheets together then stops there),\n"
    "        --topology-change sets SFA_PARAM_TOPOLOGY_CHANGE to 1 (sheets that meet merge,\n"
    "        necks pinch off; each event is printed as it happens),\n"
    "        --thin-sheet-ratio R sets SFA_PARAM_THIN_SHEET_EDGE_RATIO (above 0, at most 1;\n"
    "        default 1: edges of R l where a sheet is thinner than an edge),\n"
    "        --no-volume-correction sets SFA_PARAM_VOLUME_CORRECTION to 0 (the volume then\n"
    "        changes as the operations themselves change it), --no-smoothing leaves the\n"
    "        steps that are not adapted unsmoothed (with --adapt-every 0: advection alone).\n"
    "        Prints a table every R steps (20) and, with --out, writes DIR/surface.pvd and\n"
    "        one .vtu per table row; with --checkpoints, DIR/t<time>.obj at t = 0 and at\n"
    "        the quarters of the run (T/4, T/2, 3T/4, T without --steps) for bench/fidelity\n"
    "        (the shape error by backtracing), and if a call fails, DIR/failed-t<time>.obj\n"
    "        (the surface before that call); --resume goes on from such a checkpoint's mesh\n"
    "        and time (with default parameters: to look at a late stage without running all\n"
    "        of it);\n"
    "        --json adds the summary (times per phase) as one JSON line\n"
    "  vortex [--period 2|6] [same options as enright]\n"
    "        the vortex flow (paper §5.2.1, §5.2.3): a sphere of radius 0.15 at\n"
    "        (0.5, 0.75, 0.5); period 2 with DT 0.01 from N = 33 (10,892 vertices), period 6\n"
    "        with DT 0.015 from N = 48\n"
    "  remesh IN OUT [--edge-length L] [--isotropic] [--drop-unreferenced]\n"
    "        adapt mesh IN to edge length L (default: its mean edge length),\n"
    "        anisotropically unless --isotropic, print a quality summary and write the\n"
    "        result to OUT: as .vtk with its features (as for 'features'), as .vtu with\n"
    "        the feature rank as point data, in the other formats the mesh alone\n"
    "  info FILE [--drop-unreferenced]\n"
    "        read a mesh, validate it and print its measures and its components (closed or\n"
    "        open with their boundary loops, genus, volume; inside-out ones are named); a\n"
    "        mesh the library refuses gets the reason and what 'repair' would change\n"
    "  repair IN OUT\n"
    "        mend what the library refuses in a mesh from elsewhere, reporting each change:\n"
    "        merge vertices at exactly the same position, triangulate polygons (ear\n"
    "        clipping), drop faces with missing vertices, degenerate and duplicate\n"
    "        triangles, orient each component consistently, split bow-tie vertices, turn\n"
    "        inside-out closed components outward, drop unused vertices, separate the\n"
    "        sheets through an edge of three or more triangles; then say whether the\n"
    "        library accepts the result. Non-orientable components are reported, not\n"
    "        changed\n"
    "  features IN OUT [--drop-unreferenced]\n"
    "        read a mesh, detect its ridges and corners and write them: to OUT.vtk a\n"
    "        legacy VTK file for ParaView, triangles (POLYGONS) and ridge edges (LINES)\n"
    "        with cell data 'ridge', point data 'rank' (0 smooth, 1 ridge, 2 corner),\n"
    "        'aspect_ratio', 'long_direction' and 'normal' of the anisotropic metric;\n"
    "        to OUT.vtu the mesh with point data 'rank'\n"
    "  convert IN OUT\n"
    "        write mesh IN in the format of OUT, as it is (not validated)\n"
    "  Mesh files (IN, OUT, FILE) are chosen by extension, in any case: .obj (Wavefront),\n"
    "        .off, .stl (ASCII or binary; written binary, float32), .ply (ASCII or\n"
    "        binary; written binary), .mesh (Medit/MMG; quadrilaterals read as two\n"
    "        triangles), .vtk (legacy ASCII POLYDATA), .vtu (VTK XML; written binary\n"
    "        appended). Messages number vertices as the file does (from 1 in OBJ and\n"
    "        Medit files, from 0 in the others). With --drop-unreferenced, vertices no\n"
    "        triangle uses are dropped (SFA_PARAM_DROP_UNREFERENCED) instead of refused\n"
    "  --help, or --help after any command\n"
    "        this text\n"
    "  --version\n"
    "        the library's version and ABI version, and its license\n";

namespace {

// OpenMP reads OMP_WAIT_POLICY once, when its runtime starts, and by default lets its idle
// worker threads spin between loops. On a machine whose cores are busy with other work
// (another rank, another job) the spinning threads take the cores from the one doing the
// work: a remesh of the bunny took 3.7-3.9 s that way and 2.6-3.1 s with passive waiting
// beside a busy core. So, unless the user chose a policy, the tool asks for passive
// waiting. It must do so before the runtime starts, which is before any constructor of
// the program runs: functions in .preinit_array are the ones the loader runs earlier.
void wait_passively(int, char **, char **) { setenv("OMP_WAIT_POLICY", "passive", 0); }

__attribute__((section(".preinit_array"), used)) void (*const wait_passively_first)(int, char **, char **) =
    wait_passively;

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        std::fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    if (!std::strcmp(argv[1], "--version")) {
        std::printf("surfadapt %s (ABI %d), BSD-3-Clause\n", sfa_version_string(), sfa_abi_version());
        return 0;
    }
    for (int i = 2; i < argc; ++i)
        if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
            std::fputs(usage, stdout);
            return 0;
        }
    // The commands, in the order the help gives them; the message for an unknown one lists
    // them from here, so that it names every command there is.
    static const struct {
        const char *name;
        int (*run)(int, char **);
    } commands[] = {{"demo", demo_command},         {"enright", enright_command}, {"vortex", vortex_command},
                    {"remesh", remesh_command},     {"info", info_command},       {"repair", repair_command},
                    {"features", features_command}, {"convert", convert_command}};
    const size_t count = sizeof commands / sizeof commands[0];
    std::string names;
    for (size_t k = 0; k < count; ++k) {
        if (!std::strcmp(argv[1], commands[k].name))
            return commands[k].run(argc, argv);
        names += k == 0 ? "" : k + 1 < count ? ", " : " and ";
        names += commands[k].name;
    }
    std::fprintf(stderr, "surfadapt: unknown command '%s'; the commands are %s (surfadapt --help explains them)\n",
                 argv[1], names.c_str());
    return 2;
}
