/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_curve.c - one observable over one parameter, computed by
 * background threads for the explorer (see sweep.h, "Curves").
 *
 * The curve is a one-axis sweep: the same point scenes as hb_sweep_run, run
 * by hb_sim_advance in slices of SLICE_STEPS accepted steps so that a worker
 * sees a cancellation within one slice.  Results go into arrays under a
 * mutex; hb_sweep_curve_poll copies them and never waits for a point.
 *
 * Boundaries (hb_sweep_curve_start_refined).  Once two neighbouring points
 * are done and their classes differ (as --refine classes them:
 * sweep_refine_class, the observable's existence, or a whole observable's
 * value), the interval is a bracket; a worker with no point left takes a
 * bracket and bisects it on the lattice of the range (sweep_refine.c: the
 * points of FROM:TO:M, every one bit-identical to that uniform sweep) until
 * its ends are one lattice step apart.  A midpoint of a third class splits
 * the bracket in two.  The midpoints are not points of the curve.
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "csv_impl.h"
#include "sweep_impl.h"
#include "cnum.h"

#define SLICE_STEPS 2000
#define CURVE_MAX_JOBS 64

/* The per-collision observables; the run observables are named by their table. */
static const char *const obs_names[HB_CURVE_RUN] = { "e", "v_i", "x_c_r" };

struct bracket {
	long lo, hi;         /* lattice ids */
	long clo, chi;       /* their classes */
	int busy;            /* a worker is bisecting it */
};

struct hb_sweep_curve {
	struct hb_sweep *sw;
	struct hb_sweep *fine;      /* the lattice (refined), or NULL */
	struct sweep_refine rf;     /* its classes */
	long *cls;                  /* each point's class, once done */
	struct bracket *br;
	long nbr, capbr;
	char key[48];
	int obs;
	long coll_i, np;
	double *x, *y;
	int *state;
	long next, done;
	int stop;
	pthread_mutex_t mu;
	pthread_t th[CURVE_MAX_JOBS];
	int nth;
};

const char *
hb_sweep_observable_name(int obs)
{
	if (obs >= HB_CURVE_RUN && obs < HB_CURVE_COUNT)
		return hb_observables[obs - HB_CURVE_RUN].name;
	return obs >= 0 && obs < HB_CURVE_RUN ? obs_names[obs] : NULL;
}

/* The kept collision numbered i among all, or NULL (none, or thinned out). */
static const struct hb_collision *
collision_numbered(const struct hb_sim *s, long i)
{
	size_t lo = 0, hi = hb_sim_ncollisions(s);

	while (lo < hi) { /* the kept ones are in increasing i */
		size_t mid = lo + (hi - lo) / 2;
		const struct hb_collision *c = hb_sim_collision(s, mid);

		if (c->i == i)
			return c;
		if (c->i < i)
			lo = mid + 1;
		else
			hi = mid;
	}
	return NULL;
}

double
hb_sweep_observe(const struct hb_sim *s, int obs, long i)
{
	const struct hb_collision *c;

	if (obs >= HB_CURVE_RUN)
		return hb_observable_value(s, obs - HB_CURVE_RUN);
	c = collision_numbered(s, i);
	switch (obs) {
	case HB_CURVE_E: return c ? c->e : NAN;
	case HB_CURVE_VI: return c ? c->vi : NAN;
	case HB_CURVE_XCR: return c ? c->xcr : NAN;
	default: return NAN;
	}
}

/*
 * Runs point id of sw in slices; *y and *st its observable and state.
 * Returns 1 when the curve was stopped meanwhile.
 */
