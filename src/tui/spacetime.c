/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * spacetime.c - the space-time view's state: the shadow run of the
 * current scene and its buffer of body positions and contacts (see
 * spacetime.h for why and how).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "canvas.h"
#include "spacetime.h"
#include "status.h"
#include "tui.h"

static double
mono_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void
st_reset(struct spacetime *st)
{
	hb_sim_free(st->sh);
	free(st->scene);
	free(st->R);
	free(st->t);
	free(st->y);
	free(st->u);
	free(st->c);
	canvas_free(st->cv);
	st->cv = NULL;
	st->sh = NULL;
	st->scene = NULL;
	st->R = st->t = st->y = st->u = NULL;
	st->c = NULL;
	st->src = NULL;
	st->nrec = st->cap = st->nc = st->ccap = 0;
	st->nb = 0;
	st->lost = 0;
	st->failed = 0;
}

/* The shadow of the current run, from t = 0.  0, or -1 (st->failed). */
static int
st_build(struct spacetime *st, const struct hb_sim *src)
{
	const struct hb_scene *sc = hb_sim_scene(src);
	char msg[256];
	size_t vals;

	st_reset(st);
	st->src = src;
	st->scene_size = sizeof *sc;
	st->scene = malloc(sizeof *sc);
	st->sh = hb_sim_new(sc, msg, sizeof msg);
	st->nb = st->sh ? hb_sim_nbodies(st->sh) : 0;
	if (st->scene == NULL || st->sh == NULL || st->nb < 1) {
		st->failed = 1;
		return -1;
	}
	memcpy(st->scene, sc, sizeof *sc);
	st->R = calloc((size_t)st->nb, sizeof *st->R);
	vals = ST_MAX_VALUES / (size_t)st->nb;
	st->cap = vals < 256 ? 256 : vals > 16384 ? 16384 : vals;
	st->t = malloc(st->cap * sizeof *st->t);
	st->y = malloc(st->cap * (size_t)st->nb * sizeof *st->y);
	st->u = malloc(st->cap * (size_t)st->nb * sizeof *st->u);
	if (st->R == NULL || st->t == NULL || st->y == NULL || st->u == NULL) {
		st->failed = 1;
		return -1;
	}
	/*
	 * Half-lengths: a chain's bodies as the engine binds them (hb_sim_body);
	 * the two-body scenes' positions are measured so that the gap is their
	 * difference.
	 */
	if (sc->chain.n > 0) {
		for (int b = 0; b < st->nb; b++) {
			struct hb_sim_body hb;
			if (hb_sim_body(st->sh, b, &hb) == HB_OK)
				st->R[b] = hb.R;
		}
		st->k0 = sc->chain.floor ? 0 : 1;
	} else {
		st->k0 = st->nb == 1 ? 0 : 1;
	}
	st->floor_y = 0;
	st->T = sc->run.T;
	st->dt = st->T / (double)(st->cap / 2);
	st->last_j = -1;
	st->ylo = st->k0 == 0 ? st->floor_y : INFINITY;
	st->yhi = st->k0 == 0 ? st->floor_y : -INFINITY;
	return 0;
}

double
st_gap(const struct spacetime *st, int k, size_t i)
{
	const double *y = st->y + i * (size_t)st->nb;

	if (k == 0)
		return y[0] - st->R[0] - st->floor_y;
	return (y[k] - st->R[k]) - (y[k - 1] + st->R[k - 1]);
}

/* Every other record goes (the first and the last stay); the grid doubles. */
static void
st_thin(struct spacetime *st)
{
	size_t w = 0, nb = (size_t)st->nb;

	for (size_t r = 0; r < st->nrec; r++) {
		if (r % 2 == 1 && r + 1 < st->nrec)
			continue;
		st->t[w] = st->t[r];
		memmove(st->y + w * nb, st->y + r * nb, nb * sizeof *st->y);
		memmove(st->u + w * nb, st->u + r * nb, nb * sizeof *st->u);
		w++;
	}
	st->nrec = w;
	st->dt *= 2;
}

