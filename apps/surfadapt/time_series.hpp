// SPDX-License-Identifier: BSD-3-Clause
// A VTK time series for ParaView: one XML unstructured-grid file (.vtu) per saved step
// and a .pvd collection that lists them with their times.
#pragma once

#include "surfadapt.h"

#include <string>
#include <vector>

class TimeSeries {
public:
    // Files go to `directory` (created if missing) as NAME_0000.vtu ... and NAME.pvd.
    TimeSeries(std::string directory, std::string name);

    // Writes the surface as it is at time t and rewrites the collection, so that it is
    // complete even if the run stops early. Returns false with the reason in `error`.
    bool save(const sfa_surface *s, double t, std::string &error);

private:
    std::string directory_, name_;
    std::vector<std::pair<double, std::string>> steps_;
};
