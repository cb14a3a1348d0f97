// Every tunable of the adaptation, one double per key of enum sfa_param (same numbers),
// with the paper's defaults (§3.1, §4.3) and the range each may take.
#pragma once

#include <array>

namespace sfa {

enum class Param : int {
    edge_length = 0,
    anisotropic,
    ridge_angle,
    corner_angle,
    metric_min_angle,
    metric_max_angle,
    split_length_ratio,
    split_shortest_ratio,
    contract_length_ratio,
    contract_short_ratio,
    contract_small_ratio,
    small_angle,
    large_angle,
    fold_safety,
    drop_unreferenced,
    ridge_turn_angle,
    flip_dihedral_angle,
    threads,
    denoise,
    adapt_passes,
    crossing_guard,
    count
};

class Parameters {
public:
    Parameters();

    // Throws Error(Status::argument) unless key is one of enum sfa_param.
    static void require_key(int key);
    double get(Param key) const { return value_[static_cast<int>(key)]; }
    // Throws Error(Status::argument) naming the key and its range.
    void set(int key, double value);

private:
    std::array<double, static_cast<int>(Param::count)> value_;
};

} // namespace sfa