/* Records the shadow's bodies at its last sample. */
static void
st_record(struct spacetime *st, double t)
{
	size_t nb = (size_t)st->nb;

	if (st->nrec > 0 && st->t[st->nrec - 1] == t)
		st->nrec--;   /* the same instant (a jump): the later state replaces it */
	if (st->nrec == st->cap)
		st_thin(st);
	st->t[st->nrec] = t;
	for (int b = 0; b < st->nb; b++) {
		struct hb_sim_body hb;
		if (hb_sim_body(st->sh, b, &hb) != HB_OK)
			hb.y = hb.u = NAN;
		st->y[st->nrec * nb + (size_t)b] = hb.y;
		if (isfinite(hb.y)) {
			st->ylo = fmin(st->ylo, hb.y - st->R[b]);
			st->yhi = fmax(st->yhi, hb.y + st->R[b]);
		}
		st->u[st->nrec * nb + (size_t)b] = hb.u;
	}
	st->nrec++;
}

/* The interface whose gap at the last record is nearest x (the arc's pair). */
static int
st_iface_of(const struct spacetime *st, double x)
{
	int best = st->k0;
	double bd = INFINITY;

	for (int k = st->k0; k < st->nb; k++) {
		double d = fabs(st_gap(st, k, st->nrec - 1) - x);
		if (d < bd) {
			bd = d;
			best = k;
		}
	}
	return best;
}

static void
st_contact(struct spacetime *st, int k, long j, double t0, double t1)
{
	if (st->nc > 0 && st->c[st->nc - 1].j == j) {
		st->c[st->nc - 1].t1 = t1;
		return;
	}
	if (st->nc == st->ccap) {
		size_t n = st->ccap ? 2 * st->ccap : 64;
		struct st_contact *p;
		if (n > ST_MAX_CONTACTS || (p = realloc(st->c, n * sizeof *p)) == NULL) {
			st->lost++;
			return;
		}
		st->c = p;
		st->ccap = n;
	}
	st->c[st->nc++] = (struct st_contact){ .k = k, .j = j, .t0 = t0, .t1 = t1 };
}

/*
 * After a step of the shadow: a record on the grid or where a new flow
 * interval began, and the contact of the interval (its interface found
 * from the gaps).  The intervals passed since the last step (by j: the
 * arc's thinning renumbers its intervals, never their j) close the last
 * contact where it ended, and a contact begun and ended within one step
 * goes to the pair nearest touching then.
 */
static void
st_observe(struct spacetime *st)
{
	const struct hb_arc *arc = hb_sim_arc(st->sh);
	const struct hb_arc_sample *l = hb_arc_last(arc);
	const struct hb_arc_interval *iv;
	size_t ivi, m;
	int fresh;

	if (l == NULL)
		return;
	ivi = hb_arc_interval_of(arc, hb_arc_len(arc) - 1);
	iv = hb_arc_interval_at(arc, ivi);
	fresh = iv != NULL && iv->j != st->last_j;
	if (st->nrec == 0 || l->t - st->t[st->nrec - 1] >= st->dt || fresh
	    || hb_sim_end(st->sh) != HB_SIM_RUNNING)
		st_record(st, l->t);
	if (iv == NULL)
		return;
	if (fresh) {
		for (m = ivi; m > 0 && hb_arc_interval_at(arc, m - 1)->j > st->last_j; m--)
			;   /* m: the first interval after the last one seen */
		if (m > 0) {
			const struct hb_arc_interval *pv = hb_arc_interval_at(arc, m - 1);
			if (pv->q && st->nc > 0 && st->c[st->nc - 1].j == pv->j)
				st->c[st->nc - 1].t1 = pv->t1;
		}
		for (; m < ivi; m++) {
			const struct hb_arc_interval *pv = hb_arc_interval_at(arc, m);
			if (pv->q)
				st_contact(st, st_iface_of(st, 0.0), pv->j, pv->t0, pv->t1);
		}
	}
	if (iv->q)
		st_contact(st, st->nc > 0 && st->c[st->nc - 1].j == iv->j ? st->c[st->nc - 1].k
		               : st_iface_of(st, l->x), iv->j, iv->t0, l->t);
	st->last_j = iv->j;
}

/* The state, allocated on first use; NULL (and a message) on no memory. */
static struct spacetime *
st_get(struct app *a)
{
	if (a->st == NULL && (a->st = calloc(1, sizeof *a->st)) == NULL)
		app_msg(a, 1, "space-time view: out of memory");
	return a->st;
}

