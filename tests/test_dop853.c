/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_dop853.c - the DOP853 step type alone (src/core/step_dop853.c):
 * its order on a smooth problem with a known solution, the order of its
 * continuous extension inside steps, the cost of a step (first same as
 * last), and agreement with GSL's rk8pd under GSL's own driver.
 */
#include <math.h>
#include <string.h>
#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "step_dop853.h"
#include "steptest.h"

Test(dop853, order_8)
{
	double e1 = fixed_steps(hb_step_dop853, 2.0, 8), e2 = fixed_steps(hb_step_dop853, 2.0, 16);
	double order = log2(e1 / e2);

	cr_expect(order > 7.5 && order < 9.0, "observed order %.3f (errors %.3g, %.3g)", order, e1, e2);
	cr_expect_lt(e2, 1e-9, "error with 16 steps %.3g", e2);
}

/* Largest error of the dense output inside one step of length h from t = 0.3. */
static double
dense_error(double h, long *extra)
{
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_dop853, 3);
	double y[3], yerr[3], yi[3], t0 = 0.3, e = 0.0, t0s, hs;
	long n0;
	int k;

	exact(t0, y);
	cr_assert_eq(hb_dop853_dense(st, t0, yi), GSL_EINVAL, "no step made yet");
	cr_assert_eq(gsl_odeiv2_step_apply(st, t0, h, y, yerr, NULL, NULL, &sys), GSL_SUCCESS);
	cr_assert_eq(hb_dop853_last(st, &t0s, &hs), 0);
	cr_assert(t0s == t0 && hs == h);
	n0 = nfev;
	for (k = 0; k <= 16; k++) {
		double t = t0 + h * k / 16.0;

		cr_assert_eq(hb_dop853_dense(st, t, yi), GSL_SUCCESS);
		e = fmax(e, maxerr(t, yi));
	}
	*extra = nfev - n0;
	/* the ends are the step's own states */
	hb_dop853_dense(st, t0 + h, yi);
	cr_expect_lt(fabs(yi[0] - y[0]), 1e-14 * fabs(y[0]) + 1e-15);
	gsl_odeiv2_step_free(st);
	return e;
}

Test(dop853, dense_output_order_7)
{
	long extra1, extra2;
	double e1 = dense_error(0.4, &extra1), e2 = dense_error(0.2, &extra2);
	double order = log2(e1 / e2);

	/* a continuous extension of order 7 has a local error O(h^8) */
	cr_expect(order > 7.0 && order < 9.5, "dense output: observed local order %.3f (%.3g, %.3g)",
	          order - 1, e1, e2);
	cr_expect_lt(e1, 1e-7, "dense output error %.3g on a step of 0.4", e1);
	cr_expect_lt(e2, 1e-9, "dense output error %.3g on a step of 0.2", e2);
	cr_expect_eq(extra1, 3, "the dense output costs 3 evaluations once per step, not %ld", extra1);
	cr_expect_eq(extra2, 3);
}

Test(dop853, first_same_as_last)
{
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_dop853, 3);
	double y[3], yerr[3], t = 0.0;
	int i;

	exact(0.0, y);
	nfev = 0;
	for (i = 0; i < 10; i++, t += 0.1)
		gsl_odeiv2_step_apply(st, t, 0.1, y, yerr, NULL, NULL, &sys);
	cr_expect_eq(nfev, 1 + 10 * 12, "10 steps cost %ld evaluations, not 121", nfev);
	gsl_odeiv2_step_reset(st);
	nfev = 0;
	gsl_odeiv2_step_apply(st, t, 0.1, y, yerr, NULL, NULL, &sys);
	cr_expect_eq(nfev, 13, "after a reset the first stage is evaluated again");
	gsl_odeiv2_step_free(st);
}

/* Under GSL's driver with its standard control: DOP853 and rk8pd agree with the solution. */
Test(dop853, agrees_with_rk8pd)
{
	long evals[2];

	agrees_with_gsl_rk8pd(hb_step_dop853, evals);
	cr_expect_gt(evals[0], 0);
	cr_expect_gt(evals[1], 0);
}
