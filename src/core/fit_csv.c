/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_csv.c - the CSV files of measured data, as instruments and
 * spreadsheets write them: recognised by their header (a bouncing
 * sequence by t_e, drop and rebound heights by h_0, h_1 ..., separate
 * drops by v_i and e), a unit in a header ("t_e [ms]") converting its
 * column to SI (units.h), "NA" or an empty cell for a missed value, a
 * column "trial" for several sequences in one file, a UTF-8 byte-order
 * mark skipped.  Anything else is refused with the row, the column and
 * what is accepted.  See fit.h for the formats; fit_data.c checks the
 * invariant of what is read.
 */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "hybounce/units.h"
#include "cnum.h"
#include "fit_impl.h"

enum { MAX_COLS = 64, MAX_H = MAX_COLS - 2 };

/* What a column of the file is. */
enum role { R_NONE = 0, R_OBS, R_SD, R_VI, R_H, R_SDH, R_TRIAL };

struct column {
	int role;        /* enum role */
	int obs;         /* R_OBS, R_SD: enum hb_fit_obs */
	int hk;          /* R_H: i of h_i */
	double scale;    /* SI value of one unit of the header */
	double *v;       /* a value per data row (NAN: missed) */
	size_t cap;
	char name[48];   /* as in the header, for messages */
};

#define NOTHING_RECOGNISED "no data columns recognised; accepted: a column t_e (impact " \
	"times of a bouncing sequence; several sequences with a column trial), h_0, h_1, ... " \
	"(drop and rebound heights, a drop per row), or v_i with e, x_c_r and/or t_d " \
	"(separate drops), each optionally with sd_NAME and a unit in the header (t_e [ms])"

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

/* 1 for a missed value: an empty cell, NA or N/A. */
static int
missing(const char *s)
{
	return s[0] == '\0' || cnum_casecmp(s, "NA") == 0 || cnum_casecmp(s, "N/A") == 0;
}

/* The role of a column name (without its unit). */
static void
role_of(const char *name, struct column *c)
{
	static const char *const obs[HB_FIT_OBS_COUNT] = { "t_e", "e", "x_c_r", "t_d", NULL };

	c->role = R_NONE;
	for (int k = 0; k < HB_FIT_OBS_COUNT; k++) {
		if (obs[k] == NULL)
			continue;
		if (strcmp(name, obs[k]) == 0)
			c->role = R_OBS, c->obs = k;
		else if (strncmp(name, "sd_", 3) == 0 && strcmp(name + 3, obs[k]) == 0)
			c->role = R_SD, c->obs = k;
	}
	if (strcmp(name, "v_i") == 0)
		c->role = R_VI;
	else if (strcmp(name, "sd_h") == 0)
		c->role = R_SDH;
	else if (strcmp(name, "trial") == 0)
		c->role = R_TRIAL;
	else if (name[0] == 'h' && name[1] == '_' && cnum_isdigit((unsigned char)name[2])) {
		char *end;
		long k = strtol(name + 2, &end, 10);

		if (*end == '\0' && (name[2] != '0' || name[3] == '\0') && k <= MAX_H)
			c->role = R_H, c->hk = (int)k;
	}
}

/* The dimension of a column and an example of its units, for messages. */
static struct hb_unit_dim
dim_of(const struct column *c, const char **eg)
{
	if (c->role == R_VI) {
		*eg = "m/s, mm/s";
		return hb_unit_velocity;
	}
	if (c->role == R_H || c->role == R_SDH || ((c->role == R_OBS || c->role == R_SD)
	                                           && c->obs == HB_FIT_OBS_XCR)) {
		*eg = "m, mm, um";
		return hb_unit_length;
	}
	if ((c->role == R_OBS || c->role == R_SD) && c->obs == HB_FIT_OBS_E) {
		*eg = "-, 1 or none";
		return hb_unit_none;
	}
	*eg = "s, ms, us";
	return hb_unit_time;
}

/*
 * Reads header field f of column col (1-based) into c: its name, role and
 * the unit in [] or () at its end.  A column of no known name is ignored,
 * whatever follows it.
 */
