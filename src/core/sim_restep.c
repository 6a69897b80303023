/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_restep.c - the state at h into the step just accepted, from the
 * step's start (t0, u0): one step of the method of length h (a re-step),
 * kept for the step, or read from the step's continuous extension
 * (dop853) or its cubic Hermite interpolant where the location asks
 * (sim_locate.c); and the crossing of any function of the state located
 * on re-steps (a chain's limits, sim_limits.c).
 */
#include "sim_impl.h"

/* The snaps onto the boundary of C of a state in contact (sim_snap.c). */
static void
snap(struct hb_sim *s, const struct phase *p, double *u)
{
	if (p->q) {
		hbs_snap_stick(s, u);
		if (s->hug)
			hbs_snap_separation(s, u);
	}
}

/* See sim_impl.h.  0, or the rhs' or the stepper's error. */
int
hbs_restep_n(struct hb_sim *s, double h, double *u, int n)
{
	struct phase *p = s->cur;
	int i, rc;

	if (s->t0 + h == s->t0) { /* h below the resolution of t: the start (bsimp refuses such a step) */
		hbs_ucopy(s, u, s->u0);
		return 0;
	}
	if (h == s->H) {
		hbs_ucopy(s, u, s->u1);
		return 0;
	}
	if (s->use_dense || s->use_herm) {
		/* on the step's continuous extension, or its Hermite interpolant: no evaluation of f */
		if (!s->use_herm)
			n = p->L.dim;
		if (s->use_herm)
			hbs_hermite(h, s->H, n, s->u0, s->f0, s->u1, s->f1, u); /* a guide only (locate_on_steps) */
		else if ((rc = hb_dop853_dense(p->d->s, s->t0 + h, u)) != GSL_SUCCESS)
			return rc;
		for (i = 0; i < n; i++)
			if (!isfinite(u[i]))
				return GSL_FAILURE;
		snap(s, p, u);
		return 0;
	}
	for (i = 0; i < s->ncache; i++)
		if (s->cache_h[i] == h) {
			hbs_ucopy(s, u, s->cache_u + (size_t)i * (size_t)s->dim.u);
			return 0;
		}
	hbs_ucopy(s, u, s->u0);
	/* (rk8pd keeps nothing from one step to the next: nothing to reset) */
	if (p->loc->s->type != hb_step_rk8pd)
		gsl_odeiv2_step_reset(p->loc->s);
	/* the step's own slope at the start, where known (its type takes it as f there) */
	rc = gsl_odeiv2_step_apply(p->loc->s, s->t0, h, u, s->yerr,
	                           p->loc->s->type == p->d->s->type ?
	                           known_at(&p->known, s->t0, s->u0) : NULL,
	                           NULL, &p->sys);
	if (rc != GSL_SUCCESS)
		return rc;
	/* a step whose error estimate is not finite was not made (bsimp's divergence) */
	for (i = 0; i < p->L.dim; i++)
		if (!isfinite(u[i]) || !isfinite(s->yerr[i]))
			return GSL_FAILURE;
	snap(s, p, u);
	i = s->cache_next;
	s->cache_next = (s->cache_next + 1) % s->dim.ncache;
	if (s->ncache < s->dim.ncache)
		s->ncache++;
	s->cache_h[i] = h;
	hbs_ucopy(s, s->cache_u + (size_t)i * (size_t)s->dim.u, u);
	return 0;
}

/* A function of the state to locate, as the root finder sees it (struct hbs_root's value). */
struct fn {
	struct hb_sim *s;
	hbs_val_fn *val;
	const void *arg;
	double fa;              /* its value at the step's start */
};

static double
fn_value(double h, void *ctx)
{
	struct fn *f = ctx;
	struct hb_sim *s = f->s;
	double v;

	if (s->t0 + h == s->t0)
		v = f->fa;
	else if (hbs_restep_n(s, h, s->ut, s->cur->L.dim) != 0)
		return NAN;
	else
		v = f->val(s, s->t0 + h, s->ut, f->arg);
	return v >= 0.0 ? fmax(v, DBL_MIN) : v;
}

/*
 * A function val of the state (>= 0 before it crosses; fa at the step's
 * start) crosses in (0, hend] of the step: the crossed end b of its
 * bracket, located on re-steps by the engine's root finder down to a few
 * ulps of t, into *hb (INFINITY where the re-steps do not see it cross at
 * hend: a crossing at the level of round-off); its evaluations into
 * *iters.  Where Brent's bracket closes on a crossing the other way, by
 * bisection, which keeps its ends' sides.  0, or hbs_fail's status.
 */
int
hbs_locate_fn(struct hb_sim *s, hbs_val_fn *val, const void *arg, double hend, double fa, double *hb,
              int *iters)
{
	struct fn f = { s, val, arg, fa };
	struct hbs_root r = { fn_value, &f, iters, s->root, s->t0, hend, 1, 0.0 };
	double a, g;

	*iters = 1;
	if (isnan(g = fn_value(hend, &f)))
		return hbs_fail(s, HB_ENUMERIC, "a re-step to locate an event failed");
	if (!(g < 0.0)) {
		*hb = INFINITY;
		return 0;
	}
	if (hbs_root_bracket(&r, 0.0, hend, 1e-14 * hend, &a, hb) != 0 &&
	    hbs_root_bisect(&r, 0.0, hend, 1e-14 * hend, &a, hb) != 0)
		return hbs_fail(s, HB_ENUMERIC, "event location failed (no bracket)");
	return 0;
}
