/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_out.c - a figure written to its file, the same way for
 * `hybounce plot --out` and the --plot of batch, sweep and fit
 * (plot_out.h).
 */
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "plot_out.h"
#include "plot_tex.h"
#include "report.h"

static int
ends_with(const char *s, const char *suffix)
{
	size_t a = strlen(s), b = strlen(suffix);

	return a >= b && cnum_casecmp(s + a - b, suffix) == 0;
}

int
plot_out_parse(struct plot_out *o, const char *opt, const char *path, char *msg, size_t n)
{
	memset(o, 0, sizeof *o);
	o->opt = opt;
	o->path = path;
	o->dpi = 300;
	o->slot = o->datslot = -1;
	if (ends_with(path, ".png"))
		o->fmt = PLOT_PNG;
	else if (ends_with(path, ".pdf"))
		o->fmt = PLOT_PDF;
	else if (ends_with(path, ".svg"))
		o->fmt = PLOT_SVG;
	else if (ends_with(path, ".tex") && strlen(path) > 4 && path[strlen(path) - 5] != '/')
		o->fmt = PLOT_TEX;
	else {
		cnum_snprintf(msg, n, "%s %s: unknown format; expected " PLOT_OUT_ACCEPTED, opt,
		              path);
		return -1;
	}
	if (o->fmt == PLOT_TEX) {
		/* FILE.tex reads FILE.dat, beside it */
		size_t l = strlen(path) - 4;

		if (l + 5 > sizeof o->datpath) {
			cnum_snprintf(msg, n, "%s %s: the name is too long", opt, path);
			return -1;
		}
		memcpy(o->datpath, path, l);
		memcpy(o->datpath + l, ".dat", 5);
		o->datname = strrchr(o->datpath, '/') != NULL ? strrchr(o->datpath, '/') + 1
		                                              : o->datpath;
	}
	return 0;
}

int
plot_out_register(struct plot_out *o, struct hb_outputs *pol, char *msg, size_t n)
{
	char m[4096];
	size_t ol = strlen(o->opt);

	m[0] = '\0';
	if (hb_outputs_add(pol, o->path, o->opt, m, sizeof m) != HB_OK) {
		cnum_snprintf(msg, n, "%s%s%s", strncmp(m, o->opt, ol) == 0 && m[ol] == ' ' ? ""
		              : o->opt, strncmp(m, o->opt, ol) == 0 && m[ol] == ' ' ? "" : " ", m);
		return -1;
	}
	o->slot = pol->nout - 1;
	if (o->fmt == PLOT_TEX) {
		/* the policy borrows its words: a string that outlives it */
		if (hb_outputs_add(pol, o->datpath, strcmp(o->opt, "--plot") == 0
		                   ? "the data file of --plot" : "the data file of --out", m,
		                   sizeof m) != HB_OK) {
			cnum_snprintf(msg, n, "%s", m);
			return -1;
		}
		o->datslot = pol->nout - 1;
	}
	return 0;
}

int
plot_out_write(struct plot_out *o, const struct hb_outputs *pol, struct plot_figure *fig,
               char *msg, size_t n)
{
	struct hb_atomic_set set;
	char m[4096];
	FILE *f;
	int rc;

	hb_atomic_begin(&set);
	m[0] = '\0';
	f = hb_atomic_add(&set, o->path, m, sizeof m);
	if (f == NULL) {
		cnum_snprintf(msg, n, "%s %s", o->opt, m);
		return -1;
	}
	if (o->fmt == PLOT_TEX) {
		FILE *d = hb_atomic_add(&set, o->datpath, m, sizeof m);

		if (d == NULL) {
			hb_atomic_abort(&set);
			cnum_snprintf(msg, n, "%s %s", o->opt, m);
			return -1;
		}
		rc = plot_tex_write(fig, f, d, o->datname, cli_provenance(), m, sizeof m);
	} else {
		rc = plot_cairo_write(fig, o->fmt, o->dpi, f, m, sizeof m);
	}
	if (rc != 0) {
		hb_atomic_abort(&set);
		cnum_snprintf(msg, n, "%s %s: %s", o->opt, o->path, m);
		return -1;
	}
	if (hb_atomic_commit(&set, m, sizeof m) != HB_OK) {
		cnum_snprintf(msg, n, "%s %s", o->opt, m);
		return -1;
	}
	{
		struct hb_atomic_target none;

		memset(&none, 0, sizeof none);
		cli_print_wrote(o->path, pol != NULL && o->slot >= 0 ? &pol->out[o->slot].target
		                                                      : &none);
		if (o->fmt == PLOT_TEX)
			cli_print_wrote(o->datpath, pol != NULL && o->datslot >= 0
			                ? &pol->out[o->datslot].target : &none);
	}
	return 0;
}

struct plot_figure *
plot_out_figure(const struct plot_out *o, char *msg, size_t n)
{
	struct plot_figure *fig = malloc(sizeof *fig);

	if (fig == NULL)
		cnum_snprintf(msg, n, "%s %s: out of memory", o->opt, o->path);
	return fig;
}

int
plot_out_finish(struct plot_out *o, const struct hb_outputs *pol, struct plot_figure *fig,
                int built, char *msg, size_t n)
{
	int rc;

	if (built != 0) {
		free(fig);
		return -1;
	}
	rc = plot_out_write(o, pol, fig, msg, n);
	plot_figure_free(fig);
	free(fig);
	return rc;
}
