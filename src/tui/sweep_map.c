/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_map.c - the sweep view's 2-D map (m): the observable over two keys,
 * the view's key across (its range) and the key swept before it up (its
 * range).  Row j is a background curve (hb_sweep_curve_start) over the
 * first key on the scene with the second key at its j-th value, so the map
 * fills in row by row while the screen keeps drawing; polling never waits
 * and freeing cancels the row computing.  Calls no mode and no pane
 * (tests/cli/calls.sh).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "status.h"
#include "csv_impl.h" /* csv_put_num: the engine's CSV numbers, C locale (src/core) */
#include "sweep_view.h"
#include "term.h"

enum { SV_MAP_MAX = 250000 };  /* grid points at most */

void
sv_map_drop(struct sv_map *m)
{
	hb_sweep_curve_free(m->c);
	hb_sweep_free(m->rows);
	free(m->x1);
	free(m->x2);
	free(m->z);
	free(m->st);
	free(m->ry);
	free(m->rst);
	free(m->nb);
	free(m->blo);
	free(m->bhi);
	free(m->bloc);
	memset(m, 0, sizeof *m);
}

/* Starts row m->row (its curve over key1 on the scene of key2's value). */
static int
row_start(struct sv_map *m, int obs, long coll, char *msg, size_t n)
{
	struct hb_scene sc;
	struct hb_scene_keyinfo ki;

	if (hb_sweep_point_scene(m->rows, m->row, &sc, msg, n) != HB_OK)
		return -1;
	if (hb_scene_get(&sc, m->key2, &ki, NULL) == 0)
		m->x2[m->row] = ki.number;
	m->c = hb_sweep_curve_start_refined(&sc, m->key1, m->spec1, obs, coll, m->bounds ? SV_BOUND_TOL : 0,
	                                    m->jobs, msg, n);
	if (m->c == NULL)
		return -1;
	if (hb_sweep_curve_npoints(m->c) != m->n1) {
		snprintf(msg, n, "row %ld has %ld points, not %ld", m->row, hb_sweep_curve_npoints(m->c), m->n1);
		return -1;
	}
	return 0;
}

static int
is_log(const char *spec)
{
	const char *sp = strrchr(spec, ':');

	return sp != NULL && strcmp(sp + 1, "log") == 0;
}

int
sv_map_start(struct sweep_view *v, int jobs, char *msg, size_t n)
{
	struct sv_map m = { 0 };
	char arg[256];

	if (v->prevkey[0] == 0 || strcmp(v->prevkey, v->key) == 0) {
		snprintf(msg, n, "a map needs a second key: q, select another parameter, S and Enter; "
		         "m then maps it (across) against %s (up)", v->key);
		return -1;
	}
	m.jobs = jobs > 0 ? jobs : 1;
	m.bounds = v->bounds;
	snprintf(m.key1, sizeof m.key1, "%s", v->key);
	snprintf(m.spec1, sizeof m.spec1, "%s", v->spec);
	snprintf(m.key2, sizeof m.key2, "%s", v->prevkey);
	snprintf(m.spec2, sizeof m.spec2, "%s", v->prevspec);
	m.obs = v->obs;
	m.coll = v->coll;
	m.log1 = is_log(m.spec1);
	m.log2 = is_log(m.spec2);
	m.rows = hb_sweep_new(&v->base, msg, n);
	if (m.rows == NULL)
		return -1;
	snprintf(arg, sizeof arg, "%s=%s", m.key2, m.spec2);
	if (hb_sweep_vary(m.rows, arg, msg, n) != HB_OK) {
		sv_map_drop(&m);
		return -1;
	}
	m.n2 = hb_sweep_npoints(m.rows);
	m.c = hb_sweep_curve_start(&v->base, m.key1, m.spec1, v->obs, v->coll, 1, msg, n);
	if (m.c == NULL) {
		sv_map_drop(&m);
		return -1;
	}
	m.n1 = hb_sweep_curve_npoints(m.c);
	hb_sweep_curve_free(m.c);
	m.c = NULL;
	if (m.n1 < 1 || m.n2 < 1 || m.n1 > SV_MAP_MAX / m.n2) {
		snprintf(msg, n, "a map of %ld x %ld points; at most %d in all", m.n1, m.n2, SV_MAP_MAX);
		sv_map_drop(&m);
		return -1;
	}
	m.x1 = calloc((size_t)m.n1, sizeof *m.x1);
	m.x2 = calloc((size_t)m.n2, sizeof *m.x2);
	m.z = calloc((size_t)(m.n1 * m.n2), sizeof *m.z);
	m.st = calloc((size_t)(m.n1 * m.n2), sizeof *m.st);
	m.ry = calloc((size_t)m.n1, sizeof *m.ry);
	m.rst = calloc((size_t)m.n1, sizeof *m.rst);
	m.nb = calloc((size_t)m.n2, sizeof *m.nb);
	m.blo = calloc((size_t)m.n2 * SV_MAP_ROW_BOUNDS, sizeof *m.blo);
	m.bhi = calloc((size_t)m.n2 * SV_MAP_ROW_BOUNDS, sizeof *m.bhi);
	m.bloc = calloc((size_t)m.n2 * SV_MAP_ROW_BOUNDS, sizeof *m.bloc);
	if (m.x1 == NULL || m.x2 == NULL || m.z == NULL || m.st == NULL || m.ry == NULL || m.rst == NULL
	    || m.nb == NULL || m.blo == NULL || m.bhi == NULL || m.bloc == NULL)
		term_oom();
	for (long i = 0; i < m.n1 * m.n2; i++) {
		m.z[i] = NAN;
		m.st[i] = HB_CURVE_PENDING;
	}
	if (row_start(&m, v->obs, v->coll, msg, n) != 0) {
		sv_map_drop(&m);
		return -1;
	}
	m.on = 1;
	sv_map_drop(&v->map);
	v->map = m;
	v->map.done = 0;
	return 0;
}

