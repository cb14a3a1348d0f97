// Adaptation: sfa_smooth, sfa_adapt.
#include "api/boundary.hpp"

using namespace sfa;

extern "C" {

SFA_EXPORT int sfa_smooth(sfa_surface *s, int32_t iterations)
{
    return call(s, "sfa_smooth", [&] {
        require(iterations >= 0, "iterations must be >= 0");
        require_mesh(s);
        fail(Status::internal, "not implemented yet: anisotropic smoothing (paper §3.2) comes in a later release");
    });
}

SFA_EXPORT int sfa_adapt(sfa_surface *s)
{
    return call(s, "sfa_adapt", [&] {
        require_mesh(s);
        fail(Status::internal, "not implemented yet: the full adaptation (paper §3-§4) comes in a later release");
    });
}

} // extern "C"
