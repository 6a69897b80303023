/*
 * edit.c - the what-if loop: a value or the law changes, and the run
 * shows the consequence.
 *
 * An edit restarts the run from t = 0 with the new scene, the cursor
 * keeping its time: the whole consequence of the change is on screen at
 * once (runs take milliseconds).  "Branch here" (b) arms the next edit to
 * continue from the cursor instead: the run is cut there (sim_seek) and
 * goes on with the new values.  A run that contains such a branch records
 * it (a->branch_t, a->branch_j): its scene alone no longer reproduces it,
 * and an export says so.  The scene is validated first, so a refused edit
 * loses nothing.
 */
#include <ctype.h>
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "status.h"
#include "tui.h"
#include "units.h"

/* Applies a changed scene: from t = 0 (the default), or at the cursor after b. */
static void
apply_scene(struct app *a, const struct scene *sc_in, const char *what)
{
	struct scene sc = *sc_in;
	char emsg[512], tb[32];
	int restarted = 0, rc, branch = a->branch_armed;

	a->branch_armed = 0;
	if (scene_validate(&sc, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "refused (old value kept): %s", emsg);
		return;
	}
	cursor_clamp(a);
	units_format(a->tcur, UNIT_TIME, 6, tb, sizeof tb);
	if (branch) {
		size_t at = a->cursor;
		const struct arc_sample *s = arc_len(sim_arc(a->sim)) ? arc_at(sim_arc(a->sim), at) : NULL;
		long j = s ? s->j : 0;

		if (s != NULL && sim_seek(a->sim, at) != HB_OK) {
			app_msg(a, 1, "cannot branch at the cursor: %s", sim_errmsg(a->sim));
			return;
		}
		rc = sim_set_scene(a->sim, &sc, &restarted, emsg, sizeof emsg);
		if (rc != HB_OK) {
			app_msg(a, 1, "refused (old value kept): %s", emsg);
			return;
		}
		app_label_runs(a);
		if (restarted) {
			a->branch_t = -1;
			cursor_set(a, 0);
			app_msg(a, 0, "%s: cannot branch here (a change of the law in contact, the bodies or the initial state); the run restarted from t = 0",
			        what);
		} else {
			if (a->branch_t < 0) {
				a->branch_t = a->tcur;
				a->branch_j = j;
			}
			a->nbranches++;
			app_msg(a, 0, "%s from t = %s, j = %ld (branch here): the run continues from the cursor",
			        what, tb, j);
		}
	} else {
		rc = sim_set_scene(a->sim, &sc, &restarted, emsg, sizeof emsg);
		if (rc == HB_OK && !restarted && sim_restart(a->sim) != HB_OK) {
			app_msg(a, 1, "restart failed: %s", sim_errmsg(a->sim));
			return;
		}
		if (rc != HB_OK) {
			app_msg(a, 1, "refused (old value kept): %s", emsg);
			return;
		}
		app_label_runs(a);
		a->branch_t = -1;
		a->nbranches = 0;
		a->want_t = a->tcur;
		a->playing = 0;
		cursor_set(a, 0);
		a->tcur = a->want_t;
		app_msg(a, 0, "%s: the run restarted from t = 0 (b: branch here)", what);
	}
	cursor_clamp(a);
	if (a->table_sel >= app_ncollisions(a))
		a->table_sel = app_ncollisions(a) > 0 ? app_ncollisions(a) - 1 : 0;
}

void
edit_value(struct app *a, const char *key, const char *text)
{
	struct scene sc = *sim_scene(a->sim);
	char emsg[512], what[160];

	if (scene_set(&sc, key, text, emsg, sizeof emsg) != HB_OK) {
		/* add the accepted range from the panel when the message lacks it */
		for (int i = 0; i < scene_nkeys(&sc); i++) {
			struct scene_keyinfo ki;
			if (scene_key(sim_scene(a->sim), i, &ki) == 0 && strcmp(ki.key, key) == 0
			    && ki.range[0] && strstr(emsg, ki.range) == NULL) {
				size_t l = strlen(emsg);
				snprintf(emsg + l, sizeof emsg - l, "; accepted: %s", ki.range);
			}
		}
		a->branch_armed = 0;
		app_msg(a, 1, "refused (old value kept): %s", emsg);
		return;
	}
	snprintf(what, sizeof what, "%s = %s", key, text);
	apply_scene(a, &sc, what);
}

