/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_branch.c - a run with branches as a preset (sim.h: hb_sim_branch).
 *
 * The file holds the scene the run began with, then one section per
 * branch, in order:
 *
 *     [branch 1]
 *     t = 0.081234567890123456 s     the sample the run continues from
 *     j = 6                          (its jump count)
 *     x = ... m                      the state there: a check that the
 *     v = ... m/s                    replayed run is the one exported
 *     x_c = 0 m
 *     contact = no
 *     law.c = 44000 N s/m            the values from there on (the keys
 *                                    that changed, as SECTION.KEY)
 *
 * Each branch's scene is the one before it with its keys, applied in the
 * order a preset's are (the law, the bodies, the law's exponents, the
 * rest).  Every number is written so that it reads back to the same
 * double, and the writer checks that reading a branch back gives its
 * scene; where it does not, the branch lists every key, and where even
 * that fails, the header says the file does not reproduce the run.
 * hb_preset_format_run writes the whole run so (its first scene by
 * preset_write.c's hb_preset_format).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "preset_ini.h"
#include "textbuf.h"
#include "cnum.h"

#ifdef HYBOUNCE_VERSION
#define HB_PRESET_VERSION HYBOUNCE_VERSION
#else
#define HB_PRESET_VERSION "(unknown version)"
#endif

/* One key of a branch: "law.c" = "44000 N s/m", at line (0 when written). */
struct kv {
	char key[96];
	const char *value;
	int line;
};

static int
is_exponent(const struct hb_scene *sc, const char *key)
{
	int i;

	if (strncmp(key, "law.", 4) != 0)
		return 0;
	i = hb_law_param_index(sc->law, key + 4);
	return i >= 0 && strcmp(sc->law->params[i].name, key + 4) == 0 &&
	       (sc->law->params[i].flags & (HB_LAW_PARAM_EXPONENT_P | HB_LAW_PARAM_EXPONENT_N));
}

/* The pass a key is applied in: the law; the scene and bodies; exponents; the rest. */
static int
pass_of(const struct hb_scene *sc, const char *key)
{
	if (strcmp(key, "scene.law") == 0)
		return 0;
	if (strncmp(key, "scene.", 6) == 0 || strncmp(key, "body", 4) == 0)
		return 1;
	return is_exponent(sc, key) ? 2 : 3;
}

/* Applies the keys to sc in the order above, then validates it. */
static int
branch_apply(struct hb_scene *sc, const struct kv *kv, int n, const char *file, const char *sec,
             char *msg, size_t mn)
{
	struct hb_scene_error err;
	char m[512];

	for (int pass = 0; pass < 4; pass++)
		for (int i = 0; i < n; i++) {
			if (pass_of(sc, kv[i].key) != pass)
				continue;
			if (hb_scene_set_text(sc, kv[i].key, kv[i].value, &err) != HB_OK)
				return hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s] %s: %s%s%s", file,
				    kv[i].line, sec, kv[i].key, err.what, err.accepted[0] ? "; accepted: " : "",
				    err.accepted);
		}
	if (hb_scene_validate(sc, m, sizeof m) != HB_OK)
		return hb_status_set(msg, mn, HB_EINVAL, "%s: [%s]: %s", file, sec, m);
	return HB_OK;
}

/* ---- reading ------------------------------------------------------------ */

/* N of "branch N", or 0 when the name is not that. */
static int
branch_number(const char *sec)
{
	char *end;
	long k;

	if (strncmp(sec, "branch ", 7) != 0 || sec[7] < '1' || sec[7] > '9')
		return 0;
	k = strtol(sec + 7, &end, 10);
	return *end == '\0' && k < 100000 ? (int)k : 0;
}

static int
read_number(const struct preset_entry *e, const char *file, struct hb_unit_dim dim, double *v,
            char *msg, size_t mn)
{
	char m[256];

	if (hb_units_parse(e->value, dim, v, m, sizeof m) != HB_OK)
		return hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s] %s: %s", file, e->line, e->section,
		    e->name, m);
	return HB_OK;
}

