/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_step_rk8pd.c - the engine's written-out rk8pd (src/core/step_rk8pd.c)
 * against GSL's gsl_odeiv2_step_rk8pd: the same doubles bit for bit (y, the
 * error estimate, dydt_out), the same calls of the system's function and
 * the same status, on several nonlinear systems of dimensions 1 to 14 (the
 * ones with a copy of their own and others), with and without dydt_in and
 * dydt_out, signed zeros, a failing function at every stage, and whole runs
 * of GSL's evolver with its standard control (rejections included).
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "step_rk8pd.h"

enum { MAXN = 14 };

/* A system: its kind, dimension, and the evaluations counted; fail_at fails that evaluation. */
struct sys {
	int kind;
	int n;
	long calls;
	long fail_at; /* the evaluation (from 1) that returns GSL_FAILURE; 0: none */
	double t[32]; /* the times f was asked at, the first 32 */
};

static int
f(double t, const double y[], double dydt[], void *params)
{
	struct sys *p = params;
	const int n = p->n;

	if (p->calls < 32)
		p->t[p->calls] = t;
	if (++p->calls == p->fail_at)
		return GSL_FAILURE;
	for (int i = 0; i < n; i++) {
		const double a = y[i], b = y[(i + 1) % n], c = y[(i + n - 1) % n];

		switch (p->kind) {
		case 0: /* coupled oscillators with a cubic spring and a forcing */
			dydt[i] = (i % 2 == 0) ? b : -a - 0.3 * a * a * a + 0.1 * c + cos(2.0 * t + i);
			break;
		case 1: /* Lotka-Volterra ring */
			dydt[i] = a * (1.0 - b) + 0.5 * a * c - 0.25 * a;
			break;
		case 2: /* a fast decay towards a slow rotation, and a |.|^(3/2) term (Hertz's) */
			dydt[i] = -8.0 * (a - sin(t)) + b * sqrt(fabs(c)) * c - (double)i * 1e-3;
			break;
		default: /* signed zeros: f is -0 or +0 by the sign of a component and of t */
			dydt[i] = (i % 3 == 0) ? -0.0 * copysign(1.0, a) : (i % 3 == 1) ? 0.0 * t : b - b;
			break;
		}
	}
	return GSL_SUCCESS;
}

static unsigned long rng = 20261126;

static double
draw(void)
{
	rng = rng * 6364136223846793005UL + 1442695040888963407UL;
	return ((double)(rng >> 11) / 9007199254740992.0 - 0.5) * 2.0;
}

/*
 * The same doubles: the same bits, or both NaN.  (A NaN's sign and payload
 * are those of whichever NaN operand an instruction reads first, and a
 * compiler may swap the operands of a sum; the engine's right-hand sides
 * refuse a state that is not finite, so no NaN goes on in a run.)
 */
static int
same(const double *a, const double *b, int n)
{
	for (int i = 0; i < n; i++)
		if (memcmp(&a[i], &b[i], sizeof a[i]) && !(isnan(a[i]) && isnan(b[i])))
			return 0;
	return 1;
}

static gsl_odeiv2_step *
step_of(const gsl_odeiv2_step_type *T, int n)
{
	gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(T, (size_t)n);

	cr_assert_not_null(st);
	return st;
}

/*
 * The two steppers from the same (t, y), with dydt_in and dydt_out as
 * asked: bit for bit.  Returns 1 when the step ended with every component
 * finite.
 */
static const gsl_odeiv2_step_type *ours;

