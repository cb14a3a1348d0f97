// SPDX-License-Identifier: BSD-3-Clause
#include "cli.hpp"

#include "mesh_formats.h"
#include "vtk_writer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include <cerrno>
#include <sys/stat.h>

int fail(sfa_surface *s, const char *what)
{
    std::fprintf(stderr, "surfadapt: %s: %s\n", what, sfa_last_error(s));
    sfa_destroy(s);
    return 1;
}

bool ensure_directory(const std::string &path)
{
    // Each missing parent first, as mkdir -p does (bench/bench_flows.sh's checkpoints go
    // two levels below build/).
    for (size_t slash = path.find('/', 1); slash != std::string::npos; slash = path.find('/', slash + 1))
        if (mkdir(path.substr(0, slash).c_str(), 0777) != 0 && errno != EEXIST)
            return false;
    return mkdir(path.c_str(), 0777) == 0 || errno == EEXIST;
}

double measure(const sfa_surface *s, int quantity)
{
    double value = NAN;
    sfa_measure(s, quantity, &value);
    return value;
}

void print_synopsis(const char *command)
{
    const std::string text = usage, head = std::string("\n  ") + command + " ";
    size_t line = text.find(head);
    if (line == std::string::npos) {
        std::fputs("(surfadapt --help explains every command and option)\n", stderr);
        return;
    }
    // The command's first line, then the lines that continue its options (indented by more
    // than two and opening with '['); its explanation follows, indented by eight.
    const std::string prefix = "usage: surfadapt ";
    const std::string indent(prefix.size() + std::strlen(command) + 1, ' ');
    line += 3; // past "\n  "
    size_t end = text.find('\n', line);
    std::fprintf(stderr, "%s%s\n", prefix.c_str(), text.substr(line, end - line).c_str());
    while (end != std::string::npos) {
        const size_t start = text.find_first_not_of(' ', end + 1);
        if (start == std::string::npos || start - end - 1 <= 2 || text[start] != '[')
            break;
        line = start;
        end = text.find('\n', line);
        std::fprintf(stderr, "%s%s\n", indent.c_str(), text.substr(line, end - line).c_str());
    }
    std::fprintf(stderr, "(surfadapt %s --help explains the options)\n", command);
}

sfa_surface *surface_from_file(const char *path, bool drop_unreferenced)
{
    sfa_mesh_data mesh{};
    char error[512];
    int base = 0;
    if (mesh_file_read(path, &mesh, &base, error, sizeof error) != 0) {
        std::fprintf(stderr, "surfadapt: %s\n", error);
        return nullptr;
    }
    // The library names bad vertices and triangles in the numbering it is given: the file's
    // own (OBJ and Medit count from 1), so that a message's numbers are the file's. The
    // readers keep every index within int32_t in that base.
    for (int64_t i = 0; i < 3 * static_cast<int64_t>(mesh.ntris); ++i)
        mesh.tris[i] += base;
    sfa_surface *s = nullptr;
    int rc = sfa_create(&s);
    if (rc == SFA_OK) {
        sfa_set_param(s, SFA_PARAM_DROP_UNREFERENCED, drop_unreferenced ? 1 : 0);
        rc = sfa_set_mesh(s, mesh.nverts, mesh.xyz, mesh.ntris, mesh.tris, base);
        if (rc != SFA_OK) {
            fail(s, path);
            s = nullptr;
        }
    }
    mesh_free(&mesh);
    return s;
}

bool known_output_format(const char *path)
{
    if (mesh_format_of(path) != MESH_FORMAT_UNKNOWN)
        return true;
    std::fprintf(stderr, "surfadapt: %s: unknown mesh format: the extension must be one of %s\n", path,
                 mesh_format_extensions());
    return false;
}

bool read_drop_option(int argc, char **argv, int first, const char *command, bool &drop)
{
    for (int i = first; i < argc; ++i) {
        if (std::strcmp(argv[i], "--drop-unreferenced") != 0) {
            std::fprintf(stderr, "surfadapt %s: unknown option '%s'\n", command, argv[i]);
            print_synopsis(command);
            return false;
        }
        drop = true;
    }
    return true;
}

int int_option(int argc, char **argv, int &i, int lo, int hi)
{
    if (i + 1 >= argc) {
        std::fprintf(stderr, "surfadapt: %s needs a value\n", argv[i]);
        std::exit(2);
    }
    char *end = nullptr;
    const long value = std::strtol(argv[++i], &end, 10);
    if (*end != '\0' || value < lo || value > hi) {
        std::fprintf(stderr, "surfadapt: %s must be an integer from %d to %d, got '%s'\n", argv[i - 1], lo, hi,
                     argv[i]);
        std::exit(2);
    }
    return static_cast<int>(value);
}

namespace {

// The number after option argv[i] (i is advanced) if ok(number), else exit(2) naming `rule`.
template <class Ok>
double number_option(int argc, char **argv, int &i, Ok &&ok, const char *rule)
{
    if (i + 1 >= argc) {
        std::fprintf(stderr, "surfadapt: %s needs a value\n", argv[i]);
        std::exit(2);
    }
    char *end = nullptr;
    const double value = std::strtod(argv[++i], &end);
    if (*end != '\0' || !std::isfinite(value) || !ok(value)) {
        std::fprintf(stderr, "surfadapt: %s must be %s, got '%s'\n", argv[i - 1], rule, argv[i]);
        std::exit(2);
    }
    return value;
}

} // namespace

