#include "adapt/repair_settings.hpp"

#include <cmath>

namespace sfa {

RepairSettings repair_settings(const Parameters &p, double l)
{
    constexpr double degrees = 3.14159265358979323846 / 180;
    return {l,
            p.get(Param::split_length_ratio) * l,
            p.get(Param::split_shortest_ratio) * l,
            p.get(Param::contract_length_ratio) * l,
            p.get(Param::contract_short_ratio),
            p.get(Param::contract_small_ratio),
            std::cos(p.get(Param::small_angle) * degrees),
            std::cos(p.get(Param::large_angle) * degrees)};
}

} // namespace sfa
