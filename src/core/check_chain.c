/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * check_chain.c - the checks of a chain's run (check.h, hb_check_chain;
 * docs/chains.md section 5): its energy balance and momentum as
 * identities over its bodies, and each completed contact by its own
 * interface's law.  Read from the bodies, the interfaces' works and the
 * collision records, not from the clusters' ODE.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/check.h"
#include "hybounce/status.h"
#include "sim_impl.h"
#include "check_impl.h"

/* 1 if interface index i had a contact overlapping [te, ts] (the one in progress included). */
static int
in_contact_during(const struct hb_sim *s, int i, double te, double ts)
{
	size_t c;

	if (i < 0 || i >= s->nif)
		return 0;
	if (s->ifc[i].q && s->ifc[i].te < ts)
		return 1;
	for (c = 0; c < s->ncol; c++) {
		const struct hb_collision *o = &s->col[c];

		if (o->k == s->k0 + i && o->te < ts && o->ts > te)
			return 1;
	}
	return 0;
}

static void
check_contacts(const struct hb_sim *s, struct hb_check_chain *r, char *msg, size_t n)
{
	const double K = HB_CHECK_PHYS_FACTOR;
	/* thinned collisions would hide a neighbour's contact: e is then not checked */
	int whole = s->ncol_total == (long)s->ncol;
	size_t c;

	for (c = 0; c < s->ncol; c++) {
		const struct hb_collision *o = &s->col[c];
		int i = o->k - s->k0, passive, elastic;
		const struct iface *I;
		double Ei, eref, w, bound, dev;

		if (i < 0 || i >= s->nif)
			continue;
		I = &s->ifc[i];
		check_law_energy(I->law->name, &passive, &elastic);
		if (!passive)
			continue;
		r->ncontacts++;
		Ei = 0.5 * I->m * o->vi * o->vi;
		eref = fmax(Ei, o->Fcmax * o->xcmax);
		if (eref > 0.0) {
			/* the violation: elastic |W|, passive -W, relative */
			w = (elastic ? fabs(o->W) : -o->W) / eref;
			if (!(w <= r->wworst)) {
				r->wworst = isnan(w) ? INFINITY : w;
				r->wworst_at = o->i;
				r->wworst_k = o->k;
				r->W_at = o->W;
			}
		}
		/*
		 * e only where its relative motion felt its own force alone: no
		 * neighbour in contact during it, and an approach energy the
		 * run resolves (touching bodies begin a contact at v_i = 0), and
		 * not a touching pair pushed together (e NaN: sim_record.c).
		 */
		if (!whole || !(o->vi < 0.0) || !(Ei > r->tol * eref) || isnan(o->e) ||
		    in_contact_during(s, i - 1, o->te, o->ts) || in_contact_during(s, i + 1, o->te, o->ts))
			continue;
		r->nisolated++;
		bound = sqrt(1.0 + fabs(I->Fer) * o->xcr / Ei);
		dev = elastic ? fabs(o->e - bound) : o->e - bound;
		if (!(dev <= r->eworst)) {
			r->eworst = isnan(dev) ? INFINITY : dev;
			r->eworst_at = o->i;
			r->eworst_k = o->k;
			r->e_at = o->e;
			r->e_bound = bound;
		}
	}
	if (r->wworst_at >= 0 && !(r->wworst <= K * r->tol)) {
		const struct iface *I = &s->ifc[r->wworst_k - s->k0];
		int passive, elastic;

		check_law_energy(I->law->name, &passive, &elastic);
		r->failed++;
		if (elastic)
			check_append_msg(msg, n, "elastic law: collision %ld (interface %d) has "
			                 "W = %.6g J, %.3g of its energy scale, where %s dissipates "
			                 "nothing (at most %g x the tolerance %.3g accepted)", r->wworst_at,
			                 r->wworst_k, r->W_at, r->wworst, I->law->name, K, r->tol);
		else
			check_append_msg(msg, n, "passivity: collision %ld (interface %d) returns "
			                 "energy, W = %.6g J (%.3g of its energy scale), where %s can only "
			                 "absorb it (W >= 0 up to %g x the tolerance %.3g)", r->wworst_at,
			                 r->wworst_k, r->W_at, -r->wworst, I->law->name, K, r->tol);
	}
	if (r->eworst_at >= 0 && !(r->eworst <= K * r->tol)) {
		int passive, elastic;

		check_law_energy(s->ifc[r->eworst_k - s->k0].law->name, &passive, &elastic);
		r->failed++;
		check_append_msg(msg, n, "restitution: collision %ld (interface %d, no "
		                 "neighbour in contact) has e = %.9g where its law allows %s %.9g "
		                 "(at most %g x the tolerance %.3g off)", r->eworst_at, r->eworst_k,
		                 r->e_at, elastic ? "exactly" : "at most", r->e_bound, K, r->tol);
	}
}

