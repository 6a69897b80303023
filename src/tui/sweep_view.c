/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_view.c - the sweep view's state, its mode and key table (mode.h;
 * the footer and the help print it): one parameter (the
 * parameter panel's selected key), a range typed as for --vary
 * (FROM:TO:N[:log], units accepted) and an observable, computed by the
 * engine's background curve (sweep_curve_*: polling never waits, freeing
 * cancels), so the screen keeps drawing while the points come in.
 *
 * Boundaries (b): the engine bisects every interval of the current curve
 * whose ends differ in class (the observable exists or not, or a count
 * differs) to SV_BOUND_TOL of the range, as hybounce sweep --refine does;
 * the pane marks them.
 *
 * Pinning a curve keeps it (still filling in) as a ghost; changing the
 * law (L) or the range then starts a new curve to compare with.
 * Changing the parameter, observable or collision clears the pins (they
 * would not share the axes).  Export writes the current curve's finished
 * points as CSV (hb_sweep_curve_write_csv: a temporary file renamed over the
 * name, so a failed export damages nothing).
 *
 * m: the 2-D map (sweep_map.c) of the observable over this key (across)
 * and the key swept before it (up), each over its range; m again goes back
 * to the curve.  Its export writes i1,i2,KEY1,KEY2,OBS the same way.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "keys.h"
#include "law.h"
#include "mode.h"
#include "status.h"
#include "sweep_view.h"
#include "term.h"
#include "tui.h"

#define SV_DEFAULT_N 40

static prompt_fn sweep_prompt_done;

static void
curve_drop(struct sv_curve *k)
{
	hb_sweep_curve_free(k->c);
	free(k->x);
	free(k->y);
	free(k->st);
	memset(k, 0, sizeof *k);
}

static void
pins_drop(struct sweep_view *v)
{
	for (int i = 0; i < v->npins; i++)
		curve_drop(&v->pin[i]);
	v->npins = 0;
}

/* Copies the points computed so far; 1 while the curve is still computing. */
static int
curve_poll(struct sv_curve *k)
{
	if (k->c == NULL)
		return 0;
	int locating = 0;

	k->done = hb_sweep_curve_poll(k->c, k->x, k->y, k->st, k->n);
	k->failed = 0;
	for (long i = 0; i < k->n; i++)
		k->failed += k->st[i] == HB_CURVE_FAILED;
	k->nb = hb_sweep_curve_boundaries(k->c, k->blo, k->bhi, k->bloc, SV_MAX_BOUNDS);
	for (long i = 0; i < k->nb && i < SV_MAX_BOUNDS; i++)
		locating |= !k->bloc[i];
	return k->done < k->n || locating;
}

static int
jobs(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	return n > 0 ? (int)n : 1;
}

/* Starts the current curve from v->base over v->key=v->spec; errors go to the message line. */
static int
curve_start(struct app *a)
{
	struct sweep_view *v = a->sv;
	struct sv_curve k = { 0 };
	char msg[512];

	k.c = hb_sweep_curve_start_refined(&v->base, v->key, v->spec, v->obs, v->coll,
	                                   v->bounds ? SV_BOUND_TOL : 0, jobs(), msg, sizeof msg);
	if (k.c == NULL) {
		app_msg(a, 1, "sweep not started: %s", msg);
		return -1;
	}
	k.n = hb_sweep_curve_npoints(k.c);
	k.x = calloc((size_t)k.n, sizeof *k.x);
	k.y = calloc((size_t)k.n, sizeof *k.y);
	k.st = calloc((size_t)k.n, sizeof *k.st);
	if (k.x == NULL || k.y == NULL || k.st == NULL)
		term_oom();
	snprintf(k.label, sizeof k.label, "%s", v->base.law ? v->base.law->name : "?");
	curve_drop(&v->cur);
	v->cur = k;
	{
		const char *sp = strrchr(v->spec, ':');
		v->log = sp != NULL && strcmp(sp + 1, "log") == 0;
	}
	curve_poll(&v->cur);
	app_msg(a, 0, "sweep: %s over %s = %s, %ld points on %d threads%s",
	        hb_sweep_observable_name(v->obs), v->key, v->spec, k.n, jobs(),
	        v->bounds ? ", boundaries located to 1e-3 of the range (b: off)" : "");
	return 0;
}