double positive_option(int argc, char **argv, int &i)
{
    return number_option(argc, argv, i, [](double v) { return v > 0; }, "a positive number");
}

double fraction_option(int argc, char **argv, int &i)
{
    return number_option(argc, argv, i, [](double v) { return v >= 0 && v <= 1; }, "a number from 0 to 1");
}

double positive_fraction_option(int argc, char **argv, int &i)
{
    return number_option(argc, argv, i, [](double v) { return v > 0 && v <= 1; }, "a number above 0, at most 1");
}

namespace {

double angle_at(const double *a, const double *b, const double *c)
{
    double u[3], w[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        w[k] = c[k] - a[k];
    }
    const double cross[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    return std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]),
                      u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) * 180 / 3.14159265358979323846;
}

} // namespace

Quality quality_of(const sfa_surface *s)
{
    Quality q;
    sfa_get_counts(s, &q.vertices, &q.triangles);
    std::vector<double> xyz(3 * static_cast<size_t>(q.vertices));
    std::vector<int32_t> tris(3 * static_cast<size_t>(q.triangles)), rank(static_cast<size_t>(q.vertices));
    sfa_get_mesh(s, q.vertices, xyz.data(), q.triangles, tris.data(), 0);
    int32_t good = 0;
    for (int32_t t = 0; t < q.triangles; ++t) {
        bool ok = true;
        for (int k = 0; k < 3; ++k) {
            const double angle = angle_at(&xyz[3 * tris[3 * t + k]], &xyz[3 * tris[3 * t + (k + 1) % 3]],
                                          &xyz[3 * tris[3 * t + (k + 2) % 3]]);
            ok = ok && angle >= 15 && angle <= 160;
        }
        good += ok;
    }
    q.good_share = q.triangles ? static_cast<double>(good) / q.triangles : 0;
    if (sfa_get_feature_ranks(s, q.vertices, rank.data()) == SFA_OK)
        for (const int32_t r : rank)
            q.corners += r == 2;
    sfa_get_ridge_edges(s, 0, nullptr, &q.ridge_edges, 0);
    q.volume = measure(s, SFA_MEASURE_VOLUME);
    q.area = measure(s, SFA_MEASURE_AREA);
    q.min_angle = measure(s, SFA_MEASURE_MIN_ANGLE);
    q.max_angle = measure(s, SFA_MEASURE_MAX_ANGLE);
    q.mean_edge = measure(s, SFA_MEASURE_MEAN_EDGE_LENGTH);
    return q;
}

bool write_surface_vtk(const sfa_surface *s, const char *path, const std::string &title, std::string &error)
{
    int32_t nverts = 0, ntris = 0, nlines = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::vector<double> xyz(3 * static_cast<size_t>(nverts)), long_direction(xyz.size()), normal(xyz.size());
    std::vector<double> aspect_ratio(static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris)), rank(static_cast<size_t>(nverts));
    if (sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0) != SFA_OK ||
        sfa_get_feature_ranks(s, nverts, rank.data()) != SFA_OK ||
        sfa_get_vertex_frames(s, nverts, normal.data(), long_direction.data(), aspect_ratio.data()) != SFA_OK ||
        sfa_get_ridge_edges(s, 0, nullptr, &nlines, 0) != SFA_OK) {
        error = sfa_last_error(s);
        return false;
    }
    std::vector<int32_t> lines(2 * static_cast<size_t>(nlines) + 1);
    if (sfa_get_ridge_edges(s, nlines, lines.data(), &nlines, 0) != SFA_OK) {
        error = sfa_last_error(s);
        return false;
    }
    VtkFeatureMesh vtk;
    vtk.nverts = nverts;
    vtk.ntris = ntris;
    vtk.nlines = nlines;
    vtk.xyz = xyz.data();
    vtk.tris = tris.data();
    vtk.lines = lines.data();
    vtk.rank = rank.data();
    vtk.aspect_ratio = aspect_ratio.data();
    vtk.long_direction = long_direction.data();
    vtk.normal = normal.data();
    // The title is one line of at most 256 characters in the legacy format.
    return write_vtk_features(path, title.substr(0, 255).c_str(), vtk, error);
}

bool write_surface(const sfa_surface *s, const char *path, const std::string &title, std::string &error)
{
    if (mesh_format_of(path) == MESH_FORMAT_VTK)
        return write_surface_vtk(s, path, title, error);
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::vector<double> xyz(3 * static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris)), rank(static_cast<size_t>(nverts));
    if (sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0) != SFA_OK ||
        sfa_get_feature_ranks(s, nverts, rank.data()) != SFA_OK) {
        error = sfa_last_error(s);
        return false;
    }
    const sfa_mesh_data mesh{nverts, ntris, xyz.data(), tris.data()};
    char message[512];
    if (mesh_file_write(path, &mesh, title.c_str(), rank.data(), message, sizeof message) != 0) {
        error = message;
        return false;
    }
    return true;
}
