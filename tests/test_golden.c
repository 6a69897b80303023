/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_golden.c - the collision table of every paper preset against the one
 * stored in tests/golden/NAME.csv, so that a change in any number is seen.
 *
 * Each preset runs to its end as batch mode runs it; its collisions are
 * written as the CSV the batch mode writes (hb_csv_stream_collisions) and
 * compared with the stored table: the same header, the same rows, the same
 * empty fields, the index i exactly, and every other number x within
 *
 *     |x - golden| <= GOLDEN_TOL (|golden| + S),
 *
 * GOLDEN_TOL = 1e-6 (one part per million), S the scale of the column's
 * quantity in that table: the largest t_s for times, the largest |v_i| for
 * velocities, the largest x_c^max for lengths, the largest F_c^max for
 * forces, their product for energies, F_c^max times the largest t_d for
 * impulses, 1 for the ratios e and Lambda.  S keeps quantities that are
 * zero up to rounding (x_c^r of an elastic law, W of a lossless contact)
 * from asking for digits that are noise.  The engine at the presets'
 * tolerance (rtol = atol = 1e-12) reproduces itself with another stepper
 * (bsimp, rkck) or at rtol 1e-10 or 1e-13 within 5e-10 in this measure,
 * so a more accurate engine meets 1e-6 with a wide margin, while a changed
 * parameter, law or collision rule does not.
 *
 * The tables are refreshed deliberately, never by the test run:
 * `make golden` (HYBOUNCE_GOLDEN_WRITE=1) writes them from this engine.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/csv.h"
#include "testutil.h"

#define GOLDEN_TOL 1e-6
#define GOLDEN_DIR "tests/golden"
#define MAXCOL 32
#define MAXROW 4096

enum scale { S_EXACT, S_TIME, S_VELOCITY, S_LENGTH, S_FORCE, S_ENERGY, S_IMPULSE, S_ONE, S_NSCALE };

/* The scale of each column, by its CSV name. */
static const struct {
	const char *name;
	enum scale s;
} column_scale[] = {
	{ "i", S_EXACT },        { "t_e", S_TIME },       { "t_s", S_TIME },
	{ "t_d", S_TIME },       { "t_f", S_TIME },       { "v_i", S_VELOCITY },
	{ "e", S_ONE },          { "x_c_max", S_LENGTH }, { "F_c_max", S_FORCE },
	{ "x_c_r", S_LENGTH },   { "W", S_ENERGY },       { "J_Fc", S_IMPULSE },
	{ "J_Fe", S_IMPULSE },   { "Lambda", S_ONE },
};

struct table {
	char *text;                 /* owns the strings below */
	int ncol, nrow;
	const char *head[MAXCOL];
	const char **cell;          /* nrow x ncol, "" for an empty field */
};

