// SPDX-License-Identifier: BSD-3-Clause
// Library-wide entry points: version, status strings, lifecycle and the plugin table.
#include "api/boundary.hpp"

#include <cstddef>

#define SFA_STRINGIFY_(x) #x
#define SFA_STRINGIFY(x) SFA_STRINGIFY_(x)

extern "C" {

SFA_EXPORT const char *sfa_version_string(void)
{
    return SFA_STRINGIFY(SFA_VERSION_MAJOR) "." SFA_STRINGIFY(SFA_VERSION_MINOR) "." SFA_STRINGIFY(SFA_VERSION_PATCH);
}

SFA_EXPORT int sfa_abi_version(void) { return SFA_ABI_VERSION; }

// Two decimal digits each for MINOR and PATCH: beyond 99 the number would be ambiguous.
static_assert(SFA_VERSION_MINOR < 100 && SFA_VERSION_PATCH < 100, "sfa_version_number packs MINOR and PATCH in two digits");

SFA_EXPORT int sfa_version_number(void)
{
    return SFA_VERSION_MAJOR * 10000 + SFA_VERSION_MINOR * 100 + SFA_VERSION_PATCH;
}

SFA_EXPORT const char *sfa_status_string(int status)
{
    switch (status) {
    case SFA_OK: return "SFA_OK: success";
    case SFA_ERR_ARGUMENT: return "SFA_ERR_ARGUMENT: an argument is invalid";
    case SFA_ERR_MESH: return "SFA_ERR_MESH: the mesh given is not acceptable";
    case SFA_ERR_STATE: return "SFA_ERR_STATE: call out of order";
    case SFA_ERR_NUMERIC: return "SFA_ERR_NUMERIC: non-finite value or a step that would fold the surface";
    case SFA_ERR_MEMORY: return "SFA_ERR_MEMORY: out of memory";
    case SFA_ERR_INTERNAL: return "SFA_ERR_INTERNAL: internal error";
    default: return "unknown status";
    }
}

SFA_EXPORT int sfa_create(sfa_surface **out)
{
    if (!out)
        return SFA_ERR_ARGUMENT;
    *out = nullptr;
    try {
        *out = new sfa_surface();
        return SFA_OK;
    } catch (const std::bad_alloc &) {
        return SFA_ERR_MEMORY;
    } catch (...) {
        return SFA_ERR_INTERNAL;
    }
}

SFA_EXPORT void sfa_destroy(sfa_surface *s) { delete s; }

SFA_EXPORT const char *sfa_last_error(const sfa_surface *s)
{
    return s ? s->last_error : "no surface: the handle is NULL";
}

SFA_EXPORT const sfa_api *sfa_get_api(uint32_t abi_version)
{
    // Members in the order of API.md; new members are only ever appended.
    static const sfa_api table_v1 = {
        sizeof(sfa_api),
        1,
        sfa_version_string,
        sfa_abi_version,
        sfa_status_string,
        sfa_create,
        sfa_destroy,
        sfa_last_error,
        sfa_set_mesh,
        sfa_get_counts,
        sfa_get_mesh,
        sfa_set_param,
        sfa_get_param,
        sfa_set_velocities,
        sfa_move,
        sfa_advect,
        sfa_smooth,
        sfa_adapt,
        sfa_get_feature_ranks,
        sfa_measure,
        sfa_add_field,
        sfa_get_field,
        sfa_get_vertex_frames,
        sfa_get_ridge_edges,
        sfa_get_param_bounds,
        sfa_version_number,
        sfa_get_component_count,
        sfa_get_components,
        sfa_measure_component,
        sfa_set_velocities_checked,
        sfa_add_field_checked,
        sfa_set_size_field,
        sfa_set_size_field_checked,
        sfa_set_fixed_vertices,
        sfa_set_required_edges,
        sfa_add_face_field,
        sfa_add_face_field_checked,
        sfa_get_face_field,
        sfa_get_vertex_origins,
        sfa_set_field,
        sfa_set_face_field,
    };
    return abi_version == 1 ? &table_v1 : nullptr;
}

} // extern "C"
