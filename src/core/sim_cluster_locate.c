/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_locate.c - a chain's clusters of contacts: where a function
 * of their state crosses in the step just accepted (an event, a kink, an
 * extremum, a limit of the model), on re-steps of their ODE from the
 * step's start with the engine's root finder (sim_root.c), events and
 * limits guided by the step's Hermite interpolant as the pair's
 * (sim_locate.c); see sim_cluster.c for the method.
 */
#include <float.h>

#include "sim_impl.h"

/*
 * The state one step of length h from (t0, u0): into c->u1.  The last
 * CCACHE of the step are kept: the location of each function that
 * crossed re-steps to the step's end, and often to the same points as
 * another's.
 */
int
hbs_cluster_restep(struct hb_sim *s, double h)
{
	struct clusters *c = &s->cx;
	size_t n = (size_t)c->dim;
	int i, rc;

	for (i = 0; i < c->nrs; i++)
		if (c->rsh[i] == h) {
			memcpy(c->u1, c->rsu + (size_t)i * n, n * sizeof(double));
			return GSL_SUCCESS;
		}
	memcpy(c->u1, c->u0, n * sizeof(double));
	gsl_odeiv2_step_reset(c->loc);
	/* the step's own slope at the start, where known (the re-steps' type is the step's) */
	rc = gsl_odeiv2_step_apply(c->loc, c->t0, h, c->u1, c->yerr, known_at(&c->known, c->t0, c->u0),
	                           NULL, &c->sys);
	if (rc != GSL_SUCCESS)
		return rc;
	i = c->rsnext;
	c->rsnext = (c->rsnext + 1) % CCACHE;
	if (c->nrs < CCACHE)
		c->nrs++;
	c->rsh[i] = h;
	memcpy(c->rsu + (size_t)i * n, c->u1, n * sizeof(double));
	return GSL_SUCCESS;
}

/*
 * A function of a chain's clusters to locate, as the root finder sees it
 * (struct hbs_root): val's value on a re-step to h, oriented as the pair's
 * (sim_locate.c's oriented_value).  The last values asked are kept: the
 * root finder asks the bracket's ends again, and a re-step of the clusters
 * is a step of the method.
 */
#define CMEMO 8
struct cfun {
	struct hb_sim *s;
	int kind, sign0;
	hbs_val_fn *val;
	const void *arg;
	double fa;          /* its value at the step's start */
	double hend;        /* the end of the Hermite guide (herm) */
	int herm;           /* 1: values on the Hermite guide, not on re-steps */
	int n, next;
	double mh[CMEMO], mg[CMEMO];
};

static double
cfun_value(double h, void *ctx)
{
	struct cfun *f = ctx;
	struct clusters *c = &f->s->cx;
	double v;
	int i;

	for (i = 0; i < f->n; i++)
		if (f->mh[i] == h)
			return f->mg[i];
	if (c->t0 + h == c->t0)
		v = f->fa; /* the step's start */
	else if (f->herm) {
		hbs_hermite(h, f->hend, c->dim, c->u0, c->d0, c->u, c->d1, c->u1);
		v = f->val(f->s, c->t0 + h, c->u1, f->arg);
	} else if (hbs_cluster_restep(f->s, h) != GSL_SUCCESS)
		return NAN;
	else
		v = f->val(f->s, c->t0 + h, c->u1, f->arg);
	if (f->kind == FUN_EVENT)
		v = v >= 0.0 ? fmax(v, DBL_MIN) : v;
	else {
		v *= f->sign0;
		v = v > 0.0 ? v : (v == 0.0 ? DBL_MIN : v);
	}
	i = f->next;
	f->next = (f->next + 1) % CMEMO;
	if (f->n < CMEMO)
		f->n++;
	f->mh[i] = h;
	f->mg[i] = v;
	return v;
}

/*
 * The derivatives at the step's start and at (t0 + hend, the state u) for
 * the Hermite guide, once a step (and once more for another end: a limit
 * located after an event's point), evaluated where the step has not
 * evaluated them already: 0, or the rhs' error.
 */
static int
hermite_setup(struct hb_sim *s, double hend)
{
	struct clusters *c = &s->cx;
	int rc;

	if (!c->hd0) {
		if ((rc = known_eval(&c->known, &c->sys, c->t0, c->u0, c->d0)) != GSL_SUCCESS)
			return rc;
		c->hd0 = 1;
	}
	if (!(c->hh == hend)) {
		c->hh = NAN;
		if ((rc = known_eval(&c->known, &c->sys, c->t0 + hend, c->u, c->d1)) != GSL_SUCCESS)
			return rc;
		c->hh = hend;
	}
	return 0;
}

