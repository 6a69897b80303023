/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * edit.c - the what-if loop: a value or the law changes, and the run
 * shows the consequence.
 *
 * An edit restarts the run from t = 0 with the new scene, the cursor
 * keeping its time: the whole consequence of the change is on screen at
 * once (runs take milliseconds).  "Branch here" (b) arms the next edit to
 * continue from the cursor instead (hb_sim_branch: the run is replayed to
 * the cursor and goes on with the new values).  The simulator records the
 * branch, an export writes it into the preset ([branch N]) and --batch
 * replays it: the export reproduces the branched run.  a->branch_t and
 * a->nbranches mirror hb_sim_branch_get for the screen.  The scene is
 * validated first, so a refused edit
 * loses nothing.  Each edit keeps the scene before it (up to
 * APP_UNDO_MAX): u goes back to it as an edit would; U resets the selected
 * value to the scene as opened (the preset and its --set).  On a chain, a
 * (add) gives a body or an interface a key of its own that the panel does
 * not list yet (body.I.NAME, interface.K.NAME, initial.body.I.NAME): an
 * edit as any other, which adds the entry to the scene's overrides (at
 * most HB_SCENE_MAX_OVERRIDES).
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "status.h"
#include "tui.h"
#include "units.h"

/* Keeps the scene before an edit for u (the oldest is forgotten when full). */
static void
undo_push(struct app *a, const struct hb_scene *before, const char *what)
{
	if (a->nundo == APP_UNDO_MAX) {
		memmove(&a->undo[0], &a->undo[1], (APP_UNDO_MAX - 1) * sizeof a->undo[0]);
		memmove(&a->undo_what[0], &a->undo_what[1], (APP_UNDO_MAX - 1) * sizeof a->undo_what[0]);
		a->nundo--;
	}
	a->undo[a->nundo] = *before;
	snprintf(a->undo_what[a->nundo], sizeof a->undo_what[0], "%s", what);
	a->nundo++;
}

/* An edit applied: the runs labelled anew, the scene before kept for u unless undoing. */
static void
applied(struct app *a, const struct hb_scene *before, const char *what, int undo)
{
	app_label_runs(a);
	if (!undo)
		undo_push(a, before, what);
}

/* The run restarted from t = 0: no branch, the cursor at the start. */
static void
from_start(struct app *a)
{
	a->branch_t = -1;
	a->nbranches = 0;
	cursor_set(a, 0);
}

/*
 * Applies a changed scene: from t = 0 (the default), or at the cursor
 * after b.  An applied edit is kept for u unless undoing (undo 1).
 */
static void
apply_scene_how(struct app *a, const struct hb_scene *sc_in, const char *what, int undo)
{
	struct hb_scene sc = *sc_in, before = *hb_sim_scene(a->sim);
	char emsg[512], tb[32];
	int restarted = 0, rc, branch = a->branch_armed;

	a->branch_armed = 0;
	if (hb_scene_validate(&sc, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "refused (old value kept): %s", emsg);
		return;
	}
	cursor_clamp(a);
	hb_units_format(a->tcur, hb_unit_time, 6, tb, sizeof tb);
	if (branch) {
		size_t at = a->cursor;
		const struct hb_arc_sample *s = hb_arc_at(hb_sim_arc(a->sim), at);
		long j = s->j;
		double s_t = s->t;

		/* replayed from t = 0 to the cursor: the same run --batch makes of the export */
		rc = hb_sim_branch(a->sim, at, &sc, &restarted, emsg, sizeof emsg);
		if (rc != HB_OK && hb_sim_arc(a->sim) != NULL && hb_arc_len(hb_sim_arc(a->sim)) > 0 &&
		    hb_scene_validate(&sc, emsg + 256, sizeof emsg - 256) == HB_OK) {
			/* the replay failed part-way: the new values from t = 0, as an edit */
			int rs = 0;

			if (hb_sim_set_scene(a->sim, &sc, &rs, emsg + 256, sizeof emsg - 256) == HB_OK &&
			    (rs || hb_sim_restart(a->sim) == HB_OK)) {
				applied(a, &before, what, undo);
				from_start(a);
				app_msg(a, 1, "%s: cannot branch here (%.200s); the run restarted from t = 0",
				        what, emsg);
				return;
			}
		}
		if (rc != HB_OK) {
			app_msg(a, 1, "refused (old value kept): %s", emsg);
			return;
		}
		applied(a, &before, what, undo);
		if (restarted) {
			from_start(a);
			app_msg(a, 0, "%s: cannot branch here (a change of the law in contact, of the bodies in contact, a radius or the initial state); the run restarted from t = 0",
			        what);
		} else {
			const struct hb_branch *b0 = hb_sim_branch_get(a->sim, 0);

			a->nbranches = (int)hb_sim_nbranches(a->sim);
			a->branch_t = b0 != NULL ? b0->t : -1;
			a->branch_j = b0 != NULL ? b0->j : 0;
			cursor_set(a, at < hb_arc_len(hb_sim_arc(a->sim)) ? at : hb_arc_len(hb_sim_arc(a->sim)) - 1);
			if (b0 != NULL && hb_sim_nbranches(a->sim) > 0 &&
			    hb_sim_branch_get(a->sim, hb_sim_nbranches(a->sim) - 1)->t > s_t) {
				/* a chain's branch begins where the flight or step holding the cursor ends */
				hb_units_format(hb_sim_branch_get(a->sim, hb_sim_nbranches(a->sim) - 1)->t,
				                hb_unit_time, 6, tb, sizeof tb);
				j = hb_sim_branch_get(a->sim, hb_sim_nbranches(a->sim) - 1)->j;
			}
			app_msg(a, 0, "%s from t = %s, j = %ld (branch here): the run continues from the cursor; an export records the branch and --batch replays it",
			        what, tb, j);
		}
	} else {
		rc = hb_sim_set_scene(a->sim, &sc, &restarted, emsg, sizeof emsg);
		if (rc == HB_OK && !restarted && hb_sim_restart(a->sim) != HB_OK) {
			app_msg(a, 1, "restart failed: %s", hb_sim_errmsg(a->sim));
			return;
		}
		if (rc != HB_OK) {
			app_msg(a, 1, "refused (old value kept): %s", emsg);
			return;
		}
		applied(a, &before, what, undo);
		a->want_t = a->tcur;
		a->playing = 0;
		from_start(a);
		a->tcur = a->want_t;
		app_msg(a, 0, "%s: the run restarted from t = 0 (b: branch here)", what);
	}
	cursor_clamp(a);
	if (a->table_sel >= app_ncollisions(a))
		a->table_sel = app_ncollisions(a) > 0 ? app_ncollisions(a) - 1 : 0;
}