static void
check_balance(const struct hb_sim *s, struct hb_check_chain *r, char *msg, size_t n)
{
	const double K = HB_CHECK_PHYS_FACTOR;
	double escale, pscale = 0.0, Fsum = 0.0, pabs = 0.0;
	int i;

	r->kinetic0 = r->kinetic = r->absorbed = r->stored = r->loads = 0.0;
	r->p0 = r->p = 0.0;
	for (i = 0; i < s->nbody; i++) {
		const struct body *b = &s->body[i];
		double y, u;

		hbs_body_at(s, i, &y, &u);
		r->kinetic0 += 0.5 * b->m * b->u0 * b->u0;
		r->kinetic += 0.5 * b->m * u * u;
		r->loads += b->Fe * (y - b->y0);
		r->p0 += b->m * b->u0;
		r->p += b->m * u;
		pabs = fmax(pabs, fmax(fabs(b->m * u), fabs(b->m * b->u0)));
		Fsum += b->Fe;
	}
	for (i = 0; i < s->nif; i++) {
		const struct iface *I = &s->ifc[i];

		r->absorbed -= I->Wc;
		/* the contact in progress: int F_c dx_c since it began, held in the interface */
		if (I->q)
			r->stored += I->Wc0 - I->Wc;
	}
	r->dissipated = r->absorbed - r->stored;
	r->impulse = r->t * Fsum;
	escale = fmax(fmax(r->kinetic0, r->kinetic), fmax(fabs(r->absorbed), fabs(r->loads)));
	r->eresid = escale > 0.0 ?
		fabs(r->kinetic + r->absorbed - r->kinetic0 - r->loads) / escale : 0.0;
	if (!(r->eresid <= K * r->tol)) {
		r->failed++;
		check_append_msg(msg, n, "energy: K + absorbed = %.12g J (K %.9g J, stored "
		                 "%.9g J, dissipated %.9g J) against K(0) + work of the loads = "
		                 "%.12g J at t = %.9g s, %.3g of the energy scale %.6g J (at most "
		                 "%g x the tolerance %.3g)", r->kinetic + r->absorbed, r->kinetic,
		                 r->stored, r->dissipated, r->kinetic0 + r->loads, r->t, r->eresid,
		                 escale, K, r->tol);
	}
	if (s->k0 == 0)
		return; /* a floor takes momentum */
	r->momentum = 1;
	pscale = fmax(pabs, fmax(fabs(r->p0), fmax(fabs(r->p), fabs(r->impulse))));
	r->presid = pscale > 0.0 ? fabs(r->p - r->p0 - r->impulse) / pscale : 0.0;
	if (!(r->presid <= K * r->tol)) {
		r->failed++;
		check_append_msg(msg, n, "momentum: %.12g kg m/s at t = %.9g s against "
		                 "%.12g at t = 0 plus the loads' impulse %.6g, %.3g of its scale "
		                 "%.6g kg m/s (at most %g x the tolerance %.3g)", r->p, r->t, r->p0,
		                 r->impulse, r->presid, pscale, K, r->tol);
	}
}

int
hb_check_chain(const struct hb_sim *s, struct hb_check_chain *r, char *msg, size_t n)
{
	const struct hb_arc_sample *last = hb_arc_last(s->arc);

	memset(r, 0, sizeof *r);
	if (msg != NULL && n > 0)
		msg[0] = '\0';
	if (!s->chain)
		return hb_status_set(msg, n, HB_EINVAL, "not a chain's run");
	r->tol = fmax(s->sc.run.rtol, s->sc.run.atol);
	r->t = last != NULL ? last->t : 0.0;
	r->wworst_at = r->eworst_at = -1;
	r->wworst = r->eworst = -INFINITY;
	r->eresid = r->presid = r->stored = r->dissipated = NAN;
	r->limnote = hb_sim_limits(s, &r->limits);
	check_contacts(s, r, msg, n);
	if (s->end != HB_SIM_END_FAIL && last != NULL && last->t == s->t)
		check_balance(s, r, msg, n);
	return r->failed ? HB_EINVAL : 0;
}
