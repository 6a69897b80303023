/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_data.c - measured data for fit.c once read (fit_csv.c reads the CSV
 * files): the invariant every loader ends with, sequences from impact
 * times, and the data points in the one order that fit.c, fit_eval.c and
 * the front ends share.  See fit.h for the formats.
 *
 * Invariant: a struct hb_fit_data returned with status 0 has n >= 1 rows
 * and at least one data point; every value of a present column is finite
 * or NAN (a missed value, whose sd is NAN too); every sd of a value is > 0;
 * sequences and heights have ntrials >= 1 trials, each of its rows in
 * trial_row; the present t_e of a trial are strictly increasing, at least
 * 2; a trial of heights starts with its h_0 > 0 and has a rebound height
 * >= 0; the v_i of drops are given and negative.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"

static const char *const obs_names[HB_FIT_OBS_COUNT] = { "t_e", "e", "x_c_r", "t_d", "h" };

const char *
hb_fit_obs_name(int obs)
{
	return obs >= 0 && obs < HB_FIT_OBS_COUNT ? obs_names[obs] : "?";
}

void
hb_fit_data_free(struct hb_fit_data *d)
{
	if (d == NULL)
		return;
	free(d->vi);
	for (int k = 0; k < HB_FIT_OBS_COUNT; k++) {
		free(d->col[k]);
		free(d->sd[k]);
	}
	free(d->trial_row);
	free(d->file_row);
	memset(d, 0, sizeof *d);
}

/* "trial 2 (data rows 5-9): " for a file of several trials, else "". */
static void
trial_str(const struct hb_fit_data *d, size_t t, char *buf, size_t n)
{
	if (d->ntrials < 2)
		buf[0] = '\0';
	else
		snprintf(buf, n, "trial %zu (data rows %zu-%zu): ", t + 1,
		    d->file_row[d->trial_row[t]] + 1, d->file_row[d->trial_row[t + 1] - 1] + 1);
}

int
fit_data_check(struct hb_fit_data *d, char *msg, size_t mn)
{
	char tr[96];

	if (d->n == 0)
		return hb_status_set(msg, mn, HB_EINVAL, "%s: no data rows; accepted: a "
		    "header row, then a row of numbers per measurement", d->source);
	for (int k = 0; k < HB_FIT_OBS_COUNT; k++)
		for (size_t i = 0; d->sd[k] != NULL && i < d->n; i++) {
			if (d->col[k] == NULL || isnan(d->col[k][i])) {
				d->sd[k][i] = NAN; /* the sd of a missed value means nothing */
				continue;
			}
			if (!(d->sd[k][i] > 0))
				return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu: sd_%s = %g; "
				    "accepted: a standard deviation > 0 where %s is given", d->source,
				    d->file_row[i] + 1, obs_names[k], d->sd[k][i], obs_names[k]);
		}
	if (d->kind == HB_FIT_SEQUENCE) {
		const double *t = d->col[HB_FIT_OBS_TE];

		for (size_t k = 0; k < d->ntrials; k++) {
			size_t have = 0, prev = SIZE_MAX;

			trial_str(d, k, tr, sizeof tr);
			for (size_t i = d->trial_row[k]; i < d->trial_row[k + 1]; i++) {
				if (isnan(t[i]))
					continue;
				if (prev != SIZE_MAX && !(t[i] > t[prev]))
					return hb_status_set(msg, mn, HB_EINVAL, "%s: %sdata row %zu: t_e = "
					    "%.9g is not after the previous one (%.9g); accepted: impact "
					    "times in increasing order", d->source, tr, d->file_row[i] + 1,
					    t[i], t[prev]);
				prev = i;
				have++;
			}
			if (have < 2)
				return hb_status_set(msg, mn, HB_EINVAL, "%s: %sa sequence needs at least "
				    "2 impact times (the first one only aligns the clocks), it has %zu; "
				    "accepted: 2 or more rows of t_e%s", d->source, tr, have,
				    d->ntrials > 1 ? " per trial" : "");
		}
	} else if (d->kind == HB_FIT_HEIGHTS) {
		const double *h = d->col[HB_FIT_OBS_H];

		for (size_t k = 0; k < d->ntrials; k++) {
			size_t a = d->trial_row[k], have = 0;

			if (!(h[a] > 0))
				return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu, column h_0: "
				    "%g; accepted: the drop height, > 0", d->source, d->file_row[a] + 1,
				    h[a]);
			for (size_t i = a + 1; i < d->trial_row[k + 1]; i++) {
				if (isnan(h[i]))
					continue;
				if (h[i] < 0)
					return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu, column "
					    "h_%zu: %g; accepted: a rebound height >= 0", d->source,
					    d->file_row[i] + 1, i - a, h[i]);
				have++;
			}
			if (have == 0)
				return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu: no rebound "
				    "height; accepted: h_1 (or a later h_i) given in every row",
				    d->source, d->file_row[a] + 1);
		}
	} else {
		for (size_t i = 0; i < d->n; i++) {
			if (d->vi[i] == 0)
				return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu: v_i = 0; "
				    "accepted: an approach velocity other than 0", d->source, i + 1);
			d->vi[i] = -fabs(d->vi[i]);
		}
		if (d->col[HB_FIT_OBS_E] != NULL)
			for (size_t i = 0; i < d->n; i++)
				if (d->col[HB_FIT_OBS_E][i] < 0)
					return hb_status_set(msg, mn, HB_EINVAL, "%s: data row %zu: e = %g; "
					    "accepted: a restitution >= 0", d->source, i + 1,
					    d->col[HB_FIT_OBS_E][i]);
		if (hb_fit_npoints(d) == 0)
			return hb_status_set(msg, mn, HB_EINVAL, "%s: every value is missing (NA); "
			    "accepted: at least one measured e, x_c_r or t_d", d->source);
	}
	return HB_OK;
}

