/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * canvas.c - curses-free plot raster (ASCII and Braille) and axis scaling.
 *
 * Invariants: dots, ink and mark are w*h arrays, row major from the top;
 * pw = w (ASCII) or 2w (Braille), ph = h or 4h; data x0 maps onto pixel
 * column 0 and x1 onto pw - 1, y1 onto pixel row 0 and y0 onto ph - 1.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "canvas.h"
#include "units.h"

struct canvas *
canvas_new(int w, int h, int braille)
{
	struct canvas *c;
	size_t nc;

	if (w < 1)
		w = 1;
	if (h < 1)
		h = 1;
	c = calloc(1, sizeof *c);
	if (c == NULL)
		return NULL;
	nc = (size_t)w * (size_t)h;
	c->w = w;
	c->h = h;
	c->braille = braille ? 1 : 0;
	c->pw = braille ? 2 * w : w;
	c->ph = braille ? 4 * h : h;
	c->dots = calloc(nc, 1);
	c->ink = calloc(nc, 1);
	c->mark = calloc(nc, 1);
	c->mark_ink = calloc(nc, 1);
	if (c->dots == NULL || c->ink == NULL || c->mark == NULL || c->mark_ink == NULL) {
		canvas_free(c);
		return NULL;
	}
	c->x0 = 0;
	c->x1 = 1;
	c->y0 = 0;
	c->y1 = 1;
	return c;
}

void
canvas_free(struct canvas *c)
{
	if (c == NULL)
		return;
	free(c->dots);
	free(c->ink);
	free(c->mark);
	free(c->mark_ink);
	free(c);
}

void
canvas_clear(struct canvas *c)
{
	size_t nc = (size_t)c->w * (size_t)c->h;

	memset(c->dots, 0, nc);
	memset(c->ink, 0, nc);
	memset(c->mark, 0, nc);
	memset(c->mark_ink, 0, nc);
}

/* Widens [*lo, *hi] when empty or inverted; non-finite becomes [0, 1]. */
static void
widen(double *lo, double *hi)
{
	double d;

	if (!isfinite(*lo) || !isfinite(*hi)) {
		*lo = 0;
		*hi = 1;
		return;
	}
	if (*hi < *lo) {
		d = *lo;
		*lo = *hi;
		*hi = d;
	}
	if (*hi - *lo <= 1e-300 || *hi - *lo <= 1e-12 * fmax(fabs(*lo), fabs(*hi))) {
		d = fabs(*lo) * 0.1;
		if (d == 0)
			d = 1;
		*lo -= d;
		*hi += d;
	}
}

void
canvas_range(struct canvas *c, double x0, double x1, double y0, double y1)
{
	widen(&x0, &x1);
	widen(&y0, &y1);
	c->x0 = x0;
	c->x1 = x1;
	c->y0 = y0;
	c->y1 = y1;
}

double
canvas_pxf(const struct canvas *c, double x)
{
	return (x - c->x0) / (c->x1 - c->x0) * (c->pw - 1);
}

double
canvas_pyf(const struct canvas *c, double y)
{
	return (c->y1 - y) / (c->y1 - c->y0) * (c->ph - 1);
}

int
canvas_col(const struct canvas *c, double x)
{
	double p = floor(canvas_pxf(c, x) + 0.5);

	if (!(p >= 0 && p < c->pw))
		return -1;
	return c->braille ? (int)p / 2 : (int)p;
}

static void setpx1(struct canvas *c, long px, long py, int ink);

/* Sets pixel (px, py) if inside; a thick line's pixel is 2 x 2. */
static void
setpx(struct canvas *c, long px, long py, int ink)
{
	setpx1(c, px, py, ink);
	if (c->thick && c->braille) {
		setpx1(c, px + 1, py, ink);
		setpx1(c, px, py + 1, ink);
		setpx1(c, px + 1, py + 1, ink);
	}
}

static void
setpx1(struct canvas *c, long px, long py, int ink)
{
	static const unsigned char bit[4][2] = {
		{ 0x01, 0x08 }, { 0x02, 0x10 }, { 0x04, 0x20 }, { 0x40, 0x80 }
	};
	size_t k;

	if (px < 0 || py < 0 || px >= c->pw || py >= c->ph)
		return;
	if (c->braille) {
		k = (size_t)(py / 4) * (size_t)c->w + (size_t)(px / 2);
		c->dots[k] |= bit[py % 4][px % 2];
	} else {
		k = (size_t)py * (size_t)c->w + (size_t)px;
		c->dots[k] = 1;
	}
	c->ink[k] = (unsigned char)ink;
}

void
canvas_point(struct canvas *c, double x, double y, int ink)
{
	double px = floor(canvas_pxf(c, x) + 0.5), py = floor(canvas_pyf(c, y) + 0.5);

	if (!(px >= 0 && px < c->pw && py >= 0 && py < c->ph))
		return;
	setpx(c, (long)px, (long)py, ink);
}

