// SPDX-License-Identifier: BSD-3-Clause
// cgal_static [--models NAME,NAME...] [--iterations N]
//
// Static remeshing of the same models by surfadapt and by CGAL's isotropic remeshing, in
// one program, so that both see the same input, the same target edge length and the same
// machine at the same time. The models (NAMEs; all three by default):
//   part        the machined part of `surfadapt demo` (machined_part(24)), remeshed at edge
//               length 0.08 with ridge angle 30 degrees, as apps/surfadapt/demo.cpp does;
//   sphere100k  the jittered geodesic sphere of frequency 100 (100,002 vertices) and
//   sphere1m    of frequency 316 (998,562), each at its own mean edge length, as
//               bench/bench_adapt.c times them.
// surfadapt: one sfa_adapt call (default parameters but the edge length and, for the
// part, the ridge angle the demo sets), timed with the default threads and again on one
// thread (CGAL's remeshing runs on one). For the part also the demo's own schedule: calls
// until one changes the vertex count by less than 1 % (apps/surfadapt/remesh.cpp), since
// one call from the CAD tessellation does not reach the target size.
// CGAL: isotropic_remeshing at the same target edge length, N iterations (default 1,
// CGAL's own default); for the part its sharp edges are found by detect_sharp_edges at
// the same 30 degrees between the normals (the chamfer turns the surface by 45 degrees,
// so 60 would miss its two edges) and passed as edge_is_constrained_map, which keeps
// vertices on them while their edges are split and collapsed; the detection is timed
// with the remeshing, as sfa_adapt's feature detection is timed with it.
// Each time is the median of 3 runs, or of 1 where the first took over 20 s. One JSON line
// per model ("bench":"peer_static"), with the vertex counts, the mean edge length, the
// smallest and largest angle and the volume change of both results (measured alike, by
// peer_mesh.hpp) and the ratio of the times (CGAL over surfadapt).
#include "jittered_sphere.h"
#include "machined_part.h"
#include "peer_mesh.hpp"

#include "surfadapt.h"

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// apps/surfadapt/demo.cpp's part_edge_length and part_ridge_angle, and the resolution it
// generates the part at.
constexpr int part_resolution = 24;
constexpr double part_edge_length = 0.08, part_ridge_angle = 30;
// A run longer than this is not repeated.
constexpr double repeat_below_seconds = 20;
constexpr int repeats = 3;
// remesh.cpp's settling rule.
constexpr int most_settling_calls = 12;
constexpr double settled_change = 0.01;

struct Model {
    std::string name;
    FlatMesh mesh;
    double edge_length = 0; // 0: the mesh's mean edge length, as sfa_adapt takes it
    double ridge_angle = 0; // 0: surfadapt's default, and no sharp edges for CGAL
};

// One remesher's result on one model: the median time and the mesh of the last run.
struct Outcome {
    double seconds = 0;
    int runs = 0;
    int calls = 1; // sfa_adapt calls, when settling
    FlatMesh mesh;
    double mean_edge = 0;
    int32_t sharp_edges = 0; // CGAL's constrained edges after the remeshing
};

// Runs `once` up to `repeats` times; it returns the time of what it times (setting up is
// left out), or a negative number after a message. False if a run failed.
bool time_runs(const std::function<double()> &once, Outcome &outcome)
{
    std::vector<double> samples;
    do {
        const double seconds = once();
        if (seconds < 0)
            return false;
        samples.push_back(seconds);
    } while (samples.front() < repeat_below_seconds && static_cast<int>(samples.size()) < repeats);
    outcome.seconds = median_of(samples);
    outcome.runs = static_cast<int>(samples.size());
    return true;
}

double measured(const sfa_surface *s, int quantity)
{
    double value = 0;
    sfa_measure(s, quantity, &value);
    return value;
}

// A surfadapt handle holding the model's mesh with its parameters; null after a message.
sfa_surface *surfadapt_of(const Model &model, int threads)
{
    sfa_surface *s = nullptr;
    if (sfa_create(&s) != SFA_OK) {
        std::fprintf(stderr, "cgal_static: sfa_create failed\n");
        return nullptr;
    }
    if (sfa_set_mesh(s, model.mesh.vertices(), model.mesh.xyz.data(), model.mesh.triangles(), model.mesh.tris.data(),
                     0) != SFA_OK ||
        sfa_set_param(s, SFA_PARAM_EDGE_LENGTH, model.edge_length) != SFA_OK ||
        sfa_set_param(s, SFA_PARAM_THREADS, threads) != SFA_OK ||
        (model.ridge_angle > 0 && sfa_set_param(s, SFA_PARAM_RIDGE_ANGLE, model.ridge_angle) != SFA_OK)) {
        std::fprintf(stderr, "cgal_static: %s: %s\n", model.name.c_str(), sfa_last_error(s));
        sfa_destroy(s);
        return nullptr;
    }
    return s;
}

