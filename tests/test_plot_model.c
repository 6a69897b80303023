/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_plot_model.c - the figure model of hybounce plot (src/cli/plot_model.c):
 * ticks, units per axis, label markup, layout.
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>

#include "../src/cli/plot_model.h"

Test(plot_model, ticks_step_1_2_5_and_cover_the_range)
{
	double t[PLOT_MAX_TICKS];
	int n;

	plot_ticks(0, 1, 5, 0, t, &n);
	cr_assert_eq(n, 6);
	cr_assert_float_eq(t[0], 0, 1e-15);
	cr_assert_float_eq(t[1], 0.2, 1e-15);
	cr_assert_float_eq(t[5], 1, 1e-15);
	plot_ticks(-0.37, 0.52, 4, 0, t, &n);
	cr_assert(n >= 3 && n <= 6, "%d ticks", n);
	for (int k = 0; k < n; k++)
		cr_assert(t[k] >= -0.37 && t[k] <= 0.52);
	/* an index: whole steps, never 2.5 */
	plot_ticks(-0.5, 11.5, 5, 1, t, &n);
	for (int k = 0; k < n; k++)
		cr_assert_float_eq(t[k], nearbyint(t[k]), 0, "tick %g", t[k]);
	cr_assert(t[1] - t[0] == 1 || t[1] - t[0] == 2 || t[1] - t[0] == 5, "step %g", t[1] - t[0]);
	/* an empty or non-finite range has none */
	plot_ticks(1, 1, 5, 0, t, &n);
	cr_assert_eq(n, 0);
	plot_ticks(0, INFINITY, 5, 0, t, &n);
	cr_assert_eq(n, 0);
}

Test(plot_model, axis_takes_its_own_si_prefix)
{
	struct plot_axis a;

	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, -2.6e-4, 0, "m", 0, 5);
	cr_assert_str_eq(a.unit, "\xc2\xb5m");   /* the micro sign, not "u" */
	cr_assert_float_eq(a.scale, 1e-6, 1e-20);
	cr_assert(a.lo < -2.6e-4 && a.hi == 0, "0 stays at the edge");
	cr_assert(a.nticks >= 2);
	/* a minus sign, no decimals where the ticks are whole */
	cr_assert_str_eq(a.ticklabel[0], "\xe2\x88\x92" "200");

	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, 0, 380, "N", 0, 5);
	cr_assert_str_eq(a.unit, "N");
	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, -0.62, 0.37, "m/s", 0, 5);
	cr_assert_str_eq(a.unit, "mm/s");
	/* a pure number far from 1: a power of ten in the unit's place */
	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, -2.2e-4, 0, "", 0, 5);
	cr_assert_str_eq(a.unit, "10^{-6}");
	/* a range kept as given (the state's t axis) */
	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, 0, 0.5, "s", 1, 5);
	cr_assert(a.lo == 0 && a.hi == 0.5);
	cr_assert_str_eq(a.unit, "ms");
	/* a constant up to rounding is shown around its value, not as noise */
	memset(&a, 0, sizeof a);
	plot_axis_fit(&a, 425.11643695131, 425.11643695132, "N", 0, 5);
	cr_assert(a.hi - a.lo > 1, "range %g", a.hi - a.lo);
}

Test(plot_model, markup_splits_sub_and_superscripts)
{
	struct plot_run r[8];
	int n = plot_markup("F_c^max (kN)", r, 8);

	cr_assert_eq(n, 4);
	cr_assert_str_eq(r[0].text, "F");
	cr_assert_eq(r[0].kind, 0);
	cr_assert_str_eq(r[1].text, "c");
	cr_assert_eq(r[1].kind, 1);
	cr_assert_str_eq(r[2].text, "max");
	cr_assert_eq(r[2].kind, 2);
	cr_assert_str_eq(r[3].text, " (kN)");
	n = plot_markup("z_{c,1}", r, 8);
	cr_assert_eq(n, 2);
	cr_assert_str_eq(r[1].text, "c,1");
	n = plot_markup("t", r, 8);
	cr_assert_eq(n, 1);
	cr_assert_str_eq(r[0].text, "t");
}