/*
 * Liang-Barsky clipping of the segment (ax, ay) - (bx, by) in pixel space
 * to [-0.5, pw - 0.5] x [-0.5, ph - 0.5].  Returns 0 when nothing is left.
 */
static int
clip(const struct canvas *c, double *ax, double *ay, double *bx, double *by)
{
	double t0 = 0, t1 = 1, dx = *bx - *ax, dy = *by - *ay;
	double p[4] = { -dx, dx, -dy, dy };
	double q[4] = { *ax + 0.5, c->pw - 0.5 - *ax, *ay + 0.5, c->ph - 0.5 - *ay };
	int i;

	for (i = 0; i < 4; i++) {
		if (p[i] == 0) {
			if (q[i] < 0)
				return 0;
			continue;
		}
		double r = q[i] / p[i];
		if (p[i] < 0) {
			if (r > t1)
				return 0;
			if (r > t0)
				t0 = r;
		} else {
			if (r < t0)
				return 0;
			if (r < t1)
				t1 = r;
		}
	}
	*bx = *ax + t1 * dx;
	*by = *ay + t1 * dy;
	*ax = *ax + t0 * dx;
	*ay = *ay + t0 * dy;
	return 1;
}

void
canvas_line(struct canvas *c, double xa, double ya, double xb, double yb, int ink)
{
	double ax = canvas_pxf(c, xa), ay = canvas_pyf(c, ya);
	double bx = canvas_pxf(c, xb), by = canvas_pyf(c, yb);
	long x0, y0, x1, y1, dx, dy, sx, sy, err, e2, guard;

	if (!isfinite(ax) || !isfinite(ay) || !isfinite(bx) || !isfinite(by))
		return;
	if (!clip(c, &ax, &ay, &bx, &by))
		return;
	x0 = lround(ax);
	y0 = lround(ay);
	x1 = lround(bx);
	y1 = lround(by);
	/* Bresenham */
	dx = labs(x1 - x0);
	dy = -labs(y1 - y0);
	sx = x0 < x1 ? 1 : -1;
	sy = y0 < y1 ? 1 : -1;
	err = dx + dy;
	for (guard = 0; guard <= 4L * (c->pw + c->ph); guard++) {
		setpx(c, x0, y0, ink);
		if (x0 == x1 && y0 == y1)
			break;
		e2 = 2 * err;
		if (e2 >= dy) {
			err += dy;
			x0 += sx;
		}
		if (e2 <= dx) {
			err += dx;
			y0 += sy;
		}
	}
}

void
canvas_mark(struct canvas *c, int col, int row, char ch, int ink)
{
	size_t k;

	if (col < 0 || row < 0 || col >= c->w || row >= c->h)
		return;
	k = (size_t)row * (size_t)c->w + (size_t)col;
	c->mark[k] = ch;
	c->mark_ink[k] = (unsigned char)ink;
}

char
canvas_glyph(int ink)
{
	static const char g[] = "*.o+x#%@";

	if (ink < 1 || ink > (int)(sizeof g - 1))
		return '*';
	return g[ink - 1];
}

int
canvas_cell(const struct canvas *c, int col, int row, char *out)
{
	size_t k;
	unsigned m;

	out[0] = ' ';
	out[1] = 0;
	if (col < 0 || row < 0 || col >= c->w || row >= c->h)
		return 0;
	k = (size_t)row * (size_t)c->w + (size_t)col;
	if (c->mark[k]) {
		out[0] = c->mark[k];
		return c->mark_ink[k];
	}
	m = c->dots[k];
	if (m == 0)
		return 0;
	if (c->braille) {
		/* U+2800 + m in UTF-8: E2 A0+(m>>6) 80+(m&63) */
		out[0] = (char)0xE2;
		out[1] = (char)(0xA0 + (m >> 6));
		out[2] = (char)(0x80 + (m & 0x3F));
		out[3] = 0;
	} else {
		out[0] = canvas_glyph(c->ink[k]);
	}
	return c->ink[k];
}

size_t
canvas_row(const struct canvas *c, int row, char *buf, size_t n)
{
	size_t len = 0, l;
	char cell[8];
	int col;

	for (col = 0; col < c->w; col++) {
		canvas_cell(c, col, row, cell);
		l = strlen(cell);
		if (len + l < n)
			memcpy(buf + len, cell, l);
		len += l;
	}
	if (n > 0)
		buf[len < n ? len : n - 1] = 0;
	return len;
}

/* ---- axes ----------------------------------------------------------- */