static int
one_step(int kind, int n, double t, double h, const double *y0, int with_in, int with_out,
         long fail_at)
{
	const gsl_odeiv2_step_type *T[2] = { gsl_odeiv2_step_rk8pd, ours };
	double y[2][MAXN], yerr[2][MAXN], out[2][MAXN], in[MAXN];
	struct sys p[2];
	int rc[2];
	const size_t bytes = (size_t)n * sizeof(double);

	for (int k = 0; k < 2; k++) {
		gsl_odeiv2_step *st = step_of(T[k], n);
		gsl_odeiv2_system sys = { f, NULL, (size_t)n, &p[k] };

		p[k] = (struct sys){ kind, n, 0, 0, { 0 } };
		if (with_in)
			cr_assert_eq(f(t, y0, in, &p[k]), GSL_SUCCESS);
		p[k].calls = 0;
		p[k].fail_at = fail_at;
		memcpy(y[k], y0, bytes);
		memset(yerr[k], 0x5a, sizeof yerr[k]);
		memset(out[k], 0x5a, sizeof out[k]);
		rc[k] = gsl_odeiv2_step_apply(st, t, h, y[k], yerr[k], with_in ? in : NULL,
		                              with_out ? out[k] : NULL, &sys);
		gsl_odeiv2_step_free(st);
	}
	cr_assert_eq(rc[1], rc[0], "kind %d, dim %d, fail at %ld: status %d, GSL's %d", kind, n,
	             fail_at, rc[1], rc[0]);
	cr_assert_eq(p[1].calls, p[0].calls, "kind %d, dim %d: %ld evaluations, GSL's %ld", kind, n,
	             p[1].calls, p[0].calls);
	cr_assert(!memcmp(p[1].t, p[0].t, sizeof p[0].t), "kind %d, dim %d: f asked at other times",
	          kind, n);
	cr_assert(same(y[1], y[0], n), "kind %d, dim %d, in %d, out %d: y differs", kind, n,
	          with_in, with_out);
	if (rc[0] != GSL_SUCCESS) {
		cr_assert(same(y[1], y0, n), "a failed step leaves y as it was");
		return 0;
	}
	cr_assert(same(yerr[1], yerr[0], n), "kind %d, dim %d, in %d, out %d: yerr differs",
	          kind, n, with_in, with_out);
	if (with_out)
		cr_assert(same(out[1], out[0], n), "kind %d, dim %d: dydt_out differs", kind, n);
	for (int i = 0; i < n; i++)
		if (!isfinite(y[0][i]))
			return 0;
	return 1;
}

/* Both copies: the widest lanes the processor has, and two lanes. */
static const gsl_odeiv2_step_type *const *
copies(void)
{
	static const gsl_odeiv2_step_type *c[3];

	c[0] = hb_step_rk8pd;
	c[1] = hb_step_rk8pd_2lanes;
	return c;
}

Test(step_rk8pd, one_step_bit_for_bit)
{
	for (const gsl_odeiv2_step_type *const *c = copies(); *c; c++) {
		int finite = 0, total = 0;

		ours = *c;
		for (int kind = 0; kind < 4; kind++)
		for (int n = 1; n <= MAXN; n++)
			for (int rep = 0; rep < 6; rep++) {
				double y0[MAXN];
				const double t = 3.0 * draw(), h = ldexp(fabs(draw()) + 0.01, -rep);

				for (int i = 0; i < n; i++)
					y0[i] = kind == 3 ? (draw() < 0 ? -0.0 : 0.0) : 1.5 * draw();
				finite += one_step(kind, n, t, rep % 2 ? -h : h, y0, rep % 2, rep / 2 % 2, 0);
				finite += one_step(kind, n, t, h, y0, !(rep % 2), rep / 2 % 2, 0);
				total += 2;
			}
		/* the comparisons are of numbers, not of NaNs */
		cr_assert_eq(finite, total, "%d of %d steps ended finite", finite, total);
	}
}

/* f fails at each of its evaluations in turn: the same status, calls, and y untouched. */
Test(step_rk8pd, failing_function)
{
	for (const gsl_odeiv2_step_type *const *c = copies(); *c; c++)
		for (int n = 1; n <= MAXN; n += 3)
			for (long at = 1; at <= 14; at++) {
				double y0[MAXN];

				ours = *c;
				for (int i = 0; i < n; i++)
					y0[i] = draw();
				one_step(0, n, 0.5, 0.1, y0, 0, 1, at);
				one_step(1, n, 0.5, 0.1, y0, 1, 1, at);
				one_step(2, n, 0.5, 0.1, y0, 1, 0, at);
			}
}

