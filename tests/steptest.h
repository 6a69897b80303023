/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * steptest.h - the smooth test problem of the step types' tests
 * (test_dop853.c, test_vern98.c), with a known solution and a count of
 * evaluations, the global error of n fixed steps, and the agreement with
 * GSL's rk8pd under GSL's own driver.
 */
#ifndef HYBOUNCE_STEPTEST_H
#define HYBOUNCE_STEPTEST_H

#include <math.h>
#include <string.h>
#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

/* evaluations of f since it was last set to 0 */
static long nfev;

/* y1' = y1 cos t (y1 = exp(sin t)); y2' = y3, y3' = -y2 (y2 = sin t, y3 = cos t). */
static inline int
f(double t, const double y[], double dy[], void *params)
{
	(void)params;
	nfev++;
	dy[0] = y[0] * cos(t);
	dy[1] = y[2];
	dy[2] = -y[1];
	return GSL_SUCCESS;
}

static inline void
exact(double t, double y[3])
{
	y[0] = exp(sin(t));
	y[1] = sin(t);
	y[2] = cos(t);
}

static inline double
maxerr(double t, const double y[3])
{
	double e[3];

	exact(t, e);
	return fmax(fabs(y[0] - e[0]), fmax(fabs(y[1] - e[1]), fabs(y[2] - e[2])));
}

/* Global error at t = tend of n fixed steps of type T from t = 0. */
static inline double
fixed_steps(const gsl_odeiv2_step_type *T, double tend, int n)
{
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(T, 3);
	double y[3], yerr[3], t = 0.0, h = tend / n;
	int i;

	exact(0.0, y);
	for (i = 0; i < n; i++) {
		cr_assert_eq(gsl_odeiv2_step_apply(st, t, h, y, yerr, NULL, NULL, &sys), GSL_SUCCESS);
		t = (i + 1) * h;
	}
	gsl_odeiv2_step_free(st);
	return maxerr(tend, y);
}

/*
 * Under GSL's driver with its standard control (rtol = atol = 1e-12), T
 * and GSL's rk8pd each reach the solution at t = 20 to 1e-9 and agree to
 * 1e-9; evals: the evaluations each took (T's, then rk8pd's).
 */
static inline void
agrees_with_gsl_rk8pd(const gsl_odeiv2_step_type *T, long evals[2])
{
	const gsl_odeiv2_step_type *types[2] = { T, gsl_odeiv2_step_rk8pd };
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	double yend[2][3];
	int k;

	for (k = 0; k < 2; k++) {
		gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys, types[k], 1e-3, 1e-12, 1e-12);
		double t = 0.0, y[3];

		exact(0.0, y);
		nfev = 0;
		cr_assert_eq(gsl_odeiv2_driver_apply(d, &t, 20.0, y), GSL_SUCCESS);
		evals[k] = nfev;
		cr_expect_lt(maxerr(20.0, y), 1e-9, "%s: error %.3g at t = 20", types[k]->name,
		             maxerr(20.0, y));
		memcpy(yend[k], y, sizeof y);
		gsl_odeiv2_driver_free(d);
	}
	cr_expect_lt(fabs(yend[0][0] - yend[1][0]), 1e-9);
	cr_expect_lt(fabs(yend[0][1] - yend[1][1]), 1e-9);
}

#endif
