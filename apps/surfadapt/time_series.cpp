// SPDX-License-Identifier: BSD-3-Clause
#include "time_series.hpp"

#include "cli.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace {

bool fail_with(std::string &error, const std::string &path)
{
    error = "cannot write " + path + ": " + std::strerror(errno ? errno : EIO);
    return false;
}

} // namespace

TimeSeries::TimeSeries(std::string directory, std::string name) : directory_(std::move(directory)), name_(std::move(name))
{
}

bool TimeSeries::save(const sfa_surface *s, double time, std::string &error)
{
    if (!ensure_directory(directory_))
        return fail_with(error, directory_);
    int32_t nverts = 0, ntris = 0;
    sfa_get_counts(s, &nverts, &ntris);
    std::vector<double> xyz(3 * static_cast<size_t>(nverts));
    std::vector<int32_t> tris(3 * static_cast<size_t>(ntris));
    if (sfa_get_mesh(s, nverts, xyz.data(), ntris, tris.data(), 0) != SFA_OK) {
        error = sfa_last_error(s);
        return false;
    }
    char file[64];
    std::snprintf(file, sizeof file, "_%04zu.vtu", steps_.size());
    const std::string vtu = name_ + file, path = directory_ + "/" + vtu;
    std::FILE *f = std::fopen(path.c_str(), "w");
    if (!f)
        return fail_with(error, path);
    std::fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "<UnstructuredGrid>\n<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n"
                    "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n",
                 nverts, ntris);
    for (int32_t v = 0; v < nverts; ++v)
        std::fprintf(f, "%.17g %.17g %.17g\n", xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    std::fputs("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n", f);
    for (int32_t t = 0; t < ntris; ++t)
        std::fprintf(f, "%d %d %d\n", tris[3 * t], tris[3 * t + 1], tris[3 * t + 2]);
    std::fputs("</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">\n", f);
    for (int32_t t = 0; t < ntris; ++t)
        std::fprintf(f, "%d\n", 3 * (t + 1));
    std::fputs("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n", f);
    for (int32_t t = 0; t < ntris; ++t)
        std::fputs("5\n", f); // VTK_TRIANGLE
    std::fputs("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n", f);
    const bool written = !std::ferror(f);
    if (std::fclose(f) != 0 || !written)
        return fail_with(error, path);
    steps_.emplace_back(time, vtu);

    const std::string pvd = directory_ + "/" + name_ + ".pvd";
    f = std::fopen(pvd.c_str(), "w");
    if (!f)
        return fail_with(error, pvd);
    std::fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n", f);
    for (const auto &[at, name] : steps_)
        std::fprintf(f, "<DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s\"/>\n", at, name.c_str());
    std::fputs("</Collection>\n</VTKFile>\n", f);
    const bool collected = !std::ferror(f);
    if (std::fclose(f) != 0 || !collected)
        return fail_with(error, pvd);
    return true;
}
