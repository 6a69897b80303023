/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * error.c - error bars: the global error of each observable of a run,
 * estimated by a second run with rk8pd at a hundredth of the tolerances
 * (see error.h for the evidence behind the choice).
 */
#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/error.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"

/* A run observable that the estimate leaves out: a count of work. */
static int
is_work(int k)
{
	return k == HB_OBS_STEPS || k == HB_OBS_REJECTED || k == HB_OBS_RHS || k == HB_OBS_JAC;
}

/*
 * The error bar of value a from the tighter run's b: their difference, but
 * never below rnd, a's rounding (two runs that agree to the last bit, as a
 * flight in closed form does, still carry it).
 */
static double
bar(double a, double b, double rnd)
{
	double d = fabs(a - b), r = rnd > 2 * DBL_EPSILON * fabs(a) ? rnd : 2 * DBL_EPSILON * fabs(a);

	if (isnan(a) && isnan(b))
		return NAN;
	return d > r ? d : r;
}

/* The collision with index i in s, or NULL (kept collisions are in order of i). */
static const struct hb_collision *
find_in(const struct hb_sim *s, long i)
{
	size_t lo = 0, hi = hb_sim_ncollisions(s);

	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		const struct hb_collision *c = hb_sim_collision(s, mid);

		if (c->i < i)
			lo = mid + 1;
		else
			hi = mid;
	}
	if (lo < hb_sim_ncollisions(s)) {
		const struct hb_collision *c = hb_sim_collision(s, lo);

		if (c->i == i && c->complete)
			return c;
	}
	return NULL;
}

void
hb_error_scene(const struct hb_scene *sc, struct hb_scene *tight, int *at_floor)
{
	*tight = *sc;
	*at_floor = hb_error_tighten(tight);
}

int
hb_error_compare(const struct hb_sim *s, const struct hb_sim *t, struct hb_error_estimate *e,
                 char *msg, size_t n)
{
	size_t nc = hb_sim_ncollisions(s), k;
	double tround;

	memset(e, 0, sizeof *e);
	e->stepper = hb_sim_scene(t)->run.stepper;
	e->rtol = hb_sim_scene(t)->run.rtol;
	e->atol = hb_sim_scene(t)->run.atol;
	e->at_floor = e->rtol > hb_sim_scene(s)->run.rtol / HB_ERROR_TIGHTEN;
	if (hb_sim_end(t) == HB_SIM_END_FAIL || hb_sim_end(t) == HB_SIM_RUNNING)
		return hb_status_set(msg, n, hb_sim_end(t) == HB_SIM_RUNNING ? HB_EINVAL : HB_ENUMERIC,
		                     "the second run of the error estimate "
		                     "(rk8pd, rtol %.3g) %s%s", e->rtol,
		                     hb_sim_end(t) == HB_SIM_RUNNING ? "has not ended" : "failed: ",
		                     hb_sim_end(t) == HB_SIM_RUNNING ? "" : hb_sim_errmsg(t));
	e->coll = calloc(nc > 0 ? nc : 1, sizeof *e->coll);
	if (e->coll == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "error estimate: out of memory");
	tround = sqrt((double)hb_sim_stats(s)->steps);
	tround = (tround > 4 ? tround : 4) * DBL_EPSILON;
	for (k = 0; k < nc; k++) {
		const struct hb_collision *a = hb_sim_collision(s, k), *b;
		struct hb_collision *d = &e->coll[e->ncoll];

		if (!a->complete)
			continue;
		b = find_in(t, a->i);
		d->i = a->i;
		d->j = a->j;
		d->complete = 1;
		for (int c = 0; c < hb_collision_ncolumns; c++) {
			const struct hb_collision_column *col = &hb_collision_columns[c];
			double *dst, rnd;

			if (col->index)
				continue;
			dst = (double *)((char *)d + col->off);
			/* a time, or a difference of times: the rounding of t,
			 * which is a sum of the steps that reach it (about
			 * sqrt(steps) ulps), and at least a few ulps (the location
			 * of an event ends on a bracket of that width) */
			rnd = col->off == offsetof(struct hb_collision, te) ||
			      col->off == offsetof(struct hb_collision, ts) ||
			      col->off == offsetof(struct hb_collision, td) ||
			      col->off == offsetof(struct hb_collision, tf)
			          ? tround * fabs(a->ts) : 0;
			*dst = b != NULL ? bar(hb_collision_value(a, col), hb_collision_value(b, col), rnd)
			                 : NAN;
		}
		d->xcr_sum = b != NULL ? bar(a->xcr_sum, b->xcr_sum, 0) : NAN;
		e->ncoll++;
	}
	for (int o = 0; o < HB_OBS_COUNT; o++)
		e->obs[o] = is_work(o) ? NAN
		            : hb_observables[o].whole
		                ? fabs(hb_observable_value(s, o) - hb_observable_value(t, o))
		                : bar(hb_observable_value(s, o), hb_observable_value(t, o), 0);
	e->other_total = hb_sim_collisions_total(t);
	e->other_rhs = hb_sim_stats(t)->rhs;
	return HB_OK;
}

int
hb_error_estimate(const struct hb_sim *s, const volatile int *stop,
                  struct hb_error_estimate *e, char *msg, size_t n)
{
	struct hb_scene sc;
	struct hb_sim *t;
	int rc, at_floor;

