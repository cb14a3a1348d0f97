// SPDX-License-Identifier: BSD-3-Clause
// What the commands of the surfadapt tool share: errors, options, reading a mesh into a
// surface, a quality summary, and writing a surface with its features for ParaView.
#pragma once

#include "surfadapt.h"

#include <cstdint>
#include <string>

extern const char *const usage;

// Prints "surfadapt: what: <the library's message>", destroys s, returns 1.
int fail(sfa_surface *s, const char *what);

// Creates the directory if it is missing (not its parents); false if it cannot.
bool ensure_directory(const std::string &path);

// sfa_measure, NaN if it fails.
double measure(const sfa_surface *s, int quantity);

// Reads an OBJ/OFF file into a new surface; prints why and returns nullptr on failure.
sfa_surface *surface_from_file(const char *path, bool drop_unreferenced);

// The options after the file names of `info` and `features`: only --drop-unreferenced.
// Prints the usage and returns false on anything else.
bool read_drop_option(int argc, char **argv, int first, const char *command, bool &drop);

// The value after option argv[i] (i is advanced), or exit(2) with a message.
int int_option(int argc, char **argv, int &i, int lo, int hi);
double positive_option(int argc, char **argv, int &i);
double fraction_option(int argc, char **argv, int &i); // in [0, 1]

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
