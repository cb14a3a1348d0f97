// SPDX-License-Identifier: BSD-3-Clause
// Remeshing a static surface: sfa_adapt at a chosen edge length, with a quality summary.
#pragma once

#include "surfadapt.h"

// Adapts s at `edge_length` (three sfa_adapt calls, enough for a factor of two either
// way), isotropically if asked, prints the before/after summary and writes `out` (format
// by extension, write_surface) unless it is nullptr. Returns the exit status; s is the caller's to destroy.
int remesh_surface(sfa_surface *s, const char *name, double edge_length, bool isotropic, const char *out);
