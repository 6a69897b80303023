/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * blit.c - a canvas copied to the screen (see blit.h).  Cells go in as wide
 * characters (add_wch): a Braille cell as a string would be decoded again
 * byte by byte, the larger part of a frame's cost.
 */
#include <curses.h>
#include <wchar.h>

#include "blit.h"
#include "canvas.h"

void
blit_canvas(const struct canvas *c, int y, int x, int curcol, int colour, blit_style *style)
{
	char cell[8];

	for (int r = 0; r < c->h; r++)
		for (int k = 0; k < c->w; k++) {
			int ink = canvas_cell(c, k, r, cell);
			attr_t attr = 0;
			short pair = 0;
			wchar_t wc[2] = { (unsigned char)cell[0], 0 };
			cchar_t cc;

			if (ink > 0)
				style(ink, colour, &attr, &pair);
			if (k == curcol) {
				if (cell[0] == ' ')
					wc[0] = ':';
				attr |= A_REVERSE;
			}
			if (wc[0] == ' ' && attr == 0 && pair == 0)
				continue;
			if ((unsigned char)cell[0] == 0xE2)   /* U+2800 + m (canvas_cell) */
				wc[0] = (wchar_t)(0x2800 + (((unsigned char)cell[1] - 0xA0) << 6) +
				                  ((unsigned char)cell[2] - 0x80));
			setcchar(&cc, wc, attr, pair, NULL);
			mvadd_wch(y + r, x + k, &cc);
		}
}
