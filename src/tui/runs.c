/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * runs.c - the runs the explorer holds: the current one (opened from a
 * preset), up to APP_MAX_PINS pinned runs to compare with, their labels,
 * restarts and exports.
 *
 * A pinned run is labelled by what differs from the current one
 * ("c = 4400 N s/m" against "c = 44000 N s/m"); the labels are rebuilt
 * whenever the current scene changes (app_label_runs).
 */
#include <limits.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "csv.h"
#include "outputs.h"
#include "term.h"
#include "status.h"
#include "tui.h"
#include "units.h"

/*
 * Opens a preset as a run, replaying the branches it records (an export
 * after b): the run is then the one exported.  NULL with msg on an error.
 */
struct hb_sim *
load_sim(const char *name, const char *const *sets, int nsets, char *path, size_t pn,
         char *msg, size_t n)
{
	struct hb_scene sc;
	struct hb_branch *br = NULL;
	struct hb_sim *s;
	size_t nbr = 0;

	if (hb_preset_open_branched(name, sets, nsets, &sc, &br, &nbr, path, pn, msg, n) != HB_OK)
		return NULL;
	s = hb_sim_new(&sc, msg, n);
	for (size_t k = 0; s != NULL && k < nbr; k++) {
		char m[512];
		int restarted = 0;

		if (hb_sim_branch_at(s, &br[k], NULL, &restarted, m, sizeof m) != HB_OK || restarted) {
			snprintf(msg, n, "%s: [branch %zu]: %s", path, k + 1,
			         restarted ? "its values cannot continue the run there" : m);
			hb_sim_free(s);
			s = NULL;
		}
	}
	free(br);
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

/* How early a differing key is named in a label: the law first, names last. */
static int
key_rank(const struct hb_scene_keyinfo *k)
{
	size_t l = strlen(k->key);

	if (strcmp(k->section, "law") == 0)
		return 0;
	if (l >= 5 && strcmp(k->key + l - 5, ".name") == 0)
		return 2;
	return 1;
}

/*
 * Writes into out "label = value" (as a has it) of the keys where scenes a
 * and b differ: the first (the law's first), then "+N" for the others;
 * "same scene" when nothing differs.
 */
static void
diff_label(const struct hb_scene *a, const struct hb_scene *b, char *out, size_t n)
{
	int shown = 0, more = 0, na = hb_scene_nkeys(a), nb = hb_scene_nkeys(b);

	out[0] = 0;
	for (int rank = 0; rank < 3; rank++)
		for (int i = 0; i < na; i++) {
			struct hb_scene_keyinfo ka, kb;
			int found = 0;

			if (hb_scene_key(a, i, &ka) != 0 || ka.readonly || key_rank(&ka) != rank)
				continue;
			for (int k = 0; k < nb && !found; k++)
				if (hb_scene_key(b, k, &kb) == 0 && strcmp(ka.key, kb.key) == 0)
					found = 1 + (strcmp(ka.value, kb.value) != 0);
			if (found != 2)
				continue;
			if (shown < 1) {
				size_t l = strlen(out);
				snprintf(out + l, n - l, "%s%s = %s", shown ? ", " : "", ka.label, ka.value);
				shown++;
			} else {
				more++;
			}
		}
	if (more > 0) {
		size_t l = strlen(out);
		snprintf(out + l, n - l, " +%d", more);
	}
	if (shown == 0 && strcmp(a->law->name, b->law->name) != 0)
		snprintf(out, n, "law = %s", a->law->name);
	else if (shown == 0)
		snprintf(out, n, "same scene");
}

void
app_label_runs(struct app *a)
{
	const struct hb_scene *cur = hb_sim_scene(a->sim);

	if (a->npins == 0) {
		snprintf(a->run_label, sizeof a->run_label, "%.40s/%.20s", a->preset, cur->law->name);
		return;
	}
	for (int i = 0; i < a->npins; i++)
		diff_label(hb_sim_scene(a->pin[i].sim), cur, a->pin[i].label, sizeof a->pin[i].label);
	/* the current run: its values of what differs from the first pin */
	diff_label(cur, hb_sim_scene(a->pin[0].sim), a->run_label, sizeof a->run_label);
}

static void
adopt_sim(struct app *a, struct hb_sim *s, const char *path)
{
	hb_sim_free(a->sim);
	a->sim = s;
	snprintf(a->preset_path, sizeof a->preset_path, "%s", path);
	base_name(path, a->preset, sizeof a->preset);
	app_label_runs(a);
	a->cursor = 0;
	a->tcur = 0;
	a->want_t = -1;
	/* a preset that records branches was replayed with them (load_sim) */
	a->branch_t = hb_sim_nbranches(s) > 0 ? hb_sim_branch_get(s, 0)->t : -1;
	a->branch_j = hb_sim_nbranches(s) > 0 ? hb_sim_branch_get(s, 0)->j : 0;
	a->branch_armed = 0;
	a->nbranches = (int)hb_sim_nbranches(s);
	a->table_sel = a->table_top = 0;
	a->param_sel = 1;
	a->param_top = 0;
	a->speed = speed_default(hb_sim_scene(s)->run.T);
	a->zoom_i = 0;
	a->origin = *hb_sim_scene(s);
	a->nundo = 0;
}

void
app_adopt(struct app *a, struct hb_sim *s, const char *path)
{
	adopt_sim(a, s, path);
}

void
app_open_preset(struct app *a, const char *name)
{
	char path[512], emsg[512];
	struct hb_sim *s = load_sim(name, NULL, 0, path, sizeof path, emsg, sizeof emsg);

	if (s == NULL) {
		app_msg(a, 1, "cannot open %s: %s", name, emsg);
		return;
	}
	adopt_sim(a, s, path);
	a->playing = 1;
	app_msg(a, 0, "opened %s", path);
}

void
pins_clear(struct app *a)
{
	for (int i = 0; i < a->npins; i++)
		hb_sim_free(a->pin[i].sim);
	a->npins = 0;
	app_label_runs(a);
}

/*
 * Pins the current run: it stays drawn (in its own colour and marker), and
 * a copy of it becomes the current run, to be edited.
 */
void
act_pin(struct app *a)
{
	char emsg[512];
	struct hb_sim *s;

	if (a->npins >= APP_MAX_PINS) {
		app_msg(a, 1, "at most %d pinned runs; P clears them", APP_MAX_PINS);
		return;
	}
	s = hb_sim_new(hb_sim_scene(a->sim), emsg, sizeof emsg);
	if (s == NULL) {
		app_msg(a, 1, "cannot pin: %s", emsg);
		return;
	}
	a->pin[a->npins].sim = a->sim;
	a->pin[a->npins].branched = a->branch_t >= 0;
	a->npins++;
	a->sim = s;
	a->branch_t = -1;
	a->nbranches = 0;
	a->want_t = a->tcur;
	app_label_runs(a);
	cursor_set(a, 0);
	a->tcur = a->want_t;
	app_msg(a, 0, "pinned run %d (%c); now change a value or the law and compare (P clears)",
	        a->npins, "#*o@"[a->npins - 1 < 4 ? a->npins - 1 : 3]);
}

void
act_unpin(struct app *a)
{
	pins_clear(a);
	app_msg(a, 0, "pinned runs cleared");
}

/* The paper's third study: three presets pinned together. */
void
act_study3(struct app *a)
{
	static const char *names[3] = {
		"permanent-contact-shccl", "permanent-contact-bwshccl", "permanent-contact-bwmcl"
	};
	struct hb_sim *s[3] = { NULL, NULL, NULL };
	char path[3][512], emsg[512];
	int i;

	for (i = 0; i < 3; i++) {
		s[i] = load_sim(names[i], NULL, 0, path[i], sizeof path[i], emsg, sizeof emsg);
		if (s[i] == NULL) {
			app_msg(a, 1, "third study: %s", emsg);
			for (int k = 0; k < i; k++)
				hb_sim_free(s[k]);
			return;
		}
	}
	pins_clear(a);
	for (i = 0; i < 2; i++)
		a->pin[i].sim = s[i];
	a->npins = 2;
	adopt_sim(a, s[2], path[2]);
	a->view = VIEW_WHOLE;
	a->playing = 1;
	app_msg(a, 0, "third study: SHCCL, BWSHCCL and BWMCL on one substrate, pinned together");
}

void
act_restart(struct app *a)
{
	if (hb_sim_restart(a->sim) != HB_OK) {
		app_msg(a, 1, "restart failed: %s", hb_sim_errmsg(a->sim));
		return;
	}
	a->branch_t = -1;
	a->nbranches = 0;
	cursor_set(a, 0);
	a->table_sel = a->table_top = 0;
	app_msg(a, 0, "restarted from t = 0");
}

/* The preset picker's report: Enter opens that preset (its path). */
static void
preset_chosen(struct app *a, const char *path)
{
	app_open_preset(a, path);
}

void
act_preset(struct app *a)
{
	int n;

	free(a->presets);
	a->presets = NULL;
	a->npresets = 0;
	n = hb_preset_list(&a->presets);
	if (n < 0)
		term_oom();
	a->npresets = n;
	if (n == 0) {
		const char *const *d = hb_preset_dirs();
		char where[1024] = "";
		for (int i = 0; d[i] != NULL; i++) {
			size_t l = strlen(where);
			snprintf(where + l, sizeof where - l, "%s%s", i ? ", " : "", d[i]);
		}
		app_msg(a, 1, "no presets found (looked in %s; HYBOUNCE_PRESETS adds folders)", where);
		return;
	}
	a->pick_kind = PICK_PRESET;
	a->pick_done = preset_chosen;
	a->pick_sel = a->pick_top = 0;
	for (int i = 0; i < n; i++)
		if (strcmp(a->presets[i].name, a->preset) == 0)
			a->pick_sel = i;
	mode_push(a, &mode_preset);
}

/* ---- export ------------------------------------------------------------ */

/* The export prompt's report: Enter exports under that base name. */
static void
export_prompt_done(struct app *a, const char *text, int how)
{
	if (how == PROMPT_ENTER)
		export_do(a, text);
}

void
act_export(struct app *a)
{
	time_t t = time(NULL);
	struct tm tm;
	char stamp[32], cwd[PATH_MAX], base[96];

	localtime_r(&t, &tm);
	strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
	if (getcwd(cwd, sizeof cwd) == NULL)
		snprintf(cwd, sizeof cwd, ".");
	snprintf(base, sizeof base, "%.40s-%s", a->preset, stamp);
	prompt_open(a, PROMPT_EXPORT, export_prompt_done, base, "export to %s/BASE-trace.csv, -collisions.csv, .preset; BASE",
	            cwd);
}

/* " (replaced)" and the like: how a target of the export was written, for the message. */
static const char *
how_written(const struct hb_atomic_target *t)
{
	if (t->how == HB_ATOMIC_IN_PLACE)
		return " (written in place)";
	if (t->via_link)
		return t->how == HB_ATOMIC_REPLACE ? " (through a link, replacing its target)" : " (through a link)";
	return t->how == HB_ATOMIC_REPLACE ? " (replaced the existing file)" : "";
}

/*
 * Writes BASE-trace.csv, BASE-collisions.csv and the scene as BASE.preset
 * through hb_csv_export_with(): all or nothing, never over the preset being
 * run or a shipped preset.  A second export never replaces the first: when
 * one of the three files is there, BASE-2 (BASE-3, ...) is used instead,
 * and the message says where it wrote.
 */
void
export_do(struct app *a, const char *base0)
{
	char trace[600], coll[600], scene[600], emsg[512], note[256] = "", base[560];
	struct hb_csv_export_report *rep;
	struct hb_csv_export_opts eo = { 0 };
	struct hb_outputs inputs;
	int renamed = 0;

	if (base0[0] == 0) {
		app_msg(a, 1, "export cancelled: empty name");
		return;
	}
	snprintf(base, sizeof base, "%s", base0);
	for (int k = 2; ; k++) {
		snprintf(trace, sizeof trace, "%s-trace.csv", base);
		snprintf(coll, sizeof coll, "%s-collisions.csv", base);
		snprintf(scene, sizeof scene, "%s.preset", base);
		if (!tui_path_taken(trace) && !tui_path_taken(coll) && !tui_path_taken(scene))
			break;
		if (k >= 1000) {
			app_msg(a, 1, "export failed, nothing written: %.100s-2 ... -999 are all taken; "
			        "type another name", base0);
			return;
		}
		snprintf(base, sizeof base, "%.500s-%d", base0, k);
		renamed = 1;
	}
	rep = calloc(1, sizeof *rep);
	if (rep == NULL)
		term_oom();
	eo.trace = trace;
	eo.coll = coll;
	eo.scene = scene;
	eo.run_preset = a->preset_path;
	eo.provenance = a->opt != NULL ? a->opt->provenance : NULL;
	/* the measured data shown (--data) is an input too (outputs.h) */
	hb_outputs_init(&inputs);
	if (a->opt != NULL)
		hb_outputs_input(&inputs, a->opt->data, "the data file (--data)");
	eo.outputs = &inputs;
	if (hb_csv_export_with(a->sim, &eo, rep, emsg, sizeof emsg) != HB_OK) {
		app_msg(a, 1, "export failed, nothing written: %s", emsg);
		free(rep);
		return;
	}
	if (hb_sim_unrecorded(a->sim) >= 0) {
		char tb[32];
		hb_units_format(hb_sim_unrecorded(a->sim), hb_unit_time, 6, tb, sizeof tb);
		snprintf(note, sizeof note,
		         "; NOTE: the values changed at t = %s in a way a preset cannot record: the scene file does NOT reproduce this run (its first line says so; r, then export, gives a reproducible run)",
		         tb);
	} else if (hb_sim_nbranches(a->sim) > 0) {
		char tb[32];
		hb_units_format(hb_sim_branch_get(a->sim, 0)->t, hb_unit_time, 6, tb, sizeof tb);
		snprintf(note, sizeof note, "; the scene file records the %zu branch%s (the first at t = %s) and --batch replays %s",
		         hb_sim_nbranches(a->sim), hb_sim_nbranches(a->sim) == 1 ? "" : "es", tb,
		         hb_sim_nbranches(a->sim) == 1 ? "it" : "them");
	}
	if (renamed) {
		size_t l = strlen(note);

		snprintf(note + l, sizeof note - l, "; %.100s-* is an earlier export, kept", base0);
	}
	app_msg(a, hb_sim_unrecorded(a->sim) >= 0 || renamed, "wrote %s%s, %s%s and %s%s (%zu samples, %zu collisions)%s", trace,
	        how_written(&rep->target[0]), coll, how_written(&rep->target[1]),
	        rep->scene[0] ? rep->scene : "no scene", rep->scene[0] ? how_written(&rep->target[2]) : "",
	        hb_arc_len(hb_sim_arc(a->sim)), hb_sim_ncollisions(a->sim), note);
	free(rep);
}

/* c: the table's differences against pinned run 1, 2, ..., then off. */
void
act_compare(struct app *a)
{
	if (a->npins == 0) {
		a->compare = 0;
		app_msg(a, 1, "no pinned run to compare with: p pins the current run");
		return;
	}
	a->compare = (a->compare + 1) % (a->npins + 1);
	if (a->focus != FOCUS_TABLE) {
		/* show the table (one bottom pane at a time below 130 columns) */
		a->focus = FOCUS_TABLE;
		app_relayout(a);
	}
	if (a->compare)
		app_msg(a, 0, "table: differences of each collision against pinned run %d (%s)",
		        a->compare, a->pin[a->compare - 1].label);
	else
		app_msg(a, 0, "table: the current run only");
}