/*
 * A function val (of this kind, see hbs_crossed; fa at the step's start,
 * gmax the largest |value| it has had) crosses in (0, hend] of the step
 * from (t0, u0) to (t0 + hend, u): the crossed end b of its bracket,
 * located on re-steps by the engine's root finder (sim_root.c, as the
 * pair's) down to a few ulps of t (the stalls of Brent's method closed for
 * every kind of function), into *hb; the evaluations into *iters.  An
 * event (and a limit) is first found on the step's cubic Hermite
 * interpolant (its slopes at the step's ends, the step's own where it
 * evaluated them, known.h, else evaluated), as the pair's under a GSL
 * stepper (sim_locate.c, locate_on_steps); kinks and extrema are not (on
 * the BWMCL cradle that took 11% more evaluations: a switching function
 * zero to rounding over a band sends the guide astray).  The clusters'
 * events, kinks and extrema are located with it, and the model's limits
 * (sim_limits.c).
 */
int
hbs_cluster_locate(struct hb_sim *s, int kind, hbs_val_fn *val, const void *arg, double hend, double fa,
                   double gmax, double *hb, int *iters)
{
	struct clusters *c = &s->cx;
	struct cfun f = { s, kind, kind == FUN_EVENT || fa > 0.0 ? 1 : -1, val, arg, fa, 0.0, 0, 0, 0, { 0 }, { 0 } };
	struct hbs_root r = { cfun_value, &f, iters, s->root, c->t0, hend, 1,
	                      100.0 * DBL_EPSILON * gmax };
	double a, g;
	int rc;

	*iters = 0;
	/*
	 * The far end as the re-steps see it: the accepted step's length is
	 * t - t0, which may differ from the h it was taken with by rounding,
	 * so that a crossing at the level of round-off may not be there for
	 * the re-steps.  Then there is none to locate (*hb = INFINITY): an
	 * event whose function is negative at the step's end is taken when
	 * the next step begins.
	 */
	(*iters)++;
	if (isnan(g = cfun_value(hend, &f)))
		return hbs_fail(s, HB_ENUMERIC, "a re-step to locate an event failed");
	if (!(g < 0.0)) {
		*hb = INFINITY;
		return 0;
	}
	if (kind == FUN_EVENT && hermite_setup(s, hend) == 0) {
		/*
		 * Found first on the cubic Hermite interpolant of the step (no
		 * evaluations), then bracketed on re-steps in a window about
		 * that point, widened until it holds the crossing (at last the
		 * whole step), as the pair's location (sim_locate.c).
		 */
		double ah, bh, d = 1e-3 * hend, gl = NAN, gu = NAN, g0, slope, x1, w;
		int tries;

		f.herm = 1;
		f.hend = hend;
		f.n = 0;
		/* to 1e-6 of the step: the Newton estimate from a real value below corrects it */
		rc = hbs_root_bracket(&r, 0.0, hend, 1e-6 * hend, &ah, &bh);
		if (rc == 0) { /* the interpolant's slope about bh */
			gl = cfun_value(fmax(0.0, bh - d), &f);
			gu = cfun_value(fmin(hend, bh + d), &f);
		}
		f.herm = 0;
		f.n = 0;
		if (rc == 0 && isfinite(g0 = cfun_value(bh, &f))) {
			/*
			 * The value on a re-step at bh and the interpolant's slope
			 * give a Newton estimate x1 of the root; the window runs
			 * from bh to just beyond x1, widened until it holds the
			 * crossing.
			 */
			(*iters)++;
			slope = (gu - gl) / (fmin(hend, bh + d) - fmax(0.0, bh - d));
			x1 = isfinite(slope) && slope < 0 ? bh - g0 / slope : bh;
			w = fmax(0.05 * fabs(x1 - bh), 16.0 * DBL_EPSILON * fabs(c->t0 + bh));
			for (tries = 0; tries < 5; tries++, w *= 16.0) {
				double lo = g0 > 0 ? bh : fmax(0.0, fmin(bh, x1) - w);
				double up = g0 > 0 ? fmin(hend, fmax(bh, x1) + w) : bh;

				if (hbs_root_bracket(&r, lo, up, 1e-14 * hend, &a, hb) == 0)
					return 0;
			}
		}
	}
	/*
	 * Over the whole step; where Brent's bracket closes on a crossing the
	 * other way (a gap at the level of its rounding crosses back and
	 * forth), by bisection, which keeps its ends' sides.
	 */
	if (hbs_root_bracket(&r, 0.0, hend, 1e-14 * hend, &a, hb) != 0 &&
	    hbs_root_bisect(&r, 0.0, hend, 1e-14 * hend, &a, hb) != 0)
		return hbs_fail(s, HB_ENUMERIC, "event location failed (no bracket)");
	return 0;
}
