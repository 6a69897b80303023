/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * cursor.c - the primitives of the time cursor and of the run's
 * collisions (the completed ones and the live one), which the panes, the
 * modes and nav.c's moves all use.  They read the run and set the cursor,
 * and call no other file of the explorer (tests/cli/calls.sh).
 */
#include "tui.h"

long
app_ncollisions(const struct app *a)
{
	struct hb_collision live;

	return (long)hb_sim_ncollisions(a->sim) + (hb_sim_contact_live(a->sim, &live) ? 1 : 0);
}

const struct hb_collision *
app_collision(const struct app *a, long i, struct hb_collision *live)
{
	size_t nc = hb_sim_ncollisions(a->sim);

	if (i < 0)
		return NULL;
	if ((size_t)i < nc)
		return hb_sim_collision(a->sim, (size_t)i);
	if ((size_t)i == nc && hb_sim_contact_live(a->sim, live))
		return live;
	return NULL;
}

void
cursor_set(struct app *a, size_t i)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	size_t n = hb_arc_len(arc);

	if (n == 0) {
		a->cursor = 0;
		a->tcur = 0;
		return;
	}
	if (i >= n)
		i = n - 1;
	a->cursor = i;
	a->tcur = hb_arc_at(arc, i)->t;
}

void
cursor_clamp(struct app *a)
{
	size_t n = hb_arc_len(hb_sim_arc(a->sim));

	if (n == 0)
		a->cursor = 0;
	else if (a->cursor >= n)
		a->cursor = n - 1;
}

long
coll_at_cursor(const struct app *a)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *s;

	if (hb_arc_len(arc) == 0)
		return -1;
	s = hb_arc_at(arc, a->cursor);
	if (!s->q)
		return -1;
	for (long i = 0; i < app_ncollisions(a); i++) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, i, &live);
		if (c && c->j == s->j)
			return i;
	}
	return -1;
}

void
cursor_to_collision(struct app *a, long i)
{
	struct hb_collision live;
	const struct hb_collision *c = app_collision(a, i, &live);

	if (c == NULL)
		return;
	cursor_set(a, hb_arc_find(hb_sim_arc(a->sim), c->te, c->j));
	a->table_sel = i;
}
