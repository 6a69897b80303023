/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_refine.c - what --refine asks for (see sweep.h, "Refinement"):
 * the observable and its classes, the tolerance, and the lattice of each
 * refined axis.  The rounds that bisect the grid are in sweep_refine_run.c.
 *
 * Lattice.  An axis FROM:TO:N refined by `levels` bisections holds the
 * M = (N - 1) * 2^levels + 1 values of FROM:TO:M, made as hb_sweep_vary
 * makes them: value i is FROM + (TO - FROM) * i / (M - 1), and
 * (i * 2^levels) / ((N - 1) * 2^levels) is the same double as i / (N - 1),
 * so the grid of the spec is every 2^levels-th lattice value, to the bit,
 * and every point the refinement computes is a point of the uniform sweep
 * FROM:TO:M, to the bit.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/observables.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "cnum.h"
#include "sweep_impl.h"

/* A lattice of at most this many intervals per axis (TOL >= about 1e-6). */
#define REFINE_MAX_INTERVALS (1L << 20)
#define REFINE_TAG "; sweep: --refine "

#define REFINE_HELP "expected --refine OBSERVABLE[:TOL] or OBSERVABLE<X[:TOL] (or >X), " \
	"with OBSERVABLE a column of runs.csv (e.g. collisions, t_pc, e_first<0.5:1e-3)"

long
sweep_refine_class(const struct sweep_refine *rf, double v, int failed)
{
	if (failed)
		return LONG_MIN;          /* a failed run is a class of its own */
	if (rf->op != 0) {
		if (isnan(v))
			return 2;
		return rf->op == '<' ? v < rf->thr : v > rf->thr;
	}
	if (hb_observables[rf->obs].whole)
		return isnan(v) ? LONG_MIN + 1 : (long)v;
	return !isnan(v);             /* exists or not: t_pc, e_first ... */
}

/* Field k (0-based) of the CSV line p (len bytes, no newline) into buf. */
static int
csv_field(const char *p, size_t len, int k, char *buf, size_t n)
{
	size_t i = 0, w = 0;

	for (int f = 0; f < k; f++) {      /* skip k fields */
		int q = 0;

		for (; i < len; i++) {
			if (p[i] == '"')
				q = !q;
			else if (p[i] == ',' && !q)
				break;
		}
		if (i >= len)
			return -1;
		i++;
	}
	if (i < len && p[i] == '"') {
		for (i++; i < len && w + 1 < n; i++) {
			if (p[i] == '"' && i + 1 < len && p[i + 1] == '"')
				buf[w++] = p[i++];
			else if (p[i] == '"')
				break;
			else
				buf[w++] = p[i];
		}
	} else {
		for (; i < len && p[i] != ',' && w + 1 < n; i++)
			buf[w++] = p[i];
	}
	buf[w] = '\0';
	return 0;
}

int
sweep_block_observable(const struct hb_sweep *sw, const char *blk, size_t len, int obs,
                       double *v, int *failed)
{
	const char *r;
	size_t rl;
	char f[256], *end;

	/* The runs row is the block's last line. */
	if (len < 3 || blk[len - 1] != '\n')
		return HB_EINVAL;
	r = blk + len - 1;
	while (r > blk && r[-1] != '\n')
		r--;
	rl = (size_t)(blk + len - 1 - r);
	if (rl < 2 || r[0] != 'r' || r[1] != ',')
		return HB_EINVAL;
	/* r, id, the axes, status, message, the observables */
	if (csv_field(r, rl, 2 + sw->naxes, f, sizeof f) != 0)
		return HB_EINVAL;
	*failed = strcmp(f, "failed") == 0;
	if (csv_field(r, rl, 2 + sw->naxes + 2 + obs, f, sizeof f) != 0)
		return HB_EINVAL;
	if (f[0] == '\0') {
		*v = NAN;
		return HB_OK;
	}
	*v = cnum_strtod(f, &end);
	return *end == '\0' ? HB_OK : HB_EINVAL;
}

/* OBSERVABLE[<X|>X][:TOL] into rf. */
static int
parse_spec(struct sweep_refine *rf, const char *spec, char *msg, size_t n)
{
	char name[64], *end;
	const char *colon = strchr(spec, ':'), *op;
	size_t l = colon ? (size_t)(colon - spec) : strlen(spec);

	rf->tol = 1e-3;
	if (colon != NULL) {
		rf->tol = cnum_strtod(colon + 1, &end);
		if (end == colon + 1 || *end != '\0' || !(rf->tol > 0 && rf->tol < 1))
			return hb_status_set(msg, n, HB_EINVAL, "--refine %s: TOL '%s': accepted: a "
			                     "number between 0 and 1, the fraction of each axis "
			                     "(default 1e-3)", spec, colon + 1);
	}
	op = memchr(spec, '<', l);
	if (op == NULL)
		op = memchr(spec, '>', l);
	if (op != NULL) {
		char thr[64];

		snprintf(thr, sizeof thr, "%.*s", (int)(l - (size_t)(op - spec) - 1), op + 1);
		rf->op = *op;
		rf->thr = cnum_strtod(thr, &end);
		if (thr[0] == '\0' || *end != '\0' || !isfinite(rf->thr))
			return hb_status_set(msg, n, HB_EINVAL, "--refine %s: threshold '%s': "
			                     "accepted: a number in SI units (e.g. e_first<0.5)",
			                     spec, thr);
		l = (size_t)(op - spec);
	}
	if (l == 0 || l >= sizeof name)
		return hb_status_set(msg, n, HB_EINVAL, "--refine '%s': " REFINE_HELP, spec);
	snprintf(name, sizeof name, "%.*s", (int)l, spec);
	if ((rf->obs = hb_observable_find(name)) < 0) {
		char list[1024];
		size_t u = 0;

		list[0] = '\0';
		for (int k = 0; k < HB_OBS_COUNT && u < sizeof list; k++)
			u += (size_t)snprintf(list + u, sizeof list - u, "%s%s", k ? ", " : "",
			                      hb_observables[k].name);
		return hb_status_set(msg, n, HB_EINVAL, "--refine %s: unknown observable '%s'; "
		                     "accepted: %s", spec, name, list);
	}
	return HB_OK;
}