static int
header_col(const char *path, long lineno, int col, const char *f, struct column *c,
           char *msg, size_t mn)
{
	char name[48], unit[64];
	const char *b = strpbrk(f, "[("), *eg;
	size_t nl = b != NULL ? (size_t)(b - f) : strlen(f);
	struct hb_unit_dim dim;
	char um[256], num[80];

	snprintf(c->name, sizeof c->name, "%s", f);
	c->scale = 1;
	while (nl > 0 && isspace((unsigned char)f[nl - 1]))
		nl--;
	if (nl >= sizeof name) {
		c->role = R_NONE;
		return HB_OK;
	}
	memcpy(name, f, nl);
	name[nl] = '\0';
	role_of(name, c);
	if (c->role == R_NONE || b == NULL)
		return HB_OK;
	{
		size_t ul = strlen(b + 1);
		char close = *b == '[' ? ']' : ')';

		if (ul == 0 || b[ul] != close || ul - 1 >= sizeof unit)
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row, column %d "
			    "(%s): the unit is not closed by '%c'; accepted: NAME [UNIT] or NAME "
			    "(UNIT), as t_e [ms]", path, lineno, col, f, close);
		memcpy(unit, b + 1, ul - 1);
		unit[ul - 1] = '\0';
	}
	if (c->role == R_TRIAL)
		return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row, column %d (%s): a "
		    "trial is a label; accepted: trial, without a unit", path, lineno, col, f);
	dim = dim_of(c, &eg);
	{
		char *u = unit, *e = unit + strlen(unit);

		while (isspace((unsigned char)*u))
			u++;
		while (e > u && isspace((unsigned char)e[-1]))
			*--e = '\0';
		if (dim.kg == 0 && dim.m == 0 && dim.s == 0
		    && (*u == '\0' || strcmp(u, "-") == 0 || strcmp(u, "1") == 0))
			return HB_OK;
		snprintf(num, sizeof num, "1 %s", u);
		if (*u == '\0' || hb_units_parse(num, dim, &c->scale, um, sizeof um) != HB_OK
		    || !(c->scale > 0) || !isfinite(c->scale))
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row, column %d (%s): "
			    "unit '%s'%s%s; accepted: a unit of its quantity (%s)", path, lineno,
			    col, f, u, *u != '\0' ? ": " : "", *u != '\0' ? um : "", eg);
	}
	return HB_OK;
}

/* The kind of data the header names; a column that kind does not use becomes R_NONE. */
static int
header_kind(const char *path, long lineno, struct column *c, int nc, struct hb_fit_data *d,
            int *kmax, char *msg, size_t mn)
{
	int has_te = 0, has_vi = 0, has_drop_obs = 0, hcol[MAX_H + 1];

	*kmax = -1;
	for (int k = 0; k <= MAX_H; k++)
		hcol[k] = -1;
	for (int i = 0; i < nc; i++) {
		for (int j = 0; j < i; j++)
			if (c[i].role != R_NONE && c[j].role == c[i].role && c[j].obs == c[i].obs
			    && c[j].hk == c[i].hk)
				return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row, column %d "
				    "(%s): the same as column %d (%s); accepted: each column once",
				    path, lineno, i + 1, c[i].name, j + 1, c[j].name);
		has_te |= c[i].role == R_OBS && c[i].obs == HB_FIT_OBS_TE;
		has_vi |= c[i].role == R_VI;
		has_drop_obs |= c[i].role == R_OBS && c[i].obs != HB_FIT_OBS_TE;
		if (c[i].role == R_H) {
			hcol[c[i].hk] = i;
			if (c[i].hk > *kmax)
				*kmax = c[i].hk;
		}
	}
	if (*kmax >= 0) {
		if (has_te || has_vi)
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row: heights (h_0 ...) "
			    "and %s in one file; accepted: one kind of data per file", path, lineno,
			    has_te ? "impact times (t_e)" : "drops (v_i)");
		for (int k = 0; k <= *kmax; k++)
			if (hcol[k] < 0)
				return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row: h_%d without "
				    "h_%d; accepted: h_0 (the drop height), h_1, ... h_K (the apex after "
				    "each bounce), every one", path, lineno, *kmax, k);
		if (*kmax < 1)
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: header row: h_0 without "
			    "h_1; accepted: h_0 (the drop height), h_1, ... h_K (the apex after each "
			    "bounce)", path, lineno);
		d->kind = HB_FIT_HEIGHTS;
		for (int i = 0; i < nc; i++)
			if (c[i].role != R_H && c[i].role != R_SDH)
				c[i].role = R_NONE;
		return HB_OK;
	}
	if (has_te) {
		d->kind = HB_FIT_SEQUENCE;
		for (int i = 0; i < nc; i++)
			if (!((c[i].role == R_OBS || c[i].role == R_SD) && c[i].obs == HB_FIT_OBS_TE)
			    && c[i].role != R_TRIAL)
				c[i].role = R_NONE;
		return HB_OK;
	}
	if (has_vi && has_drop_obs) {
		d->kind = HB_FIT_DROPS;
		for (int i = 0; i < nc; i++) {
			int used = c[i].role == R_VI || c[i].role == R_OBS;

			/* an sd counts with its column */
			for (int j = 0; c[i].role == R_SD && j < nc; j++)
				used |= c[j].role == R_OBS && c[j].obs == c[i].obs;
			if (!used)
				c[i].role = R_NONE;
		}
		return HB_OK;
	}
	return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: " NOTHING_RECOGNISED, path, lineno);
}

