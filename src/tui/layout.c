/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * layout.c - pane geometry (see layout.h).  Pure functions of the size.
 */
#include <string.h>

#include "layout.h"

static struct rect
rect(int y, int x, int h, int w)
{
	struct rect r = { y, x, h < 0 ? 0 : h, w < 0 ? 0 : w };
	return r;
}

int
layout_compute(int cols, int lines, int show_params, struct layout *L)
{
	int mid, bottom, left, ro;

	memset(L, 0, sizeof *L);
	L->cols = cols;
	L->lines = lines;
	if (cols < LAYOUT_MIN_COLS || lines < LAYOUT_MIN_LINES) {
		L->too_small = 1;
		return -1;
	}
	L->status = rect(0, 0, 1, cols);
	/* the readout: two rows where one cannot hold every value */
	ro = lines >= 23 && cols < LAYOUT_READOUT_COLS ? 2 : 1;
	L->readout = rect(lines - 2 - ro, 0, ro, cols);
	L->msg = rect(lines - 2, 0, 1, cols);
	L->footer = rect(lines - 1, 0, 1, cols);
	mid = lines - 3 - ro; /* rows 1 .. lines-3-ro */
	/* the bottom pane: about a third, at least 7 rows (header + 6), less
	 * on short terminals so that the plots keep 8 rows */
	bottom = mid / 3;
	if (bottom < 7)
		bottom = 7;
	if (mid - bottom < 12 && mid - 12 >= 6)
		bottom = mid - 12; /* 80x23: the plots keep 12 rows, the table 5 */
	if (lines < LAYOUT_FULL_LINES)
		bottom = mid - 8;
	if (cols >= LAYOUT_WIDE_COLS) {
		L->wide = 1;
		left = cols - LAYOUT_PARAMS_W - 1;
		L->plots = rect(1, 0, mid - bottom, left);
		L->table = rect(1 + mid - bottom, 0, bottom, left);
		L->params = rect(1, left + 1, mid, LAYOUT_PARAMS_W);
		L->table_visible = L->params_visible = 1;
	} else {
		L->plots = rect(1, 0, mid - bottom, cols);
		if (show_params) {
			L->params = rect(1 + mid - bottom, 0, bottom, cols);
			L->params_visible = 1;
		} else {
			L->table = rect(1 + mid - bottom, 0, bottom, cols);
			L->table_visible = 1;
		}
	}
	return 0;
}

void
layout_present(struct layout *L)
{
	L->plots = rect(1, 0, L->readout.y - 1, L->cols);
	L->table_visible = L->params_visible = 0;
	L->table.h = L->params.h = 0;
	L->wide = 0;
}

int
layout_stack(int h, int n, int extra, int *hs)
{
	int avail = h - extra, used = 0, i;

	if (n < 1)
		return 0;
	if (avail < n)
		avail = n;
	for (i = 0; i < n; i++) {
		hs[i] = avail / n + (i < avail % n ? 1 : 0);
		used += hs[i];
	}
	return used;
}

int
layout_scroll(int top, int sel, int h, int n)
{
	if (sel < top)
		top = sel;
	if (sel >= top + h)
		top = sel - h + 1;
	if (top > n - h)
		top = n - h;
	return top < 0 ? 0 : top;
}
