/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * nav.c - the time cursor, the collisions and the selection of the
 * focused table: moving around a run without changing it.
 *
 * The cursor is a sample index into the current run's arc (always valid:
 * < hb_arc_len); tcur is the time it stands for.  Every function here only
 * reads the run (hb_sim_arc, hb_sim_collision) and moves the cursor or a
 * selection.  The cursor's primitives, which every pane uses, are
 * cursor.c's.
 */
#include <curses.h>
#include <math.h>
#include <string.h>

#include "cnum.h" /* ASCII case fold (src/core) */
#include "tui.h"

/* The table selection follows the cursor onto a contact (one the table shows). */
static void
follow(struct app *a)
{
	long i = coll_at_cursor(a);

	if (i >= 0 && table_shows(a, i))
		a->table_sel = i;
}

static void
jump_move(struct app *a, int dir)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	size_t k, nk = hb_arc_nintervals(arc);

	a->playing = 0;
	if (hb_arc_len(arc) == 0 || nk == 0)
		return;
	k = hb_arc_interval_of(arc, a->cursor);
	if (dir > 0) {
		if (k + 1 < nk)
			cursor_set(a, hb_arc_interval_at(arc, k + 1)->first);
		else
			app_msg(a, 0, "no later jump (yet)");
	} else {
		if (a->cursor > hb_arc_interval_at(arc, k)->first && k > 0)
			cursor_set(a, hb_arc_interval_at(arc, k)->first);
		else if (k > 0)
			cursor_set(a, hb_arc_interval_at(arc, k - 1)->first);
		else {
			cursor_set(a, 0);
			app_msg(a, 0, "no earlier jump");
		}
	}
	follow(a);
}

/*
 * A chain's collisions are listed in the order they end and overlap in
 * time: the next (previous) one shown is the one that commences next
 * (last) after the cursor's time, by (t_e, i); at the selected one's
 * commencement, after (before) that one.
 */
static long
chain_coll_next(struct app *a, int dir)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	struct hb_collision live;
	const struct hb_collision *c = table_shows(a, a->table_sel) ? app_collision(a, a->table_sel, &live) : NULL;
	double t0 = hb_arc_at(arc, a->cursor)->t, bt = 0;
	long i0 = -1, best = -1, nc = app_ncollisions(a);

	if (c != NULL && hb_arc_find_t(arc, c->te) == a->cursor) {
		t0 = c->te;
		i0 = a->table_sel;
	}
	for (long i = 0; i < nc; i++) {
		if (!table_shows(a, i) || (c = app_collision(a, i, &live)) == NULL)
			continue;
		int after = c->te > t0 || (c->te == t0 && i > i0);
		int before = c->te < t0 || (c->te == t0 && i < i0);
		if (dir > 0 && after && (best < 0 || c->te < bt))
			best = i, bt = c->te;
		if (dir < 0 && before && (best < 0 || c->te >= bt))
			best = i, bt = c->te;
	}
	return best;
}

static void
coll_move(struct app *a, int dir)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	long nc = app_ncollisions(a), i, best = -1;
	const struct hb_arc_sample *s;
	size_t first;

	a->playing = 0;
	if (hb_arc_len(arc) == 0)
		return;
	s = hb_arc_at(arc, a->cursor);
	first = hb_arc_interval_at(arc, hb_arc_interval_of(arc, a->cursor))->first;
	for (i = hb_sim_scene(a->sim)->chain.n > 0 ? nc : 0; i < nc; i++) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, i, &live);
		if (c == NULL || !table_shows(a, i))
			continue;
		if (dir > 0 && c->j > s->j) {
			best = i;
			break;
		}
		if (dir < 0 && (c->j < s->j || (c->j == s->j && a->cursor > first)))
			best = i;
	}
	if (hb_sim_scene(a->sim)->chain.n > 0)
		best = chain_coll_next(a, dir);
	if (best < 0) {
		if (table_iface(a) >= 0)
			app_msg(a, 0, dir > 0 ? "no later collision of interface %d (yet; i: every interface's)"
			        : "no earlier collision of interface %d (i: every interface's)", table_iface(a));
		else
			app_msg(a, 0, dir > 0 ? "no later collision (yet)" : "no earlier collision");
		return;
	}
	cursor_to_collision(a, best);
}

