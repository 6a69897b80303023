/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_data.c - measured data for fit.c: CSV files recognised by their
 * columns (a bouncing sequence by t_e, separate drops by v_i and e), and
 * sequences from impact times.  See fit.h for the formats.
 *
 * Invariant: a struct hb_fit_data returned with status 0 has n >= 1 rows, every
 * present column holds n finite values, every sd is > 0, and the t_e of a
 * sequence are strictly increasing.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/input.h"
#include "hybounce/status.h"
#include "cnum.h"

enum { MAX_COLS = 64 };

static const char *const obs_names[HB_FIT_OBS_COUNT] = { "t_e", "e", "x_c_r", "t_d" };

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
	memset(d, 0, sizeof *d);
}

/* Splits line in place at commas; trims blanks and one pair of quotes. */
static int
split(char *line, char **f, int max)
{
	int nf = 0;
	char *p = line;

	for (;;) {
		char *end = strchr(p, ',');
		char *s = p, *e;

		if (end != NULL)
			*end = '\0';
		while (isspace((unsigned char)*s))
			s++;
		e = s + strlen(s);
		while (e > s && isspace((unsigned char)e[-1]))
			*--e = '\0';
		if (e - s >= 2 && *s == '"' && e[-1] == '"') {
			e[-1] = '\0';
			s++;
		}
		if (nf == max)
			return -1;
		f[nf++] = s;
		if (end == NULL)
			return nf;
		p = end + 1;
	}
}

/* Appends v to a growing array. */
static int
push(double **a, size_t n, size_t *cap, double v)
{
	if (n == *cap) {
		size_t nc = *cap ? 2 * *cap : 64;
		double *t = realloc(*a, nc * sizeof *t);

		if (t == NULL)
			return -1;
		*a = t;
		*cap = nc;
	}
	(*a)[n] = v;
	return 0;
}

/* Checks the invariant of the header comment. */
static int
check_data(struct hb_fit_data *d, char *msg, size_t mn)
{
	if (d->n == 0)
		return hb_status_set(msg, mn, HB_EINVAL, "%s: no data rows; accepted: a "
		    "header row, then a row of numbers per measurement", d->source);
	for (int k = 0; k < HB_FIT_OBS_COUNT; k++)
		for (size_t i = 0; d->sd[k] != NULL && i < d->n; i++)
			if (!(d->sd[k][i] > 0))
				return hb_status_set(msg, mn, HB_EINVAL, "%s: row %zu: sd_%s = %g; "
				    "accepted: a standard deviation > 0", d->source, i + 1,
				    obs_names[k], d->sd[k][i]);
	if (d->kind == HB_FIT_SEQUENCE) {
		if (d->n < 2)
			return hb_status_set(msg, mn, HB_EINVAL, "%s: a sequence needs at least 2 "
			    "impact times (the first one only aligns the clocks); accepted: 2 or "
			    "more rows of t_e", d->source);
		for (size_t i = 1; i < d->n; i++)
			if (!(d->col[HB_FIT_OBS_TE][i] > d->col[HB_FIT_OBS_TE][i - 1]))
				return hb_status_set(msg, mn, HB_EINVAL, "%s: row %zu: t_e = %.9g is "
				    "not after the previous one (%.9g); accepted: impact times in "
				    "increasing order", d->source, i + 1, d->col[HB_FIT_OBS_TE][i],
				    d->col[HB_FIT_OBS_TE][i - 1]);
	} else {
		for (size_t i = 0; i < d->n; i++) {
			if (d->vi[i] == 0)
				return hb_status_set(msg, mn, HB_EINVAL, "%s: row %zu: v_i = 0; accepted: "
				    "an approach velocity other than 0", d->source, i + 1);
			d->vi[i] = -fabs(d->vi[i]);
		}
		if (d->col[HB_FIT_OBS_E] != NULL)
			for (size_t i = 0; i < d->n; i++)
				if (d->col[HB_FIT_OBS_E][i] < 0)
					return hb_status_set(msg, mn, HB_EINVAL, "%s: row %zu: e = %g; "
					    "accepted: a restitution >= 0", d->source, i + 1,
					    d->col[HB_FIT_OBS_E][i]);
	}
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
	if (d->col[HB_FIT_OBS_TE] == NULL || (sd != NULL && d->sd[HB_FIT_OBS_TE] == NULL)) {
		hb_fit_data_free(d);
		return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
	}
	for (size_t i = 0; i < n; i++) {
		d->col[HB_FIT_OBS_TE][i] = t[i];
		if (sd != NULL)
			d->sd[HB_FIT_OBS_TE][i] = sd[i];
	}
	if ((st = check_data(d, msg, mn)) != HB_OK)
		hb_fit_data_free(d);
	return st;
}

/* Which column of the file feeds which array: -1 ignored. */
struct colmap {
	double **dst;
	size_t cap;
};

int
hb_fit_data_parse(const char *text, size_t len, const char *name, struct hb_fit_data *d,
                  char *msg, size_t mn)
{
	FILE *f;
	int st;

	memset(d, 0, sizeof *d);
	if (len == 0)
		return hb_status_set(msg, mn, HB_EINVAL, "%s: empty file; accepted: a CSV file "
		    "with a header row (t_e, or v_i and e ...)", name);
	if ((f = fmemopen((void *)text, len, "r")) == NULL)
		return hb_status_set(msg, mn, HB_ENOMEM, "%s: out of memory", name);
	st = hb_fit_data_read(f, name, d, msg, mn);
	fclose(f);
	return st;
}

