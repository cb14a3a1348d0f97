// SPDX-License-Identifier: BSD-3-Clause
// The one exception type of the library: a status code of the public interface and a
// message that names the offending element and the rule it breaks. Thrown anywhere below
// the C boundary; src/api turns it into a return status and sfa_last_error().
#pragma once

#include <stdexcept>
#include <string>

namespace sfa {

// Mirrors enum sfa_status of the public header; kept separate so that the algorithm
// layers do not include the C header.
enum class Status : int {
    ok = 0,
    argument = 1,
    mesh = 2,
    state = 3,
    numeric = 4,
    memory = 5,
    internal = 6,
};

class Error : public std::runtime_error {
public:
    Error(Status status, const std::string &message) : std::runtime_error(message), status_(status) {}
    Status status() const noexcept { return status_; }

private:
    Status status_;
};

} // namespace sfa