/* Reads the entries of section "branch k" into *b, on top of the scene before it. */
static int
read_one(const struct preset_entry *e, int n, const char *file, int k, struct hb_branch *b,
         char *msg, size_t mn)
{
	static const char *const fixed[] = { "t", "j", "x", "v", "x_c", "contact" };
	int have[6] = { 0 }, nkv = 0, st, line = 0;
	struct kv *kv = malloc((size_t)n * sizeof *kv);
	char sec[32];

	if (kv == NULL)
		return hb_status_set(msg, mn, HB_ENOMEM, "%s: out of memory", file);
	snprintf(sec, sizeof sec, "branch %d", k);
	for (int i = 0; i < n; i++) {
		const struct preset_entry *p = &e[i];
		int f;

		if (strcmp(p->section, sec) != 0)
			continue;
		line = line ? line : p->line;
		for (f = 0; f < 6 && strcmp(p->name, fixed[f]) != 0; f++)
			;
		st = HB_OK;
		if (f == 0)
			st = read_number(p, file, hb_unit_time, &b->t, msg, mn);
		else if (f == 1) {
			char *end;

			b->j = strtol(p->value, &end, 10);
			if (end == p->value || *end != '\0' || b->j < 0)
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s] j: '%s' is not a jump "
				    "count; accepted: a whole number >= 0", file, p->line, sec, p->value);
		} else if (f == 2)
			st = read_number(p, file, hb_unit_length, &b->x, msg, mn);
		else if (f == 3)
			st = read_number(p, file, hb_unit_velocity, &b->v, msg, mn);
		else if (f == 4)
			st = read_number(p, file, hb_unit_length, &b->xc, msg, mn);
		else if (f == 5) {
			b->q = strcmp(p->value, "yes") == 0;
			if (!b->q && strcmp(p->value, "no") != 0)
				st = hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s] contact: '%s'; "
				    "accepted: yes, no", file, p->line, sec, p->value);
		} else if (strchr(p->name, '.') == NULL || strlen(p->name) >= sizeof kv[0].key) {
			st = hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s] %s: unknown key; accepted: "
			    "t, j, x, v, x_c, contact and the scene's keys as SECTION.KEY (law.c, "
			    "run.T, ...)", file, p->line, sec, p->name);
		} else {
			snprintf(kv[nkv].key, sizeof kv[nkv].key, "%s", p->name);
			kv[nkv].value = p->value;
			kv[nkv].line = p->line;
			nkv++;
		}
		if (f < 6 && st == HB_OK)
			have[f] = 1;
		if (st != HB_OK) {
			free(kv);
			return st;
		}
	}
	for (int f = 0; f < 6; f++)
		if (!have[f]) {
			free(kv);
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s]: no %s; accepted: a branch "
			    "gives t, j, x, v, x_c and contact (where the run continues) and the keys that "
			    "change", file, line, sec, fixed[f]);
		}
	st = branch_apply(&b->sc, kv, nkv, file, sec, msg, mn);
	free(kv);
	return st;
}

int
preset_branches_read(const struct preset_entry *e, int n, const char *file,
                     const struct hb_scene *sc, struct hb_branch **br, size_t *nbr, char *msg,
                     size_t mn)
{
	int kmax = 0, st = HB_OK;
	struct hb_branch *b;

	*br = NULL;
	*nbr = 0;
	for (int i = 0; i < n; i++) {
		int k;

		if (!preset_is_branch(e[i].section))
			continue;
		if ((k = branch_number(e[i].section)) == 0)
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s]: not a branch's name; "
			    "accepted: [branch 1], [branch 2], ... in order", file, e[i].line,
			    e[i].section);
		if (k > kmax + 1)
			return hb_status_set(msg, mn, HB_EINVAL, "%s:%d: [%s]: comes before [branch %d]; "
			    "accepted: [branch 1], [branch 2], ... in order", file, e[i].line,
			    e[i].section, kmax + 1);
		kmax = k > kmax ? k : kmax;
	}
	if (kmax == 0)
		return HB_OK;
	b = calloc((size_t)kmax, sizeof *b);
	if (b == NULL)
		return hb_status_set(msg, mn, HB_ENOMEM, "%s: out of memory", file);
	for (int k = 1; k <= kmax && st == HB_OK; k++) {
		b[k - 1].sc = k == 1 ? *sc : b[k - 2].sc;
		st = read_one(e, n, file, k, &b[k - 1], msg, mn);
		if (st == HB_OK && k > 1 && (b[k - 1].t < b[k - 2].t ||
		    (b[k - 1].t == b[k - 2].t && b[k - 1].j <= b[k - 2].j)))
			st = hb_status_set(msg, mn, HB_EINVAL, "%s: [branch %d]: begins before [branch "
			    "%d] ends; accepted: branches in order of t", file, k, k - 1);
	}
	if (st != HB_OK) {
		free(b);
		return st;
	}
	*br = b;
	*nbr = (size_t)kmax;
	return HB_OK;
}