int
hb_fit_data_read(FILE *f, const char *path, struct hb_fit_data *d, char *msg, size_t mn)
{
	char *line = NULL, *fld[MAX_COLS];
	size_t lcap = 0;
	ssize_t len;
	long lineno = 0;
	int ncol = 0, st = HB_OK, have_hdr = 0;
	int idx_vi = -1, idx[HB_FIT_OBS_COUNT], idx_sd[HB_FIT_OBS_COUNT];
	struct colmap map[MAX_COLS];
	char hname[MAX_COLS][32];

	memset(d, 0, sizeof *d);
	memset(map, 0, sizeof map);
	snprintf(d->source, sizeof d->source, "%s", path);
	for (int k = 0; k < HB_FIT_OBS_COUNT; k++)
		idx[k] = idx_sd[k] = -1;

	while ((len = getline(&line, &lcap, f)) != -1) {
		char *p = line;
		int nf;

		lineno++;
		if (strlen(line) != (size_t)len) {
			/* A NUL byte would end the row there: refused, not truncated. */
			int c = 0;

			for (const char *q = line; *q != '\0'; q++)
				c += *q == ',';
			if (have_hdr && c < ncol)
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu, column %d "
				    "(%s): a NUL byte; accepted: text (a CSV file of numbers)", path,
				    lineno, d->n + 1, c + 1, hname[c]);
			else
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row, column %d: a "
				    "NUL byte; accepted: text (a CSV file of numbers)", path, lineno, c + 1);
			goto out;
		}
		/* A UTF-8 byte-order mark (a spreadsheet's CSV) is no part of the header. */
		if (lineno == 1 && len >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)
			p += 3;
		while (len > 0 && (line[len - 1] == '\n' || line[len - 1] == '\r'))
			line[--len] = '\0';
		while (isspace((unsigned char)*p))
			p++;
		if (*p == '\0' || *p == '#')
			continue;
		if ((nf = split(p, fld, MAX_COLS)) < 0) {
			st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: more than %d columns; "
			    "accepted: at most %d", path, lineno, MAX_COLS, MAX_COLS);
			goto out;
		}
		if (!have_hdr) { /* the header decides what the file is */
			have_hdr = 1;
			ncol = nf;
			for (int c = 0; c < nf; c++) {
				snprintf(hname[c], sizeof hname[c], "%s", fld[c]);
				for (int k = 0; k < HB_FIT_OBS_COUNT; k++) {
					if (strcmp(fld[c], obs_names[k]) == 0)
						idx[k] = c;
					if (strncmp(fld[c], "sd_", 3) == 0
					    && strcmp(fld[c] + 3, obs_names[k]) == 0)
						idx_sd[k] = c;
				}
				if (strcmp(fld[c], "v_i") == 0)
					idx_vi = c;
			}
			if (idx[HB_FIT_OBS_TE] >= 0) {
				d->kind = HB_FIT_SEQUENCE;
				map[idx[HB_FIT_OBS_TE]].dst = &d->col[HB_FIT_OBS_TE];
				if (idx_sd[HB_FIT_OBS_TE] >= 0)
					map[idx_sd[HB_FIT_OBS_TE]].dst = &d->sd[HB_FIT_OBS_TE];
			} else if (idx_vi >= 0 && (idx[HB_FIT_OBS_E] >= 0 || idx[HB_FIT_OBS_XCR] >= 0
			                           || idx[HB_FIT_OBS_TD] >= 0)) {
				d->kind = HB_FIT_DROPS;
				map[idx_vi].dst = &d->vi;
				for (int k = HB_FIT_OBS_E; k < HB_FIT_OBS_COUNT; k++) {
					if (idx[k] >= 0)
						map[idx[k]].dst = &d->col[k];
					if (idx[k] >= 0 && idx_sd[k] >= 0)
						map[idx_sd[k]].dst = &d->sd[k];
				}
			} else {
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: no data columns recognised; "
				    "accepted: a column t_e (impact times of one bouncing sequence), or "
				    "v_i with e, x_c_r and/or t_d (separate drops), each optionally with "
				    "sd_NAME", path, lineno);
				goto out;
			}
			continue;
		}
		if (nf != ncol) {
			st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: %d fields, the header has %d; "
			    "accepted: one field per column of the header, separated by commas "
			    "(numbers with a decimal point)", path, lineno, nf, ncol);
			goto out;
		}
		for (int c = 0; c < nf; c++) {
			char *end;
			double v;

			if (map[c].dst == NULL)
				continue;
			errno = 0;
			v = cnum_strtod(fld[c], &end);
			if (fld[c][0] == '\0' || *end != '\0' || !isfinite(v)) {
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: column %s: '%.40s%s'; "
				    "accepted: a finite number in SI units", path, lineno, hname[c],
				    fld[c], strlen(fld[c]) > 40 ? "..." : "");
				goto out;
			}
			if (push(map[c].dst, d->n, &map[c].cap, v) != 0) {
				st = hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
				goto out;
			}
		}
		d->n++;
	}
	if (ferror(f)) {
		st = hb_status_set(msg, mn, HB_EIO, "%s: %s", path, strerror(errno));
		goto out;
	}
	if (!have_hdr) {
		st = hb_status_set(msg, mn, HB_EINVAL, "%s: empty file; accepted: a CSV file with "
		    "a header row (t_e, or v_i and e ...)", path);
		goto out;
	}
	st = check_data(d, msg, mn);
out:
	free(line);
	if (st != HB_OK)
		hb_fit_data_free(d);
	return st;
}

size_t
hb_fit_npoints(const struct hb_fit_data *d)
{
	size_t np = 0;

	if (d->kind == HB_FIT_SEQUENCE)
		return d->n > 0 ? d->n - 1 : 0;
	for (int k = HB_FIT_OBS_E; k < HB_FIT_OBS_COUNT; k++)
		if (d->col[k] != NULL)
			np += d->n;
	return np;
}
