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
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hybounce/fit.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "fit_impl.h"
#include "clock.h"
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
	size_t unit;     /* trial (sequences, heights) or drop row */
	int fail;
	double cpu;      /* CPU seconds of the run, on its thread */
	char msg[384];
};

struct pool {
	const struct hb_fit_data *d;
	const size_t *pidx; /* the point of each value (fit_points) */
	struct task *t;
	size_t ntask, next;
	size_t npts;
	double penalty;
	double *out;
	pthread_mutex_t lock;
};

/* "trial 3: " when the data hold several, else "". */
static void
trial_prefix(const struct hb_fit_data *d, size_t k, char *buf, size_t n)
{
	if (d->ntrials > 1)
		snprintf(buf, n, "trial %zu: ", k + 1);
	else
		buf[0] = '\0';
}

/*
 * The run of one trial of a sequence (impact times) or of heights (from
 * rest at h_0): stops at the jump cap after the collisions the trial needs.
 */
static void
run_trial(struct pool *pl, struct task *tk)
{
	const struct hb_fit_data *d = pl->d;
	const int heights = d->kind == HB_FIT_HEIGHTS;
	const int ob = heights ? HB_FIT_OBS_H : HB_FIT_OBS_TE;
	const double *v = d->col[ob];
	size_t a = d->trial_row[tk->unit], b = d->trial_row[tk->unit + 1];
	/* collisions needed: the impacts of the trial, or those before its last apex */
	size_t need = heights ? b - a - 1 : b - a, nc, r = a;
	struct hb_scene sc = *tk->sc;
	double *o = pl->out + (size_t)tk->s * pl->npts;
	const size_t *pi = pl->pidx + (size_t)ob * d->n;
	struct hb_collision live = { 0 };
	int have_live;
	struct hb_sim *s;
	char m[256], tp[32];

	trial_prefix(d, tk->unit, tp, sizeof tp);
	if (heights) {
		double g = sc.loads.g, fall = g > 0 ? sqrt(2 * v[a] / g) : 0;

		sc.init.x0 = v[a];
		sc.init.v0 = 0;
		/* every flight is at most twice the fall from h_0 */
		if (sc.run.T < 10 * fall * (double)(2 * need + 1) + 1)
			sc.run.T = 10 * fall * (double)(2 * need + 1) + 1;
	} else {
		double span;

		while (isnan(v[r]))
			r++;
		span = v[b - 1] - v[r];
		for (size_t i = b - 1; isnan(v[i]); i--)
			span = v[i - 1] - v[r];
		if (sc.run.T < 10 * span + 1)
			sc.run.T = 10 * span + 1; /* room for the fall before the first impact */
	}
	sc.run.J = 2 * (long)need;
	for (size_t i = a; i < b; i++)
		if (pi[i] != SIZE_MAX)
			o[pi[i]] = pl->penalty;
	if (heights && !(sc.loads.g > 0)) {
		tk->fail = 1;
		cnum_snprintf(tk->msg, sizeof tk->msg, "%sloads.g = %g m/s^2: no apex", tp, sc.loads.g);
		return;
	}
	if ((s = hb_sim_new(&sc, m, sizeof m)) == NULL) {
		tk->fail = 1;
		snprintf(tk->msg, sizeof tk->msg, "%s%s", tp, m);
		return;
	}
	if (hb_sim_advance(s, STEPS_PER_COLLISION * (long)(need + 1), 0) != HB_OK) {
		tk->fail = 1;
		snprintf(tk->msg, sizeof tk->msg, "%s%s", tp, hb_sim_errmsg(s));
	}
	nc = hb_sim_ncollisions(s);
	/*
	 * A run that ends in permanent contact has all its later impacts at the
	 * commencement of that contact, and no rebound after it: as a flight
	 * shrinks to nothing the impacts after it merge there, so the
	 * residuals stay continuous in the parameters.
	 */
	/* (a run with no completed collision reproduces none: it fails below) */
	have_live = nc > 0 && nc < need && !tk->fail && hb_sim_contact_live(s, &live);
	if (nc < need && !have_live && !tk->fail) {
		tk->fail = 1;
		if (nc == 0)
			snprintf(tk->msg, sizeof tk->msg, "%sthe run has no collision (%s)", tp,
			    hb_sim_end_str(s));
		else
			snprintf(tk->msg, sizeof tk->msg, "%sthe run gives %zu collision%s (%s), the "
			    "data %s %zu", tp, nc, nc == 1 ? "" : "s", hb_sim_end_str(s),
			    heights ? "need" : "has", need);
	}
	if (!tk->fail && heights) {
		for (size_t i = a + 1; i < b; i++) {
			size_t c = i - a - 1; /* the apex after impact c */
			double vs = 0;

			if (pi[i] == SIZE_MAX)
				continue;
			if (c < nc)
				vs = hb_sim_collision(s, c)->e * hb_sim_collision(s, c)->vi;
			o[pi[i]] = vs * vs / (2 * sc.loads.g);
		}
	} else if (!tk->fail) {
		size_t cr = r - a;
		double t0 = cr < nc ? hb_sim_collision(s, cr)->te : live.te;

		for (size_t i = r + 1; i < b; i++) {
			size_t c = i - a;

			if (pi[i] != SIZE_MAX)
				o[pi[i]] = (c < nc ? hb_sim_collision(s, c)->te : live.te) - t0;
		}
	}
	hb_sim_free(s);
}