/* ---- writing ------------------------------------------------------------ */

/*
 * The "SECTION.KEY = VALUE" lines of a preset text (hb_preset_format),
 * into kv (values point into text, which is cut at each line's end).
 */
static int
split_lines(char *text, struct kv *kv, int max)
{
	char sec[32] = "";
	int n = 0;

	for (char *p = text; p != NULL && *p != '\0';) {
		char *nl = strchr(p, '\n'), *eq;

		if (nl != NULL)
			*nl = '\0';
		if (p[0] == '[') {
			char *close = strchr(p, ']');

			if (close != NULL && (size_t)(close - p - 1) < sizeof sec) {
				memcpy(sec, p + 1, (size_t)(close - p - 1));
				sec[close - p - 1] = '\0';
			}
		} else if (p[0] != ';' && (eq = strstr(p, " =")) != NULL && n < max) {
			*eq = '\0';
			snprintf(kv[n].key, sizeof kv[n].key, "%s.%s", sec, p);
			kv[n].value = eq[2] == ' ' ? eq + 3 : eq + 2;
			kv[n].line = 0;
			n++;
		}
		p = nl != NULL ? nl + 1 : NULL;
	}
	return n;
}

static char *
format_alloc(const struct hb_scene *sc)
{
	size_t len = hb_preset_format(sc, NULL, 0);
	char *buf = malloc(len + 1);

	if (buf != NULL)
		hb_preset_format(sc, buf, len + 1);
	return buf;
}

/* 1 when the keys applied to before give b's scene, as written. */
static int
reads_back(const struct hb_scene *before, const struct hb_branch *b, const struct kv *kv, int n)
{
	struct hb_scene sc = *before;
	char m[512], *x, *y;
	int same;

	if (branch_apply(&sc, kv, n, "", "", m, sizeof m) != HB_OK)
		return 0;
	x = format_alloc(&sc);
	y = format_alloc(&b->sc);
	same = x != NULL && y != NULL && strcmp(x, y) == 0;
	free(x);
	free(y);
	return same;
}

enum { MAXKV = 256 };

/*
 * Appends "[branch k]" for b (the scene before it: before) to o.  Returns 1
 * when reading it back gives b's scene, else 0 (the section is written
 * all the same).
 */
static int
preset_branch_format(struct textbuf *o, int k, const struct hb_scene *before,
                     const struct hb_branch *b)
{
	char *tb = format_alloc(before), *ta = format_alloc(&b->sc), v[96];
	struct kv *kb = calloc(MAXKV, sizeof *kb), *ka = calloc(MAXKV, sizeof *ka);
	struct kv *out = calloc(MAXKV, sizeof *out);
	int nb, na, nout = 0, exact = 0;

	textbuf_printf(o, "\n[branch %d]\n", k);
	textbuf_printf(o, "t = %s\n", hb_units_format_exact(b->t, hb_unit_time, v, sizeof v));
	textbuf_printf(o, "j = %ld\n", b->j);
	textbuf_printf(o, "x = %s\n", hb_units_format_exact(b->x, hb_unit_length, v, sizeof v));
	textbuf_printf(o, "v = %s\n", hb_units_format_exact(b->v, hb_unit_velocity, v, sizeof v));
	textbuf_printf(o, "x_c = %s\n", hb_units_format_exact(b->xc, hb_unit_length, v, sizeof v));
	textbuf_printf(o, "contact = %s\n", b->q ? "yes" : "no");
	if (tb == NULL || ta == NULL || kb == NULL || ka == NULL || out == NULL)
		goto done;
	nb = split_lines(tb, kb, MAXKV);
	na = split_lines(ta, ka, MAXKV);
	/* the keys whose value changed (all of them under another law), then every key */
	for (int all = 0; all < 2 && !exact; all++) {
		int law_changed = 0;

		nout = 0;
		for (int i = 0; i < na; i++) {
			int same = 0;

			for (int j = 0; j < nb && !same; j++)
				same = strcmp(ka[i].key, kb[j].key) == 0 && strcmp(ka[i].value, kb[j].value) == 0;
			if (!same && strcmp(ka[i].key, "scene.law") == 0)
				law_changed = 1;
			if (!same || all)
				out[nout++] = ka[i];
		}
		if (law_changed && !all) {
			nout = 0;
			for (int i = 0; i < na; i++)
				out[nout++] = ka[i];
		}
		exact = reads_back(before, b, out, nout);
	}
	for (int i = 0; i < nout; i++)
		textbuf_printf(o, "%s =%s%s\n", out[i].key,
		    out[i].value[0] == ';' || out[i].value[0] == '#' ? "" : " ", out[i].value);
done:
	free(tb);
	free(ta);
	free(kb);
	free(ka);
	free(out);
	return exact;
}