double
view_span(const struct app *a)
{
	const struct hb_arc_sample *l = hb_arc_last(hb_sim_arc(a->sim));
	double T = hb_sim_scene(a->sim)->run.T;

	if (a->view == VIEW_FOLLOW)
		return T / 10;
	if (a->view == VIEW_ZOOM) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, a->zoom_i, &live);
		if (c)
			return 1.5 * fmax(c->ts - c->te, 1e-9);
	}
	return l && hb_sim_end(a->sim) != HB_SIM_RUNNING ? l->t : T;
}

static void
scrub(struct app *a, int dir)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	double d = view_span(a) / 100;

	if (hb_arc_len(arc) == 0)
		return;
	a->playing = 0;
	a->tcur += dir * d;
	if (a->tcur < 0)
		a->tcur = 0;
	if (a->tcur > hb_arc_last(arc)->t)
		a->tcur = hb_arc_last(arc)->t;
	a->cursor = hb_arc_find_t(arc, a->tcur);
	follow(a);
}

void
zoom_on(struct app *a, int view)
{
	long i = coll_at_cursor(a);

	if (i < 0)
		i = a->table_sel;
	if (app_ncollisions(a) == 0) {
		app_msg(a, 1, "no collision yet");
		return;
	}
	if (i >= app_ncollisions(a))
		i = app_ncollisions(a) - 1;
	if (!table_shows(a, i)) {
		app_msg(a, 1, "interface %d has no collision (yet; i: every interface's)", table_iface(a));
		return;
	}
	a->zoom_i = i;
	a->view = view;
	a->table_sel = i;
}

/* Rows of the focused pane that a page holds. */
static long
page_rows(const struct app *a)
{
	int h = a->focus == FOCUS_PARAMS ? a->L.params.h : a->L.table.h;

	return h > 2 ? h - 2 : 1;
}

void
sel_move(struct app *a, long d)
{
	if (a->focus == FOCUS_TABLE) {
		/* d rows of those shown (every collision, or interface k's: i) */
		long n = table_nrows(a), r = table_row_of(a, a->table_sel), i;
		if (!table_shows(a, a->table_sel) && d > 0)
			r--;    /* a selection not shown: its row is the next one's */
		r += d;
		if (r >= n)
			r = n - 1;
		if (r < 0)
			r = 0;
		if ((i = table_row_coll(a, r)) >= 0)
			a->table_sel = i;
	} else {
		struct param_row rows[256];
		int n = params_rows(hb_sim_scene(a->sim), rows, 256), s = a->param_sel;
		int step = d > 0 ? 1 : -1;
		for (long k = 0; k < (d > 0 ? d : -d); k++) {
			int t = s + step;
			while (t >= 0 && t < n && rows[t].key < 0)
				t += step;
			if (t < 0 || t >= n)
				break;
			s = t;
		}
		a->param_sel = s;
	}
}

/* ---- actions ---------------------------------------------------------- */

void act_step_fwd(struct app *a) { a->playing = 0; cursor_set(a, a->cursor + 1); follow(a); }
void act_step_back(struct app *a)
{
	a->playing = 0;
	cursor_set(a, a->cursor > 0 ? a->cursor - 1 : 0);
	follow(a);
}
void act_prev_jump(struct app *a) { jump_move(a, -1); }
void act_next_jump(struct app *a) { jump_move(a, 1); }
void act_prev_coll(struct app *a) { coll_move(a, -1); }
void act_next_coll(struct app *a) { coll_move(a, 1); }
void act_scrub_back(struct app *a) { scrub(a, -1); }
void act_scrub_fwd(struct app *a) { scrub(a, 1); }
void act_home(struct app *a) { a->playing = 0; cursor_set(a, 0); follow(a); }
void act_end(struct app *a) { a->playing = 0; cursor_set(a, (size_t)-1); follow(a); }
void act_up(struct app *a) { sel_move(a, -1); }
void act_down(struct app *a) { sel_move(a, 1); }
void act_pgup(struct app *a) { sel_move(a, -page_rows(a)); }
void act_pgdn(struct app *a) { sel_move(a, page_rows(a)); }
void act_top(struct app *a) { sel_move(a, -100000); }
void act_bottom(struct app *a) { sel_move(a, 100000); }

