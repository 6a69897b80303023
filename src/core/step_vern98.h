/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_vern98.h - Verner's "most efficient" explicit Runge-Kutta 9(8)
 * pair, as a GSL odeiv2 step type.  Internal to the engine.
 *
 * 16 stages: the 9th-order solution from stages 1 and 8..15, an embedded
 * 8th-order solution that also uses stage 16, and the difference of the
 * two as the error estimate (of the 8th-order solution: h^9 per step).
 *
 *     gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_vern98, dim);
 *     gsl_odeiv2_step_apply(st, t, h, y, yerr, NULL, NULL, &sys);
 *
 * First same as last: the derivative at a step's end is evaluated (it is
 * the 17th stage of Verner's interpolating extension) and used as the
 * first stage of the next step when that step starts at the same (t, y):
 * an accepted step costs 16 evaluations, a rejected one 15.
 * gsl_odeiv2_step_reset forgets it; reset whenever the system changes.
 * There is no continuous extension here: the engine locates events on the
 * step's cubic Hermite interpolant, as it does under rk8pd.
 */
#ifndef HYBOUNCE_STEP_VERN98_H
#define HYBOUNCE_STEP_VERN98_H

#include <gsl/gsl_odeiv2.h>

extern const gsl_odeiv2_step_type *const hb_step_vern98;

/*
 * The pair's tableau as the step uses it (for the order conditions of
 * tests/test_vern98.c): a[i][j], the nodes c, the 9th-order weights b and
 * the estimate's weights e (8th-order weights less b); stages from 0.
 */
void
hb_vern98_tableau(double a[16][16], double c[16], double b[16], double e[16]);

#endif
