/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_table.c - the collision table of the batch report (batch_report.h):
 * one row per completed collision, in fixed units chosen per column from
 * the data's magnitude (ASCII only), then the contact in progress if any;
 * with --error, the table of error bars in the same columns and units.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/collisions.h"
#include "hybounce/columns.h"
#include "hybounce/error.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/units.h"

#include "batch_report.h"

enum col_kind { COL_INDEX, COL_VALUE, COL_RATIO, COL_IFACE };

struct col {
	const char *name;
	const char *base;  /* "s", "m", "m/s", "N", "J"; NULL: dimensionless */
	size_t off;        /* offset of the double in struct hb_collision */
	int kind;
	/* chosen from the data: */
	double scale;
	char unit[24];
	int dec, sci, width;
};

enum { NCOLS_MAX = 32 };

/*
 * The columns of the batch table, from the table of columns.h; a chain's
 * has its interface k after i.
 */
static int
cols_from_table(struct col *cols, int chain)
{
	int nc = 0;

	for (int k = 0; k < hb_collision_ncolumns && nc < NCOLS_MAX; k++) {
		const struct hb_collision_column *cc = &hb_collision_columns[k];
		if (!(cc->shown & HB_COLUMN_BATCH))
			continue;
		memset(&cols[nc], 0, sizeof cols[nc]);
		cols[nc].name = cc->label;
		cols[nc].base = cc->unit[0] ? cc->unit : NULL;
		cols[nc].off = cc->off;
		cols[nc].kind = cc->index ? COL_INDEX : cc->unit[0] ? COL_VALUE : COL_RATIO;
		cols[nc].scale = 1;
		nc++;
		if (cc->index && chain && nc < NCOLS_MAX) {
			memset(&cols[nc], 0, sizeof cols[nc]);
			cols[nc].name = "k";
			cols[nc].kind = COL_IFACE;
			cols[nc].scale = 1;
			nc++;
		}
	}
	return nc;
}

/* A whole-number column: the collision's index i, or a chain's interface k. */
static int
col_whole(const struct col *c)
{
	return c->kind == COL_INDEX || c->kind == COL_IFACE;
}

static double
col_get(const struct col *c, const struct hb_collision *k)
{
	return *(const double *)((const char *)k + c->off);
}

/* Picks scale, unit and decimals for a column from its largest magnitude. */
static void
col_choose(struct col *c, double mag)
{
	double m;
	int digits;

	c->scale = 1;
	c->unit[0] = '\0';
	if (c->base != NULL) {
		char lab[16];

		c->scale = hb_units_axis(mag > 0 ? mag : 1, c->base, lab, sizeof lab);
		snprintf(c->unit, sizeof c->unit, "%s", lab); /* ASCII: "um" */
		if (!(c->scale > 0) || !isfinite(c->scale)) {
			c->scale = 1;
			snprintf(c->unit, sizeof c->unit, "%s", c->base);
		}
	}
	m = mag / c->scale;
	c->sci = 0;
	if (m == 0 || !isfinite(m)) {
		c->dec = 3;
		return;
	}
	if (m >= 1e6 || m < 1e-3) {
		c->sci = 1;
		return;
	}
	digits = (int)floor(log10(m)) + 1;   /* digits before the point, may be <= 0 */
	c->dec = 5 - digits;
	if (c->dec < 0)
		c->dec = 0;
	if (c->dec > 7)
		c->dec = 7;
}

/*
 * A contact in progress has its own magnitudes (its values so far: x_c^r
 * is its indentation now, v_i of a contact begun at rest is tiny), while
 * the column's unit and decimals come from the completed collisions: in
 * fixed notation its value would read 0 or spread over many digits.  1
 * when v (in the column's unit) reads in it: 0, or a nonzero digit among
 * its decimals and under 1e6.
 */
static int
fixed_fits(const struct col *c, double v)
{
	double a = fabs(v);

	return a == 0 || (a >= 0.5 * pow(10, -c->dec) && a < 1e6);
}

static void
col_cell(const struct col *c, const struct hb_collision *k, char *buf, size_t n)
{
	double v;

	if (c->kind == COL_INDEX) {
		snprintf(buf, n, "%ld", k->i);
		return;
	}
	if (c->kind == COL_IFACE) {
		snprintf(buf, n, "%d", k->k);
		return;
	}
	v = col_get(c, k);
	/* e is defined at the separation: not for the contact in progress. */
	if (!k->complete && c->off == offsetof(struct hb_collision, e))
		v = NAN;
	if (isnan(v))
		snprintf(buf, n, "-");
	else if (c->sci || (!k->complete && !fixed_fits(c, v / c->scale)))
		snprintf(buf, n, "%.4e", v / c->scale);
	else
		snprintf(buf, n, "%.*f", c->dec, v / c->scale);
}

static void
col_head(const struct col *c, char *buf, size_t n)
{
	if (c->unit[0])
		snprintf(buf, n, "%s [%s]", c->name, c->unit);
	else
		snprintf(buf, n, "%s", c->name);
}

