/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset.c - scenes in INI files, read with inih (see preset.h).
 *
 * Reading is in two passes.  inih first collects every (section, key,
 * value, line) into a list, through a line reader of our own that counts
 * lines (this inih build hands no line number to the handler); then the
 * list is applied to hb_scene_defaults() in an order that makes the meaning
 * of each value independent of where it stands in the file:
 *     [scene] law  (loads the law's defaults),
 *     the rest of [scene],
 *     [body1], [body2]  (a body section given in the file starts from an
 *                        empty body: no material, no density, R = inf),
 *     [law] p and n  (the units of k, c, beta, gamma depend on them),
 *     the rest of [law], [loads], [initial], [run].
 * Then the scene is validated as a whole.  Every error is reported as
 * "FILE:LINE: [section] key: message; accepted: ...".
 *
 * inih's options are process globals in this build; each parse sets them
 * under a lock and puts them back (preset_ini.h).  Finding presets is in
 * preset_find.c.
 *
 * [branch N] sections (a run that changed its values part-way) are read
 * by preset_branch.c, for hb_preset_open_branched only; the other openers
 * refuse them.  Opening a preset (its file read once, --set applied, the
 * whole validated) is in preset_open.c; writing is in preset_write.c.
 */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <ini.h>

#include "hybounce/atomic.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "preset_ini.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

#define PRESET_MAX_ENTRIES 512

struct collect {
	struct preset_entry *e;
	int n;
	int oom;
	int overflow_line; /* first line with a section or key name too long */
	int toomany_line;  /* first key beyond PRESET_MAX_ENTRIES */
};

struct source {
	const char *p;
	int line;
	int long_line; /* first line longer than the reader's buffer, 0 if none */
};

/* fgets over a string, one line per call, counting lines. */
static char *
source_read(char *str, int num, void *stream)
{
	struct source *s = stream;
	int k = 0;

	if (*s->p == '\0')
		return NULL;
	s->line++;
	while (*s->p != '\0' && k < num - 1) {
		char c = *s->p++;
		str[k++] = c;
		if (c == '\n')
			break;
	}
	str[k] = '\0';
	if (k == num - 1 && str[k - 1] != '\n' && *s->p != '\0') {
		/* The line does not fit: skip its rest and remember it. */
		if (s->long_line == 0)
			s->long_line = s->line;
		while (*s->p != '\0' && *s->p != '\n')
			s->p++;
		if (*s->p == '\n')
			s->p++;
	}
	return str;
}

struct handler_ctx {
	struct collect *c;
	struct source *src;
};

static int
collect_handler(void *user, const char *section, const char *name, const char *value)
{
	struct handler_ctx *h = user;
	struct collect *c = h->c;
	struct preset_entry *e;

	if (c->n >= PRESET_MAX_ENTRIES) {
		if (c->toomany_line == 0)
			c->toomany_line = h->src->line;
		return 1;
	}
	e = &c->e[c->n];
	if (strlen(section) >= sizeof e->section || strlen(name) >= sizeof e->name) {
		if (c->overflow_line == 0)
			c->overflow_line = h->src->line;
		return 1;
	}
	e->value = strdup(value);
	if (e->value == NULL) {
		c->oom = 1;
		return 1;
	}
	strcpy(e->section, section);
	strcpy(e->name, name);
	e->line = h->src->line;
	c->n++;
	return 1;
}

void
preset_entries_free(struct preset_entry *e, int n)
{
	for (int i = 0; i < n; i++)
		free(e[i].value);
	free(e);
}

static void
collect_free(struct collect *c)
{
	preset_entries_free(c->e, c->n);
	c->e = NULL;
	c->n = 0;
}

/* The sections, in the order a preset is written. */
const char *const preset_sections[PRESET_NSECTIONS] = { "scene", "body1", "body2", "law", "chain",
	"striker", "loads", "initial", "run" };

static int
section_index(const char *s)
{
	for (size_t i = 0; i < PRESET_NSECTIONS; i++)
		if (strcmp(preset_sections[i], s) == 0)
			return (int)i;
	return -1;
}

/* "section.name" of an entry, into key (at least 97 bytes: the parts are bounded). */
static void
entry_key(const struct preset_entry *e, char *key)
{
	size_t ls = strlen(e->section), ln = strlen(e->name);

	memcpy(key, e->section, ls);
	key[ls] = '.';
	memcpy(key + ls + 1, e->name, ln + 1);
}

/* 1 if key "SECTION.NAME" is in the table (or the current law's parameters). */
static int
key_known(const struct hb_scene *sc, const struct preset_entry *e)
{
	char key[128];

	entry_key(e, key);
	if (scene_override_is_key(key)) /* [body.I], [interface.K], [initial] body.I.* */
		return 1;
	if (strcmp(e->section, "law") == 0) {
		int i = hb_law_param_index(sc->law, e->name);
		return i >= 0 && strcmp(sc->law->params[i].name, e->name) == 0;
	}
	entry_key(e, key);
	return scene_keydef_find(key) != NULL;
}

/* The keys of a section, for "known keys" messages. */
static void
known_list(const struct hb_scene *sc, const char *section, char *buf, size_t n)
{
	size_t sl = strlen(section);

	buf[0] = '\0';
	if (strcmp(section, "law") == 0) {
		for (int i = 0; i < sc->law->n_params; i++) {
			size_t l = strlen(buf);
			snprintf(buf + l, n - l, "%s%s", i ? ", " : "", sc->law->params[i].name);
		}
		return;
	}
	for (int k = 0; k < scene_nkeydefs; k++) {
		const char *key = scene_keydefs[k].key;
		if (strncmp(key, section, sl) == 0 && key[sl] == '.') {
			size_t l = strlen(buf);
			snprintf(buf + l, n - l, "%s%s", buf[0] ? ", " : "", key + sl + 1);
		}
	}
}

/* "FILE:LINE: [section] name: WHAT; accepted: ACCEPTED" */
static int
entry_error(const struct preset_entry *e, const char *file, const struct hb_scene_error *err, char *msg,
            size_t n)
{
	return hb_status_set(msg, n, HB_EINVAL, "%s:%d: [%s] %s: %s%s%s", file, e->line, e->section,
	    e->name, err->what, err->accepted[0] ? "; accepted: " : "", err->accepted);
}

/* Applies one entry through hb_scene_set_text. */
static int
apply(struct hb_scene *sc, const struct preset_entry *e, const char *file, char *msg, size_t n)
{
	struct hb_scene_error err;
	char key[128];

	if (!key_known(sc, e)) {
		char list[256];
		known_list(sc, e->section, list, sizeof list);
		return hb_status_set(msg, n, HB_EINVAL, "%s:%d: [%s] %s: unknown key; known keys: %s",
		    file, e->line, e->section, e->name, list);
	}
	entry_key(e, key);
	if (hb_scene_set_text(sc, key, e->value, &err) == HB_OK)
		return HB_OK;
	return entry_error(e, file, &err, msg, n);
}

static const struct preset_entry *
entry_find(const struct collect *c, const char *section, const char *name)
{
	for (int i = 0; i < c->n; i++)
		if (strcmp(c->e[i].section, section) == 0 &&
		    (name == NULL || strcmp(c->e[i].name, name) == 0))
			return &c->e[i];
	return NULL;
}

static int
is_string_key(const struct preset_entry *e)
{
	char key[128];
	const struct scene_keydef *kd;

	entry_key(e, key);
	kd = scene_keydef_find(key);
	return kd != NULL && kd->store == ST_STRING;
}

/* Is entry e a law exponent (p or n) of the current law? */
static int
is_exponent(const struct hb_scene *sc, const struct preset_entry *e)
{
	int i = hb_law_param_index(sc->law, e->name);

	return i >= 0 && strcmp(sc->law->params[i].name, e->name) == 0 &&
	    (sc->law->params[i].flags & (HB_LAW_PARAM_EXPONENT_P | HB_LAW_PARAM_EXPONENT_N));
}

/* branches: 1 when [branch N] sections are taken (and left to preset_branch.c) */
static int
load_entries(struct collect *c, const char *file, struct hb_scene *sc, int branches, char *msg,
             size_t n)
{
	int st;

	/* Sections, duplicates and empty values. */
	for (int i = 0; i < c->n; i++) {
		const struct preset_entry *e = &c->e[i];
		if (preset_is_branch(e->section) && !branches)
			return hb_status_set(msg, n, HB_EINVAL, "%s:%d: [%s]: this preset records a run "
			    "with branches (the explorer's b: it changed values part-way), which "
			    "hybounce --batch and the explorer replay and this command does not; "
			    "accepted: a preset without [branch] sections", file, e->line, e->section);
		if (preset_is_branch(e->section))
			continue;
		if (section_index(e->section) < 0 && !scene_override_is_section(e->section))
			return hb_status_set(msg, n, HB_EINVAL,
			    "%s:%d: [%s] %s: unknown section; known sections: scene, body1, body2, "
			    "law, chain, striker, loads, initial, run, and a chain's body.I and "
			    "interface.K", file, e->line, e->section, e->name);
		for (int j = 0; j < i; j++)
			if (strcmp(c->e[j].section, e->section) == 0 &&
			    strcmp(c->e[j].name, e->name) == 0)
				return hb_status_set(msg, n, HB_EINVAL,
				    "%s:%d: [%s] %s: duplicate key (first given on line %d); "
				    "accepted: one value per key", file, e->line, e->section, e->name,
				    c->e[j].line);
		if (e->value[0] == '\0' && !is_string_key(e))
			return hb_status_set(msg, n, HB_EINVAL,
			    "%s:%d: [%s] %s: empty value; accepted: key = value", file, e->line,
			    e->section, e->name);
	}

	hb_scene_defaults(sc);
	/* [scene] law first, then the rest of [scene]. */
	const struct preset_entry *law = entry_find(c, "scene", "law");
	if (law != NULL && (st = apply(sc, law, file, msg, n)) != HB_OK)
		return st;
	for (int i = 0; i < c->n; i++)
		if (strcmp(c->e[i].section, "scene") == 0 && &c->e[i] != law &&
		    (st = apply(sc, &c->e[i], file, msg, n)) != HB_OK)
			return st;

	/* Bodies: a section present starts from an empty body. */
	for (int b = 0; b < 2; b++) {
		const char *sec = b == 0 ? "body1" : "body2";
		const struct preset_entry *E, *nu, *rho, *mass;
		if (entry_find(c, sec, NULL) == NULL)
			continue;
		memset(&sc->body[b], 0, sizeof sc->body[b]);
		sc->body[b].R = INFINITY;
		for (int i = 0; i < c->n; i++)
			if (strcmp(c->e[i].section, sec) == 0 &&
			    (st = apply(sc, &c->e[i], file, msg, n)) != HB_OK)
				return st;
		E = entry_find(c, sec, "E");
		nu = entry_find(c, sec, "nu");
		rho = entry_find(c, sec, "rho");
		mass = entry_find(c, sec, "mass");
		if ((E == NULL) != (nu == NULL)) {
			const struct preset_entry *e = E != NULL ? E : nu;
			return hb_status_set(msg, n, HB_EINVAL,
			    "%s:%d: [%s] %s: a material needs both E and nu; accepted: both, or "
			    "neither (then give the mass and type law.k)", file, e->line, sec,
			    e->name);
		}
		if (rho != NULL && mass != NULL) {
			const struct preset_entry *e = rho->line > mass->line ? rho : mass;
			return hb_status_set(msg, n, HB_EINVAL,
			    "%s:%d: [%s] %s: give rho (with R) or mass, not both; accepted: one "
			    "of them", file, e->line, sec, e->name);
		}
	}
	hb_scene_derive(sc, NULL, 0);

	/* [law]: the exponents first. */
	for (int pass = 0; pass < 2; pass++)
		for (int i = 0; i < c->n; i++) {
			const struct preset_entry *e = &c->e[i];
			if (strcmp(e->section, "law") != 0 || is_exponent(sc, e) != (pass == 0))
				continue;
			if ((st = apply(sc, e, file, msg, n)) != HB_OK)
				return st;
		}
	/* [body.I] and [interface.K]: an interface's law first, then its exponents */
	for (int pass = 0; pass < 3; pass++)
		for (int i = 0; i < c->n; i++) {
			const struct preset_entry *e = &c->e[i];
			if (!scene_override_is_section(e->section) ||
			    scene_override_pass(sc, e->section, e->name) != pass)
				continue;
			if ((st = apply(sc, e, file, msg, n)) != HB_OK)
				return st;
		}
	static const char *const rest[] = { "chain", "striker", "loads", "initial", "run" };
	for (size_t s = 0; s < sizeof rest / sizeof rest[0]; s++)
		for (int i = 0; i < c->n; i++)
			if (strcmp(c->e[i].section, rest[s]) == 0 &&
			    (st = apply(sc, &c->e[i], file, msg, n)) != HB_OK)
				return st;

	/* The scene as a whole; name the line of the key at fault. */
	struct hb_scene_error err;
	st = hb_scene_check(sc, &err);
	if (st != HB_OK) {
		/* a chain's body.I.NAME, interface.K.NAME: the section is all but NAME */
		const char *dot = scene_override_is_key(err.key) && strncmp(err.key, "initial.", 8) != 0
		    ? strrchr(err.key, '.') : strchr(err.key, '.');
		char sec[32] = "";
		const struct preset_entry *e = NULL;
		if (dot == NULL || (size_t)(dot - err.key) >= sizeof sec) {
			char m[512];
			return hb_status_set(msg, n, st, "%s: %s", file, hb_scene_error_str(&err, m, sizeof m));
		}
		memcpy(sec, err.key, (size_t)(dot - err.key));
		sec[dot - err.key] = '\0';
		e = entry_find(c, sec, dot + 1);
		if (e == NULL)
			e = entry_find(c, sec, NULL);
		if (e != NULL)
			return hb_status_set(msg, n, st, "%s:%d: [%s] %s: %s%s%s", file, e->line, sec,
			    dot + 1, err.what, err.accepted[0] ? "; accepted: " : "", err.accepted);
		return hb_status_set(msg, n, st, "%s: [%s] %s: %s%s%s", file, sec, dot + 1, err.what,
		    err.accepted[0] ? "; accepted: " : "", err.accepted);
	}
	return HB_OK;
}

/* The one lock around inih's globals (preset_ini.h). */
static pthread_mutex_t ini_lock = PTHREAD_MUTEX_INITIALIZER;

void
preset_ini_begin(struct preset_ini_saved *sv)
{
	pthread_mutex_lock(&ini_lock);
	sv->multiline = ini_allow_multiline;
	sv->inline_comments = ini_allow_inline_comments;
	sv->inline_prefixes = ini_inline_comment_prefixes;
	sv->start_prefixes = ini_start_comment_prefixes;
	sv->no_value = ini_allow_no_value;
	sv->stop_on_first_error = ini_stop_on_first_error;
	sv->max_line = ini_max_line;
	ini_allow_multiline = 0;
	ini_allow_inline_comments = 1;
	ini_inline_comment_prefixes = (char *)";#";
	ini_start_comment_prefixes = (char *)";#";
	ini_allow_no_value = 0;
	ini_stop_on_first_error = 0;
	ini_max_line = PRESET_MAX_LINE;
}

void
preset_ini_end(const struct preset_ini_saved *sv)
{
	ini_allow_multiline = sv->multiline;
	ini_allow_inline_comments = sv->inline_comments;
	ini_inline_comment_prefixes = sv->inline_prefixes;
	ini_start_comment_prefixes = sv->start_prefixes;
	ini_allow_no_value = sv->no_value;
	ini_stop_on_first_error = sv->stop_on_first_error;
	ini_max_line = sv->max_line;
	pthread_mutex_unlock(&ini_lock);
}

int
preset_load_text(const char *text, const char *name, struct hb_scene *sc,
                 struct preset_entry **keep, int *nkeep, char *msg, size_t n)
{
	struct collect c = { 0 };
	struct source src = { text, 0, 0 };
	struct handler_ctx h = { &c, &src };
	struct preset_ini_saved sv;
	int r, st;

	if (name == NULL)
		name = "(string)";
	c.e = malloc(PRESET_MAX_ENTRIES * sizeof *c.e); /* entries 0..c.n-1 are written whole */
	if (c.e == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", name);
	preset_ini_begin(&sv);
	r = ini_parse_stream(source_read, &src, collect_handler, &h);
	preset_ini_end(&sv);
	if (src.long_line != 0 && (r <= 0 || src.long_line <= r))
		st = hb_status_set(msg, n, HB_EINVAL,
		    "%s:%d: line too long; accepted: at most %d characters", name, src.long_line,
		    PRESET_MAX_LINE - 3);
	else if (r > 0)
		st = hb_status_set(msg, n, HB_EINVAL,
		    "%s:%d: malformed line (expected key = value or [section]); accepted: "
		    "[section], key = value, ; comment", name, r);
	else if (c.toomany_line)
		st = hb_status_set(msg, n, HB_EINVAL, "%s:%d: too many keys; accepted: at most %d "
		    "key = value lines (a preset has about 40)", name, c.toomany_line,
		    PRESET_MAX_ENTRIES);
	else if (r < 0 || c.oom)
		st = hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", name);
	else if (c.overflow_line)
		st = hb_status_set(msg, n, HB_EINVAL,
		    "%s:%d: section or key name too long; accepted: the keys of preset.h", name,
		    c.overflow_line);
	else if (c.n == 0)
		/* not the default scene in disguise: an empty file is a mistake */
		st = hb_status_set(msg, n, HB_EINVAL,
		    "%s: the preset is empty (no key = value line); expected [scene], [body1], "
		    "[body2], [law], [loads], [initial] and [run] sections with their keys, "
		    "as in presets/*.preset", name);
	else
		st = load_entries(&c, name, sc, keep != NULL, msg, n);
	if (st == HB_OK && keep != NULL) {
		*keep = c.e;
		*nkeep = c.n;
	} else
		collect_free(&c);
	return st;
}

int
hb_preset_load_string(const char *text, const char *name, struct hb_scene *sc, char *msg, size_t n)
{
	return preset_load_text(text, name, sc, NULL, NULL, msg, n);
}