/*
 * i: the collisions table shows a chain's interface k alone, each i the
 * next k (k0 .. n - 1: 0 is the floor's), then every interface's again.
 * The selection stays on a collision shown: the nearest one at or after
 * it, else the last before it.
 */
void
act_table_iface(struct app *a)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	int nb = hb_sim_nbodies(a->sim), k0 = sc->chain.floor ? 0 : 1, k = table_iface(a);
	long n = app_ncollisions(a), sel = -1;

	if (sc->chain.n == 0 || nb - k0 < 2) {
		a->table_k = 0;
		app_msg(a, 1, "one interface only: the table lists every collision (i shows one interface of a chain)");
		return;
	}
	k = k < 0 ? k0 : k + 1;
	a->table_k = k < nb ? k + 1 : 0;
	for (long i = a->table_sel; i < n && sel < 0; i++)
		if (table_shows(a, i))
			sel = i;
	for (long i = a->table_sel < n ? a->table_sel : n - 1; i >= 0 && sel < 0; i--)
		if (table_shows(a, i))
			sel = i;
	if (sel >= 0)
		a->table_sel = sel;
	if (a->table_k == 0)
		app_msg(a, 0, "table: every interface's collisions, %ld (i: interface %d alone)", n, k0);
	else if (k == 0)
		app_msg(a, 0, "table: interface 0 alone (the floor and body 1), %ld of %ld collisions (i: the next)",
		        table_nrows(a), n);
	else
		app_msg(a, 0, "table: interface %d alone (bodies %d and %d), %ld of %ld collisions (i: the next)",
		        k, k, k + 1, table_nrows(a), n);
}

void
act_focus(struct app *a)
{
	a->focus = a->focus == FOCUS_TABLE ? FOCUS_PARAMS : FOCUS_TABLE;
	app_relayout(a);
}

/* ---- the parameter panel: search and sections ------------------------------ */

/* Case-insensitive strstr (ASCII fold: the same under a Turkish locale). */
static int
contains(const char *hay, const char *needle)
{
	size_t n = strlen(needle);

	if (n == 0)
		return 1;
	for (; *hay; hay++)
		if (cnum_ncasecmp(hay, needle, n) == 0)
			return 1;
	return 0;
}

/* 1 if s begins with needle (ASCII case fold). */
static int
begins(const char *s, const char *needle)
{
	return cnum_ncasecmp(s, needle, strlen(needle)) == 0;
}

/*
 * How well a parameter matches a search (lower is better, -1: not at all):
 * its name (the key's last part, "c" of law.c), key or label equal to the
 * text, then beginning with it, then holding it; a derived value, never
 * typed, after every parameter.
 */
static int
match_rank(const struct hb_scene_keyinfo *ki, const char *text)
{
	const char *dot = strrchr(ki->key, '.'), *name = dot ? dot + 1 : ki->key;
	int r;

	if (cnum_casecmp(name, text) == 0 || cnum_casecmp(ki->key, text) == 0
	    || cnum_casecmp(ki->label, text) == 0)
		r = 0;
	else if (begins(name, text) || begins(ki->key, text) || begins(ki->label, text))
		r = 1;
	else if (contains(ki->key, text) || contains(ki->label, text))
		r = 2;
	else
		return -1;
	return ki->readonly ? r + 3 : r;
}