	memset(e, 0, sizeof *e);
	hb_error_scene(hb_sim_scene(s), &sc, &at_floor);
	t = hb_sim_new(&sc, msg, n);
	if (t == NULL)
		return HB_EINVAL;
	do {
		if (stop != NULL && *stop != 0) {
			hb_sim_free(t);
			return hb_status_set(msg, n, HB_EINVAL, "error estimate interrupted");
		}
		rc = hb_sim_advance(t, 0, 0.1);
	} while (rc == HB_OK && hb_sim_end(t) == HB_SIM_RUNNING);
	if (rc != HB_OK && rc != HB_EDONE && hb_sim_end(t) != HB_SIM_END_FAIL) {
		rc = hb_status_set(msg, n, rc, "the second run of the error estimate (rk8pd, rtol %.3g) "
		                   "failed: %s", sc.run.rtol, hb_sim_errmsg(t));
		hb_sim_free(t);
		return rc;
	}
	rc = hb_error_compare(s, t, e, msg, n);
	hb_sim_free(t);
	return rc;
}

void
hb_error_free(struct hb_error_estimate *e)
{
	if (e == NULL)
		return;
	free(e->coll);
	e->coll = NULL;
	e->ncoll = 0;
}

int
hb_error_tighten(struct hb_scene *sc)
{
	int at_floor = 0;

	sc->run.stepper = HB_STEPPER_RK8PD;
	sc->run.atol /= HB_ERROR_TIGHTEN;
	sc->run.rtol /= HB_ERROR_TIGHTEN;
	if (sc->run.rtol < HB_ERROR_RTOL_MIN) {
		sc->run.rtol = HB_ERROR_RTOL_MIN;
		at_floor = 1;
	}
	return at_floor;
}

int
hb_error_observable(int k)
{
	return k >= 0 && k < HB_OBS_COUNT && !is_work(k);
}

const struct hb_collision *
hb_error_find(const struct hb_error_estimate *e, long i)
{
	for (size_t k = 0; e != NULL && k < e->ncoll; k++)
		if (e->coll[k].i == i)
			return &e->coll[k];
	return NULL;
}

double
hb_error_relative(const struct hb_collision *value, const struct hb_collision *err,
                  const struct hb_collision_column *col)
{
	double d, sz;

	if (col->index || value == NULL || err == NULL)
		return NAN;
	d = hb_collision_value(err, col);
	if (col->off == offsetof(struct hb_collision, te) ||
	    col->off == offsetof(struct hb_collision, ts))
		sz = fabs(value->td);
	else if (col->off == offsetof(struct hb_collision, xcr))
		sz = fabs(value->xcmax);
	else if (col->off == offsetof(struct hb_collision, W))
		/* the collision's energy scale: W is near 0 when elastic */
		sz = fmax(fabs(value->W), fabs(value->JFc * value->vi));
	else
		sz = fabs(hb_collision_value(value, col));
	if (isnan(d) || !(sz > 0) || !isfinite(sz))
		return NAN;
	return d / sz;
}

int
hb_error_check(const struct hb_sim *s, const struct hb_error_estimate *e, double *worst,
               char *msg, size_t n)
{
	const double rtol = hb_sim_scene(s)->run.rtol, limit = HB_ERROR_CHECK_FACTOR * rtol;
	int rc = HB_OK;

	*worst = 0;
	if (msg != NULL && n > 0)
		msg[0] = '\0';
	if (e->other_total != hb_sim_collisions_total(s))
		rc = hb_status_set(msg, n, HB_ENUMERIC, "the number of collisions is not sure: %ld "
		                   "here, %ld at rtol %.3g", hb_sim_collisions_total(s),
		                   e->other_total, e->rtol);
	for (size_t k = 0; k < hb_sim_ncollisions(s); k++) {
		const struct hb_collision *a = hb_sim_collision(s, k), *d;

		if (!a->complete)
			continue;
		d = hb_error_find(e, a->i);
		for (int c = 0; c < hb_collision_ncolumns; c++) {
			const struct hb_collision_column *col = &hb_collision_columns[c];
			double r;

			if (col->index)
				continue;
			if (d == NULL) {
				if (rc == HB_OK)
					rc = hb_status_set(msg, n, HB_ENUMERIC, "collision %ld has no "
					                   "counterpart at rtol %.3g", a->i, e->rtol);
				break;
			}
			r = hb_error_relative(a, d, col);
			if (isnan(r))
				continue;
			if (r / rtol > *worst)
				*worst = r / rtol;
			if (r > limit && rc == HB_OK)
				rc = hb_status_set(msg, n, HB_ENUMERIC, "collision %ld: %s has an error "
				                   "of %.2g (%s), above %g x rtol = %.3g", a->i,
				                   col->name, r,
				                   col->off == offsetof(struct hb_collision, te) ||
				                   col->off == offsetof(struct hb_collision, ts)
				                       ? "of t_d"
				                       : col->off == offsetof(struct hb_collision, xcr)
				                           ? "of x_c^max" : "relative",
				                   HB_ERROR_CHECK_FACTOR, limit);
		}
	}
	return rc;
}
