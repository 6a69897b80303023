/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_sweep.c - the figure of a sweep (plot_cmd.h: plot_build_sweep):
 * an observable against the varied key, one curve per collision index,
 * or a heat map over two varied keys with its colour legend.  It reads
 * what the sweep wrote (DIR/runs.csv, DIR/collisions.csv; the keys' units
 * from DIR/sweep.preset), so that `hybounce plot DIR` and
 * `hybounce sweep --plot` draw the same figure.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hybounce/columns.h"
#include "hybounce/observables.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "plot_cmd.h"

enum { MAX_FIELDS = 64, MAX_KEYS = 8 };

/* Splits a CSV line in place (quotes "..." with "" inside); the number of fields. */
static int
split(char *line, char **field, int max)
{
	int n = 0;
	char *p = line;

	line[strcspn(line, "\r\n")] = '\0';
	while (n < max) {
		if (*p == '"') {
			char *w = ++p;

			field[n++] = w;
			while (*p != '\0') {
				if (*p == '"' && p[1] == '"') {
					*w++ = '"';
					p += 2;
				} else if (*p == '"') {
					p++;
					break;
				} else {
					*w++ = *p++;
				}
			}
			*w = '\0';
			p += strcspn(p, ",");
		} else {
			field[n++] = p;
			p += strcspn(p, ",");
		}
		if (*p != ',') {
			*p = '\0';
			break;
		}
		*p++ = '\0';
	}
	return n;
}

static double
num(const char *s)
{
	char *end;
	double v;

	if (*s == '\0')
		return NAN;
	v = cnum_strtod(s, &end);
	return *end == '\0' ? v : NAN;
}

struct sweep_data {
	int nkeys;
	char key[MAX_KEYS][48];
	size_t n, cap;
	double *kv[MAX_KEYS];   /* the keys' values of run r */
	double *rv;             /* the runs.csv observable of run r */
	long *id;
};

static void
data_free(struct sweep_data *d)
{
	for (int k = 0; k < MAX_KEYS; k++)
		free(d->kv[k]);
	free(d->rv);
	free(d->id);
}

static int
grow(struct sweep_data *d)
{
	size_t cap = d->cap ? 2 * d->cap : 256;
	void *p;

	for (int k = 0; k < d->nkeys; k++) {
		if ((p = realloc(d->kv[k], cap * sizeof(double))) == NULL)
			return -1;
		d->kv[k] = p;
	}
	if ((p = realloc(d->rv, cap * sizeof(double))) == NULL)
		return -1;
	d->rv = p;
	if ((p = realloc(d->id, cap * sizeof(long))) == NULL)
		return -1;
	d->id = p;
	d->cap = cap;
	return 0;
}

/* runs.csv: the keys (the columns between id and status) and obs (-1: none). */
static int
read_runs(const char *path, const char *obs, struct sweep_data *d, char *msg, size_t mn)
{
	FILE *f = fopen(path, "r");
	char *line = NULL, *field[MAX_FIELDS];
	size_t cap = 0;
	int nf, status = -1, col = -1, rc = -1;
	long row = 1;

	if (f == NULL) {
		cnum_snprintf(msg, mn, "%s: cannot be read (%s); expected a sweep's folder (hybounce "
		              "sweep --out DIR) or its runs.csv", path, strerror(errno));
		return -1;
	}
	if (getline(&line, &cap, f) < 0 || (nf = split(line, field, MAX_FIELDS)) < 3 ||
	    strcmp(field[0], "id") != 0) {
		cnum_snprintf(msg, mn, "%s: not a sweep's runs.csv (its first column is not id); "
		              "expected a sweep's folder (hybounce sweep --out DIR) or its runs.csv",
		              path);
		goto out;
	}
	for (int k = 1; k < nf; k++)
		if (strcmp(field[k], "status") == 0) {
			status = k;
			break;
		}
	if (status < 2) {
		cnum_snprintf(msg, mn, "%s: not a sweep's runs.csv (no varied key before its "
		              "status column); expected id, the varied keys, status, ...", path);
		goto out;
	}
	d->nkeys = status - 1;
	if (d->nkeys > MAX_KEYS)
		d->nkeys = MAX_KEYS;
	for (int k = 0; k < d->nkeys; k++)
		cnum_snprintf(d->key[k], sizeof d->key[k], "%s", field[k + 1]);
	if (obs != NULL) {
		for (int k = status + 1; k < nf; k++)
			if (strcmp(field[k], obs) == 0)
				col = k;
	}
	while (getline(&line, &cap, f) >= 0) {
		row++;
		nf = split(line, field, MAX_FIELDS);
		if (nf <= status)
			continue;   /* a short line: a row being written */
		if (d->n == d->cap && grow(d) != 0) {
			cnum_snprintf(msg, mn, "out of memory reading %s", path);
			goto out;
		}
		d->id[d->n] = strtol(field[0], NULL, 10);
		for (int k = 0; k < d->nkeys; k++)
			d->kv[k][d->n] = num(field[k + 1]);
		d->rv[d->n] = col >= 0 && col < nf ? num(field[col]) : NAN;
		d->n++;
	}
	if (d->n == 0) {
		cnum_snprintf(msg, mn, "%s: no run in it yet; expected a sweep that has computed "
		              "points", path);
		goto out;
	}
	rc = 0;
out:
	(void)row;
	free(line);
	fclose(f);
	return rc;
}