/* ---- a run as a preset --------------------------------------------------- */

/* hb_preset_format's text less its first line (the header), appended to o. */
static void
body_of(struct textbuf *o, const struct hb_scene *sc)
{
	size_t len = hb_preset_format(sc, NULL, 0);
	char *buf = malloc(len + 1);
	const char *nl;

	if (buf == NULL) {
		o->len += len;   /* as textbuf does when the text does not fit */
		return;
	}
	hb_preset_format(sc, buf, len + 1);
	nl = strchr(buf, '\n');
	textbuf_printf(o, "%s", nl != NULL ? nl + 1 : buf);
	free(buf);
}

size_t
hb_preset_format_run(const struct hb_sim *s, char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };
	size_t nb = hb_sim_nbranches(s);
	double un = hb_sim_unrecorded(s);
	char tb[48];
	int exact = 1;

	if (nb == 0 && un < 0)
		return hb_preset_format(hb_sim_scene(s), buf, n);
	if (buf != NULL && n > 0)
		buf[0] = '\0';
	if (un >= 0) {
		hb_units_format_exact(un, hb_unit_time, tb, sizeof tb);
		textbuf_printf(&o, "; hybounce %s preset: does NOT reproduce the run: its values "
		    "changed at t = %s in a way a preset cannot record; these are the values at its "
		    "end\n", HB_PRESET_VERSION, tb);
		body_of(&o, hb_sim_scene(s));
		return o.len;
	}
	/* the branches first, to know whether each reads back; the header then goes before them */
	{
		struct textbuf b = { NULL, 0, 0 };
		char *bbuf;

		for (size_t k = 0; k < nb; k++)
			exact &= preset_branch_format(&b, (int)k + 1, k ? &hb_sim_branch_get(s, k - 1)->sc
			                                               : hb_sim_scene0(s), hb_sim_branch_get(s, k));
		bbuf = malloc(b.len + 1);
		if (bbuf != NULL) {
			b = (struct textbuf){ bbuf, b.len + 1, 0 };
			for (size_t k = 0; k < nb; k++)
				preset_branch_format(&b, (int)k + 1, k ? &hb_sim_branch_get(s, k - 1)->sc
				                                       : hb_sim_scene0(s), hb_sim_branch_get(s, k));
		}
		if (exact)
			textbuf_printf(&o, "; hybounce %s preset: a run with %zu branch%s: the scene below "
			    "from t = 0, then each [branch N] from its sample (t, j) on with the values it "
			    "names; hybounce --batch and the explorer replay them exactly\n",
			    HB_PRESET_VERSION, nb, nb == 1 ? "" : "es");
		else
			textbuf_printf(&o, "; hybounce %s preset: does NOT reproduce the run exactly: a "
			    "[branch N] below does not read back to the values the run took there\n",
			    HB_PRESET_VERSION);
		body_of(&o, hb_sim_scene0(s));
		if (bbuf != NULL)
			textbuf_printf(&o, "%s", bbuf);
		else
			o.len += b.len;
		free(bbuf);
	}
	return o.len;
}
