/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_flight.c - flight in closed form: the parabola, its event by a quadratic, the
 * pre-jump state placed in D ulp by ulp (see sim.c for the method); a
 * chain's flight, every body on its parabola and the earliest of its
 * interfaces' events.
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
double
hbs_flight_event(double x, double v, double a)
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
	double tau = hbs_flight_event(x0, v0, a), tend, tapex = INFINITY;
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

/* The event interface's gap at t, with its work since the flight began and its pair's centre of mass. */
static void
chain_iface_at(struct hb_sim *s, double t, double x0, double Ee0)
{
	struct iface *I = s->I;

	s->t = t;
	hbs_chain_gap(s, s->ia, t, &I->x, &I->v);
	I->Ee = Ee0 + I->Fer * (I->x - x0);
	hbs_chain_pair_com(s);
}

/*
 * A flight of a chain (no interface in contact, constant loads): every
 * body on its parabola; the event is the earliest of the interfaces'
 * (the lowest one of those at the same instant), each found by
 * hbs_flight_event on its gap, whose acceleration is the difference of its
 * bodies'.  The interface of the event is the one the interval records;
 * only its bodies are evaluated along the flight, and set where the event
 * places them.
 */
int
hbs_chain_flight(struct hb_sim *s)
{
	const double T = s->sc.run.T, t0 = s->t;
	double best = INFINITY, x0, v0, Ee0, tend;
	int i, k = -1, rc, it = 0;

	for (i = 0; i < s->nif; i++) {
		const struct iface *J = &s->ifc[i];
		double x, v, a = s->body[J->hi].a - (J->lo >= 0 ? s->body[J->lo].a : 0.0), tau;

		hbs_chain_gap(s, i, t0, &x, &v);
		if (!isfinite(v * v) || !isfinite(x + v * (T - t0)))
			return hbs_fail(s, HB_ENUMERIC, "the flight overflows a double: v^2 and x + v T must be finite");
		tau = hbs_flight_event(x, v, a);
		if (tau < best) {
			best = tau;
			k = i;
		}
	}
	if (k >= 0)
		hbs_chain_activate(s, k);
	hbs_chain_gap(s, s->ia, t0, &x0, &v0);
	Ee0 = s->I->Ee;
	s->st.flights_closed++;
	tend = fmin(best, T - t0);
	for (i = 1; i < FLIGHT_SAMPLES; i++) {
		double tk = tend * i / FLIGHT_SAMPLES;

		if (tk <= 0.0)
			continue;
		chain_iface_at(s, t0 + tk, x0, Ee0);
		if ((rc = hbs_push_sample(s, HB_ARC_STEP)))
			return rc;
	}
	if (best > T - t0) {
		chain_iface_at(s, T, x0, Ee0);
		if ((rc = hbs_push_sample(s, HB_ARC_END)))
			return rc;
		hbs_finish_T(s);
		return 0;
	}
	/* the event: the state placed in D by the checker's test, ulp by ulp */
	{
		struct iface *I = s->I;
		double te = t0 + best, tprev, xp, vp;

		hbs_chain_gap(s, s->ia, te, &I->x, &I->v);
		while (!(I->x <= 0.0 && I->v <= 0.0) && it < 1000) {
			te = nextafter(te, INFINITY);
			hbs_chain_gap(s, s->ia, te, &I->x, &I->v);
			it++;
		}
		if (!(I->x <= 0.0 && I->v <= 0.0))
			return hbs_fail(s, HB_ENUMERIC, "flight event could not be placed in D");
		tprev = te > t0 ? nextafter(te, -INFINITY) : te;
		hbs_chain_gap(s, s->ia, tprev, &xp, &vp);
		hbs_chain_settle(s, s->ia, te);
		chain_iface_at(s, te, x0, Ee0);
		return hbs_jump(s, best == 0.0 ? HB_LOCATE_START : HB_LOCATE_CLOSED_FORM, it, te - tprev,
		                fmax(xp, vp), fmax(I->x, I->v));
	}
}