// sfa_adapt on the model with `threads` (0: OpenMP's default); `settle`: as the demo calls
// it, until a call changes the vertex count by less than 1 %.
bool run_surfadapt(const Model &model, int threads, bool settle, Outcome &outcome)
{
    return time_runs(
        [&]() {
            sfa_surface *s = surfadapt_of(model, threads);
            if (!s)
                return -1.0;
            const auto start = PeerClock::now();
            int32_t vertices = model.mesh.vertices();
            double change = 1;
            outcome.calls = 0;
            do {
                if (sfa_adapt(s) != SFA_OK) {
                    std::fprintf(stderr, "cgal_static: %s: sfa_adapt: %s\n", model.name.c_str(), sfa_last_error(s));
                    sfa_destroy(s);
                    return -1.0;
                }
                ++outcome.calls;
                int32_t now = 0;
                sfa_get_counts(s, &now, nullptr);
                change = std::abs(static_cast<double>(now - vertices)) / vertices;
                vertices = now;
            } while (settle && outcome.calls < most_settling_calls && change >= settled_change);
            const double seconds = seconds_since(start);
            int32_t nverts = 0, ntris = 0;
            sfa_get_counts(s, &nverts, &ntris);
            outcome.mesh.xyz.resize(3 * static_cast<size_t>(nverts));
            outcome.mesh.tris.resize(3 * static_cast<size_t>(ntris));
            sfa_get_mesh(s, nverts, outcome.mesh.xyz.data(), ntris, outcome.mesh.tris.data(), 0);
            outcome.mean_edge = measured(s, SFA_MEASURE_MEAN_EDGE_LENGTH);
            sfa_destroy(s);
            return seconds;
        },
        outcome);
}

bool run_cgal(const Model &model, double edge_length, int iterations, Outcome &outcome)
{
    return time_runs(
        [&]() {
            PeerMesh mesh;
            if (!to_peer_mesh(model.mesh.vertices(), model.mesh.xyz.data(), model.mesh.triangles(),
                              model.mesh.tris.data(), mesh)) {
                std::fprintf(stderr, "cgal_static: %s is not a valid surface mesh for CGAL\n", model.name.c_str());
                return -1.0;
            }
            auto sharp = mesh.add_property_map<PeerMesh::Edge_index, bool>("e:sharp", false).first;
            const auto start = PeerClock::now();
            if (model.ridge_angle > 0) {
                PMP::detect_sharp_edges(mesh, model.ridge_angle, sharp);
                PMP::isotropic_remeshing(
                    faces(mesh), edge_length, mesh,
                    CGAL::parameters::number_of_iterations(iterations).edge_is_constrained_map(sharp));
            } else {
                PMP::isotropic_remeshing(faces(mesh), edge_length, mesh,
                                         CGAL::parameters::number_of_iterations(iterations));
            }
            const double seconds = seconds_since(start);
            mesh.collect_garbage();
            outcome.mesh = to_flat_mesh(mesh);
            outcome.mean_edge = mean_edge_length(mesh);
            outcome.sharp_edges = 0;
            for (PeerMesh::Edge_index e : mesh.edges())
                outcome.sharp_edges += sharp[e] ? 1 : 0;
            return seconds;
        },
        outcome);
}

// The enclosed volume of a closed oriented mesh (the divergence theorem, about its first
// vertex, which keeps the terms small).
double enclosed_volume(const FlatMesh &mesh)
{
    const double *o = mesh.xyz.data();
    double six = 0;
    for (int32_t t = 0; t < mesh.triangles(); ++t) {
        const double *a = &mesh.xyz[3 * mesh.tris[3 * t]], *b = &mesh.xyz[3 * mesh.tris[3 * t + 1]],
                     *c = &mesh.xyz[3 * mesh.tris[3 * t + 2]];
        const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]}, v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]},
                     w[3] = {c[0] - o[0], c[1] - o[1], c[2] - o[2]};
        six += u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
               u[2] * (v[0] * w[1] - v[1] * w[0]);
    }
    return six / 6;
}

// A JSON line, built field by field.
class JsonLine {
  public:
    JsonLine &text(const std::string &name, const std::string &value)
    {
        fields_ += (fields_.empty() ? "\"" : ",\"") + name + "\":\"" + value + "\"";
        return *this;
    }
    JsonLine &number(const std::string &name, double value, const char *format = "%.4g")
    {
        char digits[64];
        std::snprintf(digits, sizeof digits, format, value);
        fields_ += (fields_.empty() ? "\"" : ",\"") + name + "\":" + digits;
        return *this;
    }
    std::string str() const { return "{" + fields_ + "}"; }

  private:
    std::string fields_;
};

// One remesher's figures, each name starting with `prefix`: time, runs, vertices, mean
// edge length, angles and the change of the enclosed volume from the input's.
void add_outcome(JsonLine &line, const std::string &prefix, const Outcome &outcome, double volume0)
{
    const AngleFigures angles = angle_figures(outcome.mesh);
    line.number(prefix + "_s", outcome.seconds, "%.4f")
        .number(prefix + "_runs", outcome.runs)
        .number(prefix + "_vertices", outcome.mesh.vertices(), "%.0f")
        .number(prefix + "_mean_edge", outcome.mean_edge, "%.5g")
        .number(prefix + "_min_angle", angles.smallest, "%.2f")
        .number(prefix + "_max_angle", angles.largest, "%.2f")
        .number(prefix + "_good_angles", angles.good_share, "%.3f")
        .number(prefix + "_volume_change", (enclosed_volume(outcome.mesh) - volume0) / volume0, "%.2e");
}

