/* SPDX-License-Identifier: BSD-3-Clause */
/* Random valid surfaces and smooth velocity fields for the soak (tests/soak/soak.c).
 *
 * Everything is drawn from a shapes_rng, so one seed gives the same surface, parameters and
 * flows on every run and platform: a finding is replayed from its seed alone. */
#ifndef SURFADAPT_SOAK_SURFACES_H
#define SURFADAPT_SOAK_SURFACES_H

#include "support/shapes.h"

#include <stddef.h>

/* A generated surface: the mesh (0-based, outward, valid for sfa_set_mesh), the centre and
 * half-diagonal of its bounding box (the frame the flows are expressed in), and a short
 * description for the call log. */
typedef struct soak_surface {
    sfa_mesh_data mesh;
    double centre[3];
    double size;
    char what[256];
} soak_surface;

/* One of: sphere, jittered sphere, torus, box, cone, capped cylinder, slab (thin box), thin
 * ellipsoid, several components of different sizes (some nearly touching), an open bent
 * sheet, an open tube, an open spherical cap; rotated, renumbered, scaled by 10^[-6, 6] and
 * sometimes moved up to 10^6 times its size from the origin (far inside the header's
 * coordinate range, |x| <= 1e50). At most a few thousand vertices. */
soak_surface soak_random_surface(shapes_rng *rng);

/* Velocity fields, all smooth; all but expansion are divergence-free, so the volume a
 * closed component loses under them is the time integration's error alone. */
enum soak_flow_kind {
    FLOW_ROTATION,
    FLOW_SHEAR,
    FLOW_VORTEX,      /* the single-vortex flow (LeVeque), periodic in time */
    FLOW_DEFORMATION, /* Enright's three-dimensional deformation, periodic in time */
    FLOW_TRANSLATION,
    FLOW_EXPANSION,   /* uniform expansion or contraction about the centre */
    FLOW_KINDS
};

typedef struct soak_flow {
    int kind;
    double centre[3], size; /* the surface's frame: x' = R^T (x - centre) / size */
    double R[9];            /* a random orientation, so that no flow is axis-aligned */
    double a[3];            /* the flow's own parameters (axis, rate, direction) */
    double period;          /* of the time-periodic flows */
} soak_flow;

soak_flow soak_random_flow(shapes_rng *rng, const soak_surface *surface);
const char *soak_flow_name(int kind);
int soak_flow_divergence_free(int kind);

/* sfa_velocity_fn: ctx is a const soak_flow *. Velocities are in units of the surface's
 * size per unit time, at most a few. */
void soak_flow_eval(void *ctx, int32_t n, const double *xyz, double t, double *vel);

#endif
