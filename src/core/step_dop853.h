/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_dop853.h - Dormand and Prince's explicit Runge-Kutta 8(5,3) pair
 * with its 7th-order continuous extension, as a GSL odeiv2 step type.
 * Internal to the engine.
 *
 * The method is DOP853 of Hairer, Norsett and Wanner (Solving Ordinary
 * Differential Equations I, 2nd ed., section II.10, and the reference code
 * dop853.f): 12 stages, the 8th-order solution, an error estimate built from
 * the embedded 5th- and 3rd-order solutions, and a dense output of order 7
 * from three more stages.
 *
 *     gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_dop853, dim);
 *     gsl_odeiv2_step_apply(st, t, h, y, yerr, NULL, NULL, &sys);
 *     hb_dop853_dense(st, t + 0.3 * h, yi);   // y at t + 0.3 h on the last step
 *
 * First same as last: the derivative at a step's end is kept and used as
 * the first stage of the next step when that step starts at the same (t, y)
 * (an accepted step costs 12 evaluations, a rejected one 11).
 * gsl_odeiv2_step_reset forgets it; reset whenever the system changes.
 * The three stages of the dense output are computed on the first call to
 * hb_dop853_dense after a step, so a step that needs no interpolation pays
 * nothing for it.
 */
#ifndef HYBOUNCE_STEP_DOP853_H
#define HYBOUNCE_STEP_DOP853_H

#include <gsl/gsl_odeiv2.h>

extern const gsl_odeiv2_step_type *const hb_step_dop853;

/*
 * The continuous extension of the last step made by st (a dop853 step):
 * y(t) for t in [t0, t0 + h] of that step, into y (dim values).  Returns
 * GSL_SUCCESS, GSL_EINVAL when st is not a dop853 step or has made no step
 * since its last reset, or the error of the system's function.
 */
int
hb_dop853_dense(gsl_odeiv2_step *st, double t, double y[]);

/* The last step of st: its start t0 and length h.  Returns 0, or -1 if none. */
int
hb_dop853_last(const gsl_odeiv2_step *st, double *t0, double *h);

#endif
