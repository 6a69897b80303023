/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * plot_map.c - heat maps in the figure model (plot_model.h): the
 * sequential colour map, a panel's cells and its colour legend.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plot_model.h"

/* viridis (matplotlib's, by van der Walt and Smith) at 10 even steps,
 * linear between them */
static const unsigned char viridis[10][3] = {
	{ 0x44, 0x01, 0x54 }, { 0x48, 0x28, 0x78 }, { 0x3e, 0x4a, 0x89 }, { 0x31, 0x68, 0x8e },
	{ 0x26, 0x82, 0x8e }, { 0x1f, 0x9e, 0x89 }, { 0x35, 0xb7, 0x79 }, { 0x6d, 0xcd, 0x59 },
	{ 0xb4, 0xde, 0x2c }, { 0xfd, 0xe7, 0x25 },
};

void
plot_colormap(double t, double rgb[3])
{
	double u;
	int k;

	if (isnan(t)) {
		rgb[0] = rgb[1] = rgb[2] = 1;
		return;
	}
	t = fmin(1, fmax(0, t));
	u = t * 9;
	k = (int)floor(u);
	if (k >= 9)
		k = 8;
	u -= k;
	for (int c = 0; c < 3; c++)
		rgb[c] = ((1 - u) * viridis[k][c] + u * viridis[k + 1][c]) / 255;
}

static double
map_place(double v, double lo, double hi, int log)
{
	if (!isfinite(v))
		return NAN;
	if (log)
		return v > 0 && lo > 0 && hi > lo ? log10(v / lo) / log10(hi / lo) : NAN;
	return hi > lo ? (v - lo) / (hi - lo) : 0.5;
}

void
plot_map_colour(const struct plot_panel *p, double v, double rgb[3])
{
	plot_colormap(map_place(v, p->vlo, p->vhi, p->vlog), rgb);
}

int
plot_map_set(struct plot_panel *p, const double *x_edges, size_t nx, const double *y_edges,
             size_t ny, const double *v, double vlo, double vhi, int vlog)
{
	free(p->mx);
	free(p->my);
	free(p->mv);
	p->mnx = p->mny = 0;
	p->mx = malloc((nx + 1) * sizeof *p->mx);
	p->my = malloc((ny + 1) * sizeof *p->my);
	p->mv = malloc((nx * ny > 0 ? nx * ny : 1) * sizeof *p->mv);
	if (p->mx == NULL || p->my == NULL || p->mv == NULL)
		return -1;
	memcpy(p->mx, x_edges, (nx + 1) * sizeof *p->mx);
	memcpy(p->my, y_edges, (ny + 1) * sizeof *p->my);
	if (nx * ny > 0)
		memcpy(p->mv, v, nx * ny * sizeof *p->mv);
	p->mnx = nx;
	p->mny = ny;
	p->vlo = vlo;
	p->vhi = vhi;
	p->vlog = vlog && vlo > 0 && vhi > vlo;
	return 0;
}

struct plot_panel *
plot_colorbar_add(struct plot_figure *f, const struct plot_panel *of, const char *title,
                  const char *unit)
{
	enum { N = 128 };
	double xe[2] = { 0, 1 }, ye[N + 1], v[N];
	double lo = of->vlo, hi = of->vhi;
	int log = of->vlog;
	struct plot_panel *b;

	if (!(hi > lo)) {   /* one value: a band around it */
		double d = lo != 0 ? fabs(lo) * 0.1 : 1;

		lo -= d;
		hi += d;
		log = 0;
	}
	b = plot_panel_add(f, "", "", title, unit);
	if (b == NULL)
		return NULL;
	for (int k = 0; k <= N; k++)
		ye[k] = log ? lo * pow(hi / lo, (double)k / N) : lo + (hi - lo) * k / N;
	for (int k = 0; k < N; k++)
		v[k] = log ? sqrt(ye[k] * ye[k + 1]) : 0.5 * (ye[k] + ye[k + 1]);
	if (plot_map_set(b, xe, 1, ye, N, v, of->vlo, of->vhi, of->vlog) != 0)
		return NULL;
	b->colorbar = 1;
	b->xlabels = 0;
	b->ya.log = log;
	plot_axis_fit(&b->xa, 0, 1, "", 1, 2);
	b->xa.nticks = 0;
	plot_axis_fit(&b->ya, lo, hi, unit, 1, 5);
	return b;
}

