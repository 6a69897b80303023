/*
 * app.c - the explorer's loop: key (with a timeout) -> action -> a bounded
 * slice of computation -> playback -> one frame.
 *
 * The simulation computes ahead of the display: every frame calls
 * sim_advance(sim, 0, budget) with a budget of a few milliseconds, so the
 * screen never freezes however long or stiff a run is.  Playback is
 * separate: the cursor advances in simulated time at the chosen speed
 * (simulated seconds per wall second), slowed inside contacts when slow
 * motion is on, and never passes the last computed sample.
 *
 * Every change of state happens here (drawing code only reads it).  Errors
 * from the engine go to the message line; nothing computed is lost by a
 * refused edit or a failed export.
 */
#include <ctype.h>
#include <curses.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app.h"
#include "keys.h"
#include "scene.h"
#include "csv.h"
#include "status.h"
#include "term.h"
#include "tui.h"
#include "units.h"

#define DEFAULT_PRESET "steel-on-bitumen"
#define FRAME_MS 20           /* frame period while computing or playing */
#define IDLE_MS 250           /* getch timeout when idle (to see signals) */
#define COMPUTE_BUDGET 0.012  /* s of computation per frame */
#define SLOW_WALL 2.0         /* a contact lasts about this many wall seconds in slow motion */
#define SLOW_SPAN 3.0         /* slow motion ends this many contact durations after t_e */