int
fit_data_one_trial(struct hb_fit_data *d)
{
	d->ntrials = 1;
	d->trial_row = malloc(2 * sizeof *d->trial_row);
	d->file_row = malloc((d->n ? d->n : 1) * sizeof *d->file_row);
	if (d->trial_row == NULL || d->file_row == NULL)
		return HB_ENOMEM;
	d->trial_row[0] = 0;
	d->trial_row[1] = d->n;
	for (size_t i = 0; i < d->n; i++)
		d->file_row[i] = i;
	return HB_OK;
}

int
hb_fit_data_from_times(const double *t, const double *sd, size_t n, const char *source,
                    struct hb_fit_data *d, char *msg, size_t mn)
{
	int st;

	memset(d, 0, sizeof *d);
	snprintf(d->source, sizeof d->source, "%s", source);
	d->kind = HB_FIT_SEQUENCE;
	d->n = n;
	d->col[HB_FIT_OBS_TE] = malloc((n ? n : 1) * sizeof(double));
	if (sd != NULL)
		d->sd[HB_FIT_OBS_TE] = malloc((n ? n : 1) * sizeof(double));
	if (d->col[HB_FIT_OBS_TE] == NULL || (sd != NULL && d->sd[HB_FIT_OBS_TE] == NULL)
	    || fit_data_one_trial(d) != HB_OK) {
		hb_fit_data_free(d);
		return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
	}
	for (size_t i = 0; i < n; i++) {
		if (!isfinite(t[i])) {
			hb_fit_data_free(d);
			return hb_status_set(msg, mn, HB_EINVAL, "%s: impact %zu: t_e = %g; accepted: "
			    "finite times", source, i, t[i]);
		}
		d->col[HB_FIT_OBS_TE][i] = t[i];
		if (sd != NULL)
			d->sd[HB_FIT_OBS_TE][i] = sd[i];
	}
	if ((st = fit_data_check(d, msg, mn)) != HB_OK)
		hb_fit_data_free(d);
	return st;
}

/* The first row of trial k with a value of column v (there is one: the invariant). */
static size_t
first_given(const struct hb_fit_data *d, const double *v, size_t k)
{
	size_t i = d->trial_row[k];

	while (i + 1 < d->trial_row[k + 1] && isnan(v[i]))
		i++;
	return i;
}

