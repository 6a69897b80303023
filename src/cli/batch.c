/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch.c - batch mode: load a preset, apply --set overrides, run the
 * simulator to its end, print a report for a reader of the paper and write
 * the CSV files.
 *
 * The report (stdout; stderr when a CSV goes to stdout) has three parts:
 *  1. a header block: preset, law, system, bodies, loads, initial state,
 *     derived values and the run settings (with the per-component scales
 *     of the absolute tolerance);
 *  2. the collision table, one row per completed collision, in fixed units
 *     chosen per column from the data's magnitude (ASCII only), then the
 *     contact in progress if any;
 *  3. a summary: why the run ended, the end state and the work done.
 * --quiet keeps only the summary.  Errors, and the "wrote FILE" lines of an
 * export, go to stderr.
 *
 * "--trace -" or "--collisions -" (not both) writes that CSV to stdout,
 * after the files, and then the report goes to stderr, so that stdout holds
 * the CSV alone (GNU tar sends its -v listing to stderr with -f - the same
 * way).  No "wrote" line and no .preset beside "-": the scene is saved
 * beside the other CSV when that one is a file.  A reader that stops
 * early (| head) ends the process by SIGPIPE, or, with SIGPIPE ignored,
 * the write stops at the EPIPE without a message.
 *
 * Bad input is refused before anything runs: the preset, every --set and
 * the export paths are checked first, so a bad invocation (exit 2) never
 * leaves a CSV behind.  A run that fails numerically (exit 1) still prints
 * and writes what it computed.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/arc.h"
#include "hybounce/atomic.h"
#include "hybounce/check.h"
#include "hybounce/collisions.h"
#include "hybounce/columns.h"
#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/law.h"
#include "hybounce/observables.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "batch.h"
#include "batch_bodies.h"
#include "batch_chain_check.h"
#include "plot_cmd.h"
#include "plot_out.h"
#include "report.h"
#include "signals.h"
#include "clock.h"

#define PROG "hybounce"

/* N m^-3/2: the Hertz coefficient k_H = 4/3 E* sqrt(R_e). */
static const struct hb_unit_dim dim_kH = { 1, -0.5, -2, 0, 0 };

static void
err(const char *msg)
{
	fprintf(stderr, PROG ": %s\n", msg);
}

/* A value with its unit, 6 significant digits, into buf. */
static const char *
fmt(double v, struct hb_unit_dim d, char *buf, size_t n)
{
	if (isinf(v))
		snprintf(buf, n, "%s", v > 0 ? "inf" : "-inf");
	else if (isnan(v))
		snprintf(buf, n, "-");
	else
		hb_units_format(v, d, 6, buf, n);
	return buf;
}

/*
 * Prints text word-wrapped to 79 columns, every line starting with indent
 * (the first line too).
 */
static void
print_wrapped(FILE *out, const char *indent, const char *text)
{
	const int width = 79 - (int)strlen(indent);
	const char *p = text;

	while (*p != '\0') {
		int len = (int)strlen(p), cut = len;

		if (len > width) {
			cut = width;
			while (cut > 0 && p[cut] != ' ')
				cut--;
			if (cut == 0) /* one long word */
				for (cut = width; p[cut] != '\0' && p[cut] != ' '; cut++)
					;
		}
		fprintf(out, "%s%.*s\n", indent, cut, p);
		p += cut;
		while (*p == ' ')
			p++;
	}
}

/* ------------------------------------------------------------------ */
/* Input: preset, --set, export paths                                  */

/* 1 if an export path names standard output ("-"). */
static int
is_stdout(const char *path)
{
	return path != NULL && strcmp(path, "-") == 0;
}

/* 1 if path ends in suffix. */
static int
ends_with(const char *path, const char *suffix)
{
	size_t a = strlen(path), b = strlen(suffix);

	return a >= b && strcmp(path + a - b, suffix) == 0;
}

/*
 * Checks, before the run, that an export path can be written (atomic.h:
 * a new or replaced file needs a writable folder, a device or FIFO is
 * written in place, a folder is refused).  Returns 0, or 2 after printing
 * why.
 */
