/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * canvas.h - curses-free plot raster and axis scaling.
 *
 * A canvas is a grid of w x h character cells.  Each cell holds a set of
 * "pixels": one per cell in ASCII mode, a 2 x 4 block of Braille dots in
 * Braille mode (U+2800 block, only where the locale is UTF-8).  Pixels are
 * addressed from the top-left corner; data coordinates map linearly onto
 * them, the range's ends onto the first and last pixel.  Each cell also
 * remembers the ink (1: the current run; 2.. ghosts of pinned runs) of the
 * last curve drawn through it, and may carry a mark (a single ASCII
 * character such as '|' that replaces the cell's dots).
 *
 * Nothing here calls curses: the explorer copies canvas_cell() into its
 * windows, and tests compare canvas_row() with expected strings.
 */
#ifndef HYBOUNCE_CANVAS_H
#define HYBOUNCE_CANVAS_H

#include <stddef.h>

enum { CANVAS_MAX_INK = 8 };

struct canvas {
	int w, h;               /* cells */
	int braille;            /* 1: 2 x 4 Braille dots per cell */
	int pw, ph;             /* pixels */
	unsigned char *dots;    /* w*h dot masks (ASCII: bit 0 only) */
	unsigned char *ink;     /* w*h inks, 0 where empty */
	char *mark;             /* w*h marks, 0 where none */
	unsigned char *mark_ink;
	double x0, x1, y0, y1;  /* data range */
	int thick;              /* Braille: each pixel also sets the ones below and to its right */
};

/* A w x h canvas (w, h >= 1), cleared, range [0,1] x [0,1]. NULL on no memory. */
struct canvas *
canvas_new(int w, int h, int braille);

void
canvas_free(struct canvas *c);

/* Clears dots, inks and marks (keeps the range). */
void
canvas_clear(struct canvas *c);

/* Sets the data range shown.  A degenerate range is widened to be drawable. */
void
canvas_range(struct canvas *c, double x0, double x1, double y0, double y1);

/* Pixel column / row of a data value (may lie outside [0, pw) / [0, ph)). */
double
canvas_pxf(const struct canvas *c, double x);
double
canvas_pyf(const struct canvas *c, double y);

/* Cell column of a data abscissa, or -1 when outside the canvas. */
int
canvas_col(const struct canvas *c, double x);

/* One pixel at data point (x, y) in ink; ignored outside the canvas. */
void
canvas_point(struct canvas *c, double x, double y, int ink);

/* A straight segment between two data points, clipped to the canvas. */
void
canvas_line(struct canvas *c, double xa, double ya, double xb, double yb, int ink);

/* Puts mark ch at cell (col, row) (ignored outside). */
void
canvas_mark(struct canvas *c, int col, int row, char ch, int ink);

/*
 * The text of cell (col, row) into out (at least 4 bytes + NUL: one
 * ASCII character or one UTF-8 Braille character; " " when empty).
 * Returns the cell's ink (the mark's ink for a mark), 0 when empty.
 */
int
canvas_cell(const struct canvas *c, int col, int row, char *out);

/*
 * The text of row `row` into buf (NUL-terminated, truncated to n).
 * Returns the number of bytes it needs (like snprintf).
 */
size_t
canvas_row(const struct canvas *c, int row, char *buf, size_t n);

/* The ASCII glyph of an ink: '*' for 1, then '.', 'o', '+', 'x', '#' ... */
char
canvas_glyph(int ink);

/* ---- axes ----------------------------------------------------------- */

enum { AXIS_MAX_TICKS = 24 };

struct axis {
	double lo, hi;          /* the range shown: the data range widened to whole ticks */
	double step;            /* tick spacing, SI */
	int nticks;
	double tick[AXIS_MAX_TICKS];
	double scale;           /* labels show value / scale */
	char unit[16];          /* "mm", "kN", "ms"; "" for none */
	int decimals;           /* digits after the point in labels */
};

/*
 * "Nice" step for a span divided into about `parts` parts: 1, 2 or 5 times
 * a power of ten, the smallest not below span / parts.
 */
double
canvas_nice_step(double span, int parts);

/*
 * Scales an axis for data in [lo, hi] with at most max_ticks ticks
 * (2 <= max_ticks <= AXIS_MAX_TICKS) spaced by a 1-2-5 step, the range
 * widened to whole steps.  base is the SI unit ("m", "N", "s"), whose prefix
 * is chosen by hb_units_axis() from the largest magnitude; NULL for a plain
 * number (scale 1, no unit).  A degenerate range (lo == hi) is widened
 * around the value; a non-finite one becomes [0, 1].  Returns 0.
 */
int
canvas_axis(double lo, double hi, int max_ticks, const char *base, struct axis *ax);

/* The label of value v on axis ax ("25", "-1.5", "0"; never "-0"). Returns buf. */
char *
canvas_tick_label(const struct axis *ax, double v, char *buf, size_t n);

/*
 * Writes an axis line of `width` characters into buf: tick labels placed at
 * the column of each tick (data range [x0, x1] mapped onto columns
 * 0 .. width-1), skipping labels that would overlap, and the unit (if
 * any) at the right end.  Returns buf.
 */
char *
canvas_axis_line(const struct axis *ax, double x0, double x1, int width, char *buf, size_t n);

#endif