/*
 * Prints the table of the completed collisions and, below a rule, the
 * contacts in progress (a chain's interfaces may be in contact side by
 * side), by increasing interface.
 */
static void print_error_table(FILE *out, const struct hb_sim *s, const struct col *cols,
                              int ncols, const struct hb_error_estimate *est);

/* Row r: completed collision r, then the contacts in progress (in *live); NULL past them. */
static const struct hb_collision *
row(const struct hb_sim *s, size_t r, size_t nc, struct hb_collision *live)
{
	if (r < nc)
		return hb_sim_collision(s, r);
	return hb_sim_contact_live_nth(s, r - nc, live) ? live : NULL;
}

void
batch_print_table(FILE *out, const struct hb_sim *s, const struct hb_error_estimate *est)
{
	struct col cols[NCOLS_MAX];
	size_t nc = hb_sim_ncollisions(s), nlive = hb_sim_contacts_live(s), r;
	struct hb_collision live;
	char buf[64];
	int c, w;
	const int ncols = cols_from_table(cols, hb_sim_scene(s)->chain.n > 0);

	for (c = 0; c < ncols; c++) {
		double mag = 0;

		/* Units from the completed collisions; the live rows only when alone. */
		for (r = 0; r < nc + nlive; r++) {
			const struct hb_collision *k = row(s, r, nc, &live);
			double v;

			if (k == NULL || col_whole(&cols[c]) || (r >= nc && nc > 0))
				continue;
			v = fabs(col_get(&cols[c], k));
			if (isfinite(v) && v > mag)
				mag = v;
		}
		if (!col_whole(&cols[c]))
			col_choose(&cols[c], mag);
		col_head(&cols[c], buf, sizeof buf);
		w = (int)strlen(buf);
		for (r = 0; r < nc + nlive; r++) {
			const struct hb_collision *k = row(s, r, nc, &live);

			if (k == NULL)
				continue;
			col_cell(&cols[c], k, buf, sizeof buf);
			if ((int)strlen(buf) > w)
				w = (int)strlen(buf);
		}
		cols[c].width = w;
	}

	if (hb_sim_collisions_total(s) > (long)nc)
		fprintf(out, "collisions (%ld completed; %zu kept, the older ones thinned)\n",
		        hb_sim_collisions_total(s), nc);
	else
		fprintf(out, "collisions (%zu completed)\n", nc);
	for (c = 0; c < ncols; c++) {
		col_head(&cols[c], buf, sizeof buf);
		fprintf(out, "%s%*s", c ? "  " : "", cols[c].width, buf);
	}
	fprintf(out, "\n");
	for (r = 0; r < nc + nlive; r++) {
		const struct hb_collision *k = row(s, r, nc, &live);

		if (k == NULL)
			break;
		if (r == nc && nlive == 1)
			fprintf(out, "contact in progress (values so far; t_s is the last sample):\n");
		else if (r == nc)
			fprintf(out, "contacts in progress, %zu (values so far; t_s is the last sample):\n", nlive);
		for (c = 0; c < ncols; c++) {
			col_cell(&cols[c], k, buf, sizeof buf);
			fprintf(out, "%s%*s", c ? "  " : "", cols[c].width, buf);
		}
		fprintf(out, "\n");
	}
	fprintf(out, "\n");
	if (est != NULL)
		print_error_table(out, s, cols, ncols, est);
}

/*
 * --error: the error bars of the completed collisions, a table with the
 * columns and units of the collision table above.
 */
static void
print_error_table(FILE *out, const struct hb_sim *s, const struct col *cols, int ncols,
                  const struct hb_error_estimate *est)
{
	char buf[64];
	int c;

	fprintf(out, "error bars (estimated global error of each value above, same units: "
	        "the run again with rk8pd at rtol %.3g, atol %.3g%s)\n", est->rtol, est->atol,
	        est->at_floor ? "; less than 100 x tighter, the bars less sure" : "");
	for (c = 0; c < ncols; c++) {
		col_head(&cols[c], buf, sizeof buf);
		fprintf(out, "%s%*s", c ? "  " : "", cols[c].width, buf);
	}
	fprintf(out, "\n");
	for (size_t r = 0; r < hb_sim_ncollisions(s); r++) {
		const struct hb_collision *k = hb_sim_collision(s, r);
		const struct hb_collision *d = hb_error_find(est, k->i);

		for (c = 0; c < ncols; c++) {
			double v = d != NULL && !col_whole(&cols[c]) ? col_get(&cols[c], d) : NAN;

			if (cols[c].kind == COL_INDEX)
				snprintf(buf, sizeof buf, "%ld", k->i);
			else if (cols[c].kind == COL_IFACE)
				snprintf(buf, sizeof buf, "%d", k->k);
			else if (isnan(v))
				snprintf(buf, sizeof buf, "-");
			else
				snprintf(buf, sizeof buf, "%.0e", v / cols[c].scale);
			fprintf(out, "%s%*s", c ? "  " : "", cols[c].width, buf);
		}
		fprintf(out, "\n");
	}
	fprintf(out, "\n");
}
