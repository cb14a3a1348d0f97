// SPDX-License-Identifier: BSD-3-Clause
// Motion: sfa_set_velocities, sfa_move, sfa_advect.
#include "api/boundary.hpp"

#include "motion/explicit_step.hpp"
#include "motion/rk4_step.hpp"
#include "motion/safe_motion.hpp"

#include <cmath>
#include <utility>

using namespace sfa;

namespace {

void require_time_step(double dt)
{
    if (!(std::isfinite(dt) && dt > 0)) {
        char message[100];
        std::snprintf(message, sizeof message, "dt must be finite and > 0, got %g", dt);
        fail(Status::argument, message);
    }
}

// For a mesh that is set, `vel` not NULL.
void set_velocities(sfa_surface *s, const double *vel)
{
    std::vector<Vec3> velocity(s->mesh.pos.size());
    for (size_t v = 0; v < velocity.size(); ++v) {
        velocity[v] = Vec3(vel[3 * v], vel[3 * v + 1], vel[3 * v + 2]);
        if (!velocity[v].allFinite()) {
            char message[160];
            std::snprintf(message, sizeof message, "vertex %zu has a non-finite velocity (%g, %g, %g)",
                          v + static_cast<size_t>(s->index_base), velocity[v].x(), velocity[v].y(),
                          velocity[v].z());
            fail(Status::numeric, message);
        }
    }
    s->velocity.swap(velocity);
}

// Topology change needs sheets to meet before they pass through each other.
bool collision_safe(const Parameters &params)
{
    return params.get(Param::collision_safe_motion) != 0 || params.get(Param::topology_change) != 0;
}

// Sheets that meet move together where they cannot merge (motion/safe_motion.hpp).
bool in_contact(const Parameters &params) { return params.get(Param::topology_change) != 0; }

} // namespace

extern "C" {

SFA_EXPORT int sfa_set_velocities(sfa_surface *s, const double *vel)
{
    return call(s, "sfa_set_velocities", [&] {
        require(vel != nullptr, "vel is NULL");
        require_mesh(s);
        set_velocities(s, vel);
    });
}

SFA_EXPORT int sfa_set_velocities_checked(sfa_surface *s, int32_t nverts, const double *vel)
{
    return call(s, "sfa_set_velocities_checked", [&] {
        require(vel != nullptr, "vel is NULL");
        require_mesh(s);
        require_count(s, "vertices", s->mesh.num_vertices(), nverts);
        set_velocities(s, vel);
    });
}

SFA_EXPORT int sfa_move(sfa_surface *s, double dt, double *dt_taken)
{
    return call(s, "sfa_move", [&] {
        require(dt_taken != nullptr, "dt_taken is NULL");
        require_time_step(dt);
        require_mesh(s);
        if (s->velocity.empty())
            fail(Status::state, "no velocities have been set (call sfa_set_velocities first)");
        const double safety = s->params.get(Param::fold_safety);
        Step step = collision_safe(s->params)
                        ? collision_safe_explicit_step(s->mesh, s->velocity, dt, safety, s->index_base,
                                                       in_contact(s->params), &s->collision_blocks)
                        : explicit_step(s->mesh, s->velocity, dt, safety, s->index_base);
        s->mesh.pos.swap(step.positions);
        *dt_taken = step.dt_taken;
    });
}

SFA_EXPORT int sfa_advect(sfa_surface *s, sfa_velocity_fn f, void *ctx, double t, double dt, double *dt_taken)
{
    return call(s, "sfa_advect", [&] {
        require(f != nullptr, "the velocity callback f is NULL");
        require(dt_taken != nullptr, "dt_taken is NULL");
        require(std::isfinite(t), "t must be finite");
        require_time_step(dt);
        require_mesh(s);
        const VelocityField field = [f, ctx](int32_t n, const double *xyz, double time, double *vel) {
            f(ctx, n, xyz, time, vel);
        };
        const double safety = s->params.get(Param::fold_safety);
        Step step = collision_safe(s->params)
                        ? collision_safe_rk4_step(s->mesh, field, t, dt, safety, s->index_base, in_contact(s->params),
                                                  &s->collision_blocks)
                        : rk4_step(s->mesh, field, t, dt, safety, s->index_base);
        s->mesh.pos.swap(step.positions);
        *dt_taken = step.dt_taken;
    });
}

} // extern "C"
