// SPDX-License-Identifier: BSD-3-Clause
// Unit test of the partial analysis inside an adaptation pass: after splitting, contraction
// and flipping, the vertices whose fans the edit reported changed are analysed anew
// (TrackedAnalysis), and the result must be what a full analysis of the changed mesh
// gives, to the last bit.
#include "adapt/contract.hpp"
#include "adapt/flip.hpp"
#include "adapt/split.hpp"
#include "adapt/settings.hpp"
#include "geometry/tracked_analysis.hpp"
#include "mesh/validate.hpp"

#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <setjmp.h>
#include <vector>

extern "C" {
#include <cmocka.h>

#include "support/shapes.h"
}

using namespace sfa;

namespace {

// The library's defaults (the paper's).
const FeatureThresholds thresholds = feature_thresholds(Parameters());
const MetricBounds bounds = metric_bounds(Parameters());

// Bitwise equality of every per-vertex entry.
void assert_same_geometry(const SurfaceAnalysis &updated, const SurfaceAnalysis &full)
{
    assert_int_equal(updated.metric.size(), full.metric.size());
    for (size_t v = 0; v < full.metric.size(); ++v) {
        assert_true(updated.quadric[v] == full.quadric[v]);
        assert_true(updated.eigen[v].values == full.eigen[v].values);
        assert_true(updated.eigen[v].vectors == full.eigen[v].vectors);
        const VertexMetric &a = updated.metric[v], &b = full.metric[v];
        assert_true(a.normal == b.normal && a.major == b.major && a.minor == b.minor);
        assert_true(a.m_major == b.m_major && a.m_minor == b.m_minor);
    }
}

void each_pass_leaves_the_analysis_a_full_one_would_give(void **)
{
    // A jittered ellipsoid refined (splits) and then coarsened (contractions); flips follow both.
    sfa_mesh_data shape = shape_ellipsoid(3, 1, 0.6, 0.3);
    shapes_rng rng = rng_seed(5);
    for (int32_t k = 0; k < 3 * shape.nverts; ++k)
        shape.xyz[k] += 0.01 * (rng_uniform(&rng) - 0.5);
    TriMesh mesh = validated_mesh(MeshInput{shape.nverts, shape.xyz, shape.ntris, shape.tris, 0, false});
    const Parameters parameters;
    int32_t splits = 0, contractions = 0, flips = 0;
    for (double length : {0.06, 0.25}) {
        SurfaceAnalysis geometry = analyze_surface(mesh, thresholds, bounds);
        MeshEdit edit(mesh);
        CarriedFeatures features(geometry.features);
        TrackedAnalysis tracked(geometry, mesh);
        edit.attach(features);
        edit.attach(tracked);
        const CarriedConstraints no_constraints;
        const PassContext context{edit, features, nullptr, no_constraints, nullptr};
        const RepairSettings repair = repair_settings(parameters, length);

        splits += splitting_pass(context, geometry, repair);
        tracked.update(mesh, bounds);
        assert_same_geometry(geometry, analyze_geometry(mesh, bounds));

        int64_t clearance_tests = 0;
        contractions += contraction_pass(context, geometry, repair, clearance_tests);
        edit.compact();
        tracked.update(mesh, bounds);
        assert_same_geometry(geometry, analyze_geometry(mesh, bounds));

        geometry.features = features.as_features(mesh);
        flips += flipping_pass(context, geometry, flip_settings(parameters));
        tracked.update(mesh, bounds);
        assert_same_geometry(geometry, analyze_geometry(mesh, bounds));
    }
    print_message("%d splits, %d contractions, %d flips\n", splits, contractions, flips);
    assert_true(splits > 100 && contractions > 100 && flips > 100);
    mesh_free(&shape);
}

} // namespace

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_pass_leaves_the_analysis_a_full_one_would_give),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
