/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_known.c - the right-hand side where the step just accepted
 * evaluated it (src/core/known.c): at the step's start and end it is f
 * there, bit for bit, while the state is not moved between steps; where
 * it is moved without a reset (GSL 2.7's evolver then takes the last
 * step's dydt_out as it is) the start slope is still the step's own, so
 * that a re-step given it reproduces the step; it is forgotten on a reset,
 * a forget, or another step; and a re-step given it as dydt_in gives the
 * same doubles as one that evaluates f, with one evaluation fewer.
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "known.h"
#include "step_dop853.h"
#include "step_rk8pd.h"

enum { N = 5 };

static long calls;

/* a forced chain of Duffing oscillators: nonlinear, with t in it */
static int
f(double t, const double y[], double dydt[], void *params)
{
	(void)params;
	calls++;
	for (int i = 0; i < N; i++)
		dydt[i] = -y[i] - 0.3 * y[i] * y[i] * y[i] + 0.2 * y[(i + 1) % N] + cos(3.0 * t + i);
	return GSL_SUCCESS;
}

static const gsl_odeiv2_system sys = { f, NULL, N, NULL };

struct run {
	gsl_odeiv2_step *st;
	gsl_odeiv2_evolve *e;
	gsl_odeiv2_control *c;
	struct known_f k;
	double t, h, y[N];
};

static void
run_new(struct run *r, const gsl_odeiv2_step_type *T)
{
	r->st = gsl_odeiv2_step_alloc(T, N);
	r->e = gsl_odeiv2_evolve_alloc(N);
	r->c = gsl_odeiv2_control_standard_new(1e-14, 1e-12, 1.0, 0.0);
	cr_assert(r->st && r->e && r->c);
	known_init(&r->k, r->e, r->st);
	r->t = 0.0;
	r->h = 1e-3;
	for (int i = 0; i < N; i++)
		r->y[i] = 0.1 * (i + 1);
}

static void
run_free(struct run *r)
{
	gsl_odeiv2_control_free(r->c);
	gsl_odeiv2_evolve_free(r->e);
	gsl_odeiv2_step_free(r->st);
}

/* One step as hbs_evolve takes it: its start into (t0, y0). */
static void
step(struct run *r, double *t0, double *y0)
{
	*t0 = r->t;
	memcpy(y0, r->y, sizeof r->y);
	cr_assert_eq(gsl_odeiv2_evolve_apply(r->e, r->c, r->st, &sys, &r->t, 10.0, &r->h, r->y), GSL_SUCCESS);
	known_keep(&r->k, *t0);
}

/* f(t, y) as known equals f evaluated there, bit for bit. */
static void
assert_known_is_f(const struct run *r, double t, const double *y)
{
	const double *k = known_at(&r->k, t, y);
	double fy[N];

	cr_assert_not_null(k, "f at t = %.17g is known", t);
	f(t, y, fy, NULL);
	cr_assert(!memcmp(k, fy, sizeof fy), "the known f at t = %.17g is f there, bit for bit", t);
}

Test(known, start_and_end_of_each_step)
{
	struct run r;
	double t0, y0[N], other[N];
	int i;

	run_new(&r, hb_step_rk8pd);
	cr_assert_null(known_at(&r.k, r.t, r.y), "nothing known before a step");
	for (i = 0; i < 40; i++) {
		step(&r, &t0, y0);
		assert_known_is_f(&r, t0, y0);
		assert_known_is_f(&r, r.t, r.y);
		memcpy(other, r.y, sizeof other);
		other[2] = nextafter(other[2], 1.0);
		cr_assert_null(known_at(&r.k, r.t, other), "one ulp off: not known");
		cr_assert_null(known_at(&r.k, nextafter(r.t, 1.0), r.y), "t one ulp off: not known");
	}
	cr_assert_gt(r.e->failed_steps, 0, "the run had rejected steps (h grows from 1e-3)");
	run_free(&r);
}

Test(known, forgotten_on_reset_and_forget)
{
	struct run r;
	double t0, y0[N];

	run_new(&r, hb_step_rk8pd);
	step(&r, &t0, y0);
	step(&r, &t0, y0);
	cr_assert_not_null(known_at(&r.k, r.t, r.y));
	gsl_odeiv2_evolve_reset(r.e);
	cr_assert_null(known_at(&r.k, r.t, r.y), "a reset of the evolver forgets");
	cr_assert_null(known_at(&r.k, t0, y0));
	step(&r, &t0, y0);
	assert_known_is_f(&r, t0, y0);
	step(&r, &t0, y0);
	cr_assert_null(known_at(&r.k, t0 - 1e-3, y0), "not the step before's");
	known_forget(&r.k);
	cr_assert_null(known_at(&r.k, r.t, r.y), "known_forget forgets");
	run_free(&r);
}

/*
 * A state moved between steps without a reset: GSL's evolver takes the
 * last step's dydt_out as the start slope, which is not f there.  The
 * slope known at the start is the one the step took: a re-step to the
 * step's end given it returns the step's end, bit for bit; the end's is f
 * there.
 */
Test(known, moved_state_the_steps_own_slope)
{
	struct run r;
	gsl_odeiv2_step *loc = gsl_odeiv2_step_alloc(hb_step_rk8pd, N);
	double t0, y0[N], fy[N], u[N], err[N];

	run_new(&r, hb_step_rk8pd);
	step(&r, &t0, y0);
	step(&r, &t0, y0);
	r.y[1] += 1e-3;
	step(&r, &t0, y0);
	cr_assert_eq(known_at(&r.k, t0, y0), r.e->dydt_in, "the step's own start slope");
	f(t0, y0, fy, NULL);
	cr_assert(memcmp(r.e->dydt_in, fy, sizeof fy) != 0, "which is not f there (GSL's evolver)");
	memcpy(u, y0, sizeof u);
	cr_assert_eq(gsl_odeiv2_step_apply(loc, t0, r.t - t0, u, err, known_at(&r.k, t0, y0), NULL, &sys),
	             GSL_SUCCESS);
	cr_assert(!memcmp(u, r.y, sizeof u), "a re-step given it reproduces the step");
	assert_known_is_f(&r, r.t, r.y);
	gsl_odeiv2_step_free(loc);
	run_free(&r);
}

/* A re-step from the step's start given the known f there: the same doubles, one evaluation fewer. */
Test(known, restep_bit_for_bit)
{
	struct run r;
	gsl_odeiv2_step *loc = gsl_odeiv2_step_alloc(hb_step_rk8pd, N);
	double t0, y0[N];
	int i;

	run_new(&r, hb_step_rk8pd);
	for (i = 0; i < 10; i++) {
		double a[N], b[N], ea[N], eb[N], H = r.t, frac[] = { 0.13, 0.5, 0.999 };
		long ca, cb;

		step(&r, &t0, y0);
		H = r.t - t0;
		for (int j = 0; j < 3; j++) {
			memcpy(a, y0, sizeof a);
			memcpy(b, y0, sizeof b);
			calls = 0;
			cr_assert_eq(gsl_odeiv2_step_apply(loc, t0, frac[j] * H, a, ea, NULL, NULL, &sys), GSL_SUCCESS);
			ca = calls;
			calls = 0;
			cr_assert_eq(gsl_odeiv2_step_apply(loc, t0, frac[j] * H, b, eb,
			                                   known_at(&r.k, t0, y0), NULL, &sys), GSL_SUCCESS);
			cb = calls;
			cr_assert(!memcmp(a, b, sizeof a) && !memcmp(ea, eb, sizeof ea),
			          "step %d, re-step to %g of it: the same doubles", i, frac[j]);
			cr_assert_eq(cb, ca - 1, "one evaluation fewer (%ld against %ld)", cb, ca);
		}
	}
	gsl_odeiv2_step_free(loc);
	run_free(&r);
}

/*
 * A step type that does not take dydt_in (dop853 keeps its own first same
 * as last) or is implicit: nothing is known from its steps.
 */
Test(known, other_types)
{
	struct run r;
	double t0, y0[N];

	run_new(&r, hb_step_dop853);
	step(&r, &t0, y0);
	step(&r, &t0, y0);
	cr_assert_null(known_at(&r.k, t0, y0));
	cr_assert_null(known_at(&r.k, r.t, r.y));
	run_free(&r);

	cr_assert(!known_exact_type(gsl_odeiv2_step_rk4imp));
	cr_assert(!known_exact_type(gsl_odeiv2_step_bsimp));
	cr_assert(known_exact_type(hb_step_rk8pd) && known_exact_type(gsl_odeiv2_step_rkf45));
}