/*
 * Fixes the shades' range from the rows done (0 .. upto - 1) once one of
 * them has a value: their least and greatest.  Later values outside it
 * are drawn in the end shades and counted in the legend.
 */
static void
fix_range(struct sv_map *m, long upto)
{
	double lo = INFINITY, hi = -INFINITY;

	if (m->zfixed)
		return;
	for (long i = 0; i < upto * m->n1; i++)
		if (m->st[i] == HB_CURVE_DONE && isfinite(m->z[i])) {
			lo = fmin(lo, m->z[i]);
			hi = fmax(hi, m->z[i]);
		}
	if (!isfinite(lo))
		return;
	m->zfixed = 1;
	m->zlo = lo;
	m->zhi = hi;
}

int
sv_map_rescale(struct sv_map *m)
{
	int was = m->zfixed;
	double lo = m->zlo, hi = m->zhi;

	m->zfixed = 0;
	fix_range(m, m->n2);
	if (m->zfixed) {
		m->zrescaled = 1;
		return 0;
	}
	m->zfixed = was;
	m->zlo = lo;
	m->zhi = hi;
	return -1;
}

/* Copies the row computing; once it is whole (and its boundaries located), starts the next.  1 while computing. */
int
sv_map_tick(struct sv_map *m)
{
	char msg[256];
	int locating = 0;

	if (m->c == NULL)
		return 0;
	long k = hb_sweep_curve_poll(m->c, m->x1, m->ry, m->rst, m->n1);
	long *nb = &m->nb[m->row];
	double *blo = m->blo + m->row * SV_MAP_ROW_BOUNDS, *bhi = m->bhi + m->row * SV_MAP_ROW_BOUNDS;
	int *bloc = m->bloc + m->row * SV_MAP_ROW_BOUNDS;

	*nb = hb_sweep_curve_boundaries(m->c, blo, bhi, bloc, SV_MAP_ROW_BOUNDS);
	for (long i = 0; i < *nb && i < SV_MAP_ROW_BOUNDS; i++)
		locating |= !bloc[i];
	memcpy(m->z + m->row * m->n1, m->ry, (size_t)m->n1 * sizeof *m->ry);
	memcpy(m->st + m->row * m->n1, m->rst, (size_t)m->n1 * sizeof *m->rst);
	m->done = m->row * m->n1 + k;
	m->failed = 0;
	for (long i = 0; i < (m->row + 1) * m->n1; i++)
		m->failed += m->st[i] == HB_CURVE_FAILED;
	if (k < m->n1 || locating)
		return 1;
	fix_range(m, m->row + 1);
	/* the row is whole: the next one, on the same observable */
	hb_sweep_curve_free(m->c);
	m->c = NULL;
	if (++m->row >= m->n2)
		return 0;
	if (row_start(m, m->obs, m->coll, msg, sizeof msg) != 0) {
		/* the row's scene was valid when the map started: cannot happen but say so */
		for (long i = m->row * m->n1; i < m->n1 * m->n2; i++)
			m->st[i] = HB_CURVE_FAILED;
		m->row = m->n2;
		return 0;
	}
	return 1;
}

/* What sv_map_write_csv writes: the header, then the finished points, row by row. */
static void
fill_map(FILE *f, const void *ctx)
{
	const struct sv_map *m = ctx;
	const char *on = hb_sweep_observable_name(m->obs);

	fprintf(f, "i1,i2,%s,%s,%s\n", m->key1, m->key2, on);
	for (long j = 0; j < m->n2; j++)
		for (long i = 0; i < m->n1; i++) {
			long k = j * m->n1 + i;

			if (m->st[k] == HB_CURVE_PENDING)
				continue;
			fprintf(f, "%ld,%ld", i, j);
			csv_put_num(f, m->x1[i]);
			csv_put_num(f, m->x2[j]);
			csv_put_num(f, m->st[k] == HB_CURVE_DONE ? m->z[k] : NAN);
			fputc('\n', f);
		}
}

int
sv_map_write_csv(const struct sweep_view *v, const char *path, char *msg, size_t n)
{
	return hb_atomic_write_with(path, fill_map, &v->map, msg, n);
}
