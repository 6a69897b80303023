/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_chain_impl.h - what the files of a chain share with the engine
 * (private to it; included by sim_impl.h): its bodies and interfaces bound
 * to the scene, its clusters of contacts (the system the engine's driver
 * steps), their limits and flights.
 */
#ifndef HYBOUNCE_SIM_CHAIN_IMPL_H
#define HYBOUNCE_SIM_CHAIN_IMPL_H

/*
 * sim_chain.c: the chain of the scene (bodies, interfaces bound to the
 * scene's law); the interfaces' states are kept where the chain keeps its
 * shape.  HB_ENOMEM (the simulator as it was) when its arrays cannot grow.
 */
int
hbs_chain_bind(struct hb_sim *s);

/* ... their arrays freed */
void
hbs_chain_free(struct hb_sim *s);

/*
 * ... a chain's bodies' positions and velocities at the current state
 * (the clusters' bodies set from their interfaces and centres of mass);
 * the two-body scenes' bodies follow from their interface and centre of
 * mass on request (hbs_body_at).
 */
int
hbs_bodies_sync(struct hb_sim *s);
void
hbs_body_at(const struct hb_sim *s, int i, double *y, double *u);
void
hbs_chain_activate(struct hb_sim *s, int i);
void
hbs_chain_reset(struct hb_sim *s);
void
hbs_chain_pair_com(struct hb_sim *s);
void
hbs_chain_gap(const struct hb_sim *s, int i, double t, double *x, double *v);
void
hbs_chain_settle(struct hb_sim *s, int i, double t);

/*
 * sim_cluster.c: a chain's interfaces in contact, integrated together
 * (docs/chains.md section 8): the clusters rebuilt after a jump, a flow
 * interval begun, one accepted step with what follows from it; the
 * clusters' bodies at the current state; the limits of section 6.
 */
int
hbs_cluster_jumped(struct hb_sim *s);
/* ... the right-hand side, the watched functions at a scaled state, the state unpacked */
int
hbs_cluster_rhs(double t, const double u[], double du[], void *params);
void
hbs_cluster_watch(struct hb_sim *s, double t, const double *u, double *f, double *rate);
/* Its f[fi] alone (the same double), from only the state that function reads. */
double
hbs_cluster_watch_one(struct hb_sim *s, double t, const double *u, int fi);
void
hbs_cluster_unpack(struct hb_sim *s, double t, const double *u);
int
hbs_cluster_setup(struct hb_sim *s);
/* sim_cluster_stiff.c: the clusters' Jacobian (bsimp), their stiffness check */
int
hbs_cluster_jacobian(double t, const double u[], double *dfdu, double dfdt[], void *params);
int
hbs_cluster_stiffness(struct hb_sim *s);
/*
 * sim_cluster_step.c: what begins a step of the clusters (the interval's
 * first state already out of C, a gap between flying bodies closing now:
 * the jump is taken, *jumped = 1; else the step's target into *t1 and
 * the modes of the step set); interface i's jump into or out of contact
 * at the current state (the located instant)
 */
int
hbs_cluster_step_begin(struct hb_sim *s, double *t1, int *jumped);
int
hbs_cluster_jump(struct hb_sim *s, int i, int how, int iters, double width, double ilo, double ihi);
void
hbs_cluster_sync(struct hb_sim *s);
/* sim_limits.c: the model's limits at the end of the step just accepted, each passed located */
int
hbs_cluster_limits(struct hb_sim *s);
void
hbs_cluster_free(struct hb_sim *s);

/* sim_flight.c: a chain's flight, every body in closed form */
int
hbs_chain_flight(struct hb_sim *s);
/* ... the first tau >= 0 after which a gap x + v tau + a tau^2 / 2 leaves C (INFINITY: never) */
double
hbs_flight_event(double x, double v, double a);

/* sim_chain.c: whether a chain's run goes on with a new scene (else it restarts); its
 * flying bodies settled at t */
int
hbs_chain_continues(const struct hb_sim *s, const struct hb_scene *nsc);
void
hbs_chain_settle_flying(struct hb_sim *s);

#endif