static int
curve_point(struct hb_sweep_curve *c, const struct hb_sweep *sw, long id, double *y, int *st)
{
	struct hb_scene sc;
	struct hb_sim *s = NULL;
	char m[256];
	int stop = 0;

	*y = NAN;
	*st = HB_CURVE_FAILED;
	if (hb_sweep_point_scene(sw, id, &sc, m, sizeof m) == HB_OK)
		s = hb_sim_new(&sc, m, sizeof m);
	while (s != NULL && hb_sim_end(s) == HB_SIM_RUNNING) {
		if (hb_sim_advance(s, SLICE_STEPS, 0) != HB_OK)
			break;
		pthread_mutex_lock(&c->mu);
		stop = c->stop;
		pthread_mutex_unlock(&c->mu);
		if (stop)
			break;
	}
	if (s != NULL && !stop && hb_sim_end(s) != HB_SIM_RUNNING) {
		*y = hb_sweep_observe(s, c->obs, c->coll_i);
		*st = hb_sim_end(s) == HB_SIM_END_FAIL ? HB_CURVE_FAILED : HB_CURVE_DONE;
	}
	hb_sim_free(s);
	return stop;
}

static long
curve_class(const struct hb_sweep_curve *c, double y, int st)
{
	return sweep_refine_class(&c->rf, y, st == HB_CURVE_FAILED);
}

/* A bracket lo..hi (lattice ids) of classes clo, chi (under c->mu). */
static void
bracket_add(struct hb_sweep_curve *c, long lo, long hi, long clo, long chi)
{
	if (c->nbr == c->capbr) {
		long nc = c->capbr ? 2 * c->capbr : 16;
		struct bracket *nb = realloc(c->br, (size_t)nc * sizeof *nb);

		if (nb == NULL)
			return;   /* out of memory: that boundary is not shown */
		c->br = nb;
		c->capbr = nc;
	}
	c->br[c->nbr++] = (struct bracket){ lo, hi, clo, chi, 0 };
}

/* Point id is done: the intervals to its neighbours that are done and differ (under c->mu). */
static void
brackets_around(struct hb_sweep_curve *c, long id)
{
	for (long j = id - 1; j <= id + 1; j += 2) {
		long a = j < id ? j : id, b = a + 1;

		if (j < 0 || j >= c->np || c->state[j] == HB_CURVE_PENDING || c->cls[a] == c->cls[b])
			continue;
		bracket_add(c, a * c->rf.step, b * c->rf.step, c->cls[a], c->cls[b]);
	}
}

/* Bisects bracket k to one lattice step (taken busy, under c->mu on entry and exit). */
static int
bisect(struct hb_sweep_curve *c, long k)
{
	while (c->br[k].hi - c->br[k].lo > 1) {
		long mid = c->br[k].lo + (c->br[k].hi - c->br[k].lo) / 2, cm;
		double y;
		int st;

		pthread_mutex_unlock(&c->mu);
		if (curve_point(c, c->fine, mid, &y, &st)) {
			pthread_mutex_lock(&c->mu);
			return 1;
		}
		cm = curve_class(c, y, st);
		pthread_mutex_lock(&c->mu);
		if (cm == c->br[k].clo) {
			c->br[k].lo = mid;
		} else if (cm == c->br[k].chi) {
			c->br[k].hi = mid;
		} else {
			/* a third class: a boundary on each side */
			long hi = c->br[k].hi, chi = c->br[k].chi;

			c->br[k].hi = mid;
			c->br[k].chi = cm;
			bracket_add(c, mid, hi, cm, chi);
		}
	}
	c->br[k].busy = 0;
	return 0;
}

static void *
curve_worker(void *arg)
{
	struct hb_sweep_curve *c = arg;

	for (;;) {
		long id, k;
		int st;
		double y;

		pthread_mutex_lock(&c->mu);
		if (c->stop) {
			pthread_mutex_unlock(&c->mu);
			return NULL;
		}
		if (c->next >= c->np) {
			/* no point left: a bracket to bisect, if any */
			for (k = 0; c->fine != NULL && k < c->nbr; k++)
				if (!c->br[k].busy && c->br[k].hi - c->br[k].lo > 1)
					break;
			if (c->fine == NULL || k == c->nbr) {
				pthread_mutex_unlock(&c->mu);
				return NULL;
			}
			c->br[k].busy = 1;
			if (bisect(c, k)) {
				pthread_mutex_unlock(&c->mu);
				return NULL;
			}
			pthread_mutex_unlock(&c->mu);
			continue;
		}
		id = c->next++;
		pthread_mutex_unlock(&c->mu);

		if (curve_point(c, c->sw, id, &y, &st))
			return NULL;
		pthread_mutex_lock(&c->mu);
		c->y[id] = y;
		c->state[id] = st;
		c->done++;
		if (c->fine != NULL) {
			c->cls[id] = curve_class(c, y, st);
			brackets_around(c, id);
		}
		pthread_mutex_unlock(&c->mu);
	}
}