/* A default range around the value: a decade either way (log) when it is not 0. */
static void
default_spec(const struct hb_scene_keyinfo *ki, char *buf, size_t n)
{
	char lo[48], hi[48];
	double x = ki->number;

	if (ki->kind == HB_SCENE_KEY_NUMBER && isfinite(x) && x != 0) {
		hb_units_format(x / 10, ki->dim, 3, lo, sizeof lo);
		hb_units_format(x * 10, ki->dim, 3, hi, sizeof hi);
		snprintf(buf, n, "%s:%s:%d:log", lo, hi, SV_DEFAULT_N);
	} else if (ki->kind == HB_SCENE_KEY_WHOLE && isfinite(x)) {
		snprintf(buf, n, "%.0f:%.0f:%d", x > 1 ? floor(x / 2) : 1, x > 1 ? 2 * x : 10,
		         x > 1 ? (int)fmin(x * 1.5 + 1, SV_DEFAULT_N) : 10);
	} else if (ki->kind == HB_SCENE_KEY_NUMBER) {
		hb_units_format(-1, ki->dim, 3, lo, sizeof lo);
		hb_units_format(1, ki->dim, 3, hi, sizeof hi);
		snprintf(buf, n, "%s:%s:%d", lo, hi, SV_DEFAULT_N + 1);
	} else {
		snprintf(buf, n, "%s", ki->edit);
	}
}

static void
open_range_prompt(struct app *a)
{
	a->sv->prompt = SV_PROMPT_RANGE;
	prompt_open(a, PROMPT_SWEEP, sweep_prompt_done, a->sv->spec, "sweep %s over FROM:TO:N[:log] or V1,V2,...",
	            a->sv->key);
}

/* S: the sweep view of the selected parameter (the last curve if it is the same key). */
void
act_sweep(struct app *a)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	struct hb_scene_keyinfo ki;
	int k = param_key_index(a);

	if (k < 0 || hb_scene_key(sc, k, &ki) != 0) {
		app_msg(a, 1, "sweep: select a parameter first (Tab, then Up/Down)");
		return;
	}
	if (ki.readonly || (ki.kind != HB_SCENE_KEY_NUMBER && ki.kind != HB_SCENE_KEY_WHOLE)) {
		app_msg(a, 1, "sweep: %s is %s; a sweep varies a number that is typed (law, bodies, "
		        "loads, initial, run sections)", ki.key, ki.readonly ? "derived" : "not a number");
		return;
	}
	if (a->sv == NULL && (a->sv = calloc(1, sizeof *a->sv)) == NULL)
		term_oom();
	if (strcmp(a->sv->key, ki.key) == 0 && (a->sv->cur.c != NULL || a->sv->npins > 0)) {
		if (!mode_on(a, &mode_sweep))
			mode_push(a, &mode_sweep);
		return;
	}
	pins_drop(a->sv);
	curve_drop(&a->sv->cur);
	sv_map_drop(&a->sv->map);
	if (a->sv->key[0] != 0) {   /* the map's second key: the one swept before */
		snprintf(a->sv->prevkey, sizeof a->sv->prevkey, "%s", a->sv->key);
		snprintf(a->sv->prevspec, sizeof a->sv->prevspec, "%s", a->sv->spec);
	}
	snprintf(a->sv->key, sizeof a->sv->key, "%s", ki.key);
	default_spec(&ki, a->sv->spec, sizeof a->sv->spec);
	a->sv->base = *sc;
	if (!mode_on(a, &mode_sweep))
		mode_push(a, &mode_sweep);
	open_range_prompt(a);
}

/* Writes the map's finished points to text, or to text-2.csv ... when it is taken. */
static void
map_export(struct app *a, const char *text)
{
	struct sv_map *m = &a->sv->map;
	char path[600], msg[512];
	int renamed = tui_unused_name(text, path, sizeof path);

	if (renamed < 0) {
		app_msg(a, 1, "export failed, nothing written: %.200s and its -2 ... -999 names are "
		        "taken; type another name", text);
		return;
	}
	if (sv_map_write_csv(a->sv, path, msg, sizeof msg) != HB_OK) {
		app_msg(a, 1, "export failed, nothing written: %s", msg);
		return;
	}
	app_msg(a, renamed, "wrote %s (%ld of %ld x %ld points%s)%s%s%s", path, m->done, m->n1, m->n2,
	        m->done < m->n1 * m->n2 ? ", still computing" : "", renamed ? "; " : "",
	        renamed ? text : "", renamed ? " is an earlier export, kept" : "");
}

