// SPDX-License-Identifier: BSD-3-Clause
// Parameters: sfa_set_param, sfa_get_param, sfa_get_param_bounds.
#include "api/boundary.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_set_param(sfa_surface *s, int key, double value)
{
    return call(s, "sfa_set_param", [&] { s->params.set(key, value); });
}

SFA_EXPORT int sfa_get_param(const sfa_surface *s, int key, double *value)
{
    return call(s, "sfa_get_param", [&] {
        require(value != nullptr, "value is NULL");
        Parameters::require_key(key);
        *value = s->params.get(static_cast<Param>(key));
    });
}

// No handle, so no message: the status alone says what was wrong. The ends come from the
// table sfa_set_param checks against, so the two cannot disagree.
SFA_EXPORT int sfa_get_param_bounds(int key, double *lowest, double *highest)
{
    if (!lowest || !highest || !Parameters::is_key(key))
        return SFA_ERR_ARGUMENT;
    const ParamSpec &spec = Parameters::spec(key);
    *lowest = spec.lowest;
    *highest = spec.highest;
    return SFA_OK;
}

} // extern "C"
