// SPDX-License-Identifier: BSD-3-Clause
// A fixed sequence of pseudo-random numbers, the same on every machine (SplitMix64), for
// the unit tests' random configurations.
#pragma once

#include "mesh/tri_mesh.hpp"

#include <cstdint>

struct Numbers {
    uint64_t state;
    uint64_t next()
    {
        uint64_t z = (state += 0x9E3779B97F4A7C15u);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
        return z ^ (z >> 31);
    }
    double uniform(double lo, double hi) { return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1p-53; }
    sfa::Vec3 point(double extent)
    {
        return sfa::Vec3(uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent));
    }
    int pick(int n) { return static_cast<int>(next() % static_cast<uint64_t>(n)); }
};
