/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * blit.h - a canvas (canvas.h) copied to the curses screen, each pane
 * choosing how its inks look.
 */
#ifndef HYBOUNCE_BLIT_H
#define HYBOUNCE_BLIT_H

#include <curses.h>

struct canvas;

/* The attributes and colour pair of a cell of ink (> 0); colour: whether colours are in use. */
typedef void blit_style(int ink, int colour, attr_t *attr, short *pair);

/*
 * Copies canvas c to the screen at (y, x), the inks as style says; column
 * curcol (-1: none) is the cursor's, reversed, ':' where it is blank.
 */
void
blit_canvas(const struct canvas *c, int y, int x, int curcol, int colour, blit_style *style);

#endif
