// The analysis of a surface's current mesh with its parameters, shared by the analysis and
// adaptation entry points.
#pragma once

#include "api/boundary.hpp"

#include "geometry/analysis.hpp"

namespace sfa {

inline constexpr double radians = 3.14159265358979323846 / 180;

// The metric bounds of the parameters; throws Error(Status::argument) if the two metric
// angles are the wrong way round.
inline MetricBounds metric_bounds(const Parameters &p)
{
    const MetricBounds bounds{p.get(Param::metric_min_angle) * radians, p.get(Param::metric_max_angle) * radians,
                              p.get(Param::anisotropic) != 0};
    if (bounds.anisotropic && !(bounds.lower_ratio < bounds.upper_ratio)) {
        char message[200];
        std::snprintf(message, sizeof message,
                      "SFA_PARAM_METRIC_MIN_ANGLE (%g) must be smaller than SFA_PARAM_METRIC_MAX_ANGLE (%g)",
                      p.get(Param::metric_min_angle), p.get(Param::metric_max_angle));
        fail(Status::argument, message);
    }
    return bounds;
}

inline FeatureThresholds feature_thresholds(const Parameters &p)
{
    return {p.get(Param::ridge_angle) * radians, p.get(Param::corner_angle) * radians,
            p.get(Param::ridge_turn_angle) * radians};
}

// The analysis of `mesh` (the surface's, or a working copy of it) with the surface's
// parameters. Computed on demand: it costs about a microsecond per vertex, and a cache
// would have to follow every change of mesh or parameter.
inline SurfaceAnalysis current_analysis(const sfa_surface *s, const TriMesh &mesh)
{
    return analyze_surface(mesh, feature_thresholds(s->params), metric_bounds(s->params));
}

} // namespace sfa
