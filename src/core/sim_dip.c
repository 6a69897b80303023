/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_dip.c - the dip test: an event inside a step whose two ends are in
 * C (an indicator dips below zero and comes back: a separation or an
 * impact stepped over), predicted from each event's indicator's values
 * and rates at the step's ends and confirmed on a re-step (sim_locate.c
 * then locates what crossed before it; see sim.c for the method).
 */
#include <gsl/gsl_poly.h>

#include "sim_impl.h"

/*
 * An event inside a step whose ends are both in C (an indicator dips
 * below zero and comes back: a separation or an impact stepped over).  The
 * cubic Hermite interpolant of the indicator k from its values and rates
 * at the ends predicts where it is least; if it predicts a negative value,
 * the state there is computed.  Returns the fraction theta of the step
 * where the indicator was found negative (with the watched values there in
 * fx), or 0.
 */
static double
dip1(struct hb_sim *s, int k, double f0, double f1, double r0, double r1, double *fx)
{
	struct phase *p = s->cur;
	double H = s->H, d0, d1, c2, c3, th[2], *u = s->ua;
	int *kind = s->lka, nt, i;

	if (!(f0 >= 0.0 && f1 >= 0.0) || !isfinite(r0) || !isfinite(r1))
		return 0.0;
	d0 = H * r0;
	d1 = H * r1;
	if (d0 >= 0.0 && d1 <= 0.0)
		return 0.0; /* rising then falling: no interior minimum */
	/* P(th) = f0 + d0 th + c2 th^2 + c3 th^3; its critical points solve P'(th) = 0 */
	c2 = 3.0 * (f1 - f0) - 2.0 * d0 - d1;
	c3 = 2.0 * (f0 - f1) + d0 + d1;
	nt = gsl_poly_solve_quadratic(3.0 * c3, 2.0 * c2, d0, &th[0], &th[1]);
	for (i = 0; i < nt; i++) {
		double t = th[i], P;

		if (!(t > 0.0 && t < 1.0))
			continue;
		P = f0 + t * (d0 + t * (c2 + t * c3));
		if (P >= 0.0)
			continue;
		if (hbs_restep_n(s, t * H, u, p->L.dim))
			continue;
		hbs_watch(s, p, s->t0 + t * H, u, fx, kind);
		if (fx[k] < 0.0)
			return t;
	}
	return 0.0;
}

/*
 * ... over every event that is no candidate of the step (its ends in C):
 * the earliest theta found, with the watched values there in fx.  The
 * pair has one event, its indicator; a chain's clusters one for each
 * interface in contact and each watched gap.
 */
double
hbs_dip(struct hb_sim *s, const double *f0, const double *f1, const double *r0, const double *r1,
    const int *kind, int n, const int *cand, int ncand, double *fx)
{
	double best = 0.0;
	int i, c = 0, nev = 0;

	if (!s->chain) /* the pair's one event, its indicator f[0] */
		return ncand > 0 && cand[0] == 0 ? 0.0 : dip1(s, 0, f0[0], f1[0], r0[0], r1[0], fx);
	for (i = 0; i < n; i++) {
		double th;

		while (c < ncand && cand[c] < i)
			c++;
		if (kind[i] != FUN_EVENT)
			continue;
		nev++;
		if (c < ncand && cand[c] == i)
			continue;
		th = dip1(s, i, f0[i], f1[i], r0[i], r1[i], fx);
		if (th > 0.0 && (best == 0.0 || th < best))
			best = th;
	}
	/* with several events fx may be of another's state: the earliest's again (its re-step kept) */
	if (best > 0.0 && nev > 1 && hbs_restep_n(s, best * s->H, s->ua, s->cur->L.dim) == 0)
		hbs_watch(s, s->cur, s->t0 + best * s->H, s->ua, fx, s->lka);
	return best;
}
