// SPDX-License-Identifier: BSD-3-Clause
#include "vtk_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace {

// Closes the file on every path out.
struct File {
    std::FILE *f;
    ~File()
    {
        if (f)
            std::fclose(f);
    }
};

void write_vectors(std::FILE *f, const char *name, const double *v, int32_t n)
{
    std::fprintf(f, "VECTORS %s double\n", name);
    for (int32_t i = 0; i < n; ++i)
        std::fprintf(f, "%.17g %.17g %.17g\n", v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}

} // namespace

bool write_vtk_features(const char *path, const char *title, const VtkFeatureMesh &mesh, std::string &error)
{
    File file{std::fopen(path, "w")};
    if (!file.f) {
        error = std::string("cannot write ") + path + ": " + std::strerror(errno);
        return false;
    }
    std::FILE *f = file.f;
    std::fprintf(f, "# vtk DataFile Version 3.0\n%s\nASCII\nDATASET POLYDATA\n", title);
    std::fprintf(f, "POINTS %d double\n", mesh.nverts);
    for (int32_t i = 0; i < mesh.nverts; ++i)
        std::fprintf(f, "%.17g %.17g %.17g\n", mesh.xyz[3 * i], mesh.xyz[3 * i + 1], mesh.xyz[3 * i + 2]);
    // VTK numbers the cells of POLYDATA lines first, then polygons, whatever the order of
    // the sections; they are written in that order so that the file reads the same way.
    if (mesh.nlines > 0) {
        std::fprintf(f, "LINES %d %d\n", mesh.nlines, 3 * mesh.nlines);
        for (int32_t e = 0; e < mesh.nlines; ++e)
            std::fprintf(f, "2 %d %d\n", mesh.lines[2 * e], mesh.lines[2 * e + 1]);
    }
    std::fprintf(f, "POLYGONS %d %d\n", mesh.ntris, 4 * mesh.ntris);
    for (int32_t t = 0; t < mesh.ntris; ++t)
        std::fprintf(f, "3 %d %d %d\n", mesh.tris[3 * t], mesh.tris[3 * t + 1], mesh.tris[3 * t + 2]);

    std::fprintf(f, "CELL_DATA %d\nSCALARS ridge int 1\nLOOKUP_TABLE default\n", mesh.nlines + mesh.ntris);
    for (int32_t e = 0; e < mesh.nlines; ++e)
        std::fputs("1\n", f);
    for (int32_t t = 0; t < mesh.ntris; ++t)
        std::fputs("0\n", f);

    std::fprintf(f, "POINT_DATA %d\nSCALARS rank int 1\nLOOKUP_TABLE default\n", mesh.nverts);
    for (int32_t i = 0; i < mesh.nverts; ++i)
        std::fprintf(f, "%d\n", mesh.rank[i]);
    std::fputs("SCALARS aspect_ratio double 1\nLOOKUP_TABLE default\n", f);
    for (int32_t i = 0; i < mesh.nverts; ++i)
        std::fprintf(f, "%.17g\n", mesh.aspect_ratio[i]);
    write_vectors(f, "long_direction", mesh.long_direction, mesh.nverts);
    write_vectors(f, "normal", mesh.normal, mesh.nverts);

    // A full disk shows up at the latest when the buffers are flushed.
    const bool failed = std::ferror(f) != 0;
    file.f = nullptr;
    if (std::fclose(f) != 0 || failed) {
        error = std::string("cannot write ") + path + ": " + std::strerror(errno ? errno : EIO);
        return false;
    }
    return true;
}
