// SPDX-License-Identifier: BSD-3-Clause
// The C boundary: every entry point runs its body through call(), which turns exceptions
// into a status and a message in the handle, and clears the message on success.
#pragma once

#include "api/surface.hpp"
#include "mesh/error.hpp"
#include "mesh/parallel.hpp"

#include "surfadapt.h"

#include <cstdio>
#include <exception>
#include <new>

// The library is built with -fvisibility=hidden; only the C entry points are visible (and
// the linker version script keeps exactly sfa_* global).
#define SFA_EXPORT __attribute__((visibility("default")))

namespace sfa {

inline void set_error(const sfa_surface *s, const char *function, const char *message)
{
    std::snprintf(s->last_error, sizeof s->last_error, "%s: %s", function, message);
}

template <class Body>
int call(const sfa_surface *s, const char *function, Body &&body) noexcept
{
    if (!s)
        return SFA_ERR_ARGUMENT;
    const ThreadLimit threads(static_cast<int>(s->params.get(Param::threads)));
    try {
        body();
        s->last_error[0] = '\0';
        return SFA_OK;
    } catch (const Error &e) {
        set_error(s, function, e.what());
        return static_cast<int>(e.status());
    } catch (const std::bad_alloc &) {
        set_error(s, function, "out of memory; the surface is unchanged");
        return SFA_ERR_MEMORY;
    } catch (const std::exception &e) {
        set_error(s, function, e.what());
        return SFA_ERR_INTERNAL;
    } catch (...) {
        set_error(s, function, "unknown exception");
        return SFA_ERR_INTERNAL;
    }
}

[[noreturn]] inline void fail(Status status, const char *message) { throw Error(status, message); }

inline void require(bool condition, const char *message)
{
    if (!condition)
        fail(Status::argument, message);
}

inline void require_mesh(const sfa_surface *s)
{
    if (!s->has_mesh)
        fail(Status::state, "no mesh has been set yet (call sfa_set_mesh first)");
}

// For the checked variants of the functions that read one value set per vertex or per
// triangle: the count the host's array was made for must be the mesh's.
inline void require_count(const sfa_surface *s, const char *elements, int32_t mesh_has, int32_t array_has)
{
    if (array_has == mesh_has)
        return;
    char message[200];
    std::snprintf(message, sizeof message, "the mesh has %d %s since the last %s; the array given has %d", mesh_has,
                  elements, s->counts_set_by, array_has);
    fail(Status::argument, message);
}

} // namespace sfa
