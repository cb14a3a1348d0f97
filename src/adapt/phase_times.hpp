// SPDX-License-Identifier: BSD-3-Clause
// Wall-clock seconds spent in each phase of smoothing and adaptation, so that a host (and
// the benchmarks) can see where the time of a run goes without a profiler.
#pragma once

#include <chrono>

namespace sfa {

struct PhaseTimes {
    double analysis = 0;  // quadrics, metric, features (§2)
    double smoothing = 0; // smoothing sweeps, their field transfer and volume restoration (§3.2)
    double flipping = 0;  // flipping passes (§3.3)
    double repair = 0;    // splitting and contraction passes (§4)

    PhaseTimes &operator+=(const PhaseTimes &o)
    {
        analysis += o.analysis;
        smoothing += o.smoothing;
        flipping += o.flipping;
        repair += o.repair;
        return *this;
    }
};

// Adds the seconds from its construction to its destruction to one phase.
class PhaseClock {
public:
    explicit PhaseClock(double &phase) : phase_(phase), start_(std::chrono::steady_clock::now()) {}
    ~PhaseClock() { phase_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    PhaseClock(const PhaseClock &) = delete;
    PhaseClock &operator=(const PhaseClock &) = delete;

private:
    double &phase_;
    std::chrono::steady_clock::time_point start_;
};

// Runs fn() and adds its seconds to `phase`; returns what fn returns.
template <class Fn>
auto timed(double &phase, Fn &&fn)
{
    PhaseClock clock(phase);
    return fn();
}

} // namespace sfa
