/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_canvas.c - the explorer's curses-free plot raster and axes
 * (src/tui/canvas.c), compared as strings.
 */
#include <criterion/criterion.h>
#include <math.h>
#include <string.h>

#include "canvas.h"
#include "testutil.h"

static const char *
label(const struct axis *ax, int i)
{
	static char buf[8][32];
	return canvas_tick_label(ax, ax->tick[i], buf[i % 8], sizeof buf[0]);
}

Test(canvas, nice_step_125)
{
	assert_abs(canvas_nice_step(0.0213, 5), 0.005, 1e-15);
	assert_abs(canvas_nice_step(1.0, 5), 0.2, 1e-15);
	assert_abs(canvas_nice_step(3.0, 3), 1.0, 1e-15);
	assert_abs(canvas_nice_step(2385, 4), 1000, 1e-9);
	assert_abs(canvas_nice_step(0.37, 1), 0.5, 1e-15);
	assert_abs(canvas_nice_step(0, 4), 1, 0); /* degenerate: a usable step */
}

Test(canvas, ticks_millimetres)
{
	struct axis ax;

	canvas_axis(0, 0.0213, 6, "m", &ax);
	cr_assert_str_eq(ax.unit, "mm");
	assert_abs(ax.scale, 1e-3, 1e-18);
	assert_abs(ax.step, 0.005, 1e-15);
	cr_assert_eq(ax.nticks, 6);
	assert_abs(ax.lo, 0, 1e-18);
	assert_abs(ax.hi, 0.025, 1e-15);
	cr_assert_str_eq(label(&ax, 0), "0");
	cr_assert_str_eq(label(&ax, 1), "5");
	cr_assert_str_eq(label(&ax, 5), "25");
}

Test(canvas, ticks_kilonewtons_with_decimals)
{
	struct axis ax;

	canvas_axis(0, 2385, 6, "N", &ax);
	cr_assert_str_eq(ax.unit, "kN");
	assert_abs(ax.step, 500, 1e-9);
	cr_assert_eq(ax.nticks, 6);
	cr_assert_eq(ax.decimals, 1);
	cr_assert_str_eq(label(&ax, 0), "0.0");
	cr_assert_str_eq(label(&ax, 1), "0.5");
	cr_assert_str_eq(label(&ax, 5), "2.5");
}

Test(canvas, ticks_milliseconds)
{
	struct axis ax;

	canvas_axis(0, 0.5, 6, "s", &ax);
	cr_assert_str_eq(ax.unit, "ms");
	assert_abs(ax.step, 0.1, 1e-15);
	cr_assert_str_eq(label(&ax, 3), "300");
}

Test(canvas, ticks_negative_range_no_minus_zero)
{
	struct axis ax;

	canvas_axis(-0.0031, -0.0004, 6, "m", &ax);
	cr_assert_str_eq(ax.unit, "mm");
	assert_abs(ax.step, 0.001, 1e-15);
	cr_assert_eq(ax.nticks, 5);
	cr_assert_str_eq(label(&ax, 0), "-4");
	cr_assert_str_eq(label(&ax, 3), "-1");
	cr_assert_str_eq(label(&ax, 4), "0");
	cr_assert(ax.lo <= -0.0031 && ax.hi >= -0.0004);
}

Test(canvas, ticks_degenerate_ranges)
{
	struct axis ax;

	canvas_axis(0, 0, 6, "m", &ax);
	cr_assert(ax.hi > ax.lo);
	cr_assert(ax.nticks >= 2 && ax.nticks <= 6);
	cr_assert(ax.lo <= 0 && ax.hi >= 0);

	canvas_axis(0.02, 0.02, 6, "m", &ax);
	cr_assert(ax.hi > ax.lo);
	cr_assert(ax.lo <= 0.02 && ax.hi >= 0.02);
	cr_assert_str_eq(ax.unit, "mm");

	canvas_axis(NAN, 1, 6, "m", &ax);
	cr_assert(isfinite(ax.lo) && isfinite(ax.hi) && ax.hi > ax.lo);

	canvas_axis(3, 1, 4, NULL, &ax); /* inverted: swapped; plain number */
	cr_assert(ax.lo <= 1 && ax.hi >= 3);
	cr_assert_str_eq(ax.unit, "");
	cr_assert(ax.nticks <= 4);
}

Test(canvas, ticks_never_exceed_max)
{
	struct axis ax;
	double spans[] = { 1e-9, 0.0213, 1, 7.3, 123.4, 98765 };

	for (size_t i = 0; i < sizeof spans / sizeof spans[0]; i++)
		for (int m = 3; m <= 10; m++) {
			canvas_axis(-0.3 * spans[i], spans[i], m, NULL, &ax);
			cr_assert(ax.nticks >= 2 && ax.nticks <= m,
			          "span %g max %d gave %d ticks", spans[i], m, ax.nticks);
			cr_assert(ax.lo <= -0.3 * spans[i] * (1 - 1e-9) && ax.hi >= spans[i] * (1 - 1e-9),
			          "span %g max %d: [%g, %g]", spans[i], m, ax.lo, ax.hi);
		}
}

Test(canvas, axis_line_places_labels)
{
	struct axis ax;
	char buf[64];

	canvas_axis(0, 0.0213, 6, "m", &ax);
	canvas_axis_line(&ax, ax.lo, ax.hi, 30, buf, sizeof buf);
	/* ticks 0..25 mm over 30 columns: 0 at 0, 5 at 6, 10 at 12 (col 11.6),
	 * 15 at 17, 20 at 23; 25 (col 29) pushed left of the unit, would overlap: dropped */
	cr_assert_str_eq(buf, "0     5     10   15    20   mm");
}

