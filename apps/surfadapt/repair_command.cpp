// SPDX-License-Identifier: BSD-3-Clause
// surfadapt repair IN OUT: a mesh the library refuses, mended where the mending is
// unambiguous (repair.hpp), every change reported; and, for `info`, what repair would do.
#include "cli.hpp"
#include "commands.hpp"
#include "mesh_formats.h"
#include "repair.hpp"

#include <cstdio>
#include <string>

namespace {

// Reads `path` with its faces as the file has them. Prints why and returns false on failure.
bool read_polygons(const char *path, PolygonMesh &mesh, int &base)
{
    sfa_mesh_data data{};
    mesh_faces faces{};
    char error[512];
    if (mesh_file_read_faces(path, &data, &faces, &base, error, sizeof error) != 0) {
        std::fprintf(stderr, "surfadapt: %s\n", error);
        return false;
    }
    mesh.xyz.assign(data.xyz, data.xyz + 3 * static_cast<size_t>(data.nverts));
    mesh.face_start.clear();
    mesh.indices.clear();
    // Face f was fanned from its first corner into its triangles: the first triangle's
    // three corners, then the third corner of each further one.
    for (int32_t f = 0; f < faces.nfaces; ++f) {
        const int32_t begin = faces.first_triangle[f], end = f + 1 < faces.nfaces ? faces.first_triangle[f + 1] : data.ntris;
        mesh.face_start.push_back(static_cast<int32_t>(mesh.indices.size()));
        for (int32_t t = begin; t < end; ++t) {
            const int32_t *corner = data.tris + 3 * static_cast<size_t>(t);
            if (t == begin)
                mesh.indices.insert(mesh.indices.end(), corner, corner + 3);
            else
                mesh.indices.push_back(corner[2]);
        }
    }
    mesh.face_start.push_back(static_cast<int32_t>(mesh.indices.size()));
    mesh_faces_free(&faces);
    mesh_free(&data);
    return true;
}

} // namespace

void suggest_repair(const char *path)
{
    PolygonMesh mesh;
    int base = 0;
    if (!read_polygons(path, mesh, base))
        return;
    TriangleSoup repaired;
    const RepairReport report = repair_mesh(mesh, repaired);
    if (report.changes() == 0)
        return;
    std::fprintf(stderr, "surfadapt: 'surfadapt repair %s OUT' would report:\n", path);
    for (const std::string &line : report.lines())
        std::fprintf(stderr, "  %s\n", line.c_str());
}

int repair_command(int argc, char **argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "surfadapt repair: needs an input and an output mesh file\n");
        print_synopsis("repair");
        return 2;
    }
    const char *in = argv[2], *out = argv[3];
    if (mesh_format_of(out) == MESH_FORMAT_UNKNOWN) {
        std::fprintf(stderr, "surfadapt repair: %s: unknown mesh format: the extension must be one of %s\n", out,
                     mesh_format_extensions());
        return 2;
    }
    PolygonMesh mesh;
    int base = 0;
    if (!read_polygons(in, mesh, base))
        return 1;
    TriangleSoup repaired;
    const RepairReport report = repair_mesh(mesh, repaired);
    std::printf("%s: %zu vertices, %d faces\n", in, mesh.xyz.size() / 3, mesh.faces());
    if (report.lines().empty())
        std::printf("  nothing to repair\n");
    for (const std::string &line : report.lines())
        std::printf("  %s\n", line.c_str());

    const sfa_mesh_data result{static_cast<int32_t>(repaired.xyz.size() / 3),
                               static_cast<int32_t>(repaired.tris.size() / 3), repaired.xyz.data(),
                               repaired.tris.data()};
    char error[512];
    if (mesh_file_write(out, &result, "repaired by surfadapt", nullptr, error, sizeof error) != 0) {
        std::fprintf(stderr, "surfadapt: %s\n", error);
        return 1;
    }
    std::printf("  %d vertices, %d triangles written to %s\n", result.nverts, result.ntris, out);

    // Whether the library now accepts it, in the output file's numbering.
    const int out_base = mesh_format_index_base(mesh_format_of(out));
    for (int32_t &v : repaired.tris)
        v += out_base;
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK)
        return 1;
    const int rc = sfa_set_mesh(s, result.nverts, repaired.xyz.data(), result.ntris, repaired.tris.data(), out_base);
    if (rc != SFA_OK) {
        std::printf("  the library still refuses it: %s\n", sfa_last_error(s));
        sfa_destroy(s);
        return 1;
    }
    std::printf("  the library accepts it\n");
    sfa_destroy(s);
    return 0;
}