void
app_set_law(struct app *a, const char *law)
{
	struct scene sc = *sim_scene(a->sim);
	char emsg[512], what[96];

	if (scene_set(&sc, "scene.law", law, emsg, sizeof emsg) != HB_OK) {
		a->branch_armed = 0;
		app_msg(a, 1, "refused: %s", emsg);
		return;
	}
	snprintf(what, sizeof what, "law %s", law);
	apply_scene(a, &sc, what);
}

/* The scene_key index of the selected panel row, or -1. */
int
param_key_index(const struct app *a)
{
	struct param_row rows[256];
	int n = params_rows(sim_scene(a->sim), rows, 256);

	if (a->param_sel < 0 || a->param_sel >= n)
		return -1;
	return rows[a->param_sel].key;
}

/*
 * For a value chosen from a list (stepper, law, extension, yes/no ...):
 * the choice dir steps after the current one in the key's range ("rk8pd
 * rkf45 ...", "adhesive, none"), cycling.  Returns 0 with it in out, or -1
 * when the range is not a list holding the current value.
 */
static int
next_choice(const struct scene_keyinfo *ki, int dir, char *out, size_t n)
{
	char range[sizeof ki->range], *tok[32], *save = NULL, *t;
	int ntok = 0, cur = -1, i;

	snprintf(range, sizeof range, "%s", ki->range);
	for (t = strtok_r(range, ", ", &save); t != NULL && ntok < 32; t = strtok_r(NULL, ", ", &save)) {
		for (i = 0; t[i]; i++)
			if (!isalnum((unsigned char)t[i]) && t[i] != '_' && t[i] != '-')
				return -1; /* "(0, 1)", ">= 1": a numeric range, not a list */
		if (strcmp(t, ki->value) == 0)
			cur = ntok;
		tok[ntok++] = t;
	}
	if (cur < 0 || ntok < 2)
		return -1;
	snprintf(out, n, "%s", tok[((cur + dir) % ntok + ntok) % ntok]);
	return 0;
}

/*
 * Multiplies (dir > 0) or divides the selected value by 1.1, keeping its
 * unit; a value chosen from a list steps to the next (previous) choice.
 */
static void
nudge(struct app *a, int dir)
{
	struct scene_keyinfo ki;
	int k = param_key_index(a);
	char *end, text[96];
	double v;

	if (k < 0 || scene_key(sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	v = strtod(ki.value, &end);
	if (end == ki.value || !isfinite(v)) {
		if (next_choice(&ki, dir, text, sizeof text) == 0)
			edit_value(a, ki.key, text);
		else
			app_msg(a, 1, "%s is not a number: press Enter to type a value", ki.label);
		return;
	}
	if (v == 0) {
		app_msg(a, 1, "%s is 0: press Enter to type a value", ki.label);
		return;
	}
	v = dir > 0 ? v * 1.1 : v / 1.1;
	while (*end == ' ')
		end++;
	snprintf(text, sizeof text, "%.6g%s%s", v, *end ? " " : "", end);
	edit_value(a, ki.key, text);
}

static void
prompt_edit_begin(struct app *a)
{
	struct scene_keyinfo ki;
	int k = param_key_index(a);

	if (k < 0 || scene_key(sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	prompt_open(a, PROMPT_EDIT, ki.value, "%.47s %.47s%s", ki.key, ki.range,
	            a->branch_armed ? " (branch here)" : "");
	snprintf(a->prompt_key, sizeof a->prompt_key, "%s", ki.key);
}

/* ---- actions ---------------------------------------------------------- */

void act_nudge_up(struct app *a) { nudge(a, 1); }
void act_nudge_down(struct app *a) { nudge(a, -1); }

void
act_enter(struct app *a)
{
	if (a->focus == FOCUS_PARAMS) {
		prompt_edit_begin(a);
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
	units_format(a->tcur, UNIT_TIME, 6, tb, sizeof tb);
	a->branch_armed = !a->branch_armed;
	if (a->branch_armed)
		app_msg(a, 0, "branch here: the next edit (Enter, +/-, L) continues the run from t = %s instead of restarting it (b again: cancel)",
		        tb);
	else
		app_msg(a, 0, "branch cancelled: edits restart the run from t = 0");
}

void
act_law(struct app *a)
{
	const struct law_type *const *l = law_list();

	a->overlay = OV_LAW;
	a->pick_sel = a->pick_top = 0;
	for (int i = 0; l[i]; i++)
		if (l[i] == sim_scene(a->sim)->law)
			a->pick_sel = i;
}