void
act_spacetime(struct app *a)
{
	if (st_get(a) == NULL)
		return;
	a->st->on = !a->st->on;
	if (!a->st->on) {
		if (a->st->iface == 0 && a->st->body == 0)
			st_reset(a->st);   /* its memory back; V again computes it afresh */
		app_msg(a, 0, "space-time view off: the plots again");
		return;
	}
	app_msg(a, 0, "space-time view: each body's position against t, contacts marked # per "
	        "interface (V: back to the plots)");
}

int
spacetime_on(const struct app *a)
{
	return a->st != NULL && a->st->on;
}

/* The scene's interfaces: k0 .. nb - 1. */
static void
st_ifaces(const struct app *a, int *k0, int *nb)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);

	*nb = hb_sim_nbodies(a->sim);
	*k0 = sc->chain.n > 0 ? (sc->chain.floor ? 0 : 1) : (*nb == 1 ? 0 : 1);
}

void
act_iface(struct app *a)
{
	int k0, nb, k;

	st_ifaces(a, &k0, &nb);
	if (nb - k0 < 2) {
		app_msg(a, 1, "one interface only: the plots show it (K chooses among a chain's)");
		return;
	}
	if (st_get(a) == NULL)
		return;
	a->st->body = 0;        /* an interface instead of a body */
	k = a->st->iface - 1;   /* -1: the run's own */
	k = k < 0 ? k0 : k + 1;
	if (k >= nb) {
		a->st->iface = 0;
		if (!a->st->on)
			st_reset(a->st);
		app_msg(a, 0, "plots: each interval's interface, as the run records it (K: interface %d)", k0);
		return;
	}
	a->st->iface = k + 1;
	if (k == 0)
		app_msg(a, 0, "plots: interface 0 (the floor and body 1): x, x_c, F_c (K: the next)");
	else
		app_msg(a, 0, "plots: interface %d (bodies %d and %d): x, x_c, F_c (K: the next)", k, k, k + 1);
}

int
spacetime_iface(const struct app *a)
{
	int k0, nb;

	if (a->st == NULL || a->st->iface == 0)
		return -1;
	st_ifaces(a, &k0, &nb);
	return a->st->iface - 1 < nb ? a->st->iface - 1 : -1;   /* a scene with fewer bodies now */
}

void
act_body(struct app *a)
{
	int nb = hb_sim_nbodies(a->sim), b;

	if (st_get(a) == NULL)
		return;
	a->st->iface = 0;       /* a body instead of an interface */
	b = a->st->body;        /* the next one, 0-based; nb: the run's own */
	if (b >= nb) {
		a->st->body = 0;
		if (!a->st->on)
			st_reset(a->st);
		app_msg(a, 0, "plots: the run's own (B: body 1)");
		return;
	}
	a->st->body = b + 1;
	app_msg(a, 0, "plots: body %d%s of %d: position y and velocity u (B: the next)", b + 1,
	        b + 1 == nb && nb > 1 ? " (the top one)" : "", nb);
}

int
spacetime_body(const struct app *a)
{
	if (a->st == NULL || a->st->body == 0)
		return -1;
	return a->st->body - 1 < hb_sim_nbodies(a->sim) ? a->st->body - 1 : -1;
}

char *
spacetime_state(const struct app *a, char *buf, size_t n)
{
	int k = spacetime_iface(a), b = spacetime_body(a);

	if (k >= 0)
		snprintf(buf, n, " k=%d", k);
	else if (b >= 0)
		snprintf(buf, n, " b=%d", b + 1);
	else
		snprintf(buf, n, "%s", "");
	return buf;
}

int
spacetime_tick(struct app *a)
{
	struct spacetime *st = a->st;
	double t0;
	int n = 0;

	if ((!spacetime_on(a) && spacetime_iface(a) < 0 && spacetime_body(a) < 0) || a->branch_t >= 0)
		return 0;   /* a branched run: the scene from t = 0 is not the run (the panes say so) */
	if (st->src != a->sim || st->scene == NULL
	    || memcmp(st->scene, hb_sim_scene(a->sim), st->scene_size) != 0) {
		if (st->failed && st->src == a->sim)
			return 0;
		if (st_build(st, a->sim) != 0) {
			app_msg(a, 1, "space-time view: cannot run the scene a second time (out of memory)");
			return 0;
		}
	}
	if (st->failed || hb_sim_end(st->sh) != HB_SIM_RUNNING)
		return 0;
	if (st->nrec == 0)
		st_observe(st);   /* the start */
	t0 = mono_s();
	while (hb_sim_end(st->sh) == HB_SIM_RUNNING) {
		int rc = hb_sim_advance(st->sh, 1, 0);
		st_observe(st);
		if (rc != HB_OK)
			break;
		if (++n % 16 == 0 && mono_s() - t0 > a->budget)
			break;
	}
	return hb_sim_end(st->sh) == HB_SIM_RUNNING;
}

