/* SPDX-License-Identifier: BSD-3-Clause */
// Writing a surface and its features as a legacy ASCII VTK POLYDATA file, which ParaView
// and VisIt open directly: the triangles as POLYGONS, the ridge edges as LINES, and the
// per-vertex results of the quadric analysis as POINT_DATA.
#ifndef SURFADAPT_APP_VTK_WRITER_H
#define SURFADAPT_APP_VTK_WRITER_H

#include <cstdint>
#include <string>

// What goes into the file. Indices are 0-based. Arrays: xyz, long_direction and normal
// 3*nverts; tris 3*ntris; lines 2*nlines; rank and aspect_ratio nverts.
struct VtkFeatureMesh {
    int32_t nverts = 0, ntris = 0, nlines = 0;
    const double *xyz = nullptr;
    const int32_t *tris = nullptr;
    const int32_t *lines = nullptr;
    const int32_t *rank = nullptr;
    const double *aspect_ratio = nullptr;
    const double *long_direction = nullptr;
    const double *normal = nullptr;
};

// Writes `mesh` to `path` with `title` on the header line (one line, no newline). Cell
// data `ridge` is 1 on the lines and 0 on the triangles. Returns true, or false with the
// reason (file name and system error) in `error`.
bool write_vtk_features(const char *path, const char *title, const VtkFeatureMesh &mesh, std::string &error);

#endif
