/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_flight.c - flight in closed form: the parabola, its event by a quadratic, the
 * pre-jump state placed in D ulp by ulp (see sim.c for the method).
 */
#include "sim_impl.h"

/* State of a flight after tau under the constant acceleration a. */
static void
flight_at(double x, double v, double a, double tau, double *xo, double *vo)
{
	*xo = x + tau * (v + 0.5 * a * tau);
	*vo = v + a * tau;
}

/*
 * The first tau >= 0 after which max(x, v) < 0 (the state leaves C), for
 * x(tau) = x + v tau + a tau^2 / 2; INFINITY if it never does.
 */
static double
flight_event(double x, double v, double a)
{
	double best = INFINITY, r[2];
	int nr = 0, i;

	if (x <= 0 && v <= 0 && (x < 0 || v < 0 || a < 0) && (v < 0 || a < 0))
		return 0.0;
	/* roots of x(tau) = 0, stable form */
	if (a == 0.0) {
		if (v != 0.0)
			r[nr++] = -x / v;
	} else {
		double disc = v * v - 2.0 * a * x;

		if (disc >= 0.0) {
			double sq = sqrt(disc);
			double qq = -0.5 * (v + (v >= 0 ? sq : -sq));

			if (qq != 0.0) {
				r[nr++] = qq / (0.5 * a);
				r[nr++] = x / qq;
			} else {
				r[nr++] = 0.0;
			}
		}
	}
	for (i = 0; i < nr; i++)
		if (r[i] > 0.0 && v + a * r[i] < 0.0 && r[i] < best)
			best = r[i];
	/* v crossing zero downwards while x <= 0 */
	if (a < 0.0 && v > 0.0) {
		double tv = -v / a, xv, vv;

		flight_at(x, v, a, tv, &xv, &vv);
		if (xv <= 0.0 && tv < best)
			best = tv;
	}
	return best;
}

int
hbs_flight_closed(struct hb_sim *s)
{
	struct iface *I = s->I;
	const double T = s->sc.run.T;
	const double t0 = s->t, x0 = I->x, v0 = I->v;
	const double a = iface_Fer(s, I, t0) / I->m;
	const double Ee0 = I->Ee;
	double tau = flight_event(x0, v0, a), tend, tapex = INFINITY;
	int i, rc, it = 0;

	if (!isfinite(v0 * v0) || !isfinite(a * x0) || !isfinite(x0 + v0 * (T - t0))) {
		return hbs_fail(s, HB_ENUMERIC, "the flight overflows a double: v^2 and x + v T must be finite");
	}
	s->st.flights_closed++;
	tend = fmin(tau, T - t0);
	if (a != 0.0 && -v0 / a > 0.0 && -v0 / a < tend)
		tapex = -v0 / a;
	for (i = 1; i < FLIGHT_SAMPLES; i++) {
		double tk = tend * i / FLIGHT_SAMPLES;
		int kind = HB_ARC_STEP;

		if (tapex < tk) { /* the apex, an extremum of x */
			tk = tapex;
			tapex = INFINITY;
			i--;
			kind = HB_ARC_EXTREMUM;
		}
		if (tk <= 0.0)
			continue;
		s->t = t0 + tk;
		flight_at(x0, v0, a, s->t - t0, &I->x, &I->v);
		I->Ee = Ee0 + a * I->m * (I->x - x0);
		hbs_set_com(s);
		if ((rc = hbs_push_sample(s, kind)))
			return rc;
	}
	if (tau > T - t0) {
		s->t = T;
		flight_at(x0, v0, a, T - t0, &I->x, &I->v);
		I->Ee = Ee0 + a * I->m * (I->x - x0);
		hbs_set_com(s);
		if ((rc = hbs_push_sample(s, HB_ARC_END)))
			return rc;
		hbs_finish_T(s);
		return 0;
	}
	/* the event: place the state in D by the checker's test, ulp by ulp */
	{
		double te = t0 + tau, tprev, xp, vp;

		if (tau == 0.0)
			te = t0;
		flight_at(x0, v0, a, te - t0, &I->x, &I->v);
		while (!(I->x <= 0.0 && I->v <= 0.0) && it < 1000) {
			te = nextafter(te, INFINITY);
			flight_at(x0, v0, a, te - t0, &I->x, &I->v);
			it++;
		}
		if (!(I->x <= 0.0 && I->v <= 0.0))
			return hbs_fail(s, HB_ENUMERIC, "flight event could not be placed in D");
		tprev = te > t0 ? nextafter(te, -INFINITY) : te;
		flight_at(x0, v0, a, tprev - t0, &xp, &vp);
		s->t = te;
		I->Ee = Ee0 + a * I->m * (I->x - x0);
		hbs_set_com(s);
		return hbs_jump(s, tau == 0.0 ? HB_LOCATE_START : HB_LOCATE_CLOSED_FORM, it, te - tprev,
		            fmax(xp, vp), fmax(I->x, I->v));
	}
}