static int
check_export_path(const char *opt, const char *path)
{
	struct hb_atomic_target t;
	char msg[1024];

	if (path[0] == '\0') {
		fprintf(stderr, PROG ": %s: empty file name; accepted: %s, e.g. run.csv\n", opt,
		        HB_OUTPUTS_ACCEPTED);
		return 2;
	}
	if (ends_with(path, ".preset")) {
		fprintf(stderr, PROG ": %s %s: the scene is saved beside the CSV as "
		        "NAME.preset; give the CSV another extension (e.g. .csv)\n",
		        opt, path);
		return 2;
	}
	msg[0] = '\0';
	/* the output policy's words (outputs.h): "PATH: reason; accepted: ..." */
	if (hb_outputs_probe(path, &t, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s %s\n", opt, msg);
		return 2;
	}
	return 0;
}

/* ------------------------------------------------------------------ */
/* Header block                                                        */

static void
print_law(FILE *out, const struct hb_scene *sc)
{
	const struct hb_law_type *law = sc->law;
	double p = hb_law_exponent_p(law, sc->par), nn = hb_law_exponent_n(law, sc->par);
	char b[64];
	int i;

	fprintf(out, "law         %s: %s\n", law->name, law->title);
	fprintf(out, "            extension beyond x_c = 0 (rule R1): %s\n",
	        sc->ext ? "adhesive" : "none (clamped)");
	for (i = 0; i < law->n_params; i++) {
		const struct hb_law_param *pp = &law->params[i];

		fprintf(out, "            %-8s = %s%s\n", pp->name,
		        fmt(sc->par[i], hb_units_resolve(pp->dim, p, nn), b, sizeof b),
		        (pp->flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived
		            ? "  (derived from k_H)" : "");
	}
}

static void
print_body(FILE *out, int k, const struct hb_scene_body *bd)
{
	char e[64], r[64], rho[64], m[64];

	fprintf(out, "body %d      %s:", k + 1, bd->name[0] ? bd->name : "(unnamed)");
	if (bd->has_material)
		fprintf(out, " E = %s, nu = %g,", fmt(bd->E, hb_unit_pressure, e, sizeof e), bd->nu);
	if (bd->rho > 0)
		fprintf(out, " rho = %s,", fmt(bd->rho, hb_unit_density, rho, sizeof rho));
	fprintf(out, " R = %s%s, m = %s%s\n", fmt(bd->R, hb_unit_length, r, sizeof r),
	        isinf(bd->R) ? " (flat)" : "",
	        fmt(bd->mass, hb_unit_mass, m, sizeof m),
	        isinf(bd->mass) ? " (fixed obstacle)" : bd->mass_given ? " (given)" : "");
}

/* A chain's overrides (scene.h: body.I.*, interface.K.*, initial.body.I.*), wrapped at 79 columns. */
static void
print_overrides(FILE *out, const struct hb_scene *sc)
{
	int col = 0;

	for (int i = 0; i < sc->over.n && i < HB_SCENE_MAX_OVERRIDES; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		struct hb_scene_keyinfo ki;
		char key[64], b[128];
		int len;

		snprintf(key, sizeof key, "%s%d.%s", o->kind == HB_OVERRIDE_BODY ? "body." :
		         o->kind == HB_OVERRIDE_IFACE ? "interface." : "initial.body.", o->index, o->name);
		if (hb_scene_get(sc, key, &ki, NULL) != HB_OK)
			continue;
		len = snprintf(b, sizeof b, "%s = %s", key, ki.value);
		if (col == 0) {
			fprintf(out, "overrides   %s", b);
			col = 12 + len;
		} else if (col + 2 + len > 79) {
			fprintf(out, ",\n            %s", b);
			col = 12 + len;
		} else {
			fprintf(out, ", %s", b);
			col += 2 + len;
		}
	}
	if (col > 0)
		fprintf(out, "\n");
}

static void
print_header(FILE *out, const char *preset, const char *path,
             const struct hb_scene *sc, const struct hb_sim_stats *st)
{
	const struct hb_scene_derived *d = &sc->d;
	char a[64], b[64], c[64], e[64];
	int i, k;

	fprintf(out, "hybounce %s batch run\n", HYBOUNCE_VERSION);
	fprintf(out, "preset      %s (%s)\n", preset, path);
	fprintf(out, "title       %s\n", sc->name);
	if (sc->description[0])
		print_wrapped(out, "            ", sc->description);
	print_law(out, sc);
	if (sc->chain.n > 0) {
		/* chain.spacing = 0: the bodies touch */
		if (sc->chain.spacing == 0.0)
			snprintf(c, sizeof c, "touching");
		else
			snprintf(c, sizeof c, "%s apart", fmt(sc->chain.spacing, hb_unit_length, a, sizeof a));
		fprintf(out, "system      chain of %d bodies (each body 1, the law between neighbours%s)%s, "
		        "%s, striker (body %d) at %s\n", sc->chain.n,
		        sc->over.n > 0 ? ", but for the overrides" : "",
		        sc->chain.floor ? " on a floor" : "", c, sc->chain.n,
		        fmt(sc->chain.v, hb_unit_velocity, b, sizeof b));
	}
	else if (d->system == HB_SCENE_REDUCED)
		fprintf(out, "system      reduced H_r: body 2 is a fixed obstacle\n");
	else
		fprintf(out, "system      full H_f: two finite masses on a common axis\n");
	for (k = 0; k < (sc->chain.n > 0 ? 1 : 2); k++)
		print_body(out, k, &sc->body[k]);
	print_overrides(out, sc);
	fprintf(out, "loads       g = %s, F1 = %s, F2 = %s",
	        fmt(sc->loads.g, hb_unit_accel, a, sizeof a),
	        fmt(sc->loads.F1, hb_unit_force, b, sizeof b),
	        fmt(sc->loads.F2, hb_unit_force, c, sizeof c));
	if (sc->loads.ramp)
		fprintf(out, ", ramp: F_e0 = %s, T_s = %s, T_e = %s",
		        fmt(sc->loads.Fe0, hb_unit_force, a, sizeof a),
		        fmt(sc->loads.Ts, hb_unit_time, b, sizeof b),
		        fmt(sc->loads.Te, hb_unit_time, c, sizeof c));
	fprintf(out, "\n");
	if (sc->chain.n == 0) {
		fprintf(out, "initial     x0 = %s, v0 = %s",
		        fmt(sc->init.x0, hb_unit_length, a, sizeof a),
		        fmt(sc->init.v0, hb_unit_velocity, b, sizeof b));
		if (d->system == HB_SCENE_FULL)
			fprintf(out, ", x_m0 = %s, v_m0 = %s",
			        fmt(sc->init.xm0, hb_unit_length, a, sizeof a),
			        fmt(sc->init.vm0, hb_unit_velocity, b, sizeof b));
		fprintf(out, "\n");
	}
	fprintf(out, "derived     E* = %s, R_e = %s, m = %s",
	        fmt(d->Estar, hb_unit_pressure, a, sizeof a),
	        fmt(d->Re, hb_unit_length, b, sizeof b),
	        fmt(d->m, hb_unit_mass, c, sizeof c));
	if (d->system == HB_SCENE_FULL)
		fprintf(out, "\n            m1 = %s, m2 = %s, eta = %.6g",
		        fmt(d->m1, hb_unit_mass, a, sizeof a),
		        fmt(d->m2, hb_unit_mass, b, sizeof b), d->eta);
	fprintf(out, "\n            k_H = %s", fmt(d->kH, dim_kH, e, sizeof e));
	for (i = 0; i < sc->law->n_params; i++) {
		const struct hb_law_param *pp = &sc->law->params[i];

		if (pp->flags & HB_LAW_PARAM_STIFFNESS)
			fprintf(out, ", %s = %s%s", pp->name,
			        fmt(sc->par[i], hb_units_resolve(pp->dim,
			            hb_law_exponent_p(sc->law, sc->par),
			            hb_law_exponent_n(sc->law, sc->par)), a, sizeof a),
			        d->k_derived ? " (from the materials, Hertz)" : " (typed)");
	}
	fprintf(out, "\n");
	fprintf(out, "run         T = %s, J = %ld, stepper %s, rtol = %.3g, atol = %.3g",
	        fmt(sc->run.T, hb_unit_time, a, sizeof a), sc->run.J,
	        hb_scene_stepper_name(sc->run.stepper), sc->run.rtol, sc->run.atol);
	if (sc->run.h_max > 0)
		fprintf(out, ", h_max = %s", fmt(sc->run.h_max, hb_unit_time, b, sizeof b));
	fprintf(out, "\n");
	if (st != NULL && st->ncomp > 0) {
		char line[512];
		size_t len = 0;

		fprintf(out, "            absolute tolerance = atol x scale (scales of the last contact):\n");
		line[0] = '\0';
		for (i = 0; i < st->ncomp && i < HB_SIM_MAXCOMP && len < sizeof line; i++)
			len += (size_t)snprintf(line + len, sizeof line - len, "%s%s %.3g",
			                        i ? ", " : "", st->comp[i] ? st->comp[i] : "?",
			                        st->scale[i]);
		print_wrapped(out, "            ", line);
	}
	fprintf(out, "\n");
}

/* ------------------------------------------------------------------ */
/* Collision table                                                     */

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
	else if (c->sci)
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
 * contact in progress (live may be NULL).
 */
static void print_error_table(FILE *out, const struct hb_sim *s, const struct col *cols,
                              int ncols, const struct hb_error_estimate *est);

static void
print_table(FILE *out, const struct hb_sim *s, const struct hb_collision *live,
            const struct hb_error_estimate *est)
{
	struct col cols[NCOLS_MAX];
	size_t nc = hb_sim_ncollisions(s), r;
	char buf[64];
	int c, w;
	const int ncols = cols_from_table(cols, hb_sim_scene(s)->chain.n > 0);

	for (c = 0; c < ncols; c++) {
		double mag = 0;

		/* Units from the completed collisions; the live row only when alone. */
		for (r = 0; r <= nc; r++) {
			const struct hb_collision *k = r < nc ? hb_sim_collision(s, r) : live;
			double v;

			if (k == NULL || col_whole(&cols[c]) || (r == nc && nc > 0))
				continue;
			v = fabs(col_get(&cols[c], k));
			if (isfinite(v) && v > mag)
				mag = v;
		}
		if (!col_whole(&cols[c]))
			col_choose(&cols[c], mag);
		col_head(&cols[c], buf, sizeof buf);
		w = (int)strlen(buf);
		for (r = 0; r <= nc; r++) {
			const struct hb_collision *k = r < nc ? hb_sim_collision(s, r) : live;

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
	for (r = 0; r < nc; r++) {
		const struct hb_collision *k = hb_sim_collision(s, r);

		for (c = 0; c < ncols; c++) {
			col_cell(&cols[c], k, buf, sizeof buf);
			fprintf(out, "%s%*s", c ? "  " : "", cols[c].width, buf);
		}
		fprintf(out, "\n");
	}
	if (live != NULL) {
		fprintf(out, "contact in progress (values so far; t_s is the last sample):\n");
		for (c = 0; c < ncols; c++) {
			col_cell(&cols[c], live, buf, sizeof buf);
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

/* ------------------------------------------------------------------ */
/* Jumps, summary, check                                               */

static const char *
how_str(int how)
{
	switch (how) {
	case HB_LOCATE_START: return "start";
	case HB_LOCATE_CLOSED_FORM: return "closed-form";
	case HB_LOCATE_BRENT: return "brent";
	default: return "?";
	}
}

static void
print_jumps(FILE *out, const struct hb_arc *a)
{
	size_t k, n = hb_arc_njumps(a);

	fprintf(out, "jumps (%zu): t [s], j before the jump, the part of C that was left, "
	        "how it was located,\n"
	        "root-finder iterations, final bracket width [s], flow-set indicator "
	        "on the C side and on the D side\n", n);
	fprintf(out, "%6s  %22s  %6s  %-28s  %-11s  %5s  %10s  %11s  %11s\n",
	        "k", "t [s]", "j", "left", "how", "iter", "width [s]",
	        "ind (C)", "ind (D)");
	for (k = 0; k < n; k++) {
		const struct hb_arc_jump *jp = hb_arc_jump_at(a, k);

		fprintf(out, "%6zu  %22.17g  %6ld  %-28s  %-11s  %5d  %10.3e  %11.3e  %11.3e\n",
		        k, jp->t, jp->j, jp->left ? jp->left : "?", how_str(jp->how),
		        jp->iterations, jp->width, jp->ind_lo, jp->ind_hi);
	}
	fprintf(out, "\n");
}

/*
 * Significant digits of a value v with error bar err: down to the error's
 * first digit, 6 at least, 17 at most.
 */
static int
value_digits(double v, double err)
{
	int d = 6;

	if (err > 0 && isfinite(err) && v != 0 && isfinite(v))
		d = (int)floor(log10(fabs(v))) - (int)floor(log10(err)) + 1;
	return d < 6 ? 6 : d > 17 ? 17 : d;
}

/*
 * The run observables (observables.h), "name = value unit" in SI as a
 * sweep's runs.csv has them (6 digits; "-" where there is none), as many
 * to a line as fit in 79 columns.
 */
static void
print_observables(FILE *out, const struct hb_sim *s, const struct hb_error_estimate *est)
{
	int col = 12; /* "  observables" less the blank that each pair brings */

	fprintf(out, "  observables");
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		const struct hb_observable_def *d = &hb_observables[k];
		double v = hb_observable_value(s, k);
		char b[96];
		int len;

		if (isnan(v))
			len = snprintf(b, sizeof b, "%s = -", d->name);
		else if (d->whole)
			len = est != NULL && !isnan(est->obs[k])
			    ? snprintf(b, sizeof b, "%s = %ld +- %ld", d->name, (long)v, (long)est->obs[k])
			    : snprintf(b, sizeof b, "%s = %ld", d->name, (long)v);
		else if (est != NULL && !isnan(est->obs[k]))
			len = snprintf(b, sizeof b, "%s = %.*g +- %.0e%s%s", d->name,
			               value_digits(v, est->obs[k]), v, est->obs[k],
			               d->unit[0] ? " " : "", d->unit);
		else
			len = snprintf(b, sizeof b, "%s = %.6g%s%s", d->name, v, d->unit[0] ? " " : "",
			               d->unit);
		if (k > 0 && col + 2 + len > 79) {
			fprintf(out, ",\n              %s", b);
			col = 14 + len;
		} else {
			fprintf(out, "%s %s", k ? "," : "", b);
			col += 2 + len;
		}
	}
	fprintf(out, "\n");
}

/*
 * A chain's bodies at the end: velocity and kinetic energy of each, the
 * totals, the energy the interfaces hold (stored) and took for good
 * (dissipated) (hb_check_chain; "-" on a failed run), and momentum.
 */
static void
print_bodies(FILE *out, const struct hb_sim *s)
{
	char b1[64], b2[64], b3[64];
	double K = 0.0, P = 0.0;
	int i, n = hb_sim_nbodies(s);
	struct hb_check_chain r;

	for (i = 0; i < n; i++) {
		struct hb_sim_body b;

		hb_sim_body(s, i, &b);
		K += 0.5 * b.m * b.u * b.u;
		P += b.m * b.u;
		if (n <= 12 || i < 5 || i >= n - 5)
			fprintf(out, "  body %-6d u = %s, kinetic energy %s\n", i + 1,
			        fmt(b.u, hb_unit_velocity, b1, sizeof b1),
			        fmt(0.5 * b.m * b.u * b.u, hb_unit_energy, b2, sizeof b2));
		else if (i == 5)
			fprintf(out, "  ...\n");
	}
	hb_check_chain(s, &r, NULL, 0);
	fprintf(out, "  chain       kinetic energy %s, stored %s, dissipated %s, momentum %.9g kg m/s\n",
	        fmt(K, hb_unit_energy, b1, sizeof b1), fmt(r.stored, hb_unit_energy, b2, sizeof b2),
	        fmt(r.dissipated, hb_unit_energy, b3, sizeof b3), P);
	{
		long nlim;
		const char *note = hb_sim_limits(s, &nlim);

		if (nlim > 0) /* run.chain_limits = warn */
			fprintf(out, "  limits      passed %ld time%s (run.chain_limits = warn); the first: %s\n",
			        nlim, nlim == 1 ? "" : "s", note);
	}
}

static void
print_summary(FILE *out, const struct hb_sim *s, int sig, const struct hb_error_estimate *est)
{
	const struct hb_scene *sc = hb_sim_scene(s);
	const struct hb_arc *a = hb_sim_arc(s);
	const struct hb_arc_sample *last = hb_arc_last(a);
	const struct hb_sim_stats *st = hb_sim_stats(s);
	char b1[64], b2[64], b3[64], b4[64];
	int i;

	fprintf(out, "summary\n");
	if (sig != 0)
		fprintf(out, "  ended       interrupted by %s at t = %s, j = %ld (run.T = %s)\n",
		        cli_signal_name(sig),
		        fmt(last != NULL ? last->t : 0, hb_unit_time, b1, sizeof b1),
		        last != NULL ? last->j : 0L, fmt(sc->run.T, hb_unit_time, b2, sizeof b2));
	else
		fprintf(out, "  ended       %s\n", hb_sim_end_str(s));
	if (last != NULL) {
		fprintf(out, "  end state   t = %s, j = %ld, q_c = %d, x = %s, v = %s, x_c = %s",
		        fmt(last->t, hb_unit_time, b1, sizeof b1), last->j, last->q,
		        fmt(last->x, hb_unit_length, b2, sizeof b2),
		        fmt(last->v, hb_unit_velocity, b3, sizeof b3),
		        fmt(last->xc, hb_unit_length, b4, sizeof b4));
		for (i = 0; i < sc->law->n_z && i < HB_LAW_MAX_Z; i++)
			fprintf(out, ", z_c%d = %.6g", i + 1, last->z[i]);
		fprintf(out, "\n");
	}
	if (hb_sim_collisions_total(s) > (long)hb_sim_ncollisions(s))
		fprintf(out, "  collisions  %ld (%zu kept in the table and CSV: the older ones are "
		        "thinned, each row keeps its index i)\n", hb_sim_collisions_total(s),
		        hb_sim_ncollisions(s));
	else
		fprintf(out, "  collisions  %zu\n", hb_sim_ncollisions(s));
	print_observables(out, s, est);
	fprintf(out, "  run time    %s CPU", fmt(st->seconds, hb_unit_time, b1, sizeof b1));
	fprintf(out, ", %s wall\n", fmt(st->wall, hb_unit_time, b1, sizeof b1));
	fprintf(out, "  steps       %ld accepted, %ld rejected\n", st->steps, st->rejected);
	fprintf(out, "  evaluations %ld right-hand side, %ld Jacobian\n", st->rhs, st->jac);
	fprintf(out, "  events      %ld jumps, %ld kinks, %ld located by root finding, "
	        "%ld flights in closed form\n",
	        st->jumps, st->kinks, st->located, st->flights_closed);
	if (st->stiff) {
		char tb[32];

		fmt(st->stiff_t, hb_unit_time, tb, sizeof tb);
		if (st->switched)
			fprintf(out, "  stiffness   the contact flow is stiff from t = %s (h |lambda| up to "
			        "%.3g): run.stepper = auto went over to bsimp\n", tb, st->stiff_hrho);
		else
			fprintf(out, "  stiffness   the contact flow is stiff from t = %s: %s is held back by "
			        "stability (h |lambda| up to %.3g);\n"
			        "              --set run.stepper=auto (or bsimp) takes far fewer steps\n",
			        tb, hb_scene_stepper_name(sc->run.stepper), st->stiff_hrho);
	}
	if (st->dips > 0)
		fprintf(out, "              %ld events found inside a step whose ends were both in C\n",
		        st->dips);
	fprintf(out, "  arc         %zu samples, %zu flow intervals",
	        hb_arc_len(a), hb_arc_nintervals(a));
	if (hb_arc_thinned(a) > 0)
		fprintf(out, ", thinned %d times (past run.max_samples = %ld)",
		        hb_arc_thinned(a), sc->run.max_samples);
	if (hb_arc_skipped(a) > 0)
		fprintf(out, ", %ld flow intervals thinned out with their jumps", hb_arc_skipped(a));
	else
		fprintf(out, ", not thinned");
	fprintf(out, "\n");
	if (sc->chain.n > 0)
		print_bodies(out, s);
}

/* ------------------------------------------------------------------ */
/* The run: signals and progress                                       */

/*
 * Runs s in slices of 0.1 s to its end or to a caught signal (*sig).
 * Past one second, standard error a terminal, a progress line there,
 * rewritten in place four times a second and erased at the end.
 */
static int
run_watched(struct hb_sim *s, int *sig)
{
	const double T = hb_sim_scene(s)->run.T;
	const int tty = isatty(STDERR_FILENO);
	double start = clock_seconds(CLOCK_MONOTONIC), shown = 0;
	int rc = HB_OK;

	while (cli_signal == 0) {
		double now;

		rc = hb_sim_advance(s, 0, 0.1);
		if (rc != HB_OK || hb_sim_end(s) != HB_SIM_RUNNING)
			break;
		now = clock_seconds(CLOCK_MONOTONIC);
		if (tty && now - start > 1.0 && now - shown >= 0.25) {
			const struct hb_arc_sample *p = hb_arc_last(hb_sim_arc(s));
			char tb[32], Tb[32];

			fmt(p != NULL ? p->t : 0, hb_unit_time, tb, sizeof tb);
			fmt(T, hb_unit_time, Tb, sizeof Tb);
			fprintf(stderr, "\r" PROG ": t = %s of %s (%.0f%%), j = %ld, %zu collisions, "
			        "%.0f s; Ctrl-C stops and writes\033[K", tb, Tb,
			        p != NULL && T > 0 ? 100 * p->t / T : 0.0,
			        p != NULL ? p->j : 0L, hb_sim_ncollisions(s), now - start);
			shown = now;
		}
	}
	if (shown > 0)
		fprintf(stderr, "\r\033[K");
	*sig = cli_signal;
	return rc;
}

/*
 * Takes the branches a preset records, as the explorer took them
 * (hb_sim_branch_at).  A branch that begins where this run has no sample
 * is refused (-1); one whose state there differs from the recorded one is
 * taken with a warning: the run is not the one exported.
 */
static int
replay_branches(struct hb_sim *s, const char *path, const struct hb_branch *br, size_t nbr)
{
	char msg[1024];

	for (size_t k = 0; k < nbr; k++) {
		int same = 0, restarted = 0;

		msg[0] = '\0';
		if (hb_sim_branch_at(s, &br[k], &same, &restarted, msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": %s: [branch %zu]: %s\n", path, k + 1, msg);
			return -1;
		}
		if (restarted) {
			fprintf(stderr, PROG ": %s: [branch %zu]: its values cannot continue the run there "
			        "(the law or the bodies changed in contact); accepted: a branch the explorer "
			        "made\n", path, k + 1);
			return -1;
		}
		if (!same)
			fprintf(stderr, PROG ": warning: %s: [branch %zu]: the state at t = %.9g s differs "
			        "from the one recorded: this run is not the one the file was exported from\n",
			        path, k + 1, br[k].t);
	}
	return 0;
}

/* ------------------------------------------------------------------ */

int
batch_run(const struct batch_options *o)
{
	struct hb_scene sc;
	char path[1024], msg[4096]; /* the resolver names a refused preset whole */
	struct hb_collision live;
	struct hb_sim *s;
	struct hb_csv_export_opts eo = { 0 };
	struct plot_out po;
	struct hb_outputs pol;
	struct hb_error_estimate est_store, *est = NULL;
	struct hb_branch *br = NULL;
	size_t nbr = 0;
	int status = 0, have_live, rc, sig = 0;
	const int trace_out = is_stdout(o->trace), coll_out = is_stdout(o->collisions);
	/* The files to export; "-" goes to stdout after them. */
	const char *trace_file = trace_out ? NULL : o->trace;
	const char *coll_file = coll_out ? NULL : o->collisions;
	/* A CSV on stdout sends the report to stderr, as tar -v does with -f -. */
	FILE *out = trace_out || coll_out ? stderr : stdout;

	msg[0] = '\0';
	/* a preset may record branches (the explorer's b): they are replayed below */
	if (hb_preset_open_branched(o->preset, o->sets, o->nsets, &sc, &br, &nbr, path, sizeof path,
	                            msg, sizeof msg) != HB_OK) {
		err(msg[0] ? msg : o->preset);
		return 2;
	}
	if (o->error && nbr > 0) {
		fprintf(stderr, PROG ": --error: %s records %zu branch%s (the explorer's b); error "
		        "bars are made by a second run from t = 0, which has none; accepted: --error "
		        "on a preset without [branch] sections\n", path, nbr, nbr == 1 ? "" : "es");
		free(br);
		return 2;
	}
	if (trace_out && coll_out) {
		fprintf(stderr, PROG ": --trace - and --collisions -: only one CSV can go "
		        "to standard output; expected a file path for the other, e.g. "
		        "--trace - --collisions coll.csv\n");
		return 2;
	}
	if (trace_file != NULL && check_export_path("--trace", trace_file) != 0)
		return 2;
	if (coll_file != NULL && check_export_path("--collisions", coll_file) != 0)
		return 2;
	if (trace_file != NULL && coll_file != NULL && strcmp(trace_file, coll_file) == 0) {
		fprintf(stderr, PROG ": --trace and --collisions name the same file %s; "
		        "expected two different paths\n", trace_file);
		return 2;
	}
	/* The output policy (outputs.h): never the preset run, a shipped preset ... */
	eo.trace = trace_file;
	eo.coll = coll_file;
	eo.run_preset = path;
	eo.provenance = cli_provenance();
	eo.errors = NULL; /* set after the run, with --error */
	msg[0] = '\0';
	if ((trace_file != NULL || coll_file != NULL) &&
	    hb_csv_export_check_with(&eo, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": export: %s\n", msg);
		return 2;
	}

	/* --plot: the figure's own rules, the CSVs and the preset as the others (plot_out.h) */
	hb_outputs_init(&pol);
	hb_outputs_input(&pol, path, "the preset being run");
	/* --bodies: the same rules, with the CSVs and the scene saved beside them */
	if (o->bodies != NULL) {
		msg[0] = '\0';
		if (batch_bodies_check(&pol, o->bodies, trace_file, coll_file, msg, sizeof msg) != 0) {
			err(msg);
			return 2;
		}
	}
	if (o->plot != NULL) {
		msg[0] = '\0';
		if ((o->bodies == NULL && trace_file != NULL && hb_outputs_add(&pol, trace_file,
		                                  "--trace", msg, sizeof msg) != HB_OK) ||
		    (o->bodies == NULL && coll_file != NULL && hb_outputs_add(&pol, coll_file,
		                                  "--collisions", msg, sizeof msg) != HB_OK) ||
		    plot_out_parse(&po, "--plot", o->plot, msg, sizeof msg) != 0 ||
		    plot_out_register(&po, &pol, msg, sizeof msg) != 0) {
			err(msg);
			return 2;
		}
	}

	/*
	 * SIGINT, SIGTERM and SIGHUP end the run, and what was computed is
	 * reported and written, as after a numerical failure (signals.h).
	 */
	cli_signals_watch();
	msg[0] = '\0';
	s = hb_sim_new(&sc, msg, sizeof msg);
	if (s == NULL) {
		fprintf(stderr, PROG ": %s: %s\n", path, msg[0] ? msg : "cannot start the run");
		cli_signals_restore();
		free(br);
		return 2;
	}
	if (replay_branches(s, path, br, nbr) != 0) {
		hb_sim_free(s);
		cli_signals_restore();
		free(br);
		return 2;
	}
	free(br);
	rc = run_watched(s, &sig);
	if (hb_sim_end(s) == HB_SIM_END_FAIL || (rc != HB_OK && rc != HB_EDONE))
		status = 1;

	/* --error: the run again at a hundredth of the tolerances (error.h). */
	if (o->error && sig == 0 && hb_sim_end(s) != HB_SIM_END_FAIL) {
		msg[0] = '\0';
		if (hb_error_estimate(s, (const volatile int *)&cli_signal, &est_store, msg,
		                      sizeof msg) == HB_OK)
			est = &est_store;
		else if (cli_signal == 0) {
			fprintf(stderr, PROG ": --error: no error bars: %s\n", msg);
			status = 1;
		}
		sig = cli_signal;
	}

	/* The header comes after the run: the tolerance scales are set per contact. */
	have_live = hb_sim_contact_live(s, &live);
	if (!o->quiet) {
		/* the scene from t = 0, then where the branches the preset records begin */
		print_header(out, o->preset, path, hb_sim_scene0(s), hb_sim_stats(s));
		for (size_t k = 0; k < hb_sim_nbranches(s); k++) {
			char tb[64];

			fprintf(out, "branch %-4zu from t = %s (j = %ld) on, with the values of its "
			        "[branch %zu]\n", k + 1, fmt(hb_sim_branch_get(s, k)->t, hb_unit_time, tb,
			        sizeof tb), hb_sim_branch_get(s, k)->j, k + 1);
		}
		print_table(out, s, have_live ? &live : NULL, est);
	}
	if (o->jumps)
		print_jumps(out, hb_sim_arc(s));
	print_summary(out, s, sig, est);

	if (o->check) {
		msg[0] = '\0';
		if (hb_check_solution_pair(hb_sim_scene(s), hb_sim_arc(s), msg, sizeof msg) == HB_OK) {
			fprintf(out, "  check       solution pair: ok (%zu samples, %zu jumps: "
			         "ordered domain, flow samples in C, pre-jump samples in D, "
			         "post-jump = g(pre-jump))\n",
			         hb_arc_len(hb_sim_arc(s)), hb_arc_njumps(hb_sim_arc(s)));
		} else {
			fprintf(out, "  check       solution pair: FAILED: %s\n", msg);
			if (out != stderr)
				fprintf(stderr, PROG ": check failed: %s\n", msg);
			if (status == 0)
				status = 1;
		}
	}
	if (o->check && est != NULL) {
		double worst;

		msg[0] = '\0';
		if (hb_error_check(s, est, &worst, msg, sizeof msg) == HB_OK) {
			fprintf(out, "  check       error bars: ok (the largest is %.2g x rtol; each "
			        "must be at most %g x rtol = %.3g, relative to its value; t_e and "
			        "t_s to t_d, x_c^r to x_c^max, W to |J_Fc v_i| where larger)\n",
			        worst, HB_ERROR_CHECK_FACTOR,
			        HB_ERROR_CHECK_FACTOR * hb_sim_scene(s)->run.rtol);
		} else {
			fprintf(out, "  check       error bars: FAILED: %s\n", msg);
			if (out != stderr)
				fprintf(stderr, PROG ": check failed: %s\n", msg);
			if (status == 0)
				status = 1;
		}
	}
	if (hb_sim_scene(s)->chain.n > 0) {
		/* a chain's physics, over its bodies and per interface */
		if (batch_chain_check(out, s, o->check) && status == 0)
			status = 1;
	} else {
		/*
		 * The physics (check.h): a failure is a warning, and exit 1 with
		 * --check; a pass is said only when --check asks.
		 */
		struct hb_check_physics ph;

		msg[0] = '\0';
		if (hb_check_physics(hb_sim_scene(s), hb_sim_arc(s), &ph, msg, sizeof msg) == HB_OK) {
			if (o->check)
				fprintf(out, "  check       physics: ok (work-energy residual %.2g of the "
				        "energy scale, %.2g x the tolerance %.2g; %zu contacts: W and e "
				        "within what %s allows)\n", ph.resid, ph.resid / ph.tol, ph.tol,
				        ph.ncontacts, hb_sim_scene(s)->law->name);
		} else {
			fprintf(out, "  %-11s physics: %s: %s\n", o->check ? "check" : "warning",
			        o->check ? "FAILED" : "the run breaks what it must obey", msg);
			if (out != stderr) {
				char line[256];

				hb_check_physics_summary(&ph, line, sizeof line);
				fprintf(stderr, PROG ": %s: %s (see 'physics' in the report)\n",
				        o->check ? "check failed" : "warning", line);
			}
			if (o->check && status == 0)
				status = 1;
		}
		if (ph.nzero > 0)
			fprintf(out, "  note        collision %ld%s began at zero approach velocity "
			        "(v_i = %.3g m/s, an impact energy below what the tolerance "
			        "resolves): e = -v(t_s)/v_i means nothing there (\"-\" when v_i = 0); "
			        "what separates the bodies is the applied force\n", ph.zero_at,
			        ph.nzero > 1 ? " and others" : "", ph.vi_zero);
	}
	/* Now: the messages below come after the report. */
	if (out == stdout) {
		if (batch_flush_stdout() != 0)
			status = 2;
	} else {
		fflush(out);
	}
	/* After the report, so that it is the last thing a terminal shows. */
	if (sig != 0)
		fprintf(stderr, PROG ": interrupted by %s: what was computed is reported "
		        "and written\n", cli_signal_name(sig));
	else if (status == 1 && hb_sim_end(s) == HB_SIM_END_FAIL)
		fprintf(stderr, PROG ": the run failed: %s\n",
		        hb_sim_errmsg(s)[0] ? hb_sim_errmsg(s) : hb_status_str(rc));
	else if (rc != HB_OK && rc != HB_EDONE)
		fprintf(stderr, PROG ": the run stopped: %s\n", hb_status_str(rc));

	/*
	 * The files first, then stdout: a reader that stops early (| head)
	 * ends the process by SIGPIPE, and the files are written by then.
	 */
	if (trace_file != NULL || coll_file != NULL) {
		struct hb_csv_export_report rep;

		msg[0] = '\0';
		eo.errors = est;
		if (hb_csv_export_with(s, &eo, &rep, msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": export failed: %s\n", msg);
			status = 2;
		} else {
			if (trace_file != NULL)
				cli_print_wrote(trace_file, &rep.target[0]);
			if (coll_file != NULL)
				cli_print_wrote(coll_file, &rep.target[1]);
			if (rep.scene[0])
				cli_print_wrote(rep.scene, &rep.target[2]);
		}
	}
	if (o->bodies != NULL) {
		msg[0] = '\0';
		if (batch_bodies_write(&pol, o->bodies, s, msg, sizeof msg) != 0) {
			fprintf(stderr, PROG ": --bodies: %s\n", msg);
			status = 2;
		}
	}
	if (o->plot != NULL) {
		msg[0] = '\0';
		if (plot_write_run(&po, &pol, PLOT_STATE, s, msg, sizeof msg) != 0) {
			err(msg);
			status = 2;
		}
	}
	if (trace_out || coll_out) {
		msg[0] = '\0';
		rc = trace_out ? hb_csv_stream_arc(stdout, s, msg, sizeof msg)
		               : hb_csv_stream_collisions_err(stdout, s, est, msg, sizeof msg);
		/*
		 * EPIPE (SIGPIPE ignored): the reader has all it wanted; stop
		 * quietly, like a killed writer, with the run's status.
		 */
		if (rc != HB_OK && errno != EPIPE) {
			fprintf(stderr, PROG ": export failed: standard output: %s\n", msg);
			status = 2;
		}
		clearerr(stdout);   /* said here (or quiet on EPIPE): not again in main */
	}
	hb_error_free(est);
	hb_sim_free(s);
	if (sig == 0)
		sig = cli_signal;   /* caught while reporting: the report is whole */
	cli_signals_restore();
	/* An interrupted run: 128 + the signal, as a shell reports a kill. */
	return sig != 0 ? cli_signal_status(sig) : status;
}

int
batch_flush_stdout(void)
{
	int e = 0;

	errno = 0;
	if (fflush(stdout) != 0)
		e = errno != 0 ? errno : EIO;
	else if (ferror(stdout))
		e = EIO;
	clearerr(stdout);
	if (e == 0 || e == EPIPE)
		return 0;
	fprintf(stderr, PROG ": write error on standard output: %s\n", strerror(e));
	return 2;
}

/* ------------------------------------------------------------------ */
/* Listings                                                            */

int
batch_list_presets(void)
{
	struct hb_preset_info *pi = NULL;
	int n = hb_preset_list(&pi), i, w = 0;

	if (n < 0) {
		err("out of memory listing the presets");
		return 1;
	}
	if (n == 0) {
		const char *const *d = hb_preset_dirs();

		fprintf(stderr, PROG ": no presets found; looked in:");
		for (; d != NULL && *d != NULL; d++)
			fprintf(stderr, " %s", *d);
		fprintf(stderr, "\n");
	}
	for (i = 0; i < n; i++)
		if ((int)strlen(pi[i].name) > w)
			w = (int)strlen(pi[i].name);
	for (i = 0; i < n; i++) {
		printf("%-*s  %s\n", w, pi[i].name, pi[i].title);
		if (pi[i].description[0])
			print_wrapped(stdout, "    ", pi[i].description);
	}
	free(pi);
	return 0;
}

int
batch_list_laws(void)
{
	const struct hb_law_type *const *l;

	for (l = hb_law_list(); *l != NULL; l++) {
		const struct hb_law_type *law = *l;
		int i;

		printf("%s  %s\n", law->name, law->title);
		print_wrapped(stdout, "    ", law->description);
		printf("    internal states n_z = %d; parameters (units for the default "
		       "exponents):\n", law->n_z);
		for (i = 0; i < law->n_params; i++) {
			const struct hb_law_param *pp = &law->params[i];
			struct hb_scene_keyinfo ki; /* the typed row: unit, range, default */
			char dv[64];

			hb_scene_law_param_info(law, i, &ki);
			fmt(ki.number, ki.dim, dv, sizeof dv);
			printf("      %-8s %-14s range %-16s default %s%s\n",
			       pp->name, ki.unit[0] ? ki.unit : "(1)", ki.range, dv,
			       (pp->flags & HB_LAW_PARAM_STIFFNESS) && law->k_hertz != NULL
			           ? " (derived from k_H when both bodies have materials)" : "");
			if (ki.help[0])
				printf("      %-8s %s\n", "", ki.help);
		}
		printf("\n");
	}
	return 0;
}