static double
now_s(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void
app_msg(struct app *a, int error, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(a->msg, sizeof a->msg, fmt, ap);
	va_end(ap);
	a->msg_error = error;
}

/*
 * The engine's word on stiffness, for the message line: "" when the
 * contacts are not stiff.
 */
static const char *
stiff_note(const struct app *a, char *buf, size_t n)
{
	const struct sim_stats *st = sim_stats(a->sim);
	char tb[32];

	buf[0] = '\0';
	if (!st->stiff)
		return buf;
	units_format(st->stiff_t, UNIT_TIME, 4, tb, sizeof tb);
	if (st->switched)
		snprintf(buf, n, "; stiff contact at t = %s: auto went over to bsimp", tb);
	else
		snprintf(buf, n, "; stiff contact at t = %s: run.stepper = auto (or bsimp) is faster",
		         tb);
	return buf;
}

/* ---- speeds (1-2-5 sequence) ---------------------------------------- */

static double
speed_step(double s, int dir)
{
	double e = floor(log10(s) + 1e-9), p = pow(10, e), m = s / p;

	if (m < 1.5)
		m = 1;
	else if (m < 3.5)
		m = 2;
	else
		m = 5;
	if (dir > 0)
		m = m == 1 ? 2 : m == 2 ? 5 : 10;
	else if (dir < 0)
		m = m == 1 ? 0.5 : m == 2 ? 1 : 2;
	s = m * p;
	if (s < 1e-7)
		s = 1e-7;
	if (s > 100)
		s = 100;
	return s;
}

/* Playback speed that shows a run of length T in about 20 s. */
static double
speed_default(double T)
{
	if (!(T > 0) || !isfinite(T))
		T = 1;
	return speed_step(T / 20 * 0.99, 0);
}

/* ---- collisions ----------------------------------------------------- */

long
app_ncollisions(const struct app *a)
{
	struct collision live;

	return (long)sim_ncollisions(a->sim) + (sim_contact_live(a->sim, &live) ? 1 : 0);
}

const struct collision *
app_collision(const struct app *a, long i, struct collision *live)
{
	size_t nc = sim_ncollisions(a->sim);

	if (i < 0)
		return NULL;
	if ((size_t)i < nc)
		return sim_collision(a->sim, (size_t)i);
	if ((size_t)i == nc && sim_contact_live(a->sim, live))
		return live;
	return NULL;
}

/* ---- cursor ---------------------------------------------------------- */

static void
cursor_set(struct app *a, size_t i)
{
	const struct arc *arc = sim_arc(a->sim);
	size_t n = arc_len(arc);

	if (n == 0) {
		a->cursor = 0;
		a->tcur = 0;
		return;
	}
	if (i >= n)
		i = n - 1;
	a->cursor = i;
	a->tcur = arc_at(arc, i)->t;
}

/* Keeps the cursor valid after the arc changed (seek, restart, thinning). */
static void
cursor_clamp(struct app *a)
{
	size_t n = arc_len(sim_arc(a->sim));

	if (n == 0)
		a->cursor = 0;
	else if (a->cursor >= n)
		a->cursor = n - 1;
}

/* The collision index of the contact at the cursor, or -1 in flight. */
static long
coll_at_cursor(const struct app *a)
{
	const struct arc *arc = sim_arc(a->sim);
	const struct arc_sample *s;

	if (arc_len(arc) == 0)
		return -1;
	s = arc_at(arc, a->cursor);
	if (!s->q)
		return -1;
	for (long i = 0; i < app_ncollisions(a); i++) {
		struct collision live;
		const struct collision *c = app_collision(a, i, &live);
		if (c && c->j == s->j)
			return i;
	}
	return -1;
}

/* Moves the cursor to the first sample of collision i (its commencement). */
static void
cursor_to_collision(struct app *a, long i)
{
	struct collision live;
	const struct collision *c = app_collision(a, i, &live);

	if (c == NULL)
		return;
	cursor_set(a, arc_find(sim_arc(a->sim), c->te, c->j));
	a->table_sel = i;
}

/* ---- scene changes --------------------------------------------------- */

static void
legend_label(struct app *a)
{
	const struct scene *sc = sim_scene(a->sim);

	snprintf(a->run_label, sizeof a->run_label, "%.40s/%.20s", a->preset, sc->law->name);
}

/*
 * Applies a changed scene at the cursor: the arc is truncated at the cursor
 * and the run continues from there with the new values (sim_seek, then
 * sim_set_scene); some changes restart the run from t = 0, and the message
 * says so.  The scene is validated first, so a refused change loses nothing.
 */
static void
apply_scene(struct app *a, const struct scene *sc_in, const char *what)
{
	struct scene sc = *sc_in;
	char emsg[512];
	int restarted = 0, rc;

	if (scene_validate(&sc, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "refused: %s", emsg);
		return;
	}
	cursor_clamp(a);
	if (arc_len(sim_arc(a->sim)) > 0 && sim_seek(a->sim, a->cursor) != HB_OK) {
		app_msg(a, 1, "cannot continue from the cursor: %s", sim_errmsg(a->sim));
		return;
	}
	rc = sim_set_scene(a->sim, &sc, &restarted, emsg, sizeof emsg);
	if (rc != HB_OK) {
		app_msg(a, 1, "refused: %s", emsg);
		return;
	}
	legend_label(a);
	if (restarted) {
		cursor_set(a, 0);
		app_msg(a, 0, "%s; the run restarted from t = 0", what);
	} else {
		char tb[32];
		snprintf(tb, sizeof tb, "%.6g ms", a->tcur * 1e3);
		app_msg(a, 0, "%s; the run continues from the cursor (t = %s)", what, tb);
	}
	cursor_clamp(a);
	if (a->table_sel >= app_ncollisions(a))
		a->table_sel = app_ncollisions(a) > 0 ? app_ncollisions(a) - 1 : 0;
}

/* Sets one key of the current scene from text and applies it at the cursor. */
static void
edit_value(struct app *a, const char *key, const char *text)
{
	struct scene sc = *sim_scene(a->sim);
	struct scene_error err;
	char emsg[512], what[160];

	/* The error names the key and what is accepted (scene_error). */
	if (scene_set_text(&sc, key, text, &err) != HB_OK) {
		app_msg(a, 1, "refused (old value kept): %s", scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	snprintf(what, sizeof what, "%s = %s", key, text);
	apply_scene(a, &sc, what);
}

/* The scene_key index of the selected panel row, or -1. */
static int
param_key_index(const struct app *a)
{
	struct param_row rows[256];
	int n = params_rows(sim_scene(a->sim), rows, 256);

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
	struct scene_keyinfo ki;
	struct scene sc = *sim_scene(a->sim);
	struct scene_error err;
	int k = param_key_index(a);
	char text[96], emsg[512];
	double v;

	if (k < 0 || scene_key(sim_scene(a->sim), k, &ki) != 0)
		return;
	if (ki.readonly) {
		app_msg(a, 1, "%s is derived: computed from the bodies, never typed", ki.label);
		return;
	}
	if (ki.kind == SCENE_KEY_CHOICE) {
		if (ki.choice >= 0 && ki.nchoices >= 2)
			edit_value(a, ki.key,
			    ki.choices[((ki.choice + dir) % ki.nchoices + ki.nchoices) % ki.nchoices]);
		return;
	}
	if (ki.kind == SCENE_KEY_TEXT || !isfinite(ki.number)) {
		app_msg(a, 1, "%s is not a number: press Enter to type a value", ki.label);
		return;
	}
	if (ki.number == 0) {
		app_msg(a, 1, "%s is 0: press Enter to type a value", ki.label);
		return;
	}
	v = dir > 0 ? ki.number * 1.1 : ki.number / 1.1;
	if (ki.kind == SCENE_KEY_WHOLE)
		v = dir > 0 ? fmax(ceil(v), ki.number + 1) : fmin(floor(v), ki.number - 1);
	if (scene_set_number(&sc, ki.key, v, &err) != HB_OK) {
		app_msg(a, 1, "refused (old value kept): %s", scene_error_str(&err, emsg, sizeof emsg));
		return;
	}
	if (ki.kind == SCENE_KEY_WHOLE)
		snprintf(text, sizeof text, "%.0f", v);
	else
		units_format(v, ki.dim, 6, text, sizeof text);
	snprintf(emsg, sizeof emsg, "%s = %s", ki.key, text);
	apply_scene(a, &sc, emsg);
}

/* Loads a preset (name or path) with the command line's --set overrides. */
static struct sim *
load_sim(const char *name, const char *const *sets, int nsets, char *path, size_t pn,
         char *msg, size_t n)
{
	struct scene sc;
	struct sim *s;

	if (preset_resolve(name, path, pn, msg, n) != HB_OK)
		return NULL;
	if (preset_open(path, sets, nsets, &sc, msg, n) != HB_OK)
		return NULL;
	s = sim_new(&sc, msg, n);
	return s;
}

/* File name without folder and ".preset". */
static void
base_name(const char *path, char *out, size_t n)
{
	const char *b = strrchr(path, '/');
	char *dot;

	snprintf(out, n, "%s", b ? b + 1 : path);
	dot = strstr(out, ".preset");
	if (dot != NULL && dot[7] == 0)
		*dot = 0;
}

static void
adopt_sim(struct app *a, struct sim *s, const char *path)
{
	sim_free(a->sim);
	a->sim = s;
	snprintf(a->preset_path, sizeof a->preset_path, "%s", path);
	base_name(path, a->preset, sizeof a->preset);
	legend_label(a);
	a->cursor = 0;
	a->tcur = 0;
	a->table_sel = a->table_top = 0;
	a->param_sel = 1;
	a->param_top = 0;
	a->speed = speed_default(sim_scene(s)->run.T);
	a->zoom_i = 0;
}

void
app_open_preset(struct app *a, const char *name)
{
	char path[512], emsg[512];
	struct sim *s = load_sim(name, NULL, 0, path, sizeof path, emsg, sizeof emsg);

	if (s == NULL) {
		app_msg(a, 1, "cannot open %s: %s", name, emsg);
		return;
	}
	adopt_sim(a, s, path);
	a->playing = 1;
	app_msg(a, 0, "opened %s", path);
}

void
app_set_law(struct app *a, const char *law)
{
	struct scene sc = *sim_scene(a->sim);
	char emsg[512], what[96];

	if (scene_set(&sc, "scene.law", law, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "refused: %s", emsg);
		return;
	}
	snprintf(what, sizeof what, "law %s", law);
	apply_scene(a, &sc, what);
}

static void
pins_clear(struct app *a)
{
	for (int i = 0; i < a->npins; i++)
		sim_free(a->pin[i].sim);
	a->npins = 0;
}

static void
pin_current(struct app *a)
{
	char emsg[512];
	struct sim *s;
	const struct scene *sc = sim_scene(a->sim);

	if (a->npins >= APP_MAX_PINS - 1) {
		app_msg(a, 1, "at most %d pinned runs; P clears them", APP_MAX_PINS - 1);
		return;
	}
	s = sim_new(sc, emsg, sizeof emsg);
	if (s == NULL) {
		app_msg(a, 1, "cannot pin: %s", emsg);
		return;
	}
	a->pin[a->npins].sim = a->sim;
	snprintf(a->pin[a->npins].label, sizeof a->pin[0].label, "%s", a->run_label);
	a->npins++;
	a->sim = s;
	legend_label(a);
	cursor_clamp(a);
	cursor_set(a, arc_find_t(sim_arc(a->sim), a->tcur));
	app_msg(a, 0, "pinned %s as ghost %d; change a parameter or the law and compare",
	        a->pin[a->npins - 1].label, a->npins);
}

/* The paper's third study: three presets pinned together. */
static void
study_three(struct app *a)
{
	static const char *names[3] = {
		"permanent-contact-shccl", "permanent-contact-bwshccl", "permanent-contact-bwmcl"
	};
	struct sim *s[3] = { NULL, NULL, NULL };
	char path[3][512], emsg[512];
	int i;

	for (i = 0; i < 3; i++) {
		s[i] = load_sim(names[i], NULL, 0, path[i], sizeof path[i], emsg, sizeof emsg);
		if (s[i] == NULL) {
			app_msg(a, 1, "third study: %s", emsg);
			for (int k = 0; k < i; k++)
				sim_free(s[k]);
			return;
		}
	}
	pins_clear(a);
	for (i = 0; i < 2; i++) {
		a->pin[i].sim = s[i];
		snprintf(a->pin[i].label, sizeof a->pin[i].label, "%s", sim_scene(s[i])->law->name);
	}
	a->npins = 2;
	adopt_sim(a, s[2], path[2]);
	snprintf(a->run_label, sizeof a->run_label, "%s", sim_scene(s[2])->law->name);
	a->view = VIEW_WHOLE;
	a->playing = 1;
	app_msg(a, 0, "third study: SHCCL, BWSHCCL and BWMCL on one substrate, pinned together");
}

static void
export_begin(struct app *a)
{
	time_t t = time(NULL);
	struct tm tm;
	char stamp[32];

	localtime_r(&t, &tm);
	strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
	a->overlay = OV_PROMPT;
	a->prompt_kind = PROMPT_EXPORT;
	snprintf(a->prompt_title, sizeof a->prompt_title, "export to BASE-trace.csv etc.; BASE");
	snprintf(a->prompt_buf, sizeof a->prompt_buf, "%s-%s", a->preset, stamp);
}

static void
export_do(struct app *a, const char *base)
{
	char trace[600], coll[600], scene[600], emsg[512];

	if (base[0] == 0) {
		app_msg(a, 1, "export cancelled: empty name");
		return;
	}
	snprintf(trace, sizeof trace, "%s-trace.csv", base);
	snprintf(coll, sizeof coll, "%s-collisions.csv", base);
	scene[0] = 0;
	if (csv_export(a->sim, trace, coll, scene, sizeof scene, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "export failed, nothing written: %s", emsg);
		return;
	}
	app_msg(a, 0, "wrote %s, %s and %s (%zu samples, %zu collisions)", trace, coll,
	        scene[0] ? scene : "the scene", arc_len(sim_arc(a->sim)), sim_ncollisions(a->sim));
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
	a->overlay = OV_PROMPT;
	a->prompt_kind = PROMPT_EDIT;
	snprintf(a->prompt_key, sizeof a->prompt_key, "%s", ki.key);
	snprintf(a->prompt_title, sizeof a->prompt_title, "%.47s %.47s", ki.key, ki.range);
	snprintf(a->prompt_buf, sizeof a->prompt_buf, "%s", ki.edit); /* reads back exactly */
}

static void
prompt_key(struct app *a, int ch)
{
	size_t l = strlen(a->prompt_buf);

	if (ch == 27) {
		a->overlay = OV_NONE;
		app_msg(a, 0, "cancelled");
	} else if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		char buf[256];
		snprintf(buf, sizeof buf, "%s", a->prompt_buf);
		a->overlay = OV_NONE;
		if (a->prompt_kind == PROMPT_EDIT)
			edit_value(a, a->prompt_key, buf);
		else
			export_do(a, buf);
	} else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
		if (l > 0)
			a->prompt_buf[l - 1] = 0;
	} else if (ch == 21) { /* C-u */
		a->prompt_buf[0] = 0;
	} else if (ch >= 32 && ch < 127 && l + 1 < sizeof a->prompt_buf) {
		a->prompt_buf[l] = (char)ch;
		a->prompt_buf[l + 1] = 0;
	}
}

/* ---- navigation ------------------------------------------------------ */

static void
jump_move(struct app *a, int dir)
{
	const struct arc *arc = sim_arc(a->sim);
	size_t k, nk = arc_nintervals(arc);

	if (arc_len(arc) == 0 || nk == 0)
		return;
	k = arc_interval_of(arc, a->cursor);
	if (dir > 0) {
		if (k + 1 < nk)
			cursor_set(a, arc_interval_at(arc, k + 1)->first);
		else
			app_msg(a, 0, "no later jump (yet)");
	} else {
		if (a->cursor > arc_interval_at(arc, k)->first && k > 0)
			cursor_set(a, arc_interval_at(arc, k)->first);
		else if (k > 0)
			cursor_set(a, arc_interval_at(arc, k - 1)->first);
		else {
			cursor_set(a, 0);
			app_msg(a, 0, "no earlier jump");
		}
	}
}

static void
coll_move(struct app *a, int dir)
{
	const struct arc *arc = sim_arc(a->sim);
	long nc = app_ncollisions(a), i, best = -1;
	const struct arc_sample *s;
	size_t first;

	if (arc_len(arc) == 0)
		return;
	s = arc_at(arc, a->cursor);
	first = arc_interval_at(arc, arc_interval_of(arc, a->cursor))->first;
	for (i = 0; i < nc; i++) {
		struct collision live;
		const struct collision *c = app_collision(a, i, &live);
		if (c == NULL)
			continue;
		if (dir > 0 && c->j > s->j) {
			best = i;
			break;
		}
		if (dir < 0 && (c->j < s->j || (c->j == s->j && a->cursor > first)))
			best = i;
	}
	if (best < 0) {
		app_msg(a, 0, dir > 0 ? "no later collision (yet)" : "no earlier collision");
		return;
	}
	cursor_to_collision(a, best);
}

static double
view_span(const struct app *a)
{
	const struct arc_sample *l = arc_last(sim_arc(a->sim));
	double T = sim_scene(a->sim)->run.T;

	if (a->view == VIEW_FOLLOW)
		return T / 10;
	if (a->view == VIEW_ZOOM) {
		struct collision live;
		const struct collision *c = app_collision(a, a->zoom_i, &live);
		if (c)
			return 1.5 * fmax(c->ts - c->te, 1e-9);
	}
	return l && sim_end(a->sim) != SIM_RUNNING ? l->t : T;
}

static void
scrub(struct app *a, int dir)
{
	const struct arc *arc = sim_arc(a->sim);
	double d = view_span(a) / 100;

	if (arc_len(arc) == 0)
		return;
	a->playing = 0;
	a->tcur += dir * d;
	if (a->tcur < 0)
		a->tcur = 0;
	if (a->tcur > arc_last(arc)->t)
		a->tcur = arc_last(arc)->t;
	a->cursor = arc_find_t(arc, a->tcur);
}

static void
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
	a->zoom_i = i;
	a->view = view;
	a->table_sel = i;
}