bool make_model(const std::string &name, Model &model)
{
    int32_t nverts = 0, ntris = 0;
    double *xyz = nullptr;
    int32_t *tris = nullptr;
    int status = -1;
    model.name = name;
    if (name == "part") {
        status = machined_part(part_resolution, &nverts, &xyz, &ntris, &tris);
        model.edge_length = part_edge_length;
        model.ridge_angle = part_ridge_angle;
    } else if (name == "sphere100k" || name == "sphere1m") {
        status = jittered_sphere(name == "sphere100k" ? 100 : 316, &nverts, &xyz, &ntris, &tris);
    } else {
        std::fprintf(stderr, "cgal_static: unknown model '%s' (part, sphere100k, sphere1m)\n", name.c_str());
        return false;
    }
    if (status != 0) {
        std::fprintf(stderr, "cgal_static: out of memory\n");
        return false;
    }
    model.mesh.xyz.assign(xyz, xyz + 3 * static_cast<size_t>(nverts));
    model.mesh.tris.assign(tris, tris + 3 * static_cast<size_t>(ntris));
    std::free(xyz);
    std::free(tris);
    return true;
}

bool compare(const std::string &name, int iterations)
{
    Model model;
    if (!make_model(name, model))
        return false;
    // The target both remeshers get: the model's, or the mean edge length surfadapt takes
    // when SFA_PARAM_EDGE_LENGTH is 0, as surfadapt measures it.
    double edge_length = model.edge_length;
    if (edge_length == 0) {
        sfa_surface *s = surfadapt_of(model, 0);
        if (!s)
            return false;
        edge_length = measured(s, SFA_MEASURE_MEAN_EDGE_LENGTH);
        sfa_destroy(s);
    }
    const bool part = model.ridge_angle > 0;
    Outcome surfadapt, surfadapt_one_thread, settled, cgal;
    if (!run_surfadapt(model, 0, false, surfadapt) || !run_surfadapt(model, 1, false, surfadapt_one_thread) ||
        (part && !run_surfadapt(model, 0, true, settled)) || !run_cgal(model, edge_length, iterations, cgal))
        return false;
    int threads = 1;
#ifdef _OPENMP
    threads = omp_get_max_threads();
#endif
    const double volume0 = enclosed_volume(model.mesh);
    const AngleFigures angles = angle_figures(model.mesh);
    JsonLine line;
    line.text("bench", "peer_static")
        .text("peer", "cgal_isotropic_remeshing")
        .text("cgal", CGAL_VERSION_STR)
        .text("model", name)
        .number("vertices", model.mesh.vertices(), "%.0f")
        .number("triangles", model.mesh.triangles(), "%.0f")
        .number("min_angle", angles.smallest, "%.2f")
        .number("max_angle", angles.largest, "%.2f")
        .number("good_angles", angles.good_share, "%.3f")
        .number("edge_length", edge_length, "%.6g")
        .number("sharp_edge_angle", model.ridge_angle)
        .number("cgal_iterations", iterations)
        .number("sfa_threads", threads);
    add_outcome(line, "sfa", surfadapt, volume0);
    line.number("sfa_1thread_s", surfadapt_one_thread.seconds, "%.4f");
    if (part) {
        add_outcome(line, "sfa_settled", settled, volume0);
        line.number("sfa_settled_calls", settled.calls);
    }
    add_outcome(line, "cgal", cgal, volume0);
    if (part)
        line.number("cgal_sharp_edges", cgal.sharp_edges);
    line.number("time_ratio", cgal.seconds / surfadapt.seconds, "%.3g")
        .number("time_ratio_1thread", cgal.seconds / surfadapt_one_thread.seconds, "%.3g");
    if (part)
        line.number("time_ratio_settled", cgal.seconds / settled.seconds, "%.3g");
    std::printf("%s\n", line.str().c_str());
    std::fflush(stdout);
    return true;
}

int usage()
{
    std::fprintf(stderr, "usage: cgal_static [--models part,sphere100k,sphere1m] [--iterations N]\n");
    return 2;
}

} // namespace

int main(int argc, char **argv)
{
    std::string models = "part,sphere100k,sphere1m";
    int iterations = 1;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--models") && i + 1 < argc)
            models = argv[++i];
        else if (!std::strcmp(argv[i], "--iterations") && i + 1 < argc)
            iterations = std::atoi(argv[++i]);
        else
            return usage();
    }
    if (iterations < 1)
        return usage();
    std::istringstream names(models);
    for (std::string name; std::getline(names, name, ',');)
        if (!compare(name, iterations))
            return 1;
    return 0;
}