Test(canvas, ascii_plot_rows)
{
	struct canvas *c = canvas_new(5, 3, 0);
	char row[64];

	canvas_range(c, 0, 4, 0, 2);
	canvas_line(c, 0, 1, 4, 1, 2);  /* a ghost: the middle row */
	canvas_point(c, 0, 0, 1);
	canvas_point(c, 2, 1, 1);
	canvas_point(c, 4, 2, 1);
	canvas_row(c, 0, row, sizeof row);
	cr_assert_str_eq(row, "    *");
	canvas_row(c, 1, row, sizeof row);
	cr_assert_str_eq(row, "..*..");
	canvas_row(c, 2, row, sizeof row);
	cr_assert_str_eq(row, "*    ");
	canvas_mark(c, 1, 2, '|', 1);
	canvas_row(c, 2, row, sizeof row);
	cr_assert_str_eq(row, "*|   ");
	canvas_free(c);
}

Test(canvas, ascii_line_diagonal_and_clipping)
{
	struct canvas *c = canvas_new(4, 4, 0);
	char row[64];

	canvas_range(c, 0, 3, 0, 3);
	canvas_line(c, -3, -3, 6, 6, 1); /* clipped to the diagonal */
	canvas_row(c, 0, row, sizeof row);
	cr_assert_str_eq(row, "   *");
	canvas_row(c, 3, row, sizeof row);
	cr_assert_str_eq(row, "*   ");
	canvas_clear(c);
	canvas_line(c, 10, 10, 20, 20, 1); /* wholly outside */
	for (int r = 0; r < 4; r++) {
		canvas_row(c, r, row, sizeof row);
		cr_assert_str_eq(row, "    ");
	}
	canvas_free(c);
}

Test(canvas, braille_dots)
{
	struct canvas *c = canvas_new(1, 1, 1);
	char row[16];

	cr_assert_eq(c->pw, 2);
	cr_assert_eq(c->ph, 4);
	canvas_range(c, 0, 1, 0, 3);
	canvas_point(c, 0, 3, 1);   /* top-left: dot 1 */
	canvas_point(c, 1, 0, 1);   /* bottom-right: dot 8 */
	canvas_row(c, 0, row, sizeof row);
	cr_assert_str_eq(row, "\xE2\xA2\x81"); /* U+2881 */
	canvas_clear(c);
	canvas_line(c, 0, 0, 0, 3, 1); /* the left column: dots 1,2,3,7 */
	canvas_row(c, 0, row, sizeof row);
	cr_assert_str_eq(row, "\xE2\xA1\x87"); /* U+2847 */
	canvas_free(c);
}

Test(canvas, braille_row_of_two_cells)
{
	struct canvas *c = canvas_new(2, 1, 1);
	char row[16];
	size_t len;

	canvas_range(c, 0, 3, 0, 3);
	canvas_line(c, 0, 0, 3, 0, 1); /* the bottom pixel row: dots 7 and 8 in each cell */
	len = canvas_row(c, 0, row, sizeof row);
	cr_assert_eq(len, 6);
	cr_assert_str_eq(row, "\xE2\xA3\x80\xE2\xA3\x80"); /* U+28C0 twice */
	cr_assert_eq(canvas_col(c, 0), 0);
	cr_assert_eq(canvas_col(c, 3), 1);
	cr_assert_eq(canvas_col(c, 3.5), -1);
	canvas_free(c);
}

Test(canvas, row_truncates_safely)
{
	struct canvas *c = canvas_new(6, 1, 0);
	char row[4];

	canvas_range(c, 0, 5, 0, 1);
	canvas_line(c, 0, 0, 5, 0, 1);
	cr_assert_eq(canvas_row(c, 0, row, sizeof row), 6);
	cr_assert_str_eq(row, "***");
	canvas_free(c);
}

/* A horizon of 1e308 s: short tick labels, never 30 digits (issue: run.T = 1e308). */
Test(canvas, ticks_huge_values_stay_short)
{
	struct axis ax;
	char lab[32], line[128];

	canvas_axis(0, 1e308, 6, "s", &ax);
	for (int i = 0; i < ax.nticks; i++) {
		canvas_tick_label(&ax, ax.tick[i], lab, sizeof lab);
		cr_assert(strlen(lab) <= 9, "label '%s'", lab);
	}
	canvas_axis_line(&ax, ax.lo, ax.hi, 70, line, sizeof line);
	cr_assert(strstr(line, "e+") != NULL, "'%s'", line);
	cr_assert(strlen(line) <= 70);
}

/* Presentation's thick lines: a Braille pixel is 2 x 2, a thin one 1 x 1. */
Test(canvas, thick_line_is_two_pixels_high)
{
	struct canvas *thin = canvas_new(10, 2, 1), *thick = canvas_new(10, 2, 1);
	char cell[8];

	cr_assert_not_null(thin);
	cr_assert_not_null(thick);
	thick->thick = 1;
	canvas_range(thin, 0, 1, 0, 1);
	canvas_range(thick, 0, 1, 0, 1);
	/* a horizontal line on pixel row 0 of 8 (y = 1: the top) */
	canvas_line(thin, 0, 1, 1, 1, 1);
	canvas_line(thick, 0, 1, 1, 1, 1);
	canvas_cell(thin, 4, 0, cell);
	cr_assert_str_eq(cell, "\xe2\xa0\x89");   /* U+2809: dots 1 and 4, the top row */
	canvas_cell(thick, 4, 0, cell);
	cr_assert_str_eq(cell, "\xe2\xa0\x9b");   /* U+281B: dots 1, 2, 4, 5, two rows */
	canvas_free(thin);
	canvas_free(thick);
}