Test(plot_model, layout_stacks_panels_inside_the_figure)
{
	static struct plot_figure f;
	const double x[] = { 0, 1, 2 }, y[] = { 0, 1, 4 };

	plot_figure_init(&f, 252, 400);
	for (int k = 0; k < 4; k++) {
		struct plot_panel *p = plot_panel_add(&f, "t", "s", "x", "m");

		cr_assert_not_null(p);
		cr_assert_eq(plot_series_add(p, "", x, y, 3, 0, 1, 0), 0);
		plot_axis_fit(&p->xa, 0, 2, "s", 1, 5);
		plot_axis_fit(&p->ya, 0, 4, "m", 0, 4);
		p->xlabels = k == 3;
	}
	plot_legend_add(&f, "contact", -1, 0, 0);
	plot_figure_layout(&f, NULL, NULL);
	for (int k = 0; k < 4; k++) {
		const struct plot_panel *p = &f.p[k];

		cr_assert(p->fx > 0 && p->fx + p->fw < f.w, "panel %d inside across", k);
		cr_assert(p->fy > f.ly + f.lh_box, "panel %d below the legend", k);
		cr_assert(p->fy + p->fh < f.h, "panel %d inside down", k);
		if (k > 0) {
			cr_assert(p->fy > f.p[k - 1].fy + f.p[k - 1].fh, "panels %d, %d apart", k - 1, k);
			cr_assert_float_eq(p->fx, f.p[0].fx, 1e-12, "one t axis");
			cr_assert_float_eq(p->fw, f.p[0].fw, 1e-12, "one t axis");
		}
	}
	plot_figure_free(&f);
	cr_assert_eq(f.npanels, 0);
}

Test(plot_model, log_axis_ticks_at_decades)
{
	struct plot_axis a;

	memset(&a, 0, sizeof a);
	a.log = 1;
	plot_axis_fit(&a, 1e3, 1e5, "N s/m", 1, 5);
	cr_assert_eq(a.nticks, 3);
	cr_assert_float_eq(a.tick[0], 1e3, 1e-9);
	cr_assert_float_eq(a.tick[2], 1e5, 1e-6);
	cr_assert_str_eq(a.ticklabel[1], "10^{4}");
	cr_assert_str_eq(a.unit, "N s/m");   /* no prefix on a log axis */
	cr_assert_float_eq(plot_axis_pos(&a, 1e4), 0.5, 1e-12);
	/* within one decade: 1-2-5 */
	plot_axis_fit(&a, 1.5e-3, 9e-3, "", 1, 5);
	cr_assert(a.nticks >= 2, "%d ticks", a.nticks);
	/* a range that is not positive falls back to a linear axis */
	a.log = 1;
	plot_axis_fit(&a, -1, 1, "", 0, 5);
	cr_assert_eq(a.log, 0);
}

Test(plot_model, colormap_lightness_rises_for_greyscale)
{
	double prev = -1, rgb[3];

	for (int k = 0; k <= 100; k++) {
		double g;

		plot_colormap(k / 100.0, rgb);
		g = 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2];
		cr_assert(g > prev, "grey level falls at %d: %g after %g", k, g, prev);
		prev = g;
	}
	plot_colormap(NAN, rgb);
	cr_assert(rgb[0] == 1 && rgb[1] == 1 && rgb[2] == 1, "no value: white");
}

Test(plot_model, colorbar_panel_sits_right_of_its_map)
{
	struct plot_figure f;
	struct plot_panel *p, *b;
	double xe[3] = { 0, 1, 2 }, ye[2] = { 0, 1 }, v[2] = { 1, 3 };

	plot_figure_init(&f, 252, 200);
	p = plot_panel_add(&f, "a", "", "b", "");
	cr_assert_eq(plot_map_set(p, xe, 2, ye, 1, v, 1, 3, 0), 0);
	plot_axis_fit(&p->xa, 0, 2, "", 1, 5);
	plot_axis_fit(&p->ya, 0, 1, "", 1, 5);
	b = plot_colorbar_add(&f, p, "e", "");
	cr_assert_not_null(b);
	plot_figure_layout(&f, NULL, NULL);
	p = &f.p[0];
	b = &f.p[1];
	cr_assert(b->colorbar);
	cr_assert(b->fx > p->fx + p->fw, "the legend right of the map");
	cr_assert(b->fx + b->fw < f.w, "inside the figure");
	cr_assert_float_eq(b->fy, p->fy, 1e-9);
	cr_assert_float_eq(b->fh, p->fh, 1e-9);
	cr_assert_float_eq(b->ya.lo, 1, 1e-12);
	cr_assert_float_eq(b->ya.hi, 3, 1e-12);
	plot_figure_free(&f);
}
