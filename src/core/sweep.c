/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep.c - the points of a sweep: the sweep, the scene of a point, the
 * spec file and the runs header (see sweep.h); its axes from "KEY=SPEC" are
 * made in sweep_axis.c.  A point run into its journal
 * block is in sweep_block.c; the threads, the journal and the merge in
 * sweep_pool.c, sweep_run.c, sweep_journal.c and sweep_merge.c.
 *
 * Values.  Every axis value is canonical: the value read back from the
 * scene after hb_scene_set, as text a %.17g SI number or a word such as a
 * law name.  A point's scene applies exactly those texts, and runs.csv shows
 * exactly those texts, so "--batch --set KEY=VALUE" with a row's values
 * reproduces the point to the bit.  A range keeps its values as the doubles
 * read back (8 bytes a value; %.17g gives the text again, the same
 * characters), or, when every value between its ends is the formula's
 * double itself, computes them when asked (sweep_axis_num); a list keeps
 * their texts.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hybounce/arc.h"
#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/observables.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "csv_impl.h"
#include "sweep_impl.h"
#include "scene_keys.h"
#include "cnum.h"

struct hb_sweep *
hb_sweep_new(const struct hb_scene *base, char *msg, size_t n)
{
	struct hb_sweep *sw = calloc(1, sizeof *sw);

	if (sw == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	sw->base = *base;
	sw->max_points = HB_SWEEP_MAX_POINTS;
	return sw;
}

void
hb_sweep_set_max_points(struct hb_sweep *sw, long max, const char *more)
{
	sw->max_points = max < 1 ? 1 : max > SWEEP_MAX_POINTS ? SWEEP_MAX_POINTS : max;
	snprintf(sw->more, sizeof sw->more, "%s", more != NULL ? more : "");
}

void
hb_sweep_free(struct hb_sweep *sw)
{
	if (sw == NULL)
		return;
	for (int k = 0; k < sw->naxes; k++)
		sweep_axis_free(&sw->ax[k]);
	free(sw);
}

int
hb_sweep_naxes(const struct hb_sweep *sw)
{
	return sw->naxes;
}

long
hb_sweep_npoints(const struct hb_sweep *sw)
{
	long p = 1;

	if (sw->naxes == 0)
		return 0;
	for (int k = 0; k < sw->naxes; k++)
		p *= sw->ax[k].n;
	return p;
}

/* Index of axis k at point id (row-major, the last axis fastest). */
long
sweep_axis_index(const struct hb_sweep *sw, long id, int k)
{
	for (int i = sw->naxes - 1; i > k; i--)
		id /= sw->ax[i].n;
	return id % sw->ax[k].n;
}

int
hb_sweep_point_value(const struct hb_sweep *sw, long id, int k, char *buf, size_t n)
{
	char t[64];

	if (k < 0 || k >= sw->naxes || id < 0 || id >= hb_sweep_npoints(sw))
		return HB_EINVAL;
	snprintf(buf, n, "%s", sweep_axis_text(&sw->ax[k], sweep_axis_index(sw, id, k), t, sizeof t));
	return HB_OK;
}

/*
 * The base scene with the axes' values of point id, not validated.  A
 * range's value goes in as its double (hb_scene_set_number: the double
 * that its %.17g text reads back to, without the text made and parsed
 * again); a list's as its text.
 */
int
sweep_point_values(const struct hb_sweep *sw, long id, struct hb_scene *out, char *msg, size_t n)
{
	char m[512], t[64];

	if (id < 0 || id >= hb_sweep_npoints(sw))
		return hb_status_set(msg, n, HB_EINVAL, "point %ld: no such point", id);
	if (sw->fast) {
		*out = sw->fast_base;
		for (int k = 0; k < sw->naxes; k++) {
			const struct axis *a = &sw->ax[k];
			double v = sweep_axis_num(a, sweep_axis_index(sw, id, k));

			if (a->par >= 0)
				out->par[a->par] = v;
			else
				memcpy((char *)out + a->off, &v, sizeof v);
		}
		(void)hb_scene_derive(out, NULL, 0);   /* an error shows in the validation */
		return HB_OK;
	}
	*out = sw->base;
	for (int k = 0; k < sw->naxes; k++) {
		const struct axis *a = &sw->ax[k];
		long i = sweep_axis_index(sw, id, k);
		struct hb_scene_error e;

		if (a->val == NULL) {
			if (hb_scene_set_number(out, a->key, sweep_axis_num(a, i), &e) == HB_OK)
				continue;
			hb_scene_error_str(&e, m, sizeof m);
		} else {
			m[0] = '\0';
			if (hb_scene_set(out, a->key, a->val[i], m, sizeof m) == HB_OK)
				continue;
		}
		return hb_status_set(msg, n, HB_EINVAL, "point %ld: %s=%s: %s", id, a->key,
		                     sweep_axis_text(a, i, t, sizeof t), m);
	}
	return HB_OK;
}

/* See sweep_impl.h. */
int
sweep_point_refused(const struct hb_sweep *sw, long id, const char *why, char *msg, size_t n)
{
	char vals[512] = "", t[64];
	size_t l = 0;

	for (int k = 0; k < sw->naxes && l < sizeof vals; k++)
		l += (size_t)snprintf(vals + l, sizeof vals - l, "%s%s=%s", k ? " " : "",
		                      sw->ax[k].key,
		                      sweep_axis_text(&sw->ax[k], sweep_axis_index(sw, id, k), t, sizeof t));
	return hb_status_set(msg, n, HB_EINVAL, "point %ld (%s): %s", id, vals, why);
}

int
hb_sweep_point_scene(const struct hb_sweep *sw, long id, struct hb_scene *out, char *msg, size_t n)
{
	char m[512];
	int rc;

	if ((rc = sweep_point_values(sw, id, out, msg, n)) != HB_OK)
		return rc;
	m[0] = '\0';
	if (hb_scene_validate(out, m, sizeof m) != HB_OK)
		return sweep_point_refused(sw, id, m, msg, n);
	return HB_OK;
}

int
hb_sweep_check(const struct hb_sweep *sw, char *msg, size_t n)
{
	struct hb_scene sc;
	long np = hb_sweep_npoints(sw);

	if (np == 0)
		return hb_status_set(msg, n, HB_EINVAL, "nothing to vary; expected at least one "
		                  "--vary KEY=SPEC");
	if (sw->rf.on) {
		/* The grid's points; those between are in ranges of valid values. */
		for (long g = 0; g < sweep_refine_grid_points(sw); g++)
			if (hb_sweep_point_scene(sw, sweep_refine_grid_id(sw, g), &sc, msg, n) != HB_OK)
				return HB_EINVAL;
		return HB_OK;
	}
	for (long id = 0; id < np; id++)
		if (hb_sweep_point_scene(sw, id, &sc, msg, n) != HB_OK)
			return HB_EINVAL;
	return HB_OK;
}

size_t
hb_sweep_spec_format(const struct hb_sweep *sw, char *buf, size_t n)
{
	size_t len = hb_preset_format(&sw->base, buf, n);

	len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
	    "\n; The sweep (hybounce sweep FILE --out DIR runs it):\n");
	for (int k = 0; k < sw->naxes; k++)
		len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
		                        "; sweep: --vary %s=%s\n", sw->ax[k].key, sw->ax[k].spec);
	if (sw->rf.on)
		len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
		                        "; sweep: --refine %s\n", sw->rf.spec);
	if (sw->error)
		len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
		                        "%s\n", SWEEP_ERROR_LINE);
	return len;
}

/* id, the axes, status, message, the run observables (observables.h),
 * [OBS_err of each with an error bar (--error),] [refined,] cpu_s. */
size_t
hb_sweep_runs_header(const struct hb_sweep *sw, char *buf, size_t n)
{
	size_t len = (size_t)snprintf(buf, n, "id");

	for (int k = 0; k < sw->naxes; k++)
		len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
		                        ",%s", sw->ax[k].key);
	len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
	                        ",status,message");
	for (int k = 0; k < HB_OBS_COUNT; k++)
		len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
		                        ",%s", hb_observables[k].name);
	for (int k = 0; sw->error && k < HB_OBS_COUNT; k++)
		if (hb_error_observable(k))
			len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0,
			                        ",%s_err", hb_observables[k].name);
	len += (size_t)snprintf(len < n ? buf + len : NULL, len < n ? n - len : 0, "%s,cpu_s",
	                        sw->rf.on ? ",refined" : "");
	return len;
}

const struct hb_scene *
sweep_base(const struct hb_sweep *sw)
{
	return &sw->base;
}