double
canvas_nice_step(double span, int parts)
{
	double raw, p10, f;

	if (parts < 1)
		parts = 1;
	if (!(span > 0) || !isfinite(span))
		return 1;
	raw = span / parts;
	p10 = pow(10, floor(log10(raw)));
	f = raw / p10;
	/* guard against log10 rounding: f must be in [1, 10) */
	if (f < 1) {
		p10 /= 10;
		f *= 10;
	}
	if (f <= 1 * (1 + 1e-9))
		f = 1;
	else if (f <= 2 * (1 + 1e-9))
		f = 2;
	else if (f <= 5 * (1 + 1e-9))
		f = 5;
	else
		f = 10;
	return f * p10;
}

/* floor(r), but r within 1e-9 of an integer counts as that integer. */
static double
floor_fuzzy(double r)
{
	double k = floor(r + 0.5);

	return fabs(r - k) <= 1e-9 * fmax(1, fabs(r)) ? k : floor(r);
}

int
canvas_axis(double lo, double hi, int max_ticks, const char *base, struct axis *ax)
{
	double step, a, b, mag;
	int parts, n;

	memset(ax, 0, sizeof *ax);
	if (max_ticks < 2)
		max_ticks = 2;
	if (max_ticks > AXIS_MAX_TICKS)
		max_ticks = AXIS_MAX_TICKS;
	widen(&lo, &hi);
	for (parts = max_ticks - 1; ; parts--) {
		step = canvas_nice_step(hi - lo, parts);
		a = floor_fuzzy(lo / step);
		b = -floor_fuzzy(-hi / step);
		n = (int)(b - a) + 1;
		if (n <= max_ticks || parts <= 1)
			break;
	}
	/* Still too many (a range across 0 needs 3 ticks): bigger steps, a few times. */
	for (int k = 0; k < 3 && n > max_ticks; k++) {
		step = canvas_nice_step(step * 1.5, 1);
		a = floor_fuzzy(lo / step);
		b = -floor_fuzzy(-hi / step);
		n = (int)(b - a) + 1;
	}
	ax->step = step;
	ax->lo = a * step;
	ax->hi = b * step;
	ax->nticks = n;
	for (int i = 0; i < n; i++) {
		ax->tick[i] = (a + i) * step;
		if (fabs(ax->tick[i]) < 1e-9 * step)
			ax->tick[i] = 0;
	}
	if (base != NULL && base[0]) {
		mag = fmax(fabs(ax->lo), fabs(ax->hi));
		ax->scale = hb_units_axis(mag > 0 ? mag : 1, base, ax->unit, sizeof ax->unit);
		if (!(ax->scale > 0) || !isfinite(ax->scale))
			ax->scale = 1;
	} else {
		ax->scale = 1;
		ax->unit[0] = 0;
	}
	{
		double s = step / ax->scale;
		ax->decimals = s >= 1 - 1e-9 ? 0 : (int)ceil(-log10(s) - 1e-9);
		if (ax->decimals > 9)
			ax->decimals = 9;
	}
	return 0;
}

char *
canvas_tick_label(const struct axis *ax, double v, char *buf, size_t n)
{
	double s = v / ax->scale;

	if (fabs(s) < 0.5 * pow(10, -ax->decimals))
		s = 0; /* never "-0" */
	if (fabs(s) >= 1e6 || !isfinite(s)) {
		/* beyond the largest prefix: a short exponent, never 30 digits */
		snprintf(buf, n, "%.3g", s);
		return buf;
	}
	snprintf(buf, n, "%.*f", ax->decimals, s);
	if (strcmp(buf, "-0") == 0)
		snprintf(buf, n, "0");
	return buf;
}

char *
canvas_axis_line(const struct axis *ax, double x0, double x1, int width, char *buf, size_t n)
{
	char lab[32];
	int i, col, next = 0, len, ulen;

	if (n == 0)
		return buf;
	if ((size_t)width >= n)
		width = (int)n - 1;
	memset(buf, ' ', (size_t)width);
	buf[width] = 0;
	ulen = (int)strlen(ax->unit);
	for (i = 0; i < ax->nticks; i++) {
		double v = ax->tick[i];
		if (v < x0 - 1e-9 * (x1 - x0) || v > x1 + 1e-9 * (x1 - x0))
			continue;
		col = (int)lround((v - x0) / (x1 - x0) * (width - 1));
		canvas_tick_label(ax, v, lab, sizeof lab);
		len = (int)strlen(lab);
		if (col + len > width - (ulen ? ulen + 1 : 0))
			col = width - (ulen ? ulen + 1 : 0) - len;
		if (col < next || col < 0)
			continue;
		memcpy(buf + col, lab, (size_t)len);
		next = col + len + 1;
	}
	if (ulen && ulen < width && width - ulen >= next)
		memcpy(buf + width - ulen, ax->unit, (size_t)ulen);
	return buf;
}
