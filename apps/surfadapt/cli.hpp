// SPDX-License-Identifier: BSD-3-Clause
// What the commands of the surfadapt tool share: errors, options, reading a mesh into a
// surface, a quality summary, and writing a surface with its features for ParaView.
#pragma once

#include "surfadapt.h"

#include <cstdint>
#include <string>

extern const char *const usage;

// After a usage error: the command's lines of `usage` (its name and options, not their
// explanation) and where the rest is, on standard error, so that the error itself stays
// on the screen.
void print_synopsis(const char *command);

// Prints "surfadapt: what: <the library's message>", destroys s, returns 1.
int fail(sfa_surface *s, const char *what);

// Creates the directory and any missing parents; false if it cannot.
bool ensure_directory(const std::string &path);

// sfa_measure, NaN if it fails.
double measure(const sfa_surface *s, int quantity);

// Reads a mesh file (format by extension, mesh_formats.h) into a new surface, in the file's
// own numbering so that the library's messages name the file's vertex and triangle
// numbers; prints why and returns nullptr on failure.
sfa_surface *surface_from_file(const char *path, bool drop_unreferenced);

// Whether `path` has an extension the tool writes; prints the supported ones if not.
bool known_output_format(const char *path);

// The options after the file names of `info` and `features`: only --drop-unreferenced.
// Prints the usage and returns false on anything else.
bool read_drop_option(int argc, char **argv, int first, const char *command, bool &drop);

// The value after option argv[i] (i is advanced), or exit(2) with a message.
int int_option(int argc, char **argv, int &i, int lo, int hi);
double positive_option(int argc, char **argv, int &i);
double fraction_option(int argc, char **argv, int &i); // in [0, 1]
double positive_fraction_option(int argc, char **argv, int &i); // in (0, 1]

// What a user wants to know of a mesh's quality.
struct Quality {
    int32_t vertices = 0, triangles = 0, corners = 0, ridge_edges = 0;
    double volume = 0, area = 0, min_angle = 0, max_angle = 0, mean_edge = 0;
    double good_share = 0; // triangles with every angle in [15, 160] degrees (the paper's bounds)
};
Quality quality_of(const sfa_surface *s);

// The surface, its ridge edges and per-vertex analysis as legacy VTK (vtk_writer.h).
// Returns false with the reason in `error`.
bool write_surface_vtk(const sfa_surface *s, const char *path, const std::string &title, std::string &error);

// Writes the surface in the format of the path's extension: .vtk with its features as
// write_surface_vtk does, .vtu with the feature rank as point data, the others the mesh
// alone. Returns false with the reason in `error`.
bool write_surface(const sfa_surface *s, const char *path, const std::string &title, std::string &error);