/*
 * A whole run of GSL's evolver with its standard control (as the engine
 * drives a phase) under both steppers: every step's t, h, y and the counts
 * the same.
 */
static void
evolve_compare(const gsl_odeiv2_step_type *mine, int kind, int n)
{
	const gsl_odeiv2_step_type *T[2] = { gsl_odeiv2_step_rk8pd, mine };
	gsl_odeiv2_evolve *e[2];
	gsl_odeiv2_control *ctl[2];
	gsl_odeiv2_step *st[2];
	struct sys p[2];
	gsl_odeiv2_system sys[2];
	double t[2] = { 0.0, 0.0 }, h[2] = { 0.5, 0.5 }, y[2][MAXN];
	int steps = 0;

	for (int k = 0; k < 2; k++) {
		st[k] = step_of(T[k], n);
		e[k] = gsl_odeiv2_evolve_alloc((size_t)n);
		ctl[k] = gsl_odeiv2_control_standard_new(1e-14, 1e-12, 1.0, 0.0);
		p[k] = (struct sys){ kind, n, 0, 0, { 0 } };
		sys[k] = (gsl_odeiv2_system){ f, NULL, (size_t)n, &p[k] };
		for (int i = 0; i < n; i++)
			y[k][i] = 0.1 * (i + 1) * (kind == 1 ? 1.0 : (i % 2 ? -1.0 : 1.0)) + 0.3;
	}
	while (t[0] < 3.0 && steps < 5000) {
		int rc[2];

		for (int k = 0; k < 2; k++)
			rc[k] = gsl_odeiv2_evolve_apply(e[k], ctl[k], st[k], &sys[k], &t[k], 3.0, &h[k],
			                                y[k]);
		cr_assert_eq(rc[1], rc[0]);
		cr_assert_eq(rc[0], GSL_SUCCESS, "kind %d, dim %d: status %d", kind, n, rc[0]);
		cr_assert(t[1] == t[0] && h[1] == h[0], "kind %d, dim %d, step %d: t or h differs", kind,
		          n, steps);
		cr_assert(!memcmp(y[1], y[0], (size_t)n * sizeof(double)),
		          "kind %d, dim %d, step %d: y differs", kind, n, steps);
		steps++;
	}
	cr_assert_eq(t[0], 3.0);
	cr_assert_eq(p[1].calls, p[0].calls);
	cr_assert_eq(e[1]->count, e[0]->count);
	cr_assert_eq(e[1]->failed_steps, e[0]->failed_steps);
	if (kind == 2)
		cr_assert_gt(e[0]->failed_steps, 0, "dim %d: no rejected step tried", n);
	for (int k = 0; k < 2; k++) {
		gsl_odeiv2_control_free(ctl[k]);
		gsl_odeiv2_evolve_free(e[k]);
		gsl_odeiv2_step_free(st[k]);
	}
}

Test(step_rk8pd, evolve_bit_for_bit)
{
	for (const gsl_odeiv2_step_type *const *c = copies(); *c; c++)
		for (int kind = 0; kind < 3; kind++)
			for (int n = 2; n <= 13; n++)
				evolve_compare(*c, kind, n);
}

/* The type answers as GSL's: its name, order, and the flags the evolver reads. */
Test(step_rk8pd, type)
{
	gsl_odeiv2_step *st = step_of(hb_step_rk8pd, 7);

	cr_expect_str_eq(gsl_odeiv2_step_name(st), "rk8pd");
	cr_expect_eq(gsl_odeiv2_step_order(st), 8);
	cr_expect_eq(hb_step_rk8pd->can_use_dydt_in, gsl_odeiv2_step_rk8pd->can_use_dydt_in);
	cr_expect_eq(hb_step_rk8pd->gives_exact_dydt_out, gsl_odeiv2_step_rk8pd->gives_exact_dydt_out);
	cr_expect_eq(gsl_odeiv2_step_reset(st), GSL_SUCCESS);
	gsl_odeiv2_step_free(st);
}