/*
 * collisions.csv: val[r * ni + c] the value of column obs of collision
 * idx[c] of run r (NaN where it has none).
 */
static int
read_collisions(const char *path, const char *obs, const struct sweep_data *d,
                const long *idx, int ni, double *val, char *msg, size_t mn)
{
	FILE *f = fopen(path, "r");
	char *line = NULL, *field[MAX_FIELDS];
	size_t cap = 0;
	int nf, col = -1;

	for (size_t k = 0; k < d->n * (size_t)ni; k++)
		val[k] = NAN;
	if (f == NULL) {
		cnum_snprintf(msg, mn, "%s: cannot be read (%s); the collisions' observables come "
		              "from it", path, strerror(errno));
		return -1;
	}
	if (getline(&line, &cap, f) >= 0 && (nf = split(line, field, MAX_FIELDS)) > 2 &&
	    strcmp(field[0], "id") == 0 && strcmp(field[1], "i") == 0)
		for (int k = 2; k < nf; k++)
			if (strcmp(field[k], obs) == 0)
				col = k;
	if (col < 0) {
		cnum_snprintf(msg, mn, "%s: no column %s; expected a sweep's collisions.csv", path,
		              obs);
		free(line);
		fclose(f);
		return -1;
	}
	while (getline(&line, &cap, f) >= 0) {
		long id, i;
		size_t r;

		nf = split(line, field, MAX_FIELDS);
		if (nf <= col)
			continue;
		id = strtol(field[0], NULL, 10);
		i = strtol(field[1], NULL, 10);
		/* runs.csv holds the runs in id order, as a sweep writes them */
		r = id >= 0 && (size_t)id < d->n && d->id[id] == id ? (size_t)id : d->n;
		for (size_t k = 0; r == d->n && k < d->n; k++)
			if (d->id[k] == id)
				r = k;
		if (r == d->n)
			continue;
		for (int c = 0; c < ni; c++)
			if (idx[c] == i)
				val[r * (size_t)ni + (size_t)c] = num(field[col]);
	}
	free(line);
	fclose(f);
	return 0;
}

/* The distinct finite values of v (n of them), sorted, into u; their count. */
static size_t
distinct(const double *v, size_t n, double *u)
{
	size_t m = 0;

	for (size_t k = 0; k < n; k++)
		if (isfinite(v[k]))
			u[m++] = v[k];
	for (size_t a = 1; a < m; a++) {   /* insertion sort: sweeps come sorted */
		double x = u[a];
		size_t b = a;

		while (b > 0 && u[b - 1] > x) {
			u[b] = u[b - 1];
			b--;
		}
		u[b] = x;
	}
	{
		size_t w = 0;

		for (size_t k = 0; k < m; k++)
			if (w == 0 || u[k] != u[w - 1])
				u[w++] = u[k];
		m = w;
	}
	return m;
}

/* 1 if the sorted values u are spaced evenly in their logarithm over a decade or more. */
static int
is_log_spaced(const double *u, size_t m)
{
	if (m < 3 || !(u[0] > 0) || u[m - 1] / u[0] < 10)
		return 0;
	{
		double r0 = log(u[1] / u[0]);

		for (size_t k = 2; k < m; k++)
			if (fabs(log(u[k] / u[k - 1]) - r0) > 1e-3 * fabs(r0))
				return 0;
	}
	return 1;
}

