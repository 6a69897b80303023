/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_compare.c - several runs in one figure (plot_cmd.h:
 * plot_build_compare): the figure of each run as plot_build draws it, its
 * curves gathered into the first run's panels (a panel only one run has,
 * a z_c of one law, is added), each run in a style of its own, the axes
 * fitted to all; and the legend that says what differs between the runs
 * (plot_compare_labels): only the keys whose values differ.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "plot_cmd.h"

/* 1 if a key is no value the user chose: derived, or the scene's words */
static int
cosmetic(const struct hb_scene_keyinfo *k)
{
	return k->readonly || strcmp(k->key, "scene.name") == 0 ||
	       strcmp(k->key, "scene.description") == 0 || strncmp(k->key, "derived.", 8) == 0;
}

void
plot_compare_labels(const struct hb_scene *const *sc, const char *const *names, int n,
                    char (*labels)[64])
{
	enum { MAXD = 3 };
	char key[MAXD][48];
	int nd = 0, more = 0, named = 0;
	struct hb_scene_keyinfo a, b;

	for (int r = 1; r < n; r++)
		named |= strcmp(names[r], names[0]) != 0;
	/* the keys of the first scene that every scene has, with a value
	 * that is not the same in all */
	for (int i = 0; i < hb_scene_nkeys(sc[0]); i++) {
		int differs = 0, common = 1;
		struct hb_scene_error e;

		if (hb_scene_key(sc[0], i, &a) != HB_OK || cosmetic(&a))
			continue;
		for (int r = 1; r < n && common; r++) {
			if (hb_scene_get(sc[r], a.key, &b, &e) != HB_OK)
				common = 0;
			else if (strcmp(a.value, b.value) != 0)
				differs = 1;
		}
		if (!common || !differs)
			continue;
		if (nd < MAXD)
			cnum_snprintf(key[nd++], sizeof key[0], "%s", a.key);
		else
			more = 1;
	}
	for (int r = 0; r < n; r++) {
		size_t l = 0;

		labels[r][0] = '\0';
		/* presets that differ in many keys: by their names */
		if (nd == 0 || (named && more)) {
			cnum_snprintf(labels[r], 64, "%s", names[r]);
			continue;
		}
		for (int k = 0; k < nd && l < 64; k++) {
			struct hb_scene_error e;

			if (hb_scene_get(sc[r], key[k], &b, &e) != HB_OK)
				continue;
			l += (size_t)cnum_snprintf(labels[r] + l, 64 - l, "%s%s = %s", k ? ", " : "",
			                           key[k], b.value);
		}
		if (more && l < 64)
			cnum_snprintf(labels[r] + l, 64 - l, ", ...");
	}
}

/* The panel of f titled as q (x and y), or a new one like it; NULL when full. */
static struct plot_panel *
panel_like(struct plot_figure *f, const struct plot_panel *q)
{
	struct plot_panel *p;

	for (int k = 0; k < f->npanels; k++)
		if (strcmp(f->p[k].ya.title, q->ya.title) == 0 &&
		    strcmp(f->p[k].xa.title, q->xa.title) == 0)
			return &f->p[k];
	p = plot_panel_add(f, q->xa.title, q->xa.base, q->ya.title, q->ya.base);
	if (p != NULL) {
		p->xa = q->xa;
		p->ya = q->ya;
	}
	return p;
}

/* Moves the curves of t into f's panels, in style `run`; those of the
 * first panel labelled (the pgfplots legend is that panel's). */
static void
gather(struct plot_figure *f, struct plot_figure *t, int run, const char *label)
{
	for (int k = 0; k < t->npanels; k++) {
		struct plot_panel *q = &t->p[k], *p = panel_like(f, q);

		for (int i = 0; i < q->ns; i++) {
			if (p == NULL || p->ns >= PLOT_MAX_SERIES)
				continue;   /* freed with t */
			p->s[p->ns] = q->s[i];
			p->s[p->ns].style = run;
			cnum_snprintf(p->s[p->ns].label, sizeof p->s[p->ns].label, "%s",
			              p == &f->p[0] && i == 0 ? label : "");
			p->ns++;
			q->s[i].x = q->s[i].y = NULL;
		}
	}
}