/* Trials seen: labels in order, and each data row's trial. */
struct trials {
	char **label;
	size_t n, cap;
	size_t *of_row;
	size_t rcap;
};

static void
trials_free(struct trials *t)
{
	for (size_t i = 0; i < t->n; i++)
		free(t->label[i]);
	free(t->label);
	free(t->of_row);
}

/* Records row's trial label s; a label seen before, not just above, is refused. */
static int
trial_row(struct trials *t, size_t row, const char *s, const char *path, long lineno,
          char *msg, size_t mn)
{
	if (s[0] == '\0')
		return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu, column trial: "
		    "empty; accepted: a label for the trial (a number or a name)", path, lineno,
		    row + 1);
	if (t->n == 0 || strcmp(t->label[t->n - 1], s) != 0) {
		for (size_t i = 0; i + 1 < t->n; i++)
			if (strcmp(t->label[i], s) == 0)
				return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu, column "
				    "trial: '%.40s' again after other trials; accepted: the rows of a "
				    "trial one after another", path, lineno, row + 1, s);
		if (t->n == t->cap) {
			size_t nc = t->cap ? 2 * t->cap : 16;
			char **l = realloc(t->label, nc * sizeof *l);

			if (l == NULL)
				return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
			t->label = l;
			t->cap = nc;
		}
		if ((t->label[t->n] = strdup(s)) == NULL)
			return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
		t->n++;
	}
	if (row == t->rcap) {
		size_t nc = t->rcap ? 2 * t->rcap : 64;
		size_t *r = realloc(t->of_row, nc * sizeof *r);

		if (r == NULL)
			return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
		t->of_row = r;
		t->rcap = nc;
	}
	t->of_row[row] = t->n - 1;
	return HB_OK;
}

/* Moves the columns read (nrow rows) into d, heights a trial per row. */
static int
assemble(struct hb_fit_data *d, struct column *c, int nc, size_t nrow, int kmax,
         const struct trials *tr)
{
	if (d->kind == HB_FIT_HEIGHTS) {
		size_t k1 = (size_t)kmax + 1;
		const double *sdh = NULL;

		for (int i = 0; i < nc; i++)
			if (c[i].role == R_SDH)
				sdh = c[i].v;
		d->n = nrow * k1;
		d->ntrials = nrow;
		d->col[HB_FIT_OBS_H] = malloc((d->n ? d->n : 1) * sizeof(double));
		d->sd[HB_FIT_OBS_H] = sdh != NULL ? malloc((d->n ? d->n : 1) * sizeof(double)) : NULL;
		d->trial_row = malloc((nrow + 1) * sizeof *d->trial_row);
		d->file_row = malloc((d->n ? d->n : 1) * sizeof *d->file_row);
		if (d->col[HB_FIT_OBS_H] == NULL || (sdh != NULL && d->sd[HB_FIT_OBS_H] == NULL)
		    || d->trial_row == NULL || d->file_row == NULL)
			return HB_ENOMEM;
		for (int i = 0; i < nc; i++)
			for (size_t t = 0; c[i].role == R_H && t < nrow; t++)
				d->col[HB_FIT_OBS_H][t * k1 + (size_t)c[i].hk] = c[i].v[t];
		for (size_t t = 0; t < nrow; t++) {
			d->trial_row[t] = t * k1;
			for (size_t k = 0; k < k1; k++) {
				d->file_row[t * k1 + k] = t;
				if (sdh != NULL)
					d->sd[HB_FIT_OBS_H][t * k1 + k] = sdh[t];
			}
		}
		d->trial_row[nrow] = d->n;
		return HB_OK;
	}
	d->n = nrow;
	for (int i = 0; i < nc; i++) {
		double **dst = c[i].role == R_VI ? &d->vi : c[i].role == R_OBS ? &d->col[c[i].obs]
		             : c[i].role == R_SD ? &d->sd[c[i].obs] : NULL;

		if (dst != NULL) {
			*dst = c[i].v;
			c[i].v = NULL;
		}
	}
	if (d->kind == HB_FIT_DROPS) {
		if (fit_data_one_trial(d) != HB_OK)
			return HB_ENOMEM;
		free(d->trial_row);
		d->trial_row = NULL;
		d->ntrials = 0;
		return HB_OK;
	}
	if (tr->n <= 1)
		return fit_data_one_trial(d);
	d->ntrials = tr->n;
	d->trial_row = malloc((tr->n + 1) * sizeof *d->trial_row);
	d->file_row = malloc(nrow * sizeof *d->file_row);
	if (d->trial_row == NULL || d->file_row == NULL)
		return HB_ENOMEM;
	d->trial_row[0] = 0;
	for (size_t i = 0; i < nrow; i++) {
		d->file_row[i] = i;
		if (i > 0 && tr->of_row[i] != tr->of_row[i - 1])
			d->trial_row[tr->of_row[i]] = i;
	}
	d->trial_row[tr->n] = nrow;
	return HB_OK;
}

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