/* Cell edges around the sorted values u: midpoints (geometric on a log axis). */
static void
edges(const double *u, size_t m, int log, double *e)
{
	for (size_t k = 1; k < m; k++)
		e[k] = log ? sqrt(u[k - 1] * u[k]) : 0.5 * (u[k - 1] + u[k]);
	if (m == 1) {
		double d = u[0] != 0 ? fabs(u[0]) * 0.1 : 0.5;

		e[0] = log ? u[0] / 1.5 : u[0] - d;
		e[1] = log ? u[0] * 1.5 : u[0] + d;
		return;
	}
	e[0] = log ? u[0] * u[0] / e[1] : 2 * u[0] - e[1];
	e[m] = log ? u[m - 1] * u[m - 1] / e[m - 1] : 2 * u[m - 1] - e[m - 1];
}

static size_t
find(const double *u, size_t m, double v)
{
	size_t a = 0, b = m;

	while (a < b) {
		size_t c = (a + b) / 2;

		if (u[c] < v)
			a = c + 1;
		else
			b = c;
	}
	return a;
}

/* "e_first" -> "e (first)", "x_c_r_total" -> "Σx_c^r" ... */
static void
run_label(const char *name, char *buf, size_t n)
{
	static const char *const map[][2] = {
		{ "e_first", "e (first)" }, { "v_i_first", "v_i (first)" },
		{ "e_last", "e (last)" }, { "v_i_last", "v_i (last)" },
		{ "x_c_r_total", "\xce\xa3x_c^r" }, { "t_pc", "t_pc" }, { "t_end", "t (end)" },
		{ "j_end", "j (end)" }, { "q_c_end", "q_c (end)" }, { "x_end", "x (end)" },
		{ "v_end", "v (end)" }, { "x_c_end", "x_c (end)" },
	};

	for (size_t k = 0; k < sizeof map / sizeof map[0]; k++)
		if (strcmp(name, map[k][0]) == 0) {
			cnum_snprintf(buf, n, "%s", map[k][1]);
			return;
		}
	cnum_snprintf(buf, n, "%s", name);
}

/* The SI unit of a key, from the sweep's own preset ("" when unknown). */
static void
key_unit(const struct hb_scene *sc, int have, const char *key, char *unit, size_t n)
{
	struct hb_scene_keyinfo ki;
	struct hb_scene_error e;

	unit[0] = '\0';
	if (have && hb_scene_get(sc, key, &ki, &e) == HB_OK && ki.kind == HB_SCENE_KEY_NUMBER)
		cnum_snprintf(unit, n, "%s", ki.unit);
}

static void
extent(const double *v, size_t n, double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t k = 0; k < n; k++)
		if (isfinite(v[k])) {
			*lo = fmin(*lo, v[k]);
			*hi = fmax(*hi, v[k]);
		}
}

