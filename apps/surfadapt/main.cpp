// surfadapt: the command-line tool. A host of the library like any other: it uses only
// the public C interface.
//
//   surfadapt demo              remesh a CAD part, then advect a sphere through the Enright flow
//   surfadapt remesh IN OUT     remesh an OBJ/OFF mesh at a chosen edge length, write VTK
//   surfadapt info FILE         validate an OBJ/OFF mesh and print its measures
//   surfadapt features IN OUT   write the detected features of a mesh as VTK for ParaView
#include "cli.hpp"
#include "commands.hpp"

#include <cstdio>
#include <cstring>
#include <string>

const char *const usage =
    "usage: surfadapt COMMAND [OPTIONS]\n"
    "\n"
    "commands:\n"
    "  demo [--mesh FILE] [--out DIR] [--subdivisions K] [--steps N]\n"
    "        first remesh FILE (default: fandisk.obj of $SFA_DATA_DIR, else ../shared/data;\n"
    "        without it a generated box) at half its mean edge length and write\n"
    "        DIR/remeshed.vtk (DIR defaults to .); then advect a sphere of radius 0.15 at\n"
    "        (0.35, 0.35, 0.35) through the Enright flow (period T = 3, dt = 0.015) with\n"
    "        fourth-order Runge-Kutta and fold control, and print volume, area and angles\n"
    "        every 20 steps. K (default 5) sets the icosphere resolution: 10*4^K+2 vertices.\n"
    "        N defaults to 200 (t = 3).\n"
    "  remesh IN OUT.vtk [--edge-length L] [--isotropic] [--drop-unreferenced]\n"
    "        adapt an OBJ or OFF mesh to edge length L (default: its mean edge length),\n"
    "        anisotropically unless --isotropic, print a quality summary and write the\n"
    "        result as legacy VTK with its features (as for 'features')\n"
    "  info FILE [--drop-unreferenced]\n"
    "        read an OBJ or OFF mesh, validate it and print its measures\n"
    "  features IN OUT.vtk [--drop-unreferenced]\n"
    "        read an OBJ or OFF mesh, detect its ridges and corners and write a legacy\n"
    "        VTK file for ParaView: triangles (POLYGONS) and ridge edges (LINES) with\n"
    "        cell data 'ridge', point data 'rank' (0 smooth, 1 ridge, 2 corner),\n"
    "        'aspect_ratio', 'long_direction' and 'normal' of the anisotropic metric\n"
    "  --help\n"
    "        this text\n";

int main(int argc, char **argv)
{
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
        std::fputs(usage, argc < 2 ? stderr : stdout);
        return argc < 2 ? 2 : 0;
    }
    const std::string command = argv[1];
    if (command == "demo")
        return demo_command(argc, argv);
    if (command == "remesh")
        return remesh_command(argc, argv);
    if (command == "enright")
        return enright_command(argc, argv);
    if (command == "vortex")
        return vortex_command(argc, argv);
    if (command == "info")
        return info_command(argc, argv);
    if (command == "features")
        return features_command(argc, argv);
    std::fprintf(stderr, "surfadapt: unknown command '%s'\n%s", argv[1], usage);
    return 2;
}