/* m: the map of this key against the one swept before, or back to the curve. */
static void
map_toggle(struct app *a)
{
	struct sweep_view *v = a->sv;
	char msg[512];

	if (v->map.on) {
		v->map.on = 0;
		app_msg(a, 0, "the curve (m: the map again, recomputed)");
		return;
	}
	if (sv_map_start(v, jobs(), msg, sizeof msg) != 0) {
		app_msg(a, 1, "map not started: %s", msg);
		return;
	}
	app_msg(a, 0, "map: %s over %s = %s (across) and %s = %s (up), %ld x %ld points, row by row",
	        hb_sweep_observable_name(v->obs), v->map.key1, v->map.spec1, v->map.key2,
	        v->map.spec2, v->map.n1, v->map.n2);
}

/* The range and export prompts' report (prompt_open): Enter starts or writes, Esc cancels. */
static void
sweep_prompt_done(struct app *a, const char *text, int how)
{
	int cancelled = how == PROMPT_CANCEL;
	struct sweep_view *v = a->sv;
	char path[600], msg[512];
	int renamed;

	if (v == NULL || how == PROMPT_TYPED)
		return;
	if (cancelled) {
		if (v->cur.c == NULL && v->npins == 0)
			mode_close(a, &mode_sweep);
		return;
	}
	if (v->prompt == SV_PROMPT_RANGE) {
		char old[sizeof v->spec];
		snprintf(old, sizeof old, "%s", v->spec);
		snprintf(v->spec, sizeof v->spec, "%s", text);
		if (curve_start(a) != 0) {
			snprintf(v->spec, sizeof v->spec, "%s", old);
			if (v->cur.c == NULL && v->npins == 0)
				mode_close(a, &mode_sweep);
		}
		return;
	}
	if (text[0] == 0) {
		app_msg(a, 1, "export cancelled: empty name");
		return;
	}
	if (v->prompt == SV_PROMPT_MAP_EXPORT) {
		map_export(a, text);
		return;
	}
	if (v->cur.c == NULL) {
		app_msg(a, 1, "export: no curve (p pinned it; L or r computes a new one)");
		return;
	}
	/* A second export never replaces the first: NAME-2.csv ... instead. */
	renamed = tui_unused_name(text, path, sizeof path);
	if (renamed < 0) {
		app_msg(a, 1, "export failed, nothing written: %.200s and its -2 ... -999 names are "
		        "taken; type another name", text);
		return;
	}
	if (hb_sweep_curve_write_csv(v->cur.c, path, msg, sizeof msg) != HB_OK) {
		app_msg(a, 1, "export failed, nothing written: %s", msg);
		return;
	}
	app_msg(a, renamed, "wrote %s (%ld of %ld points%s)%s%s%s", path, v->cur.done, v->cur.n,
	        v->cur.done < v->cur.n ? ", still computing" : "",
	        renamed ? "; " : "", renamed ? text : "", renamed ? " is an earlier export, kept" : "");
}

/* Changes the observable, collision or law and recomputes. */
static void
restart(struct app *a, int clear_pins)
{
	if (clear_pins && a->sv->npins > 0) {
		pins_drop(a->sv);
		app_msg(a, 0, "pins cleared (another observable)");
	}
	curve_start(a);
	if (a->sv->map.on) {   /* the map follows the observable */
		a->sv->map.on = 0;
		map_toggle(a);
	}
}

static void
next_law(struct app *a, int dir)
{
	struct sweep_view *v = a->sv;
	const struct hb_law_type *const *list = hb_law_list();
	int n = 0, i = 0;
	char msg[512];
	struct hb_scene sc = v->base;

	while (list[n])
		n++;
	while (i < n && list[i] != v->base.law)
		i++;
	i = ((i + dir) % n + n) % n;
	if (hb_scene_set(&sc, "scene.law", list[i]->name, msg, sizeof msg) != HB_OK) {
		app_msg(a, 1, "sweep: law %s refused: %s", list[i]->name, msg);
		return;
	}
	v->base = sc;
	curve_start(a);
}

