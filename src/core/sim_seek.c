/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_seek.c - a run continued from one of its samples (sim.h:
 * hb_sim_seek), the same run after it, bit for bit.
 *
 * A pair's (one interface's) state is its sample: it is restored from it,
 * and the flow interval the sample is in goes on from there (hb_sim_seek,
 * at the end of this file).
 *
 * A chain's state at a sample is more than the sample: every body's
 * (y, u, tb), every interface's state, the clusters and their centres of
 * mass, the integrator's step and stiffness counts.  The engine is
 * deterministic, so the state is not kept but recomputed: the run is begun
 * again from t = 0 with its scene and advanced one unit of work at a time
 * (a flight, or one step of the clusters, each with the jump it may end
 * in) until it has pushed the sample.  A unit may push more samples after
 * it (a flight's, the post-jump sample after the pre-jump one, the end
 * after the last step); those, with the jump record and the collision
 * they come with, are kept aside and given back unchanged before any
 * further work (sim_pend.c), so that the run goes on as if it had not
 * been cut.  Until then the arc, the collisions and the end are as at the
 * sample, the simulator's t and j the sample's (hb_sim_body: the bodies at
 * that t on their parabolas); the contact in progress is not reported.
 * A seek within the last unit of work needs no replay.
 *
 * Cost: a seek back costs the run from t = 0 to the sample (the time it
 * took to compute); memory: the outputs of one unit of work (at most
 * FLIGHT_SAMPLES + 1 samples).  A thinned arc (run.max_samples) holds,
 * after a replay, the samples before the cut that it had thinned out: the
 * sample cut at may then have a greater index than it had.
 */
#include "sim_impl.h"
#include "sim_sample.h"

#include "cnum.h"

/* The sample of the last unit of work at (t, j) of this kind; hb_arc_len when none. */
static size_t
in_last_unit(const struct hb_sim *s, const struct hb_arc_sample *at)
{
	size_t n = hb_arc_len(s->arc), k;

	for (k = n - s->unit_n; k < n; k++) {
		const struct hb_arc_sample *a = hb_arc_at(s->arc, k);

		if (a->t == at->t && a->j == at->j && a->kind == at->kind)
			return k;
	}
	return n;
}

/* 1 when sample a is after (t, j) in hybrid-time order. */
static int
past(const struct hb_arc_sample *a, double t, long j)
{
	return a->j > j || (a->j == j && a->t > t);
}

/* A chain's seek: the run replayed from t = 0 to the unit of work that pushed sample i. */
static int
chain_seek(struct hb_sim *s, size_t i)
{
	struct hb_arc_sample at;
	size_t n;
	int rc;

	if ((rc = hbs_pend_flush(s)) != 0)
		return rc;
	n = hb_arc_len(s->arc);
	if (i >= n)
		return HB_EINVAL;
	at = *hb_arc_at(s->arc, i);
	if (i + s->unit_n < n) {
		/* before the last unit of work: the run again from t = 0 to the unit that pushes it */
		if (s->nbr > 0 || s->unrec_t >= 0) {
			snprintf(s->err, sizeof s->err, "a chain's run whose scene changed part-way "
			         "cannot be continued from an earlier sample");
			return HB_EINVAL;
		}
		hbs_reset_state(s);
		for (;;) {
			i = in_last_unit(s, &at);
			n = hb_arc_len(s->arc);
			if (i < n || past(hb_arc_last(s->arc), at.t, at.j) || s->end != HB_SIM_RUNNING)
				break;
			rc = hb_sim_advance(s, 1, 0.0);
			if (rc != HB_OK && rc != HB_EDONE)
				break;
		}
		if (i == n) {
			char tb[40], why[sizeof s->err];

			cnum_snprintf(tb, sizeof tb, "%.17g", at.t);
			memcpy(why, s->err, sizeof why);
			snprintf(s->err, sizeof s->err, "the chain's run replayed from t = 0 has no "
			         "sample at t = %s s, j = %ld%s%.400s", tb, at.j, why[0] ? ": " : "", why);
			return HB_EINVAL;
		}
	} else {
		hbs_branches_cut(s, i); /* a branch after the sample goes with what follows it */
	}
	if ((rc = hbs_pend_put_aside(s, i)) != 0) {
		snprintf(s->err, sizeof s->err, rc == HB_ENOMEM ? "out of memory for a seek"
		         : "a chain's unit of work has no jump record before its post-jump sample");
		return rc;
	}
	return 0;
}

/*
 * hb_sim_seek: a pair's run (one interface) goes on from the sample itself,
 * which holds its whole state; the flow interval is resumed from inside
 * (sim.c's resume_interval) unless the sample is a pre-jump one.
 */
int
hb_sim_seek(struct hb_sim *s, size_t i)
{
	struct iface *I = s->I;
	const struct hb_arc_sample *a;
	const struct hb_arc_interval *iv;

	if (s->chain) /* replayed to the sample (sim_seek.c) */
		return chain_seek(s, i);
	if (i >= hb_arc_len(s->arc))
		return HB_EINVAL;
	hbs_branches_cut(s, i);
	/*
	 * The step to continue with: the one the controller proposes where the
	 * simulator stands at that sample (an edit at the run's end, a seek
	 * to it), else the one the run took from that sample.
	 */
	s->resume_h = 0.0;
	if (i + 1 < hb_arc_len(s->arc) && hb_arc_at(s->arc, i + 1)->j == hb_arc_at(s->arc, i)->j)
		s->resume_h = hb_arc_at(s->arc, i + 1)->t - hb_arc_at(s->arc, i)->t;
	else if (i + 1 == hb_arc_len(s->arc) && s->end == HB_SIM_RUNNING && !s->setup
	         && s->t == hb_arc_at(s->arc, i)->t && s->j == hb_arc_at(s->arc, i)->j && s->h > 0)
		s->resume_h = s->h;
	arc_truncate(s->arc, i + 1);
	a = hb_arc_at(s->arc, i);
	iv = hb_arc_interval_at(s->arc, hb_arc_interval_of(s->arc, i));
	/* continuing inside the interval (not at its pre-jump end) */
	s->resume = a->kind != HB_ARC_PRE_JUMP;
	s->resume_first = iv->first;
	s->resume_last = i;
	s->t = a->t;
	s->j = a->j;
	hbs_sample_get(I, s, a); /* the state the sample holds (sim_sample.h), then what follows from it */
	I->Wc0 = a->Wc + a->W;
	I->xe = a->x - a->xc;
	if (I->q) {
		const struct hb_arc_sample *f = hb_arc_at(s->arc, iv->first);

		I->te = f->t;
		I->vi = f->v;
	}
	while (s->ncol > 0 && s->col[s->ncol - 1].j >= s->j)
		s->ncol--;
	s->ncol_total = s->ncol > 0 ? s->col[s->ncol - 1].i + 1 : 0;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 >= s->j && !I->q)
		s->col[s->ncol - 1].tf = NAN;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 == s->j)
		s->col[s->ncol - 1].tf = NAN;
	for (int k = 0; k < s->nif; k++)
		s->ifc[k].ninst = 0;
	s->err[0] = s->endmsg[0] = '\0';
	s->end = HB_SIM_RUNNING;
	s->setup = 1;
	if (s->t >= s->sc.run.T)
		hbs_finish_T(s);
	else if (s->j >= s->sc.run.J)
		hbs_finish_J(s);
	return 0;
}