int
plot_build_sweep(struct plot_figure *f, const char *dir, const char *obs, const long *coll,
                 int ncoll, double w, double h, struct hb_outputs *pol, char *msg, size_t n)
{
	static char runs[4200], colls[4200], spec[4200];   /* borrowed by pol */
	struct sweep_data d;
	struct stat sb;
	struct hb_scene sc;
	char ylabel[64], yunit[32], xunit[2][32], path[1024], m[1024];
	const struct hb_collision_column *cc = NULL;
	int robs = -1, have_sc, rc = -1, ni = 1;
	long idx[PLOT_MAX_SERIES];
	double *val = NULL, *u[2] = { NULL, NULL };

	memset(&d, 0, sizeof d);
	if (obs == NULL)
		obs = "e";
	robs = hb_observable_find(obs);
	if (robs < 0) {
		cc = hb_collision_column_find(obs);
		if (cc == NULL || cc->index) {
			char acc[1024];
			size_t l = 0;

			for (int k = 0; k < hb_collision_ncolumns; k++)
				if (!hb_collision_columns[k].index && l < sizeof acc)
					l += (size_t)cnum_snprintf(acc + l, sizeof acc - l, "%s%s", l ? ", " : "",
					                           hb_collision_columns[k].name);
			for (int k = 0; k < HB_OBS_COUNT && l < sizeof acc; k++)
				l += (size_t)cnum_snprintf(acc + l, sizeof acc - l, ", %s",
				                           hb_observables[k].name);
			cnum_snprintf(msg, n, "--observable %s: unknown; expected a collision's (%s)",
			              obs, acc);
			return -1;
		}
	}
	if (robs >= 0 && ncoll > 0) {
		cnum_snprintf(msg, n, "--collisions: %s is an observable of the whole run (runs.csv); "
		              "expected no --collisions, or a collision's observable such as e", obs);
		return -1;
	}
	/* the folder, or runs.csv with the other files beside it */
	if (stat(dir, &sb) == 0 && S_ISDIR(sb.st_mode)) {
		cnum_snprintf(runs, sizeof runs, "%s/runs.csv", dir);
		cnum_snprintf(colls, sizeof colls, "%s/collisions.csv", dir);
		cnum_snprintf(spec, sizeof spec, "%s/sweep.preset", dir);
	} else {
		const char *sl = strrchr(dir, '/');
		int dl = sl != NULL ? (int)(sl - dir) + 1 : 0;

		cnum_snprintf(runs, sizeof runs, "%s", dir);
		cnum_snprintf(colls, sizeof colls, "%.*scollisions.csv", dl, dir);
		cnum_snprintf(spec, sizeof spec, "%.*ssweep.preset", dl, dir);
	}
	hb_outputs_input(pol, runs, "the sweep's runs.csv");
	if (read_runs(runs, robs >= 0 ? obs : NULL, &d, msg, n) != 0)
		goto out;
	if (d.nkeys > 2) {
		cnum_snprintf(msg, n, "%s: the sweep varies %d keys (%s, %s, %s ...); a figure draws "
		              "one or two: expected a sweep of one key (curves) or two (a heat map)",
		              runs, d.nkeys, d.key[0], d.key[1], d.key[2]);
		goto out;
	}
	if (robs < 0) {
		hb_outputs_input(pol, colls, "the sweep's collisions.csv");
		if (ncoll == 0) {
			ni = d.nkeys == 2 ? 1 : 4;
			for (int c = 0; c < ni; c++)
				idx[c] = c;
		} else {
			ni = ncoll;
			memcpy(idx, coll, (size_t)ncoll * sizeof *idx);
		}
		if (d.nkeys == 2 && ni > 1) {
			cnum_snprintf(msg, n, "--collisions: a heat map over two keys draws one "
			              "collision; expected one index i");
			goto out;
		}
		val = malloc((d.n > 0 ? d.n : 1) * (size_t)ni * sizeof *val);
		if (val == NULL) {
			cnum_snprintf(msg, n, "out of memory");
			goto out;
		}
		if (read_collisions(colls, obs, &d, idx, ni, val, msg, n) != 0)
			goto out;
		cnum_snprintf(ylabel, sizeof ylabel, "%s", cc->label);
		cnum_snprintf(yunit, sizeof yunit, "%s", cc->unit);
		if (strcmp(obs, "Lambda") == 0)
			cnum_snprintf(ylabel, sizeof ylabel, "\xce\x9b");
	} else {
		val = d.rv;
		run_label(obs, ylabel, sizeof ylabel);
		cnum_snprintf(yunit, sizeof yunit, "%s", hb_observables[robs].unit);
	}
	m[0] = '\0';
	have_sc = stat(spec, &sb) == 0 &&
	          hb_preset_open_named(spec, NULL, 0, &sc, path, sizeof path, m, sizeof m) == HB_OK;
	for (int k = 0; k < d.nkeys; k++)
		key_unit(&sc, have_sc, d.key[k], xunit[k], sizeof xunit[k]);

	for (int k = 0; k < d.nkeys; k++) {
		u[k] = malloc((d.n > 0 ? d.n : 1) * sizeof(double) + sizeof(double));
		if (u[k] == NULL) {
			cnum_snprintf(msg, n, "out of memory");
			goto out;
		}
	}
	plot_figure_init(f, w, h > 0 ? h : 0.75 * w);
	if (d.nkeys == 1) {
		size_t mu = distinct(d.kv[0], d.n, u[0]);
		struct plot_panel *p = plot_panel_add(f, d.key[0], xunit[0], ylabel, yunit);
		double lo = INFINITY, hi = -INFINITY, a, b, *y = malloc(d.n * sizeof *y);

		if (p == NULL || y == NULL) {
			free(y);
			cnum_snprintf(msg, n, "out of memory");
			goto fail;
		}
		p->xa.log = is_log_spaced(u[0], mu);
		for (int c = 0; c < ni; c++) {
			char lab[32] = "";

			size_t given = 0;

			for (size_t r = 0; r < d.n; r++) {
				y[r] = val[r * (size_t)ni + (size_t)c];
				given += isfinite(y[r]) != 0;
			}
			if (given == 0 && c > 0)
				continue;   /* no run reached collision i: no curve, no legend entry */
			if (robs < 0)
				cnum_snprintf(lab, sizeof lab, "i = %ld", idx[c]);
			if (plot_series_add(p, lab, d.kv[0], y, d.n, c, 1, 1) != 0) {
				free(y);
				cnum_snprintf(msg, n, "out of memory");
				goto fail;
			}
			if (robs < 0)
				plot_legend_add(f, lab, c, 1, 1);
			extent(y, d.n, &a, &b);
			lo = fmin(lo, a);
			hi = fmax(hi, b);
		}
		free(y);
		plot_axis_fit(&p->xa, u[0][0], u[0][mu > 0 ? mu - 1 : 0], xunit[0], 0, 5);
		plot_axis_fit(&p->ya, lo, hi, yunit, 0, 5);
	} else {
		size_t mx = distinct(d.kv[0], d.n, u[0]), my = distinct(d.kv[1], d.n, u[1]);
		double *ex = malloc((mx + 1) * sizeof *ex), *ey = malloc((my + 1) * sizeof *ey);
		double *grid = malloc((mx * my > 0 ? mx * my : 1) * sizeof *grid), lo, hi;
		struct plot_panel *p = plot_panel_add(f, d.key[0], xunit[0], d.key[1], xunit[1]);
		int lx = is_log_spaced(u[0], mx), ly = is_log_spaced(u[1], my);
		char title[96];

		if (p == NULL || ex == NULL || ey == NULL || grid == NULL || mx == 0 || my == 0) {
			free(ex);
			free(ey);
			free(grid);
			cnum_snprintf(msg, n, mx == 0 || my == 0 ? "%s: no finite value of the keys; "
			              "expected numbers" : "out of memory", runs);
			goto fail;
		}
		if (h <= 0)
			f->h = 0.8 * w;
		for (size_t k = 0; k < mx * my; k++)
			grid[k] = NAN;
		for (size_t r = 0; r < d.n; r++) {
			if (!isfinite(d.kv[0][r]) || !isfinite(d.kv[1][r]))
				continue;
			grid[find(u[1], my, d.kv[1][r]) * mx + find(u[0], mx, d.kv[0][r])] = val[r];
		}
		edges(u[0], mx, lx, ex);
		edges(u[1], my, ly, ey);
		extent(grid, mx * my, &lo, &hi);
		if (!isfinite(lo)) {
			lo = 0;
			hi = 1;
		}
		p->xa.log = lx;
		p->ya.log = ly;
		rc = plot_map_set(p, ex, mx, ey, my, grid, lo, hi, lo > 0 && hi / lo >= 100);
		plot_axis_fit(&p->xa, ex[0], ex[mx], xunit[0], 1, 5);
		plot_axis_fit(&p->ya, ey[0], ey[my], xunit[1], 1, 5);
		free(ex);
		free(ey);
		free(grid);
		if (robs < 0)
			cnum_snprintf(title, sizeof title, "%s (i = %ld)", ylabel, idx[0]);
		else
			cnum_snprintf(title, sizeof title, "%s", ylabel);
		if (rc != 0 || plot_colorbar_add(f, p, title, yunit) == NULL) {
			rc = -1;
			cnum_snprintf(msg, n, "out of memory");
			goto fail;
		}
	}
	rc = 0;
	goto out;
fail:
	plot_figure_free(f);
	rc = -1;
out:
	if (val != d.rv)
		free(val);
	free(u[0]);
	free(u[1]);
	data_free(&d);
	return rc;
}
