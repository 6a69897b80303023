/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_eval.c - the simulated observables of a data set: one run per
 * bouncing sequence, one run per drop, spread over threads.
 *
 * Each run has its own scene copy and its own sim (the simulator keeps no
 * global state), so runs are independent; a thread takes the next task from
 * a shared counter until none is left.  Results land in caller memory at
 * fixed places, so the order in which the threads finish does not matter
 * and the output is the same for any number of threads.
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hybounce/fit.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "fit_impl.h"
#include "cnum.h"

/*
 * Accepted steps a run may take per collision of the data before it is cut
 * short (a contact takes 100 to 400): a trial point where the ball sticks
 * then costs no more than a few bounces, and the cut is deterministic.
 */
#define STEPS_PER_COLLISION 5000

struct task {
	const struct hb_scene *sc;
	int s;           /* scene index */
	long row;        /* drop row, or -1 for the sequence */
	int fail;
	char msg[384];
};

struct pool {
	const struct hb_fit_data *d;
	struct task *t;
	size_t ntask, next;
	size_t npts;
	double penalty;
	double *out;
	pthread_mutex_t lock;
};

/* The run of a sequence: stops at the jump cap after the last collision. */
static void
run_sequence(struct pool *pl, struct task *tk)
{
	const struct hb_fit_data *d = pl->d;
	struct hb_scene sc = *tk->sc;
	double *o = pl->out + (size_t)tk->s * pl->npts;
	double span = d->col[HB_FIT_OBS_TE][d->n - 1] - d->col[HB_FIT_OBS_TE][0];
	struct hb_sim *s;
	size_t nc;
	char m[256];

	sc.run.J = 2 * (long)d->n;
	if (sc.run.T < 10 * span + 1)
		sc.run.T = 10 * span + 1; /* room for the fall before the first impact */
	for (size_t k = 0; k < pl->npts; k++)
		o[k] = pl->penalty;
	if ((s = hb_sim_new(&sc, m, sizeof m)) == NULL) {
		tk->fail = 1;
		snprintf(tk->msg, sizeof tk->msg, "%s", m);
		return;
	}
	if (hb_sim_advance(s, STEPS_PER_COLLISION * (long)(d->n + 1), 0) != HB_OK) {
		tk->fail = 1;
		snprintf(tk->msg, sizeof tk->msg, "%s", hb_sim_errmsg(s));
	}
	nc = hb_sim_ncollisions(s);
	if (nc > 0) {
		double t0 = hb_sim_collision(s, 0)->te;
		struct hb_collision live;

		for (size_t i = 1; i < d->n && i < nc; i++)
			o[i - 1] = hb_sim_collision(s, i)->te - t0;
		/*
		 * A run that ends in permanent contact has all its later impacts
		 * at the commencement of that contact: as a flight shrinks to
		 * nothing the impacts after it merge there, so the residuals stay
		 * continuous in the parameters.
		 */
		if (nc < d->n && !tk->fail && hb_sim_contact_live(s, &live))
			for (size_t i = nc; i < d->n; i++)
				o[i - 1] = live.te - t0;
		else if (nc < d->n && !tk->fail) {
			tk->fail = 1;
			snprintf(tk->msg, sizeof tk->msg, "the run gives %zu collision%s (%s), the "
			    "data has %zu", nc, nc == 1 ? "" : "s", hb_sim_end_str(s), d->n);
		}
	} else if (!tk->fail) {
		tk->fail = 1;
		snprintf(tk->msg, sizeof tk->msg, "the run has no collision (%s)", hb_sim_end_str(s));
	}
	hb_sim_free(s);
}

