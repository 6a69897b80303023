/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_rk8pd.h - Prince and Dormand's explicit Runge-Kutta 8(7) pair, the
 * engine's default stepper, as a GSL odeiv2 step type that gives GSL's
 * own rk8pd (gsl_odeiv2_step_rk8pd) bit for bit.  Internal to the engine.
 *
 *     gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_rk8pd, dim);
 *     gsl_odeiv2_step_apply(st, t, h, y, yerr, dydt_in, dydt_out, &sys);
 *
 * Same method, same operations in the same order, same calls of the
 * system's function: 13 stages, the 8th-order solution, the error estimate
 * h (b7 - b8) . k (signed, per component); dydt_in, when given, is the
 * first stage (12 evaluations a step), otherwise f is evaluated at (t, y)
 * (13); dydt_out, when asked for, is f evaluated at the step's end (one
 * more).  Nothing is kept from one step to the next (reset does nothing),
 * and a failing evaluation leaves y as it was, as GSL's rk8pd does.  What
 * differs is the cost: the stages written out, packed two or four
 * components to an operation (AVX where the processor has it), and a copy
 * of the step for each of the layouts' dimensions (step_rk8pd.c).
 */
#ifndef HYBOUNCE_STEP_RK8PD_H
#define HYBOUNCE_STEP_RK8PD_H

#include <gsl/gsl_odeiv2.h>

extern const gsl_odeiv2_step_type *const hb_step_rk8pd;

/* The same with two lanes whatever the processor (for the tests: both copies are compared with GSL). */
extern const gsl_odeiv2_step_type *const hb_step_rk8pd_2lanes;

/*
 * The state the last successful apply of st returned (where its dydt_out
 * was evaluated), kept until st's next apply; NULL for a step of another
 * type.
 */
const double *
hb_rk8pd_end(const gsl_odeiv2_step *st);

#endif
