/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * known.h - the right-hand side where the step just accepted evaluated it:
 * its slope at the start and f at its end, for the location's re-steps
 * from the step's start and its Hermite guides, which evaluated f there
 * again.  Internal to the engine.
 *
 *     struct known_f k;
 *     known_init(&k, e, step);
 *     rc = gsl_odeiv2_evolve_apply(e, c, step, &sys, &t, t1, &h, y);
 *     if (rc == GSL_SUCCESS) known_keep(&k, t0);
 *     const double *f0 = known_at(&k, t0, y0);          (the slope there, or NULL)
 *     known_eval(&k, &sys, t, y, dydt);                 (known, or evaluated)
 *
 * Nothing is copied: the slopes are the evolver's own e->dydt_in and
 * e->dydt_out, the start state its e->y0 and the end state the step's
 * (step_rk8pd.h, hb_rk8pd_end), which GSL and the step keep until the next
 * step; k holds the step's start time and the evolver's count of steps,
 * and what it knows is gone once the evolver steps again or is reset
 * (gsl_odeiv2_evolve_reset, gsl_odeiv2_driver_reset: the count changes).
 *
 * The start slope is the one the step took.  GSL 2.7's evolver evaluates
 * f(t0, y0) after a reset, and otherwise takes the last step's dydt_out,
 * f at that step's end, as it is: the same, bit for bit, where the state
 * and f have not been changed between the steps, which the engine keeps
 * so (a snap that moves the state, a change of scales or of the mode
 * resets the evolver; on every shipped preset the start is the last end).
 * A re-step given it reproduces the step it re-takes.  Known only for the
 * step types that take dydt_in as f(t, y) and give dydt_out as f at (t +
 * h, the y they return): known_exact_type.  f must be a function of (t, y)
 * alone while the evolver is not reset; whoever changes it otherwise (the
 * scales) calls known_forget.
 */
#ifndef HYBOUNCE_KNOWN_H
#define HYBOUNCE_KNOWN_H

#include <gsl/gsl_odeiv2.h>

struct known_f {
	const gsl_odeiv2_evolve *e; /* the evolver of the steps */
	const double *yend;         /* its step's own end state, as returned (NULL: not known) */
	int exact;                  /* 1: its step's type is one for which the slopes are known */
	unsigned long count;        /* e's count of steps after the last kept (0: nothing known) */
	double t0;                  /* that step's start */
};

/*
 * Sets k up, nothing known, for the steps of the evolver e with step
 * (allocated: its type and its own buffer of the end state are read once).
 */
void
known_init(struct known_f *k, const gsl_odeiv2_evolve *e, const gsl_odeiv2_step *step);

/* Forgets what is known (f changed without a reset of the evolver). */
static inline void
known_forget(struct known_f *k)
{
	k->count = 0;
}

/*
 * Whether step type T uses dydt_in as f(t, y) and nothing else, and gives
 * dydt_out as f evaluated at (t + h, the y it returns): the explicit
 * Runge-Kutta steps (the engine's rk8pd, dop853, vern98; GSL's rkf45,
 * rkck).  Such a step may be given a known f(t, y) as its dydt_in, with
 * the same result as evaluating it.
 */
int
known_exact_type(const gsl_odeiv2_step_type *T);

/*
 * After a step from t0 accepted by k's evolver (gsl_odeiv2_evolve_apply's
 * success): what it evaluated (two stores; its end is at t0 + the
 * evolver's last_step, where the step evaluated its dydt_out).
 */
static inline void
known_keep(struct known_f *k, double t0)
{
	k->count = k->e->count;
	k->t0 = t0;
}

/*
 * The slope at (t, u) where the last step of k's evolver evaluated it
 * (bit for bit the same t and u, at its start or its end), while the
 * evolver has not stepped since nor been reset; else NULL.
 */
const double *
known_at(const struct known_f *k, double t, const double *u);

/* known_at's slope into dydt, or f(t, u) evaluated by sys (its status). */
int
known_eval(const struct known_f *k, const gsl_odeiv2_system *sys, double t, const double *u,
           double *dydt);

#endif