/* "FROM:TO:M[:log]" from an axis's "FROM:TO:N[:log]". */
static int
lattice_spec(const struct axis *a, long m, char *buf, size_t n)
{
	const char *c1 = strchr(a->spec, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
	const char *c3 = c2 ? strchr(c2 + 1, ':') : NULL;

	if (c2 == NULL)
		return -1;
	snprintf(buf, n, "%.*s%ld%s", (int)(c2 + 1 - a->spec), a->spec, m, c3 ? c3 : "");
	return 0;
}

int
hb_sweep_refine(struct hb_sweep *sw, const char *spec, char *msg, size_t n)
{
	struct sweep_refine rf;
	long save_max = sw->max_points;
	int rc = HB_OK;

	memset(&rf, 0, sizeof rf);
	if (sw->rf.on)
		return hb_status_set(msg, n, HB_EINVAL, "--refine %s: the sweep is refined already "
		                     "(--refine %s); accepted: one --refine", spec, sw->rf.spec);
	if (strlen(spec) >= sizeof rf.spec)
		return hb_status_set(msg, n, HB_EINVAL, "--refine: value too long; accepted: up to "
		                     "%zu characters", sizeof rf.spec - 1);
	snprintf(rf.spec, sizeof rf.spec, "%s", spec);
	if ((rc = parse_spec(&rf, spec, msg, n)) != HB_OK)
		return rc;
	if (sw->naxes < 1 || sw->naxes > 2)
		return hb_status_set(msg, n, HB_EINVAL, "--refine %s: the sweep has %d axes; "
		                     "accepted: one or two --vary ranges", spec, sw->naxes);
	for (int k = 0; k < sw->naxes; k++) {
		const struct axis *a = &sw->ax[k];

		if (a->val != NULL || a->n < 2)
			return hb_status_set(msg, n, HB_EINVAL, "--refine %s: --vary %s=%s: a boundary "
			                     "is bisected between values of a range; accepted: "
			                     "FROM:TO:N or FROM:TO:N:log with N >= 2", spec, a->key,
			                     a->spec);
	}
	/* The fewest bisections that bring every axis's step to TOL of its span. */
	for (int k = 0; k < sw->naxes; k++)
		while ((double)((sw->ax[k].n - 1) << rf.levels) * rf.tol < 1 - 1e-12)
			rf.levels++;
	for (int k = 0; k < sw->naxes; k++)
		if (((sw->ax[k].n - 1) << rf.levels) > REFINE_MAX_INTERVALS)
			return hb_status_set(msg, n, HB_EINVAL, "--refine %s: %ld values on the axis of "
			                     "%s; accepted: a TOL that needs at most %ld (e.g. 1e-4)",
			                     spec, ((sw->ax[k].n - 1) << rf.levels) + 1,
			                     sw->ax[k].key, REFINE_MAX_INTERVALS + 1);
	rf.step = 1L << rf.levels;
	/* The lattices: made as hb_sweep_vary makes FROM:TO:M (no limit on M here:
	 * only the points the refinement asks for are computed). */
	sw->max_points = LONG_MAX;
	for (int k = 0; k < sw->naxes && rc == HB_OK; k++) {
		struct axis *a = &sw->ax[k], t;
		struct hb_scene sc;

		rf.grid[k] = a->n;
		memset(&t, 0, sizeof t);
		snprintf(t.key, sizeof t.key, "%s", a->key);
		if (lattice_spec(a, (a->n - 1) * rf.step + 1, t.spec, sizeof t.spec) != 0) {
			rc = hb_status_set(msg, n, HB_EINVAL, "--refine: --vary %s=%s is not a range",
			                   a->key, a->spec);
			break;
		}
		sweep_check_scene(sw, k, &sc);
		if ((rc = sweep_parse_range(&t, &sc, sw, 1, msg, n)) != HB_OK) {
			free(t.num);
			break;
		}
		free(a->num);
		a->num = t.num;
		a->ramp = t.ramp;
		a->n = t.n;
	}
	sw->max_points = save_max;
	if (rc != HB_OK)
		return rc;
	rf.on = 1;
	sw->rf = rf;
	return HB_OK;
}

int
hb_sweep_refine_from_preset(struct hb_sweep *sw, const char *text, const char *name,
                            char *msg, size_t n)
{
	return sweep_tagged_lines(sw, text, name, REFINE_TAG, hb_sweep_refine, msg, n);
}

int
hb_sweep_refined(const struct hb_sweep *sw)
{
	return sw->rf.on;
}

/* See sweep_impl.h. */
long
sweep_refine_grid_id(const struct hb_sweep *sw, long g)
{
	if (sw->naxes == 1)
		return g * sw->rf.step;
	return (g / sw->rf.grid[1]) * sw->rf.step * sw->ax[1].n + (g % sw->rf.grid[1]) * sw->rf.step;
}

/* See sweep_impl.h. */
long
sweep_refine_grid_points(const struct hb_sweep *sw)
{
	return sw->naxes == 1 ? sw->rf.grid[0] : sw->rf.grid[0] * sw->rf.grid[1];
}