void
spacetime_free(struct app *a)
{
	if (a->st == NULL)
		return;
	st_reset(a->st);
	free(a->st);
	a->st = NULL;
}

/* The last record at or before t (from the hint *i), into *i; -1 without records. */
static long
st_rec(const struct spacetime *st, double t, size_t *i)
{
	size_t k = *i;

	if (st->nrec == 0)
		return -1;
	if (k >= st->nrec || st->t[k] > t || (k + 2 < st->nrec && st->t[k + 2] <= t)) {
		/* not at the hint or the next one: bisect for the last record at or before t */
		size_t lo = 0, hi = st->nrec;
		while (hi - lo > 1) {
			size_t mid = lo + (hi - lo) / 2;
			if (st->t[mid] <= t)
				lo = mid;
			else
				hi = mid;
		}
		k = lo;
	}
	while (k + 1 < st->nrec && st->t[k + 1] <= t)
		k++;
	*i = k;
	return (long)k;
}

/*
 * The cubic Hermite segment of body b around t (record *i to *i + 1): its
 * parameter s in [0, 1], length h, end positions y0, y1 and scaled end
 * velocities m0, m1.  Returns 1 with the segment, 0 with *end the value
 * (y or u, as want_u) where there is no segment, -1 before the records.
 */
static int
segment(const struct spacetime *st, int b, double t, size_t *i, int want_u, double *end,
        double *s, double *h, double *y0, double *y1, double *m0, double *m1)
{
	size_t nb = (size_t)st->nb, k;
	const double *v = want_u ? st->u : st->y;

	if (st_rec(st, t, i) < 0)
		return -1;
	k = *i;
	if (k + 1 >= st->nrec) {
		*end = v[k * nb + (size_t)b];
		return 0;
	}
	*h = st->t[k + 1] - st->t[k];
	if (!(*h > 0)) {
		*end = v[(k + 1) * nb + (size_t)b];
		return 0;
	}
	*s = (t - st->t[k]) / *h;
	*y0 = st->y[k * nb + (size_t)b];
	*y1 = st->y[(k + 1) * nb + (size_t)b];
	*m0 = *h * st->u[k * nb + (size_t)b];
	*m1 = *h * st->u[(k + 1) * nb + (size_t)b];
	return 1;
}

double
st_y_at(const struct spacetime *st, int b, double t, size_t *i)
{
	double end = NAN, h = 0, s = 0, y0 = 0, y1 = 0, m0 = 0, m1 = 0;
	int r = segment(st, b, t, i, 0, &end, &s, &h, &y0, &y1, &m0, &m1);

	if (r <= 0)
		return r < 0 ? NAN : end;
	/* cubic Hermite: exact for a parabola (a body in free flight under a constant load) */
	return (2 * s * s * s - 3 * s * s + 1) * y0 + (s * s * s - 2 * s * s + s) * m0
	       + (-2 * s * s * s + 3 * s * s) * y1 + (s * s * s - s * s) * m1;
}

double
st_u_at(const struct spacetime *st, int b, double t, size_t *i)
{
	double end = NAN, h = 0, s = 0, y0 = 0, y1 = 0, m0 = 0, m1 = 0;
	int r = segment(st, b, t, i, 1, &end, &s, &h, &y0, &y1, &m0, &m1);

	if (r <= 0)
		return r < 0 ? NAN : end;
	/* d/dt of st_y_at's cubic: the records' velocities at both ends, linear in free flight */
	return ((6 * s * s - 6 * s) * y0 + (3 * s * s - 4 * s + 1) * m0 + (-6 * s * s + 6 * s) * y1
	        + (3 * s * s - 2 * s) * m1) / h;
}

double
st_gap_at(const struct spacetime *st, int k, double t)
{
	size_t h = 0;
	double lo, hi;

	if (k == 0)
		return st_y_at(st, 0, t, &h) - st->R[0] - st->floor_y;
	lo = st_y_at(st, k - 1, t, &h);
	hi = st_y_at(st, k, t, &h);
	return (hi - st->R[k]) - (lo + st->R[k - 1]);
}
