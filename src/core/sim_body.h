/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_body.h - a body of the chain and its motion on its parabola, shared
 * by the chain (sim_chain.c), its flights and its clusters; inline, below
 * them all.  Private to the engine.
 */
#ifndef HYBOUNCE_SIM_BODY_H
#define HYBOUNCE_SIM_BODY_H

/*
 * The chain (docs/chains.md section 1): bodies 1..N from the bottom up
 * (body[0] is body 1) and the interfaces between them, interface 0 on the
 * floor when there is one.  The two-body scenes are N = 2 without a floor
 * (the full system: chain body 1 is the scene's body 2, the lower one) and
 * N = 1 on the floor (the reduced system); a [chain] scene has chain.n
 * bodies.  One interface at a time is in contact, integrated in its own
 * coordinates (docs/chains.md section 8, a cluster of one contact); see
 * sim_chain.c for how the bodies follow.
 */
struct body {
	double m;               /* kg */
	double l;               /* half-length along the axis (radius), m; 0 when unknown */
	double y, u, tb;        /* a chain's: displacement of its centre from y0, and velocity,
	                           at time tb (the two-body scenes': from their interface,
	                           hbs_body_at) */
	double dn, up;          /* a chain's: the gap below it is (y - dn) - (y' + up') of the
	                           body below (y - dn on the floor), the gap above it likewise:
	                           dn = -(the gap below at t = 0), up = 0, so that a gap is a
	                           difference of displacements, exact (0) between touching
	                           bodies at rest, however far along the chain they are */
	double a;               /* a chain's: its constant acceleration */
	double Fe;              /* a chain's: its applied force, constant */
	double y0, u0;          /* a chain's: its position (the origin of y) and velocity at t = 0 */
	int cl;                 /* a chain's: the cluster it is in (index), -1 in flight */
};

/* Body b's position and velocity at t: its parabola from the time tb its (y, u) are of. */
static inline void
hbs_body_now(const struct body *b, double t, double *y, double *u)
{
	double tau = t - b->tb;

	*y = b->y + tau * (b->u + 0.5 * b->a * tau);
	*u = b->u + b->a * tau;
}
/* Sets body b to (y, u) at t. */
static inline void
hbs_body_set(struct body *b, double t, double y, double u)
{
	b->y = y;
	b->u = u;
	b->tb = t;
}

#endif
