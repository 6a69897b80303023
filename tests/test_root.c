/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_root.c - the root finder both integrators locate with
 * (hbs_root_bracket, src/core/sim_root.c), on functions given as their
 * oriented value: a crossing bracketed to a few ulps of t, its ends on
 * either side; a stall (a root of high multiplicity, zero to rounding
 * over a band far wider than ulps) closed by its probes to ulps, where
 * Brent's own steps run out of iterations far wider, or stopped once
 * both ends are zero to the function's noise; bisection (the chains'
 * fallback) keeping its ends' sides on a function that crosses back and
 * forth; ends that do not straddle and values that cannot be
 * computed refused without GSL's error handler.
 */
#include <float.h>
#include <math.h>

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include "sim_impl.h"

static int handler_called;

static void
handler(const char *reason, const char *file, int line, int gsl_errno)
{
	(void)reason;
	(void)file;
	(void)line;
	(void)gsl_errno;
	handler_called++;
}

/* oriented: an exact zero counts as not crossed */
static double
orient(double d)
{
	return d >= 0.0 ? fmax(d, DBL_MIN) : d;
}

/* a smooth crossing at h = 0.3: > 0 before, < 0 after */
static double
smooth(double h, void *ctx)
{
	(void)ctx;
	return orient(0.3 - h);
}

/* a crossing of multiplicity 9 at h = 0.3: zero to rounding over a band far wider than ulps */
static double
band(double h, void *ctx)
{
	double d = 0.3 - h, d2 = d * d, d4 = d2 * d2;

	(void)ctx;
	return orient(d4 * d4 * d);
}

static double
nan_inside(double h, void *ctx)
{
	(void)ctx;
	if (h == 0.0)
		return 1.0;
	if (h == 1.0)
		return -1.0;
	return NAN;
}

static int
bracket(double (*f)(double, void *), int stall, double *a, double *b, int *iter)
{
	gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	struct hbs_root r = { f, NULL, iter, solver, 1.0, 1.0, stall, 0.0 };
	int rc;

	*iter = 0;
	rc = hbs_root_bracket(&r, 0.0, 1.0, 0.0, a, b);
	gsl_root_fsolver_free(solver);
	return rc;
}

Test(root, smooth_crossing_to_ulps)
{
	double a, b, tol = 4.0 * DBL_EPSILON * 2.0;
	int it, stall;

	for (stall = 0; stall <= 1; stall++) {
		cr_assert_eq(bracket(smooth, stall, &a, &b, &it), 0);
		cr_assert(smooth(a, NULL) > 0 && smooth(b, NULL) < 0, "stall %d: [%.17g, %.17g]", stall, a, b);
		cr_assert(b - a <= tol, "stall %d: width %g > %g", stall, b - a, tol);
		cr_assert(it > 0 && it < 40, "stall %d: %d evaluations", stall, it);
	}
}

static int
bracket_noise(double (*f)(double, void *), int stall, double noise, double *a, double *b, int *iter)
{
	gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	struct hbs_root r = { f, NULL, iter, solver, 1.0, 1.0, stall, noise };
	int rc;

	*iter = 0;
	rc = hbs_root_bracket(&r, 0.0, 1.0, 0.0, a, b);
	gsl_root_fsolver_free(solver);
	return rc;
}

Test(root, stall_closed_by_probes)
{
	double a, b, tol = 4.0 * DBL_EPSILON * 2.0, noise = 100.0 * DBL_EPSILON * 0.05;
	int it;

	/* Brent's own steps: MAX_BRENT iterations leave a bracket far wider than ulps */
	cr_assert_eq(bracket(band, 0, &a, &b, &it), 0);
	cr_assert(band(a, NULL) > 0 && band(b, NULL) < 0);
	cr_assert(b - a > 1000 * tol, "width %g", b - a);
	/* with the stall closed: to ulps */
	cr_assert_eq(bracket(band, 1, &a, &b, &it), 0);
	cr_assert(band(a, NULL) > 0 && band(b, NULL) < 0);
	cr_assert(b - a <= tol, "width %g > %g", b - a, tol);
	/* ... or, given the noise of the function, once both ends are zero to it (within 1e-6 of the step) */
	cr_assert_eq(bracket_noise(band, 1, noise, &a, &b, &it), 0);
	cr_assert(band(a, NULL) > 0 && band(b, NULL) < 0);
	cr_assert(b - a <= 1e-6 && fabs(band(a, NULL)) <= noise && fabs(band(b, NULL)) <= noise,
	          "width %g, ends %g %g", b - a, band(a, NULL), band(b, NULL));
	cr_assert(b - a > tol, "the noise stop: width %g", b - a);
}

Test(root, refused_without_gsl_handler)
{
	gsl_error_handler_t *old = gsl_set_error_handler(handler);
	double a = -1, b = -1;
	int it;

	handler_called = 0;
	{
		gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
		struct hbs_root r = { smooth, NULL, &it, solver, 1.0, 1.0, 1, 0.0 };

		cr_assert_neq(hbs_root_bracket(&r, 0.0, 0.2, 0.0, &a, &b), 0, "ends that do not straddle");
		gsl_root_fsolver_free(solver);
	}
	/* a value that cannot be computed inside the bracket */
	cr_assert_neq(bracket(nan_inside, 0, &a, &b, &it), 0);
	cr_assert_neq(bracket(nan_inside, 1, &a, &b, &it), 0);
	cr_assert_eq(handler_called, 0, "GSL's error handler was called %d times", handler_called);
	gsl_set_error_handler(old);
}

/* crossing back and forth 41 times in [0, 1]: > 0 at 0, < 0 at 1 */
static double
wavy(double h, void *ctx)
{
	(void)ctx;
	return orient(cos(41.0 * M_PI * h));
}

Test(root, bisection_keeps_its_ends_sides)
{
	gsl_root_fsolver *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	double a = -1, b = -1, tol = 4.0 * DBL_EPSILON * 2.0;
	int it = 0;
	struct hbs_root r = { wavy, NULL, &it, solver, 1.0, 1.0, 1, 0.0 };

	cr_assert_eq(hbs_root_bisect(&r, 0.0, 1.0, 0.0, &a, &b), 0);
	cr_assert(wavy(a, NULL) > 0 && wavy(b, NULL) < 0, "[%.17g, %.17g]", a, b);
	cr_assert(b - a <= tol, "width %g", b - a);
	cr_assert_neq(hbs_root_bisect(&r, 0.0, 2.0 / 41.0, 0.0, &a, &b), 0, "ends on the same side");
	gsl_root_fsolver_free(solver);
}
