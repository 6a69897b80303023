/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * cursor.c - the primitives of the time cursor and of the run's
 * collisions (the completed ones and those in progress: a chain's
 * interfaces may be in contact side by side), which the panes, the
 * modes and nav.c's moves all use.  They read the run and set the cursor,
 * and call no other file of the explorer (tests/cli/calls.sh).
 */
#include "tui.h"

long
app_ncollisions(const struct app *a)
{
	return (long)(hb_sim_ncollisions(a->sim) + hb_sim_contacts_live(a->sim));
}

const struct hb_collision *
app_collision(const struct app *a, long i, struct hb_collision *live)
{
	size_t nc = hb_sim_ncollisions(a->sim);

	if (i < 0)
		return NULL;
	if ((size_t)i < nc)
		return hb_sim_collision(a->sim, (size_t)i);
	if (hb_sim_contact_live_nth(a->sim, (size_t)i - nc, live))
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

/*
 * Collision c is in progress at the cursor.  A two-body scene's contact is
 * the flow interval j the cursor's sample lies in.  A chain's interfaces
 * are in contact side by side, and a collision ends in the interval of its
 * separation, with other interfaces' jumps between: its times place it,
 * t_e <= t <= t_s (t_s is now for the contact in progress).
 */
int
coll_in_progress(const struct app *a, const struct hb_collision *c)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *s;

	if (c == NULL || hb_arc_len(arc) == 0)
		return 0;
	s = hb_arc_at(arc, a->cursor);
	if (hb_sim_scene(a->sim)->chain.n > 0)
		return c->te <= s->t && s->t <= c->ts;
	return s->q && c->j == s->j;
}

/*
 * The collision at the cursor among the table's rows, or -1: the one in
 * progress there (on a chain, of those in progress the one that commenced
 * last).
 */
long
coll_at_cursor(const struct app *a)
{
	long best = -1, n = app_ncollisions(a);
	double bt = 0;

	for (long i = 0; i < n; i++) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, i, &live);

		if (c == NULL || !table_shows(a, i) || !coll_in_progress(a, c))
			continue;
		if (hb_sim_scene(a->sim)->chain.n == 0)
			return i;
		if (best < 0 || c->te >= bt)
			best = i, bt = c->te;
	}
	return best;
}

void
cursor_to_collision(struct app *a, long i)
{
	struct hb_collision live;
	const struct hb_collision *c = app_collision(a, i, &live);

	if (c == NULL)
		return;
	/*
	 * a chain's collision ends in interval j, but other interfaces' jumps
	 * may come between its commencement and that: its time alone places it
	 */
	if (hb_sim_scene(a->sim)->chain.n > 0)
		cursor_set(a, hb_arc_find_t(hb_sim_arc(a->sim), c->te));
	else
		cursor_set(a, hb_arc_find(hb_sim_arc(a->sim), c->te, c->j));
	a->table_sel = i;
}

/* ---- the collisions table's rows: every collision, or interface k's (i) ---- */

int
table_iface(const struct app *a)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	int k = a->table_k - 1;

	/* a scene opened since with fewer interfaces, or none of a chain's: all */
	if (k < 0 || sc->chain.n == 0 || k < (sc->chain.floor ? 0 : 1) || k >= hb_sim_nbodies(a->sim))
		return -1;
	return k;
}

int
table_shows(const struct app *a, long i)
{
	struct hb_collision live;
	const struct hb_collision *c = app_collision(a, i, &live);
	int k = table_iface(a);

	return c != NULL && (k < 0 || c->k == k);
}

long
table_nrows(const struct app *a)
{
	long n = app_ncollisions(a), r = 0;

	if (table_iface(a) < 0)
		return n;
	for (long i = 0; i < n; i++)
		r += table_shows(a, i);
	return r;
}

long
table_row_of(const struct app *a, long i)
{
	long r = 0, n = app_ncollisions(a);

	if (table_iface(a) < 0)
		return i;
	for (long j = 0; j < i && j < n; j++)
		r += table_shows(a, j);
	return r;
}

long
table_row_coll(const struct app *a, long r)
{
	long n = app_ncollisions(a);

	if (r < 0)
		return -1;
	if (table_iface(a) < 0)
		return r < n ? r : -1;
	for (long i = 0; i < n; i++)
		if (table_shows(a, i) && r-- == 0)
			return i;
	return -1;
}