void
hb_sweep_curve_free(struct hb_sweep_curve *c)
{
	if (c == NULL)
		return;
	pthread_mutex_lock(&c->mu);
	c->stop = 1;
	pthread_mutex_unlock(&c->mu);
	for (int i = 0; i < c->nth; i++)
		pthread_join(c->th[i], NULL);
	pthread_mutex_destroy(&c->mu);
	hb_sweep_free(c->sw);
	hb_sweep_free(c->fine);
	free(c->cls);
	free(c->br);
	free(c->x);
	free(c->y);
	free(c->state);
	free(c);
}

struct hb_sweep_curve *
hb_sweep_curve_start(const struct hb_scene *base, const char *key, const char *spec, int obs,
                  long coll_i, int jobs, char *msg, size_t n)
{
	return hb_sweep_curve_start_refined(base, key, spec, obs, coll_i, 0, jobs, msg, n);
}

struct hb_sweep_curve *
hb_sweep_curve_start_refined(const struct hb_scene *base, const char *key, const char *spec,
                             int obs, long coll_i, double tol, int jobs, char *msg, size_t n)
{
	struct hb_sweep_curve *c;
	char arg[512], v[64];

	if (obs < 0 || obs >= HB_CURVE_COUNT) {
		hb_status_set(msg, n, HB_EINVAL, "observable %d: accepted: e, v_i, x_c_r, "
		           "collisions, t_pc, x_c_r_total", obs);
		return NULL;
	}
	if (strlen(key) >= sizeof c->key) {
		hb_status_set(msg, n, HB_EINVAL, "%s: unknown key", key);
		return NULL;
	}
	c = calloc(1, sizeof *c);
	if (c == NULL || (c->sw = hb_sweep_new(base, msg, n)) == NULL) {
		free(c);
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	pthread_mutex_init(&c->mu, NULL);
	snprintf(c->key, sizeof c->key, "%s", key);
	c->obs = obs;
	c->coll_i = coll_i;
	snprintf(arg, sizeof arg, "%s=%s", key, spec);
	/* A view needs a few thousand points at most: a range of 10^9 would
	 * freeze the caller while its values are made. */
	hb_sweep_set_max_points(c->sw, HB_SWEEP_CURVE_MAX_POINTS, "a curve shows at most that "
	                        "many: choose a smaller N");
	if (hb_sweep_vary(c->sw, arg, msg, n) != HB_OK || hb_sweep_check(c->sw, msg, n) != HB_OK) {
		hb_sweep_curve_free(c);
		return NULL;
	}
	c->np = hb_sweep_npoints(c->sw);
	if (tol > 0) {
		/* The lattice of the range (the classes: those of obs, as --refine's) */
		char rs[64];

		cnum_snprintf(rs, sizeof rs, "collisions:%.17g", tol);
		if ((c->fine = hb_sweep_new(base, msg, n)) == NULL ||
		    hb_sweep_vary(c->fine, arg, msg, n) != HB_OK ||
		    hb_sweep_refine(c->fine, rs, msg, n) != HB_OK ||
		    (c->cls = calloc((size_t)c->np, sizeof *c->cls)) == NULL) {
			if (c->fine != NULL && c->cls == NULL && msg != NULL && strstr(msg, "refine") == NULL)
				hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			hb_sweep_curve_free(c);
			return NULL;
		}
		c->rf = c->fine->rf;
		c->rf.op = 0;
		c->rf.obs = obs >= HB_CURVE_RUN ? obs - HB_CURVE_RUN : HB_OBS_T_PC; /* existence */
	}
	c->x = malloc((size_t)c->np * sizeof *c->x);
	c->y = malloc((size_t)c->np * sizeof *c->y);
	c->state = calloc((size_t)c->np, sizeof *c->state);
	if (c->x == NULL || c->y == NULL || c->state == NULL) {
		hb_sweep_curve_free(c);
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	for (long i = 0; i < c->np; i++) {
		hb_sweep_point_value(c->sw, i, 0, v, sizeof v);
		c->x[i] = cnum_strtod(v, NULL);   /* NAN-free: a word (a law name) gives 0 */
		c->y[i] = NAN;
	}
	if (jobs < 1)
		jobs = 1;
	if (jobs > CURVE_MAX_JOBS)
		jobs = CURVE_MAX_JOBS;
	for (c->nth = 0; c->nth < jobs && c->nth < c->np; c->nth++)
		if (pthread_create(&c->th[c->nth], NULL, curve_worker, c) != 0)
			break;
	if (c->nth == 0) {
		hb_sweep_curve_free(c);
		hb_status_set(msg, n, HB_ENOMEM, "cannot start a thread");
		return NULL;
	}
	return c;
}

long
hb_sweep_curve_npoints(const struct hb_sweep_curve *c)
{
	return c->np;
}

long
hb_sweep_curve_boundaries(struct hb_sweep_curve *c, double *lo, double *hi, int *located,
                          long n)
{
	long nb;

	if (c->fine == NULL)
		return 0;
	pthread_mutex_lock(&c->mu);
	nb = c->nbr;
	for (long i = 0; i < nb && i < n; i++) {
		if (lo)
			lo[i] = sweep_axis_num(&c->fine->ax[0], c->br[i].lo);
		if (hi)
			hi[i] = sweep_axis_num(&c->fine->ax[0], c->br[i].hi);
		if (located)
			located[i] = c->br[i].hi - c->br[i].lo <= 1;
	}
	pthread_mutex_unlock(&c->mu);
	return nb;
}

long
hb_sweep_curve_poll(struct hb_sweep_curve *c, double *x, double *y, int *state, long n)
{
	long done;

	if (n > c->np)
		n = c->np;
	pthread_mutex_lock(&c->mu);
	for (long i = 0; i < n; i++) {
		if (x)
			x[i] = c->x[i];
		if (y)
			y[i] = c->y[i];
		if (state)
			state[i] = c->state[i];
	}
	done = c->done;
	pthread_mutex_unlock(&c->mu);
	return done;
}

/* What hb_sweep_curve_write_csv writes: the header, then the computed points. */
struct curve_rows {
	const struct hb_sweep_curve *c;
	const double *y;
	const int *st;
};

static void
fill_curve(FILE *f, const void *ctx)
{
	const struct curve_rows *r = ctx;

	/* an observable of collision i carries i, numbered from 0 as everywhere */
	const int per_coll = r->c->obs < HB_CURVE_RUN;

	if (per_coll)
		fprintf(f, "%s,i,%s\n", r->c->key, hb_sweep_observable_name(r->c->obs));
	else
		fprintf(f, "%s,%s\n", r->c->key, hb_sweep_observable_name(r->c->obs));
	for (long i = 0; i < r->c->np; i++) {
		char v[64];

		if (r->st[i] == HB_CURVE_PENDING)
			continue;
		hb_sweep_point_value(r->c->sw, i, 0, v, sizeof v);
		fputs(v, f);
		if (per_coll)
			fprintf(f, ",%ld", r->c->coll_i);
		csv_put_num(f, r->y[i]);
		fputc('\n', f);
	}
}

int
hb_sweep_curve_write_csv(struct hb_sweep_curve *c, const char *path, char *msg, size_t n)
{
	double *y = malloc((size_t)c->np * sizeof *y);
	int *st = malloc((size_t)c->np * sizeof *st);
	int rc;

	if (y == NULL || st == NULL) {
		free(y);
		free(st);
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	hb_sweep_curve_poll(c, NULL, y, st, c->np);
	rc = hb_atomic_write_with(path, fill_curve, &(struct curve_rows){ c, y, st }, msg, n);
	free(y);
	free(st);
	return rc;
}