/* One data row's field c (1-based col) into its column; row is the data row (0-based). */
static int
cell(struct column *c, int col, const char *s, size_t row, const char *path, long lineno,
     char *msg, size_t mn)
{
	char *end;
	double v;

	if (missing(s)) {
		if (c->role == R_VI || (c->role == R_H && c->hk == 0))
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu, column %d "
			    "(%s): missing; accepted: a finite number (%s)", path, lineno, row + 1,
			    col, c->name, c->role == R_VI ? "every drop's approach velocity"
			    : "every drop's height");
		v = NAN;
	} else {
		errno = 0;
		v = cnum_strtod(s, &end) * c->scale;
		if (*end != '\0' || !isfinite(v)) {
			int unit = *end != '\0' && end != s && cnum_isalpha((unsigned char)end[strspn(end, " ")]);

			return hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu, column %s: "
			    "'%.40s%s'; accepted: a finite number (SI, or the unit of the header), or "
			    "NA or an empty cell for a missed value%s", path, lineno, row + 1, c->name,
			    s, strlen(s) > 40 ? "..." : "", unit ? "; a unit goes in the header, as "
			    "t_e [ms]" : "");
		}
	}
	if (push(&c->v, row, &c->cap, v) != 0)
		return hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
	return HB_OK;
}

int
hb_fit_data_read(FILE *f, const char *path, struct hb_fit_data *d, char *msg, size_t mn)
{
	char *line = NULL, *fld[MAX_COLS];
	size_t lcap = 0, nrow = 0;
	ssize_t len;
	long lineno = 0;
	int ncol = 0, st = HB_OK, have_hdr = 0, kmax = -1;
	struct column col[MAX_COLS];
	struct trials tr;

	memset(d, 0, sizeof *d);
	memset(col, 0, sizeof col);
	memset(&tr, 0, sizeof tr);
	snprintf(d->source, sizeof d->source, "%s", path);

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
				    lineno, nrow + 1, c + 1, col[c].name);
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
			for (int c = 0; c < nf; c++)
				if ((st = header_col(path, lineno, c + 1, fld[c], &col[c], msg, mn)) != HB_OK)
					goto out;
			if ((st = header_kind(path, lineno, col, nf, d, &kmax, msg, mn)) != HB_OK)
				goto out;
			continue;
		}
		if (nf != ncol) {
			st = hb_status_set(msg, mn, HB_EINVAL, "%s:%ld: data row %zu: %d fields, the "
			    "header has %d; accepted: one field per column of the header, separated "
			    "by commas (numbers with a decimal point; an empty field for a missed "
			    "value)", path, lineno, nrow + 1, nf, ncol);
			goto out;
		}
		for (int c = 0; c < nf; c++) {
			if (col[c].role == R_NONE)
				continue;
			st = col[c].role == R_TRIAL
			    ? trial_row(&tr, nrow, fld[c], path, lineno, msg, mn)
			    : cell(&col[c], c + 1, fld[c], nrow, path, lineno, msg, mn);
			if (st != HB_OK)
				goto out;
		}
		nrow++;
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
	if (nrow == 0) {
		st = hb_status_set(msg, mn, HB_EINVAL, "%s: no data rows; accepted: a header row, "
		    "then a row of numbers per measurement", path);
		goto out;
	}
	if (assemble(d, col, ncol, nrow, kmax, &tr) != HB_OK) {
		st = hb_status_set(msg, mn, HB_ENOMEM, "out of memory");
		goto out;
	}
	st = fit_data_check(d, msg, mn);
out:
	free(line);
	for (int c = 0; c < MAX_COLS; c++)
		free(col[c].v);
	trials_free(&tr);
	if (st != HB_OK)
		hb_fit_data_free(d);
	return st;
}