/* Splits CSV text (no quoting: the collision CSV has none) in place. */
static void
parse(char *text, struct table *t, const char *what)
{
	char *line, *save;
	int header = 1;

	memset(t, 0, sizeof *t);
	t->text = text;
	t->cell = calloc((size_t)MAXROW * MAXCOL, sizeof *t->cell);
	cr_assert_not_null(t->cell);
	for (line = strtok_r(text, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
		const char **row = header ? t->head : &t->cell[(size_t)t->nrow * MAXCOL];
		char *f = line;
		int k = 0;

		line[strcspn(line, "\r")] = '\0';
		for (;;) {
			char *end = strchr(f, ',');

			cr_assert(k < MAXCOL, "%s: more than %d columns", what, MAXCOL);
			if (end != NULL)
				*end = '\0';
			row[k++] = f;
			if (end == NULL)
				break;
			f = end + 1;
		}
		if (header) {
			t->ncol = k;
			header = 0;
			continue;
		}
		cr_assert_eq(k, t->ncol, "%s: row %d has %d fields, the header %d", what, t->nrow + 1,
		             k, t->ncol);
		t->nrow++;
		cr_assert(t->nrow < MAXROW, "%s: more than %d rows", what, MAXROW);
	}
	cr_assert(!header, "%s: no header", what);
}

static void
table_free(struct table *t)
{
	free(t->text);
	free(t->cell);
}

static const char *
cell(const struct table *t, int r, int c)
{
	return t->cell[(size_t)r * MAXCOL + c];
}

static int
column(const struct table *t, const char *name)
{
	for (int c = 0; c < t->ncol; c++)
		if (strcmp(t->head[c], name) == 0)
			return c;
	return -1;
}

/* The largest |value| of a column (0 if the column is absent or empty). */
static double
colmax(const struct table *t, const char *name)
{
	int c = column(t, name);
	double m = 0;

	for (int r = 0; c >= 0 && r < t->nrow; r++)
		if (cell(t, r, c)[0] != '\0')
			m = fmax(m, fabs(strtod(cell(t, r, c), NULL)));
	return m;
}

/* The collisions CSV of a run of preset NAME, as batch mode writes it. */
static char *
computed_csv(const char *name)
{
	struct hb_scene sc;
	struct hb_sim *s;
	char *buf = NULL, msg[512];
	size_t len = 0;
	FILE *f;

	scene_preset(name, &sc);
	s = run_scene(&sc);
	f = open_memstream(&buf, &len);
	cr_assert_not_null(f);
	cr_assert_eq(hb_csv_stream_collisions(f, s, msg, sizeof msg), HB_OK, "%s: %s", name, msg);
	fclose(f);
	hb_sim_free(s);
	return buf;
}

/* Writes the table of NAME into tests/golden/ (make golden). */
static void
write_golden(const char *name, const char *csv)
{
	char path[512], tmp[520];
	FILE *f;

	snprintf(path, sizeof path, "%s/%s.csv", GOLDEN_DIR, name);
	snprintf(tmp, sizeof tmp, "%s.tmp", path);
	f = fopen(tmp, "w");
	cr_assert_not_null(f, "%s: cannot write", tmp);
	cr_assert(fputs(csv, f) >= 0 && fclose(f) == 0, "%s: write failed", tmp);
	cr_assert_eq(rename(tmp, path), 0, "%s: rename failed", path);
	cr_log_info("wrote %s", path);
}

static void
compare(const char *name, const struct table *got, const struct table *want)
{
	double scale[S_NSCALE];

	cr_assert_eq(got->ncol, want->ncol, "%s: %d columns, the golden table has %d", name,
	             got->ncol, want->ncol);
	for (int c = 0; c < want->ncol; c++)
		cr_assert_str_eq(got->head[c], want->head[c], "%s: column %d", name, c + 1);
	cr_assert_eq(got->nrow, want->nrow, "%s: %d collisions, the golden table has %d", name,
	             got->nrow, want->nrow);

	scale[S_EXACT] = 0;
	scale[S_TIME] = colmax(want, "t_s");
	scale[S_VELOCITY] = colmax(want, "v_i");
	scale[S_LENGTH] = colmax(want, "x_c_max");
	scale[S_FORCE] = colmax(want, "F_c_max");
	scale[S_ENERGY] = scale[S_FORCE] * scale[S_LENGTH];
	scale[S_IMPULSE] = scale[S_FORCE] * colmax(want, "t_d");
	scale[S_ONE] = 1;

	for (int c = 0; c < want->ncol; c++) {
		int k = -1;

		for (size_t m = 0; m < sizeof column_scale / sizeof column_scale[0]; m++)
			if (strcmp(column_scale[m].name, want->head[c]) == 0)
				k = (int)m;
		cr_assert(k >= 0, "%s: column %s has no tolerance scale in test_golden.c", name,
		          want->head[c]);
		for (int r = 0; r < want->nrow; r++) {
			const char *g = cell(got, r, c), *w = cell(want, r, c);
			double x, y, tol;

			cr_assert_eq(g[0] == '\0', w[0] == '\0', "%s: row %d %s: '%s', golden '%s'", name,
			             r, want->head[c], g, w);
			if (w[0] == '\0')
				continue;
			x = strtod(g, NULL);
			y = strtod(w, NULL);
			tol = column_scale[k].s == S_EXACT
			          ? 0
			          : GOLDEN_TOL * (fabs(y) + scale[column_scale[k].s]);
			cr_assert(fabs(x - y) <= tol,
			          "%s: collision %d, %s = %.17g, golden %.17g (difference %.3g > "
			          "tolerance %.3g)",
			          name, r, want->head[c], x, y, fabs(x - y), tol);
		}
	}
}

Test(golden, paper_presets_reproduce_their_collision_tables, .timeout = 300)
{
	const char *write = getenv("HYBOUNCE_GOLDEN_WRITE");

	for (const char *const *p = paper_presets; *p != NULL; p++) {
		char path[512];
		struct table got, want;
		char *csv = computed_csv(*p);

		if (write != NULL && strcmp(write, "1") == 0) {
			write_golden(*p, csv);
			free(csv);
			continue;
		}
		snprintf(path, sizeof path, "%s/%s.csv", GOLDEN_DIR, *p);
		parse(csv, &got, *p);
		parse(slurp(path), &want, path);
		compare(*p, &got, &want);
		table_free(&got);
		table_free(&want);
	}
}

/* The comparison sees a change: a run with c 1e-4 higher does not match its golden table. */
Test(golden, a_changed_parameter_is_seen)
{
	struct hb_scene sc;
	struct hb_sim *s;
	char msg[512];
	double e_golden, e_now;
	struct table want;
	int c;

	scene_preset("steel-on-bitumen", &sc);
	sc.par[hb_law_param_index(sc.law, "c")] *= 1 + 1e-4;
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	s = run_scene(&sc);
	parse(slurp(GOLDEN_DIR "/steel-on-bitumen.csv"), &want, "steel-on-bitumen golden");
	c = column(&want, "e");
	cr_assert(c >= 0 && want.nrow > 0 && hb_sim_ncollisions(s) > 0);
	e_golden = strtod(cell(&want, 0, c), NULL);
	e_now = hb_sim_collision(s, 0)->e;
	cr_assert(fabs(e_now - e_golden) > GOLDEN_TOL * (fabs(e_golden) + 1),
	          "e of the first collision moved only %.3g with c 1e-4 higher: the tolerance "
	          "%.3g would not see it", fabs(e_now - e_golden), GOLDEN_TOL);
	table_free(&want);
	hb_sim_free(s);
}