size_t
fit_points(const struct hb_fit_data *d, struct hb_fit_point *pt, size_t *pidx, int *scaled)
{
	size_t np = 0;

	if (pidx != NULL)
		for (size_t i = 0; i < (size_t)HB_FIT_OBS_COUNT * d->n; i++)
			pidx[i] = SIZE_MAX;
	if (scaled != NULL)
		*scaled = 0;
	if (d->kind == HB_FIT_SEQUENCE || d->kind == HB_FIT_HEIGHTS) {
		int ob = d->kind == HB_FIT_SEQUENCE ? HB_FIT_OBS_TE : HB_FIT_OBS_H;
		const double *v = d->col[ob], *sd = d->sd[ob];
		double m = 0;

		/* the weight without sd: the largest |value| of the column */
		for (size_t k = 0; k < d->ntrials; k++) {
			size_t r = d->kind == HB_FIT_SEQUENCE ? first_given(d, v, k) : d->trial_row[k];

			for (size_t i = r + 1; i < d->trial_row[k + 1]; i++)
				if (!isnan(v[i]))
					m = fmax(m, fabs(d->kind == HB_FIT_SEQUENCE ? v[i] - v[r] : v[i]));
		}
		if (!(m > 0))
			m = 1;
		if (scaled != NULL)
			*scaled = sd == NULL;
		for (size_t k = 0; k < d->ntrials; k++) {
			size_t r = d->kind == HB_FIT_SEQUENCE ? first_given(d, v, k) : d->trial_row[k];

			for (size_t i = r + 1; i < d->trial_row[k + 1]; i++) {
				if (isnan(v[i]))
					continue;
				if (pt != NULL) {
					struct hb_fit_point *p = &pt[np];

					memset(p, 0, sizeof *p);
					p->row = d->file_row[i];
					p->obs = ob;
					p->trial = k;
					p->index = i - d->trial_row[k];
					if (d->kind == HB_FIT_SEQUENCE) {
						p->measured = v[i] - v[r];
						/* the difference of two times: the variances add */
						p->sd = sd != NULL ? hypot(sd[i], sd[r]) : m;
					} else {
						p->measured = v[i];
						p->sd = sd != NULL ? sd[i] : m;
					}
				}
				if (pidx != NULL)
					pidx[(size_t)ob * d->n + i] = np;
				np++;
			}
		}
		return np;
	}
	for (int ob = HB_FIT_OBS_E; ob < HB_FIT_OBS_COUNT; ob++) {
		double m = 0;

		if (d->col[ob] == NULL)
			continue;
		for (size_t i = 0; i < d->n; i++)
			if (!isnan(d->col[ob][i]))
				m = fmax(m, fabs(d->col[ob][i]));
		if (!(m > 0))
			m = 1;
		if (d->sd[ob] == NULL && scaled != NULL)
			*scaled = 1;
		for (size_t i = 0; i < d->n; i++) {
			if (isnan(d->col[ob][i]))
				continue;
			if (pt != NULL) {
				struct hb_fit_point *p = &pt[np];

				memset(p, 0, sizeof *p);
				p->row = i;
				p->obs = ob;
				p->trial = i;
				p->measured = d->col[ob][i];
				p->sd = d->sd[ob] != NULL ? d->sd[ob][i] : m;
			}
			if (pidx != NULL)
				pidx[(size_t)ob * d->n + i] = np;
			np++;
		}
	}
	return np;
}

size_t
hb_fit_npoints(const struct hb_fit_data *d)
{
	if (d->n == 0 || (d->kind != HB_FIT_DROPS && d->trial_row == NULL))
		return 0;
	return fit_points(d, NULL, NULL, NULL);
}

size_t
hb_fit_data_points(const struct hb_fit_data *d, struct hb_fit_point *pt)
{
	if (d->n == 0 || (d->kind != HB_FIT_DROPS && d->trial_row == NULL))
		return 0;
	return fit_points(d, pt, NULL, NULL);
}
