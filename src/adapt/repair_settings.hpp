// The thresholds of mesh repair (§4.1-§4.3), all derived from the desired edge length l
// and the public parameters.
#pragma once

#include "adapt/parameters.hpp"

namespace sfa {

struct RepairSettings {
    double desired_length;       // l
    double split_length;         // L: absolute longness
    double split_shortest;       // s: relative longness needs every nearby edge at least this long
    double contract_length;      // S: absolute small triangle
    double contract_short_ratio; // r: relative shortness
    double contract_small_ratio; // R: relative small triangle
    double cos_small_angle;      // cos theta_s
    double cos_large_angle;      // cos theta_l
};

RepairSettings repair_settings(const Parameters &parameters, double desired_length);

} // namespace sfa
