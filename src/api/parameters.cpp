// Parameters: sfa_set_param, sfa_get_param.
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

} // extern "C"