static void
sel_move(struct app *a, long d)
{
	if (a->focus == FOCUS_TABLE) {
		long n = app_ncollisions(a);
		a->table_sel += d;
		if (a->table_sel >= n)
			a->table_sel = n - 1;
		if (a->table_sel < 0)
			a->table_sel = 0;
	} else {
		struct param_row rows[256];
		int n = params_rows(sim_scene(a->sim), rows, 256), s = a->param_sel;
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

void
app_relayout(struct app *a)
{
	layout_compute(COLS, LINES, a->focus == FOCUS_PARAMS, &a->L);
}

void
app_key(struct app *a, int ch)
{
	int act;

	if (ch == KEY_RESIZE) {
		app_relayout(a);
		return;
	}
	if (a->L.too_small) {
		if (ch == 'q')
			a->quit = 1;
		return;
	}
	switch (a->overlay) {
	case OV_PROMPT:
		prompt_key(a, ch);
		return;
	case OV_LAW:
	case OV_PRESET:
		pickers_key(a, ch);
		return;
	case OV_HELP:
		if (ch == KEY_DOWN || ch == 'j')
			a->help_top++;
		else if (ch == KEY_UP || ch == 'k') {
			if (a->help_top > 0)
				a->help_top--;
		} else
			a->overlay = OV_NONE;
		return;
	default:
		break;
	}
	act = keys_action(ch, a->focus == FOCUS_PARAMS);
	switch (act) {
	case ACT_QUIT: a->quit = 1; break;
	case ACT_HELP: a->overlay = OV_HELP; a->help_top = 0; break;
	case ACT_PLAY:
		a->playing = !a->playing;
		if (a->playing && sim_end(a->sim) != SIM_RUNNING
		    && a->cursor + 1 >= arc_len(sim_arc(a->sim)))
			cursor_set(a, 0); /* at the end of a finished run: play it again */
		break;
	case ACT_STEP_FWD: a->playing = 0; cursor_set(a, a->cursor + 1); break;
	case ACT_STEP_BACK: a->playing = 0; cursor_set(a, a->cursor > 0 ? a->cursor - 1 : 0); break;
	case ACT_PREV_JUMP: a->playing = 0; jump_move(a, -1); break;
	case ACT_NEXT_JUMP: a->playing = 0; jump_move(a, 1); break;
	case ACT_PREV_COLL: a->playing = 0; coll_move(a, -1); break;
	case ACT_NEXT_COLL: a->playing = 0; coll_move(a, 1); break;
	case ACT_SCRUB_BACK: scrub(a, -1); break;
	case ACT_SCRUB_FWD: scrub(a, 1); break;
	case ACT_HOME: a->playing = 0; cursor_set(a, 0); break;
	case ACT_END: a->playing = 0; cursor_set(a, (size_t)-1); break;
	case ACT_FASTER: a->speed = speed_step(a->speed, 1); break;
	case ACT_SLOWER: a->speed = speed_step(a->speed, -1); break;
	case ACT_SLOWMO:
		a->slowmo = !a->slowmo;
		app_msg(a, 0, "slow motion through contacts %s", a->slowmo ? "on" : "off");
		break;
	case ACT_VIEW:
		a->view = (a->view + 1) % VIEW_COUNT;
		if ((a->view == VIEW_ZOOM || a->view == VIEW_LOOP) && app_ncollisions(a) == 0)
			a->view = VIEW_J;
		if (a->view == VIEW_ZOOM || a->view == VIEW_LOOP) {
			if (a->zoom_i >= app_ncollisions(a))
				a->zoom_i = app_ncollisions(a) - 1;
		}
		break;
	case ACT_ZOOM: zoom_on(a, VIEW_ZOOM); break;
	case ACT_LOOP: zoom_on(a, VIEW_LOOP); break;
	case ACT_JVIEW: a->view = a->view == VIEW_J ? VIEW_WHOLE : VIEW_J; break;
	case ACT_FOCUS:
		a->focus = a->focus == FOCUS_TABLE ? FOCUS_PARAMS : FOCUS_TABLE;
		app_relayout(a);
		break;
	case ACT_UP: sel_move(a, -1); break;
	case ACT_DOWN: sel_move(a, 1); break;
	case ACT_PGUP: sel_move(a, -(a->L.table.h > 2 ? a->L.table.h - 2 : 1)); break;
	case ACT_PGDN: sel_move(a, a->L.table.h > 2 ? a->L.table.h - 2 : 1); break;
	case ACT_ENTER:
		if (a->focus == FOCUS_PARAMS)
			prompt_edit_begin(a);
		else if (app_ncollisions(a) > 0) {
			a->playing = 0;
			a->zoom_i = a->table_sel;
			a->view = VIEW_ZOOM;
			cursor_to_collision(a, a->table_sel);
		}
		break;
	case ACT_NUDGE_UP: nudge(a, 1); break;
	case ACT_NUDGE_DOWN: nudge(a, -1); break;
	case ACT_LAW: {
		const struct law_type *const *l = law_list();
		a->overlay = OV_LAW;
		a->pick_sel = a->pick_top = 0;
		for (int i = 0; l[i]; i++)
			if (l[i] == sim_scene(a->sim)->law)
				a->pick_sel = i;
		break;
	}
	case ACT_PRESET: {
		int n;
		free(a->presets);
		a->presets = NULL;
		a->npresets = 0;
		n = preset_list(&a->presets);
		if (n < 0)
			term_oom();
		a->npresets = n;
		if (n == 0) {
			app_msg(a, 1, "no presets found (looked in $HYBOUNCE_PRESETS, ./presets and %s)",
			        HYBOUNCE_DATADIR "/presets");
			break;
		}
		a->overlay = OV_PRESET;
		a->pick_sel = a->pick_top = 0;
		for (int i = 0; i < n; i++)
			if (strcmp(a->presets[i].name, a->preset) == 0)
				a->pick_sel = i;
		break;
	}
	case ACT_RESTART:
		if (sim_restart(a->sim) != HB_OK) {
			app_msg(a, 1, "restart failed: %s", sim_errmsg(a->sim));
			break;
		}
		cursor_set(a, 0);
		a->table_sel = a->table_top = 0;
		app_msg(a, 0, "restarted from t = 0");
		break;
	case ACT_PIN: pin_current(a); break;
	case ACT_UNPIN:
		pins_clear(a);
		app_msg(a, 0, "pinned runs cleared");
		break;
	case ACT_STUDY3: study_three(a); break;
	case ACT_EXPORT: export_begin(a); break;
	case ACT_REDRAW: clear(); app_relayout(a); break;
	default:
		break;
	}
	/* navigation: the table selection follows the cursor onto a contact */
	if (act == ACT_STEP_FWD || act == ACT_STEP_BACK || act == ACT_PREV_JUMP
	    || act == ACT_NEXT_JUMP || act == ACT_SCRUB_BACK || act == ACT_SCRUB_FWD
	    || act == ACT_HOME || act == ACT_END) {
		long i = coll_at_cursor(a);
		if (i >= 0)
			a->table_sel = i;
	}
}

int
app_tick(struct app *a)
{
	static double last;
	double t = now_s(), dt = last > 0 ? t - last : 0;
	const struct arc *arc;
	int busy = 0, rc;

	last = t;
	if (dt > 0.25)
		dt = 0.25;
	if (sim_end(a->sim) == SIM_RUNNING) {
		rc = sim_advance(a->sim, 0, a->budget);
		if (rc != HB_OK && rc != HB_EDONE) {
			app_msg(a, 1, "run failed: %s (everything before is kept)", sim_errmsg(a->sim));
		} else if (sim_end(a->sim) != SIM_RUNNING && sim_stats(a->sim)->stiff) {
			char note[160];

			app_msg(a, 0, "run computed%s", stiff_note(a, note, sizeof note));
		}
		busy = 1;
	}
	for (int i = 0; i < a->npins; i++)
		if (sim_end(a->pin[i].sim) == SIM_RUNNING) {
			sim_advance(a->pin[i].sim, 0, a->budget / 4);
			busy = 1;
		}
	arc = sim_arc(a->sim);
	cursor_clamp(a);
	a->in_slow = 0;
	if (a->playing && arc_len(arc) > 0) {
		const struct arc_sample *cs = arc_at(arc, a->cursor);
		const struct arc_sample *ls = arc_last(arc);
		double sp = a->speed, tnew;
		size_t k = arc_interval_of(arc, a->cursor);

		if (a->slowmo && cs->q) {
			/* a contact as long as the last completed one takes SLOW_WALL
			 * seconds; a contact that lasts far longer (a permanent
			 * contact) is played at the normal speed after a while */
			double td = 1e-3;
			size_t nc = sim_ncollisions(a->sim);
			const struct arc_interval *iv = arc_interval_at(arc, k);
			if (nc > 0 && sim_collision(a->sim, nc - 1)->td > 0)
				td = sim_collision(a->sim, nc - 1)->td;
			if (a->tcur - iv->t0 < SLOW_SPAN * td) {
				if (sp > td / SLOW_WALL)
					sp = td / SLOW_WALL;
				a->in_slow = 1;
			}
		}
		tnew = a->tcur + sp * dt;
		/* slow motion: stop at the start of a contact rather than skip it */
		if (a->slowmo && !cs->q && k + 1 < arc_nintervals(arc)) {
			const struct arc_interval *nx = arc_interval_at(arc, k + 1);
			if (nx->q && nx->t0 <= tnew) {
				cursor_set(a, nx->first);
				tnew = -1;
			}
		}
		if (tnew >= 0) {
			if (tnew >= ls->t) {
				a->tcur = ls->t;
				a->cursor = arc_len(arc) - 1;
				if (sim_end(a->sim) != SIM_RUNNING) {
					a->playing = 0;
					char note[160];

					app_msg(a, 0, "end of the run: %s%s", sim_end_str(a->sim),
					        stiff_note(a, note, sizeof note));
				}
			} else {
				a->tcur = tnew;
				a->cursor = arc_find_t(arc, tnew);
			}
		}
		busy = 1;
	}
	return busy;
}

void
app_draw(struct app *a)
{
	erase();
	if (a->L.too_small) {
		pane_too_small_draw(a);
	} else {
		pane_plot_draw(a);
		if (a->L.table_visible)
			pane_table_draw(a);
		if (a->L.params_visible)
			pane_params_draw(a);
		pane_status_draw(a);
		if (a->overlay == OV_HELP)
			pane_help_draw(a);
		else if (a->overlay == OV_LAW || a->overlay == OV_PRESET)
			pickers_draw(a);
	}
	a->frames++;
	refresh();
}

static int
loop(struct app *a)
{
	int ch, busy = 1;

	while (!a->quit) {
		if (term_signalled()) {
			a->exit_status = 0;
			break;
		}
		timeout(busy ? FRAME_MS : IDLE_MS);
		ch = getch();
		if (ch != ERR)
			app_key(a, ch);
		if (a->quit)
			break;
		busy = app_tick(a);
		app_draw(a);
	}
	return a->exit_status;
}

int
app_run(const struct app_options *o, char *msg, size_t n)
{
	struct app *a;
	struct sim *s;
	char path[512];
	int status;

	if (n > 0)
		msg[0] = 0;
	s = load_sim(o->preset ? o->preset : DEFAULT_PRESET, o->sets, o->nsets, path,
	             sizeof path, msg, n);
	if (s == NULL)
		return 2;
	a = calloc(1, sizeof *a);
	if (a == NULL) {
		sim_free(s);
		snprintf(msg, n, "out of memory");
		return 1;
	}
	a->opt = o;
	a->budget = COMPUTE_BUDGET;
	adopt_sim(a, s, path);
	a->playing = 1;
	a->slowmo = 1;
	a->focus = FOCUS_TABLE;

	if (o->script != NULL) {
		status = script_run(a, o->script, msg, n);
	} else {
		if (term_begin(msg, n) != 0) {
			sim_free(a->sim);
			free(a);
			return 1;
		}
		a->braille = term_utf8() && !o->ascii;
		a->colour = term_colour();
		app_relayout(a);
		app_msg(a, 0, "%s: %s   (? for help)", a->preset, sim_scene(a->sim)->name);
		status = loop(a);
		term_end();
		if (term_signalled())
			snprintf(msg, n, "stopped by signal %d", term_signalled());
	}
	pins_clear(a);
	sim_free(a->sim);
	free(a->presets);
	free(a);
	return status;
}