static void
pin(struct app *a)
{
	struct sweep_view *v = a->sv;

	if (v->cur.c == NULL) {
		app_msg(a, 1, "pin: nothing new to pin (L: another law, r: another range)");
		return;
	}
	if (v->npins == SV_MAX_PINS) {
		curve_drop(&v->pin[0]);
		memmove(&v->pin[0], &v->pin[1], (SV_MAX_PINS - 1) * sizeof v->pin[0]);
		v->npins--;
	}
	v->pin[v->npins++] = v->cur;
	memset(&v->cur, 0, sizeof v->cur);
	app_msg(a, 0, "pinned %s as %d: L (or l) for another law, r for another range",
	        v->pin[v->npins - 1].label, v->npins);
}

/* The keys that change the curve (CTX_CURVE: not on the map). */
static void k_range(struct app *a) { open_range_prompt(a); }
static void k_law_next(struct app *a) { next_law(a, 1); }
static void k_law_prev(struct app *a) { next_law(a, -1); }
static void k_pin(struct app *a) { pin(a); }

static void
k_rescene(struct app *a)
{
	a->sv->base = *hb_sim_scene(a->sim);
	curve_start(a);
}


static void
k_bounds(struct app *a)
{
	struct sweep_view *v = a->sv;

	v->bounds = !v->bounds;
	if (curve_start(a) != 0)
		v->bounds = !v->bounds;   /* refused (a list): as it was */
	else if (!v->bounds)
		app_msg(a, 0, "boundaries off (b: on)");
}

static void
k_unpin(struct app *a)
{
	pins_drop(a->sv);
	app_msg(a, 0, "pins cleared");
}

static void
k_close(struct app *a)
{
	mode_close(a, &mode_sweep);
	app_msg(a, 0, "sweep view closed (S reopens it; the curve keeps computing)");
}

static void k_quit(struct app *a) { a->quit = 1; }
static void k_map(struct app *a) { map_toggle(a); }
static void k_help(struct app *a) { mode_push(a, &mode_help); }
static void k_redraw(struct app *a) { clear(); app_relayout(a); }

static void
observable(struct app *a, int dir)
{
	struct sweep_view *v = a->sv;

	v->obs = (v->obs + (dir > 0 ? 1 : HB_CURVE_COUNT - 1)) % HB_CURVE_COUNT;
	restart(a, 1);
}

static void k_obs_next(struct app *a) { observable(a, 1); }
static void k_obs_prev(struct app *a) { observable(a, -1); }

static void
collision(struct app *a, int dir)
{
	struct sweep_view *v = a->sv;

	if (v->obs != HB_CURVE_E && v->obs != HB_CURVE_VI && v->obs != HB_CURVE_XCR) {
		app_msg(a, 1, "< >: %s does not depend on a collision number (o: the observable)",
		        hb_sweep_observable_name(v->obs));
		return;
	}
	if (dir < 0) {
		if (v->coll == 0)
			return;
		v->coll--;
	} else {
		v->coll++;
	}
	restart(a, 1);
}

static void k_coll_prev(struct app *a) { collision(a, -1); }
static void k_coll_next(struct app *a) { collision(a, 1); }

static void
k_export(struct app *a)
{
	struct sweep_view *v = a->sv;
	char def[256];

	if (v->map.on) {
		snprintf(def, sizeof def, "%s-%s-%s-%s.csv", a->preset, v->map.key1, v->map.key2,
		         hb_sweep_observable_name(v->map.obs));
		v->prompt = SV_PROMPT_MAP_EXPORT;
		prompt_open(a, PROMPT_SWEEP, sweep_prompt_done, def, "export the map as CSV to");
		return;
	}
	snprintf(def, sizeof def, "%s-%s-%s.csv", a->preset, v->key, hb_sweep_observable_name(v->obs));
	v->prompt = SV_PROMPT_EXPORT;
	prompt_open(a, PROMPT_SWEEP, sweep_prompt_done, def, "export the curve as CSV to");
}

static void
k_map_shades(struct app *a)
{
	struct sv_map *m = &a->sv->map;

	if (sv_map_rescale(m) != 0) {
		app_msg(a, 1, "map: no value yet to take the shades' range from");
		return;
	}
	app_msg(a, 0, "map: the shades' range is now %.3g .. %.3g, the values of %ld points", m->zlo, m->zhi,
	        m->done);
}

