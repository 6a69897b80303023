/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_vern98.c - Verner's 9(8) step type alone (src/core/step_vern98.c):
 * the order conditions of its tableau (every rooted tree up to order 10),
 * the order of its solution and of its error estimate measured on a smooth
 * problem with a known solution, the cost of a step
 * (first same as last; a rejected step retaken keeps its first stage), and
 * agreement with GSL's rk8pd under GSL's own driver.
 */
#include <math.h>
#include <string.h>
#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "step_vern98.h"
#include "steptest.h"

/*
 * The order conditions: for every rooted tree t of order |t| <= 10,
 * b . Phi(t) = 1 / gamma(t), with Phi(t) the stage vector of the tree
 * (the product over its subtrees t_k of A Phi(t_k)) and gamma(t) its
 * density (|t| times the product of its subtrees' densities).  The trees
 * of order n are built as multisets of trees of lower order (indices
 * nondecreasing): 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 of them.
 */
enum { NTREE = 1205, MAXORD = 10 };

struct trees {
	int n;
	int ord[NTREE];
	long double gamma[NTREE];
	long double phi[NTREE][16]; /* the stage vector */
	long double aphi[NTREE][16]; /* A Phi */
	double a[16][16], c[16], b[16], e[16];
};

/* Trees of order n whose subtrees are the chosen ones so far and then indices >= from. */
static void
grow(struct trees *T, int n, int left, int from, int first, const long double *v, long double g)
{
	long double w[16];

	if (left == 0) {
		int t = T->n++;

		cr_assert_lt(t, NTREE);
		T->ord[t] = n;
		T->gamma[t] = n * g;
		for (int i = 0; i < 16; i++) {
			T->phi[t][i] = v[i];
		}
		for (int i = 0; i < 16; i++) {
			long double acc = 0;

			for (int j = 0; j < 16; j++)
				acc += (long double)T->a[i][j] * T->phi[t][j];
			T->aphi[t][i] = acc;
		}
		return;
	}
	for (int k = from; k < first; k++) {
		if (T->ord[k] > left)
			continue;
		for (int i = 0; i < 16; i++)
			w[i] = v[i] * T->aphi[k][i];
		grow(T, n, left - T->ord[k], k, first, w, g * T->gamma[k]);
	}
}

static void
build_trees(struct trees *T)
{
	long double one[16];

	for (int i = 0; i < 16; i++)
		one[i] = 1;
	hb_vern98_tableau(T->a, T->c, T->b, T->e);
	T->n = 0;
	for (int n = 1; n <= MAXORD; n++)
		grow(T, n, n - 1, 0, T->n, one, 1);
}

/* The largest |w . Phi(t) - 1 / gamma(t)| over the trees of order n. */
static double
residual(const struct trees *T, const double *w, int n, int *count)
{
	double worst = 0;

	*count = 0;
	for (int t = 0; t < T->n; t++) {
		long double s = 0;

		if (T->ord[t] != n)
			continue;
		++*count;
		for (int i = 0; i < 16; i++)
			s += (long double)w[i] * T->phi[t][i];
		worst = fmax(worst, (double)fabsl(s - 1.0L / T->gamma[t]));
	}
	return worst;
}

Test(vern98, order_conditions)
{
	static struct trees T;
	static const int count[MAXORD + 1] = { 0, 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 };
	double b8[16];
	int n, k;

	build_trees(&T);
	cr_assert_eq(T.n, NTREE, "%d trees up to order 10", T.n);
	for (int i = 0; i < 16; i++) {
		long double rs = 0;

		for (int j = 0; j < 16; j++)
			rs += T.a[i][j];
		cr_expect_lt(fabsl(rs - T.c[i]), 1e-15, "row %d sums to %.17Lg, c = %.17g", i + 1, rs,
		             T.c[i]);
		b8[i] = T.b[i] + T.e[i];
	}
	for (n = 1; n <= MAXORD; n++) {
		double r9 = residual(&T, T.b, n, &k), r8 = residual(&T, b8, n, &k);

		cr_expect_eq(k, count[n], "%d trees of order %d, not %d", k, n, count[n]);
		/* the 9th-order weights: order 9 exactly */
		if (n <= 9)
			cr_expect_lt(r9, 1e-13, "order %d: residual %.3g of the 9th-order weights", n, r9);
		else
			cr_expect_gt(r9, 1e-8, "order %d: residual %.3g: not of order 10", n, r9);
		/* the embedded weights: order 8 exactly */
		if (n <= 8)
			cr_expect_lt(r8, 1e-13, "order %d: residual %.3g of the 8th-order weights", n, r8);
		else if (n == 9)
			cr_expect_gt(r8, 1e-8, "order %d: residual %.3g: the estimate would vanish", n, r8);
	}
}