/* The run of one drop: from contact at v_i, stopped after its separation. */
static void
run_drop(struct pool *pl, struct task *tk)
{
	const struct hb_fit_data *d = pl->d;
	struct hb_scene sc = *tk->sc;
	size_t r = (size_t)tk->row, k = 0;
	double *o = pl->out + (size_t)tk->s * pl->npts;
	double v[HB_FIT_OBS_COUNT] = { 0 };
	struct hb_collision c = { 0 };
	struct hb_sim *s;
	char m[256];
	int have = 0;

	sc.init.x0 = 0;
	sc.init.v0 = d->vi[r];
	sc.run.J = 2;
	if ((s = hb_sim_new(&sc, m, sizeof m)) == NULL) {
		tk->fail = 1;
		cnum_snprintf(tk->msg, sizeof tk->msg, "drop %zu (v_i = %g m/s): %s", r + 1, d->vi[r], m);
	} else {
		if (hb_sim_advance(s, STEPS_PER_COLLISION, 0) != HB_OK) {
			tk->fail = 1;
			cnum_snprintf(tk->msg, sizeof tk->msg, "drop %zu (v_i = %g m/s): %s", r + 1,
			    d->vi[r], hb_sim_errmsg(s));
		} else if (hb_sim_ncollisions(s) > 0) {
			c = *hb_sim_collision(s, 0);
			have = 1;
		} else if (hb_sim_contact_live(s, &c)) {
			/* no separation by T or within the budget: the ball stays
			   (x_c^r and t_d so far) */
			c.e = 0;
			have = 1;
		} else {
			tk->fail = 1;
			cnum_snprintf(tk->msg, sizeof tk->msg, "drop %zu (v_i = %g m/s): no contact (%s)",
			    r + 1, d->vi[r], hb_sim_end_str(s));
		}
		hb_sim_free(s);
	}
	v[HB_FIT_OBS_E] = c.e;
	v[HB_FIT_OBS_XCR] = c.xcr;
	v[HB_FIT_OBS_TD] = c.td;
	/* points are ordered observable by observable, then row by row */
	for (int ob = HB_FIT_OBS_E; ob < HB_FIT_OBS_COUNT; ob++) {
		if (d->col[ob] == NULL)
			continue;
		o[k + r] = have && !tk->fail ? v[ob] : pl->penalty;
		k += d->n;
	}
}

static void *
worker(void *arg)
{
	struct pool *pl = arg;

	for (;;) {
		size_t i;

		pthread_mutex_lock(&pl->lock);
		i = pl->next++;
		pthread_mutex_unlock(&pl->lock);
		if (i >= pl->ntask)
			return NULL;
		if (pl->t[i].row < 0)
			run_sequence(pl, &pl->t[i]);
		else
			run_drop(pl, &pl->t[i]);
	}
}

int
fit_eval(const struct hb_scene *sc, int nsc, const struct hb_fit_data *d, int jobs,
         double penalty, double *out, int *fail, long *runs, char *msg, size_t n)
{
	struct pool pl;
	size_t per = d->kind == HB_FIT_SEQUENCE ? 1 : d->n;
	pthread_t th[64];
	int nth, started = 0;

	memset(&pl, 0, sizeof pl);
	pl.d = d;
	pl.npts = hb_fit_npoints(d);
	pl.penalty = penalty;
	pl.out = out;
	pl.ntask = (size_t)nsc * per;
	if ((pl.t = calloc(pl.ntask, sizeof *pl.t)) == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	for (size_t i = 0; i < pl.ntask; i++) {
		pl.t[i].s = (int)(i / per);
		pl.t[i].sc = &sc[i / per];
		pl.t[i].row = d->kind == HB_FIT_SEQUENCE ? -1 : (long)(i % per);
	}
	if (jobs <= 0) {
		long nc = sysconf(_SC_NPROCESSORS_ONLN);

		jobs = nc > 0 ? (int)nc : 1;
	}
	nth = jobs < 64 ? jobs : 64;
	if ((size_t)nth > pl.ntask)
		nth = (int)pl.ntask;
	pthread_mutex_init(&pl.lock, NULL);
	/* the calling thread works too; a thread that cannot start is not needed */
	for (int i = 1; i < nth; i++)
		if (pthread_create(&th[started], NULL, worker, &pl) == 0)
			started++;
	worker(&pl);
	for (int i = 0; i < started; i++)
		pthread_join(th[i], NULL);
	pthread_mutex_destroy(&pl.lock);

	if (fail != NULL)
		for (int s = 0; s < nsc; s++)
			fail[s] = 0;
	if (msg != NULL && n > 0)
		msg[0] = '\0';
	for (size_t i = 0; i < pl.ntask; i++) {
		if (!pl.t[i].fail)
			continue;
		if (fail != NULL)
			fail[pl.t[i].s] = 1;
		if (msg != NULL && n > 0 && msg[0] == '\0')
			snprintf(msg, n, "%s", pl.t[i].msg);
	}
	if (runs != NULL)
		*runs += (long)pl.ntask;
	free(pl.t);
	return HB_OK;
}