static void
sweep_other(struct app *a, int ch)
{
	char name[32];

	if (ch == KEY_MOUSE)
		return;
	keys_name(ch, name, sizeof name);
	if (a->sv->map.on && mode_binding(&mode_sweep, ch, CTX_CURVE) != NULL)
		app_msg(a, 1, "%s works on the curve: m goes back to it", name);
	else
		app_msg(a, 1, "sweep view: unknown key %s (? for its keys)", name);
}

#define CTRL(c) ((c) & 0x1f)

static const struct mode_key keys[] = {
	{ 'o', 0, CTX_ANY, k_obs_next, "o",
	  "the next observable: e, v_i, x_c^r of collision i, then the run observables of a sweep's runs.csv (collisions, t_pc ...)", "obs" },
	{ 'O', 0, CTX_ANY, k_obs_prev, "O", "the previous observable", NULL },
	{ '<', ',', CTX_ANY, k_coll_prev, "< ,", "the previous collision i (from 0, as in the table)", "<>:collision" },
	{ '>', '.', CTX_ANY, k_coll_next, "> .", "the next collision i", NULL },
	{ 'r', 0, CTX_CURVE, k_range, "r", "another range (FROM:TO:N[:log] or V1,V2,..., as --vary)", "range" },
	{ 'R', 0, CTX_CURVE, k_rescene, "R", "recompute from the current scene", NULL },
	{ 'L', 0, CTX_CURVE, k_law_next, "L", "the next law (at its defaults)", "law" },
	{ 'l', 0, CTX_CURVE, k_law_prev, "l", "the previous law", NULL },
	{ 'b', 0, CTX_CURVE, k_bounds, "b", "the boundaries on / off: each interval whose ends differ bisected in the background", "bounds" },
	{ 'p', 0, CTX_CURVE, k_pin, "p", "pin the curve (up to 3, drawn as ghosts) to compare", "pin" },
	{ 'P', 0, CTX_CURVE, k_unpin, "P", "clear the pinned curves", NULL },
	{ 'm', 0, CTX_CURVE, k_map, "m",
	  "the 2-D map of the observable over this key (across) and the key swept before it (up); with b on, each row's boundaries marked |", "map" },
	{ 'm', 0, CTX_MAP, k_map, "m", "(map) back to the curve, where r R L l b p P work", "curve" },
	{ 'r', 0, CTX_MAP, k_map_shades, "r",
	  "(map) the shades' range to the values computed so far (it is fixed by the first row, and stays while the map computes)", "shades" },
	{ 'e', 0, CTX_ANY, k_export, "e", "export the finished points (of the curve, or of the map) as CSV, never over an earlier export", "export" },
	{ 'q', 27, CTX_ANY, k_close, "q Esc", "close the view (the curve keeps computing; S on the same parameter reopens it)", "close" },
	{ 'S', 0, CTX_ANY, k_close, "S", "close the view, as q", NULL },
	{ '?', KEY_F(1), CTX_ANY, k_help, "? F1", "the help, at these keys", "keys" },
	{ KEY_F(10), 0, CTX_ANY, k_quit, "F10", "quit the explorer", NULL },
	{ CTRL('l'), 0, CTX_ANY, k_redraw, "C-l", "redraw the screen", NULL },
};

static int
sweep_context(const struct app *a)
{
	return a->sv != NULL && a->sv->map.on ? CTX_MAP : CTX_CURVE;
}

const struct mode mode_sweep = {
	.name = "sweep",
	.title = "the sweep view",
	.opener = "S",
	.keys = MODE_KEYS(keys),
	.other = sweep_other,
	.draw = pane_sweep_draw,
	.context = sweep_context,
};

int
sweep_view_open(const struct app *a)
{
	return a->sv != NULL && mode_on(a, &mode_sweep);
}

int
sweep_view_tick(struct app *a)
{
	struct sweep_view *v = a->sv;
	int busy = 0;

	if (v == NULL)
		return 0;
	busy |= curve_poll(&v->cur);
	busy |= sv_map_tick(&v->map);
	for (int i = 0; i < v->npins; i++)
		busy |= curve_poll(&v->pin[i]);
	return busy && mode_on(a, &mode_sweep);
}

void
sweep_view_free(struct app *a)
{
	if (a->sv == NULL)
		return;
	pins_drop(a->sv);
	curve_drop(&a->sv->cur);
	sv_map_drop(&a->sv->map);
	free(a->sv);
	a->sv = NULL;
}