/* The panel rows that match text, best first (ties in panel order); returns how many. */
static int
search_matches(const struct app *a, const char *text, int *out, int max)
{
	struct param_row rows[256];
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	int n = params_rows(sc, rows, 256), m = 0;

	for (int rank = 0; rank < 6; rank++)
		for (int i = 0; i < n && m < max; i++) {
			struct hb_scene_keyinfo ki;
			if (rows[i].key < 0 || hb_scene_key(sc, rows[i].key, &ki) != 0)
				continue;
			if (match_rank(&ki, text) == rank)
				out[m++] = i;
		}
	return m;
}

/* Selects match i of the last search and says which it is. */
static void
search_show(struct app *a, const int *m, int n, int i)
{
	struct param_row rows[256];
	struct hb_scene_keyinfo ki;
	const struct hb_scene *sc = hb_sim_scene(a->sim);

	params_rows(sc, rows, 256);
	a->search_i = i;
	a->param_sel = m[i];
	if (hb_scene_key(sc, rows[m[i]].key, &ki) != 0)
		return;
	if (n > 1)
		app_msg(a, 0, "%s: match %d of %d for '%s' (n/N: next/previous); Enter edits, +/- nudge",
		        ki.key, i + 1, n, a->search_text);
	else
		app_msg(a, 0, "%s: the one match for '%s'; Enter edits, +/- nudge", ki.key,
		        a->search_text);
}

void
search_do(struct app *a, const char *text, int final)
{
	int m[256], n = search_matches(a, text, m, 256);

	if (n > 0) {
		a->param_sel = m[0];
		if (final) {
			snprintf(a->search_text, sizeof a->search_text, "%s", text);
			search_show(a, m, n, 0);
		}
		return;
	}
	if (final) {
		a->param_sel = a->search_from;
		app_msg(a, 1, "no parameter matches '%s' (names as in the panel or presets: c, law.c, x0)",
		        text);
	}
}

/* The next (dir > 0) or previous match of the last search. */
static void
search_again(struct app *a, int dir)
{
	int m[256], n;

	if (a->search_text[0] == 0) {
		app_msg(a, 1, "no search yet: / searches the parameters by name");
		return;
	}
	n = search_matches(a, a->search_text, m, 256);
	if (n == 0) {
		app_msg(a, 1, "no parameter matches '%s' now", a->search_text);
		return;
	}
	if (a->focus != FOCUS_PARAMS) {
		a->focus = FOCUS_PARAMS;
		app_relayout(a);
	}
	search_show(a, m, n, ((a->search_i + dir) % n + n) % n);
}

void act_search_next(struct app *a) { search_again(a, 1); }
void act_search_prev(struct app *a) { search_again(a, -1); }

/* The search prompt's report: each edit shows the best match, Enter keeps it. */
static void
search_prompt_done(struct app *a, const char *text, int how)
{
	if (how != PROMPT_CANCEL)
		search_do(a, text, how == PROMPT_ENTER);
}

void
act_search(struct app *a)
{
	if (a->focus != FOCUS_PARAMS) {
		a->focus = FOCUS_PARAMS;
		app_relayout(a);
	}
	a->search_from = a->param_sel;
	prompt_open(a, PROMPT_SEARCH, search_prompt_done, "", "search parameters (Enter keeps, Esc cancels)");
}

/* Moves the panel selection to the first key of the next (dir > 0) or previous section. */
static void
section_move(struct app *a, int dir)
{
	struct param_row rows[256];
	int n = params_rows(hb_sim_scene(a->sim), rows, 256), i = a->param_sel, head = -1;

	/* the heading of the current section */
	for (int k = i; k >= 0; k--)
		if (rows[k].key < 0) {
			head = k;
			break;
		}
	if (dir > 0) {
		for (i = a->param_sel + 1; i < n && rows[i].key >= 0; i++)
			;
	} else {
		/* the heading before the current one */
		for (i = head - 1; i >= 0 && rows[i].key >= 0; i--)
			;
		if (i < 0)
			i = head;
	}
	if (i < 0 || i >= n)
		return;
	while (i < n && rows[i].key < 0)
		i++;
	if (i < n)
		a->param_sel = i;
}

void act_prev_section(struct app *a) { section_move(a, -1); }
void act_next_section(struct app *a) { section_move(a, 1); }