static void
apply_scene(struct app *a, const struct hb_scene *sc, const char *what)
{
	apply_scene_how(a, sc, what, 0);
}

void
edit_value(struct app *a, const char *key, const char *text)
{
	struct hb_scene sc = *hb_sim_scene(a->sim);
	struct hb_scene_error err;
	char emsg[512], what[160];

	/* The error names the key and what is accepted (scene_error). */
	if (hb_scene_set_text(&sc, key, text, &err) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "refused (old value kept): %s", hb_scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	snprintf(what, sizeof what, "%s = %s", key, text);
	apply_scene(a, &sc, what);
}

void
app_set_law(struct app *a, const char *law)
{
	struct hb_scene sc = *hb_sim_scene(a->sim);
	char emsg[512], what[96];

	if (hb_scene_set(&sc, "scene.law", law, emsg, sizeof emsg) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "refused: %s", emsg);
		return;
	}
	snprintf(what, sizeof what, "law %s", law);
	apply_scene(a, &sc, what);
}

/* The hb_scene_key index of the selected panel row, or -1. */
int
param_key_index(const struct app *a)
{
	struct param_row rows[256];
	int n = params_rows(hb_sim_scene(a->sim), rows, 256);

	if (a->param_sel < 0 || a->param_sel >= n)
		return -1;
	return rows[a->param_sel].key;
}

/*
 * Multiplies (dir > 0) or divides the selected value by 1.1, keeping its
 * unit; a value chosen from a list steps to the next (previous) choice.
 * The value is read typed (scene_keyinfo), never from its display text.
 */