Test(vern98, order_9)
{
	double e1 = fixed_steps(hb_step_vern98, 4.0, 6), e2 = fixed_steps(hb_step_vern98, 4.0, 12);
	double order = log2(e1 / e2);

	/*
	 * At least 9.  The pair's error coefficients of order 10 are small
	 * (the order conditions of order 10 are missed by 2e-6 at most), so
	 * at steps this long the next terms show too and the observed order
	 * is near 10; an 8th-order method shows 8 here.
	 */
	cr_expect(order > 8.7 && order < 11.0, "observed order %.3f (errors %.3g, %.3g)", order, e1, e2);
	cr_expect_lt(e2, 1e-9, "error with 12 steps %.3g", e2);
	cr_expect_gt(e2, 1e-13, "error with 12 steps %.3g: too small to measure an order", e2);
}

/* One step of length h from t = 0.3: the largest component of the estimate. */
static double
estimate(double h, double *true_err)
{
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_vern98, 3);
	double y[3], yerr[3];

	exact(0.3, y);
	cr_assert_eq(gsl_odeiv2_step_apply(st, 0.3, h, y, yerr, NULL, NULL, &sys), GSL_SUCCESS);
	*true_err = maxerr(0.3 + h, y);
	gsl_odeiv2_step_free(st);
	return fmax(yerr[0], fmax(yerr[1], yerr[2]));
}

Test(vern98, estimate_order_8)
{
	double t1, t2, e1 = estimate(0.4, &t1), e2 = estimate(0.2, &t2), order = log2(e1 / e2);

	/* the 8th-order solution's local error: h^9 */
	cr_expect(order > 8.4 && order < 9.7, "estimate: observed power of h %.3f (%.3g, %.3g)",
	          order, e1, e2);
	/* the step goes on with the 9th-order solution, whose own error is smaller */
	cr_expect_lt(t1, e1, "true local error %.3g, estimate %.3g", t1, e1);
	cr_expect_lt(t2, e2, "true local error %.3g, estimate %.3g", t2, e2);
}

Test(vern98, first_same_as_last)
{
	gsl_odeiv2_system sys = { f, NULL, 3, NULL };
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(hb_step_vern98, 3);
	double y[3], yerr[3], y0[3], t = 0.0;
	int i;

	exact(0.0, y);
	nfev = 0;
	for (i = 0; i < 10; i++, t += 0.1)
		gsl_odeiv2_step_apply(st, t, 0.1, y, yerr, NULL, NULL, &sys);
	cr_expect_eq(nfev, 1 + 10 * 16, "10 steps cost %ld evaluations, not 161", nfev);
	/* a step retaken from the same start (after a rejection) keeps its first stage */
	memcpy(y0, y, sizeof y);
	gsl_odeiv2_step_apply(st, t, 0.1, y, yerr, NULL, NULL, &sys);
	memcpy(y, y0, sizeof y);
	nfev = 0;
	gsl_odeiv2_step_apply(st, t, 0.05, y, yerr, NULL, NULL, &sys);
	cr_expect_eq(nfev, 16, "a retaken step costs %ld evaluations, not 16", nfev);
	gsl_odeiv2_step_reset(st);
	nfev = 0;
	gsl_odeiv2_step_apply(st, t + 0.05, 0.1, y, yerr, NULL, NULL, &sys);
	cr_expect_eq(nfev, 17, "after a reset the first stage is evaluated again");
	gsl_odeiv2_step_free(st);
}

/* Under GSL's driver with its standard control: vern98 and rk8pd agree with the solution. */
Test(vern98, agrees_with_rk8pd)
{
	long evals[2];

	agrees_with_gsl_rk8pd(hb_step_vern98, evals);
}
