/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_fit_stats.c - hb_fit_stats against numbers derived by hand: degrees
 * of freedom, reduced chi-square, the chi-square test's tails (closed form
 * for even dof), AIC and BIC in both forms, Student's t intervals, a
 * parameter at a bound.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "testutil.h"

/* A result of P = 2 free parameters, N = 6 points: 4 dof. */
static void
result_of(struct hb_fit_result *r, double cost, int scaled)
{
	memset(r, 0, sizeof *r);
	scene_preset("steel-on-bitumen", &r->fitted);
	r->np = 2;
	snprintf(r->key[0], sizeof r->key[0], "law.c");
	snprintf(r->key[1], sizeof r->key[1], "law.alpha");
	r->start[0] = 2000;
	r->value[0] = 5000;
	r->se[0] = 50;
	r->start[1] = 0.6;
	r->value[1] = 0.3;
	r->se[1] = 0.006;
	r->npoints = 6;
	r->cost = cost;
	r->sd_scaled = scaled;
}

Test(fit_stats, known_variance)
{
	struct hb_fit_result r;
	struct hb_fit_stats s;
	/* chi-square with 4 dof: Q(x) = exp(-x/2) (1 + x/2) */
	double x = 3.0, q = exp(-x / 2) * (1 + x / 2);
	double t4 = 2.7764451051977987; /* Student's t, 0.975 quantile, 4 dof */

	result_of(&r, x, 0);
	cr_assert_eq(hb_fit_stats(&r, 0.05, &s), HB_OK);
	cr_assert_eq(s.n, 6);
	cr_assert_eq(s.p, 2);
	cr_assert_eq(s.dof, 4);
	cr_assert_float_eq(s.chi2_red, 0.75, 1e-15);
	cr_assert(s.noise_stated);
	cr_assert_float_eq(s.p_above, q, 1e-12);
	cr_assert_float_eq(s.p_below, 1 - q, 1e-12);
	cr_assert_eq(s.noise, HB_FIT_NOISE_CONSISTENT);
	cr_assert_float_eq(s.aic, 3.0 + 4, 1e-12);
	cr_assert_float_eq(s.bic, 3.0 + 2 * log(6.0), 1e-12);
	cr_assert_float_eq(s.t95, t4, 1e-9);
	cr_assert_float_eq(s.lo95[0], 5000 - t4 * 50, 1e-6);
	cr_assert_float_eq(s.hi95[1], 0.3 + t4 * 0.006, 1e-10);
	cr_assert_float_eq(s.rel_se[0], 0.01, 1e-15);
	cr_assert_eq(s.at_bound[0], 0);
	cr_assert_eq(s.at_bound[1], 0);
}

Test(fit_stats, noise_test_both_tails)
{
	struct hb_fit_result r;
	struct hb_fit_stats s;

	/* Q(20; 4) = 11 exp(-10) = 5.0e-4 < 0.025: residuals above the noise */
	result_of(&r, 20, 0);
	hb_fit_stats(&r, 0.05, &s);
	cr_assert_float_eq(s.p_above, 11 * exp(-10.0), 1e-15);
	cr_assert_eq(s.noise, HB_FIT_NOISE_ABOVE);
	/* P(0.2; 4) = 1 - 1.1 exp(-0.1) = 4.7e-3 < 0.025: below */
	r.cost = 0.2;
	hb_fit_stats(&r, 0.05, &s);
	cr_assert_float_eq(s.p_below, 1 - 1.1 * exp(-0.1), 1e-12);
	cr_assert_eq(s.noise, HB_FIT_NOISE_BELOW);
	/* at level 0.001 both are consistent */
	hb_fit_stats(&r, 0.001, &s);
	cr_assert_eq(s.noise, HB_FIT_NOISE_CONSISTENT);
	cr_assert_eq(hb_fit_stats(&r, 1.5, &s), HB_EINVAL);
}

Test(fit_stats, unknown_variance_and_bound)
{
	struct hb_fit_result r;
	struct hb_fit_stats s;

	result_of(&r, 12, 1);
	r.value[0] = 1e-4;   /* law.c from 2000 to 1e-4: at its lower bound, 0 */
	hb_fit_stats(&r, 0.05, &s);
	cr_assert(!s.noise_stated);
	cr_assert_eq(s.noise, HB_FIT_NOISE_UNSTATED);
	cr_assert(isnan(s.p_above));
	cr_assert_float_eq(s.aic, 6 * log(2.0) + 4, 1e-12);
	cr_assert_float_eq(s.bic, 6 * log(2.0) + 2 * log(6.0), 1e-12);
	cr_assert_eq(s.at_bound[0], -1);
	cr_assert_eq(s.at_bound[1], 0);
}