static void
nudge(struct app *a, int dir)
{
	struct hb_scene_keyinfo ki;
	struct hb_scene sc = *hb_sim_scene(a->sim);
	struct hb_scene_error err;
	int k = param_key_index(a);
	char text[96], emsg[512];
	double v;

	if (k < 0 || hb_scene_key(hb_sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	if (ki.kind == HB_SCENE_KEY_CHOICE) {
		if (ki.choice >= 0 && ki.nchoices >= 2)
			edit_value(a, ki.key,
			    ki.choices[((ki.choice + dir) % ki.nchoices + ki.nchoices) % ki.nchoices]);
		return;
	}
	if (ki.kind == HB_SCENE_KEY_TEXT || !isfinite(ki.number)) {
		app_msg(a, 1, "%s is not a number: press Enter to type a value", ki.label);
		return;
	}
	if (ki.number == 0) {
		app_msg(a, 1, "%s is 0: press Enter to type a value", ki.label);
		return;
	}
	v = dir > 0 ? ki.number * 1.1 : ki.number / 1.1;
	if (ki.kind == HB_SCENE_KEY_WHOLE)
		v = dir > 0 ? fmax(round(v), ki.number + 1) : fmin(round(v), ki.number - 1);
	if (hb_scene_set_number(&sc, ki.key, v, &err) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "refused (old value kept): %s", hb_scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	if (ki.kind == HB_SCENE_KEY_WHOLE)
		snprintf(text, sizeof text, "%.0f", v);
	else
		hb_units_format(v, ki.dim, 6, text, sizeof text);
	snprintf(emsg, sizeof emsg, "%s = %s", ki.key, text);
	apply_scene(a, &sc, emsg);
}

/* The value prompt's report: Enter sets the key, Esc disarms a branch (b). */
static void
edit_prompt_done(struct app *a, const char *text, int how)
{
	if (how == PROMPT_CANCEL)
		a->branch_armed = 0;
	else if (how == PROMPT_ENTER)
		edit_value(a, a->prompt_key, text);
}

static void
prompt_edit_begin(struct app *a)
{
	struct hb_scene_keyinfo ki;
	int k = param_key_index(a);

	if (k < 0 || hb_scene_key(hb_sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	prompt_open(a, PROMPT_EDIT, edit_prompt_done, ki.edit /* reads back exactly */, "%.47s %.47s%s", ki.key, ki.range,
	            a->branch_armed ? " (branch here)" : "");
	snprintf(a->prompt_key, sizeof a->prompt_key, "%s", ki.key);
}

/* ---- a (add): a key of one body or interface of a chain ------------------ */

/* The panel row of key, or -1 (an override is a row once the scene holds it). */
static int
param_row_of(const struct app *a, const char *key)
{
	struct param_row rows[256];
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	int n = params_rows(sc, rows, 256);

	for (int i = 0; i < n; i++) {
		struct hb_scene_keyinfo ki;
		if (rows[i].key >= 0 && hb_scene_key(sc, rows[i].key, &ki) == 0 && strcmp(ki.key, key) == 0)
			return i;
	}
	return -1;
}

/* Sets an added key and selects its row, once the edit is applied. */
static void
add_set(struct app *a, const char *key, const char *text)
{
	int row;

	edit_value(a, key, text);
	if ((row = param_row_of(a, key)) >= 0)
		a->param_sel = row;
}

static void
add_value_done(struct app *a, const char *text, int how)
{
	if (how == PROMPT_CANCEL)
		a->branch_armed = 0;
	else if (how == PROMPT_ENTER)
		add_set(a, a->prompt_key, text);
}

/*
 * The key prompt's report: KEY (then its value is asked, the chain's as it
 * stands given), or KEY = VALUE at once.  A key the scene holds already is
 * edited as its row is; a new one needs a free entry.
 */
static void
add_key_done(struct app *a, const char *text, int how)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	struct hb_scene_keyinfo ki;
	struct hb_scene_error err;
	char key[sizeof a->prompt_key], emsg[512];
	const char *eq = strchr(text, '='), *value = NULL;
	size_t l;
	int row;

	if (how != PROMPT_ENTER) {
		if (how == PROMPT_CANCEL)
			a->branch_armed = 0;
		return;
	}
	while (*text == ' ')
		text++;
	l = eq != NULL ? (size_t)(eq - text) : strlen(text);
	while (l > 0 && text[l - 1] == ' ')
		l--;
	if (l == 0 || l >= sizeof key) {
		a->branch_armed = 0;
		app_msg(a, 1, "add: no key (body.I.NAME, interface.K.NAME or initial.body.I.NAME; a for the list)");
		return;
	}
	snprintf(key, sizeof key, "%.*s", (int)l, text);
	if (eq != NULL)
		for (value = eq + 1; *value == ' '; value++)
			;
	if (strncmp(key, "body.", 5) != 0 && strncmp(key, "interface.", 10) != 0
	    && strncmp(key, "initial.body.", 13) != 0) {
		a->branch_armed = 0;
		app_msg(a, 1, "add: %s is not a key of one body or interface; accepted: body.I.NAME, "
		        "interface.K.NAME, initial.body.I.NAME (the others are rows of the panel already)", key);
		return;
	}
	if (hb_scene_get(sc, key, &ki, &err) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "add: %s", hb_scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	row = param_row_of(a, key);
	if (row < 0 && sc->over.n >= HB_SCENE_MAX_OVERRIDES) {
		a->branch_armed = 0;
		app_msg(a, 1, "add: refused: %d of %d keys of single bodies and interfaces held, the most "
		        "a scene holds; edit one of them (their rows in the chain section), or give what "
		        "most bodies share in [body1], [law] and [chain]", sc->over.n, HB_SCENE_MAX_OVERRIDES);
		return;
	}
	if (row >= 0)
		a->param_sel = row;
	if (value != NULL && *value != 0) {
		add_set(a, key, value);
		return;
	}
	prompt_open(a, PROMPT_EDIT, add_value_done, ki.edit, "%.47s %.47s%s%s", key, ki.range,
	            row < 0 ? " (new: the chain's value now)" : "", a->branch_armed ? " (branch here)" : "");
	snprintf(a->prompt_key, sizeof a->prompt_key, "%s", key);
}

/* a: asks for a key of one body or interface of a chain, then its value. */
void
act_add(struct app *a)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	int n = sc->chain.n, k0 = sc->chain.floor ? 0 : 1;

	if (n == 0) {
		app_msg(a, 1, "add: a chain's keys of one body or interface only (this scene has two bodies: "
		        "every key is a row of the panel)");
		return;
	}
	if (a->focus != FOCUS_PARAMS) {
		a->focus = FOCUS_PARAMS;
		app_relayout(a);
	}
	prompt_open(a, PROMPT_ADD, add_key_done, "",
	            "add a key of one body or interface [= VALUE] (%d of %d held): body.I.{E,nu,rho,R,mass,F}, "
	            "initial.body.I.{v,gap} (I 1..%d), interface.K.{law,extension,PARAMETER} (K %d..%d)",
	            sc->over.n, HB_SCENE_MAX_OVERRIDES, n, k0, n - 1);
}

/* ---- actions ---------------------------------------------------------- */

void act_nudge_up(struct app *a) { nudge(a, 1); }
void act_nudge_down(struct app *a) { nudge(a, -1); }

void
act_enter(struct app *a)
{
	if (a->focus == FOCUS_PARAMS) {
		prompt_edit_begin(a);
	} else if (table_iface(a) >= 0 && !table_shows(a, a->table_sel)) {
		app_msg(a, 1, "interface %d has no collision (yet; i: every interface's)", table_iface(a));
	} else if (app_ncollisions(a) > 0) {
		a->playing = 0;
		a->zoom_i = a->table_sel;
		a->view = VIEW_ZOOM;
		cursor_to_collision(a, a->table_sel);
	}
}

void
act_branch(struct app *a)
{
	char tb[32];

	cursor_clamp(a);
	hb_units_format(a->tcur, hb_unit_time, 6, tb, sizeof tb);
	a->branch_armed = !a->branch_armed;
	if (a->branch_armed)
		app_msg(a, 0, "branch here: the next edit (Enter, +/-, L) continues the run from t = %s instead of restarting it (b again: cancel)",
		        tb);
	else
		app_msg(a, 0, "branch cancelled: edits restart the run from t = 0");
}

/* The law picker's report: Enter takes that law. */
static void
law_chosen(struct app *a, const char *law)
{
	app_set_law(a, law);
}

void
act_law(struct app *a)
{
	const struct hb_law_type *const *l = hb_law_list();

	a->pick_kind = PICK_LAW;
	a->pick_done = law_chosen;
	a->pick_sel = a->pick_top = 0;
	for (int i = 0; l[i]; i++)
		if (l[i] == hb_sim_scene(a->sim)->law)
			a->pick_sel = i;
	mode_push(a, &mode_law);
}

/* u: back to the scene before the last edit. */
void
act_undo(struct app *a)
{
	char what[200];
	int k;

	if (a->nundo == 0) {
		app_msg(a, 1, "nothing to undo: no edit since the run was opened");
		return;
	}
	k = --a->nundo;
	snprintf(what, sizeof what, "undid %s", a->undo_what[k]);
	apply_scene_how(a, &a->undo[k], what, 1);
}

/* U: the selected value back to the scene as opened. */
void
act_reset(struct app *a)
{
	struct hb_scene_keyinfo ki, oi;
	struct hb_scene sc = *hb_sim_scene(a->sim);
	struct hb_scene_error err;
	char emsg[512], what[160];
	int k = param_key_index(a), found = 0;

	if (k < 0 || hb_scene_key(hb_sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	for (int i = 0; i < hb_scene_nkeys(&a->origin) && !found; i++)
		found = hb_scene_key(&a->origin, i, &oi) == 0 && strcmp(oi.key, ki.key) == 0;
	if (!found) {
		app_msg(a, 1, "%s was not in the scene as opened (law %s): u undoes the change of law",
		        ki.key, a->origin.law->name);
		return;
	}
	if (strcmp(oi.edit, ki.edit) == 0) {
		app_msg(a, 0, "%s is already as opened: %s", ki.key, oi.value);
		return;
	}
	if (hb_scene_set_text(&sc, ki.key, oi.edit, &err) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "refused (old value kept): %s", hb_scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	snprintf(what, sizeof what, "%s reset to %s (as opened)", ki.key, oi.edit);
	apply_scene(a, &sc, what);
}
