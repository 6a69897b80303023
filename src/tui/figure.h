/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * figure.h - f's figures (private to src/tui/): figure.c saves the view,
 * figure_spacetime.c builds the space-time view's figure when V shows it.
 */
#ifndef HYBOUNCE_FIGURE_H
#define HYBOUNCE_FIGURE_H

struct app;
struct plot_figure;

enum { FIG_CURSOR_STYLE = 6 /* the palette's black, dot-dash */ };

/*
 * The space-time view in f (one panel: each body's y against t, the
 * contacts, the cursor at tcur when it is in range).  *nbodies: the bodies
 * drawn; *ncontacts: the contacts.  Returns 0, 1 when the view has nothing
 * to save yet (or a branched run), -1 out of memory.
 */
int
figure_spacetime(const struct app *a, struct plot_figure *f, double tcur, const char *cursor_label,
                 int *nbodies, long *ncontacts);

#endif