/* The run of one drop: from contact at v_i, stopped after its separation. */
static void
run_drop(struct pool *pl, struct task *tk)
{
	const struct hb_fit_data *d = pl->d;
	struct hb_scene sc = *tk->sc;
	size_t r = tk->unit;
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
	for (int ob = HB_FIT_OBS_E; ob < HB_FIT_OBS_COUNT; ob++) {
		size_t k = pl->pidx[(size_t)ob * d->n + r];

		if (k != SIZE_MAX)
			o[k] = have && !tk->fail ? v[ob] : pl->penalty;
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
		double t0 = clock_seconds(CLOCK_THREAD_CPUTIME_ID);

		if (pl->d->kind != HB_FIT_DROPS)
			run_trial(pl, &pl->t[i]);
		else
			run_drop(pl, &pl->t[i]);
		pl->t[i].cpu = clock_seconds(CLOCK_THREAD_CPUTIME_ID) - t0;
	}
}

/*
 * The wall time of the runs had each thread a core of its own: threads
 * take the tasks in order, each the next when it is free (as worker does).
 */
static double
makespan(const struct task *t, size_t n, int nth)
{
	double free_at[64] = { 0 }, end = 0;

	for (size_t i = 0; i < n; i++) {
		int k = 0;

		for (int j = 1; j < nth; j++)
			if (free_at[j] < free_at[k])
				k = j;
		free_at[k] += t[i].cpu;
		end = fmax(end, free_at[k]);
	}
	return end;
}

int
fit_eval(const struct hb_scene *sc, int nsc, const struct hb_fit_data *d, int jobs,
         double penalty, double *out, int *fail, long *runs, double *cpu, double *span,
         char *msg, size_t n)
{
	struct pool pl;
	size_t per = d->kind == HB_FIT_DROPS ? d->n : d->ntrials;
	size_t *pidx = malloc(((size_t)HB_FIT_OBS_COUNT * d->n + 1) * sizeof *pidx);
	pthread_t th[64];
	int nth, started = 0;

	memset(&pl, 0, sizeof pl);
	pl.d = d;
	pl.npts = hb_fit_npoints(d);
	pl.penalty = penalty;
	pl.out = out;
	pl.ntask = (size_t)nsc * per;
	if (pidx == NULL || (pl.t = calloc(pl.ntask ? pl.ntask : 1, sizeof *pl.t)) == NULL) {
		free(pidx);
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	fit_points(d, NULL, pidx, NULL);
	pl.pidx = pidx;
	for (size_t i = 0; i < pl.ntask; i++) {
		pl.t[i].s = (int)(i / per);
		pl.t[i].sc = &sc[i / per];
		pl.t[i].unit = i % per;
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
	for (size_t i = 0; cpu != NULL && i < pl.ntask; i++)
		*cpu += pl.t[i].cpu;
	if (span != NULL)
		*span += makespan(pl.t, pl.ntask, nth > 0 ? nth : 1);
	free(pl.t);
	free(pidx);
	return HB_OK;
}