static void
extent(const struct plot_panel *p, int y, double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (int i = 0; i < p->ns; i++)
		for (size_t k = 0; k < p->s[i].n; k++) {
			double v = y ? p->s[i].y[k] : p->s[i].x[k];

			if (isfinite(v)) {
				*lo = fmin(*lo, v);
				*hi = fmax(*hi, v);
			}
		}
}

int
plot_build_compare(struct plot_figure *f, enum plot_kind kind, const struct hb_sim *const *s,
                   const char *const *labels, int n, double w, double h, long coll, char *msg,
                   size_t mn)
{
	struct plot_figure *t = malloc(sizeof *t);
	double tmax = 0;

	if (t == NULL) {
		cnum_snprintf(msg, mn, "out of memory");
		return -1;
	}
	if (n > PLOT_MAX_SERIES) {
		free(t);
		cnum_snprintf(msg, mn, "%d runs to compare; expected at most %d", n, PLOT_MAX_SERIES);
		return -1;
	}
	for (int r = 0; r < n; r++) {
		struct plot_figure *into = r == 0 ? f : t;

		if (plot_build(into, kind, s[r], w, h, &coll, kind == PLOT_LOOP ? 1 : 0, msg, mn)
		    != 0) {
			char m[512];

			cnum_snprintf(m, sizeof m, "%s", msg);
			cnum_snprintf(msg, mn, "%s: %s", labels[r], m);
			if (r > 0)
				plot_figure_free(f);
			free(t);
			return -1;
		}
		if (r == 0) {
			for (int k = 0; k < f->npanels; k++)
				for (int i = 0; i < f->p[k].ns; i++) {
					f->p[k].s[i].style = 0;
					cnum_snprintf(f->p[k].s[i].label, sizeof f->p[k].s[i].label, "%s",
					              k == 0 && i == 0 ? labels[0] : "");
				}
		} else {
			if (kind == PLOT_STATE && t->npanels > 0)
				tmax = fmax(tmax, t->p[0].xa.hi);
			gather(f, t, r, labels[r]);
			plot_figure_free(t);
		}
		if (r == 0 && kind == PLOT_STATE && f->npanels > 0)
			tmax = f->p[0].xa.hi;
	}
	free(t);
	/* one legend entry per run; the contact shade of one run would mislead */
	f->nlegend = 0;
	for (int r = 0; r < n; r++)
		plot_legend_add(f, labels[r], r, 1, kind == PLOT_OBSERVABLES);
	for (int k = 0; k < f->npanels; k++) {
		struct plot_panel *p = &f->p[k];
		double lo, hi;

		free(p->band0);
		free(p->band1);
		p->band0 = p->band1 = NULL;
		p->nband = 0;
		extent(p, 1, &lo, &hi);
		plot_axis_fit(&p->ya, lo, hi, p->ya.base, 0, 4);
		if (kind == PLOT_STATE) {
			p->xlabels = k == f->npanels - 1;
			plot_axis_fit(&p->xa, 0, tmax > 0 ? tmax : 1, "s", 1, 5);
		} else {
			extent(p, 0, &lo, &hi);
			if (kind == PLOT_OBSERVABLES)
				plot_axis_fit(&p->xa, isfinite(lo) ? lo - 0.5 : 0, isfinite(hi) ? hi + 0.5 : 1,
				              "", 1, 5);
			else
				plot_axis_fit(&p->xa, lo, hi, p->xa.base, 0, 5);
		}
	}
	if (kind == PLOT_STATE && h <= 0)
		f->h = w / 252 * 72 * (0.7 + 0.85 * f->npanels) + 1.4 * f->font * (n > 2 ? 1 : 0);
	return 0;
}
