/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_open.c - a preset opened (see preset.h): its file read once and
 * bounded (hb_input_read; a text file, no NUL bytes), its text loaded onto
 * the defaults (preset.c: preset_load_text), the --set KEY=VALUE arguments
 * applied in order, the scene validated as a whole, and, for
 * hb_preset_open_branched, its [branch N] sections read (preset_branch.c).
 * A preset named rather than given by path is found by preset_find.c.
 */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/input.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"

#include "preset_ini.h"

/* Reads a whole file into a malloc'd string, once, bounded (input.h). */
static int
read_file(const char *path, char **out, char *msg, size_t n)
{
	char *buf = NULL;
	size_t len = 0;
	int st = hb_input_read(path, HB_INPUT_PRESET_MAX, &buf, &len, msg, n);

	if (st != HB_OK)
		return st;
	if (strlen(buf) != len) {
		free(buf);
		return hb_status_set(msg, n, HB_EINVAL, "%s: not a text file (contains NUL bytes); "
		    "expected a preset: text lines [section] and key = value", path);
	}
	*out = buf;
	return HB_OK;
}

int
hb_preset_load(const char *path, struct hb_scene *sc, char *msg, size_t n)
{
	char *text = NULL;
	int st = read_file(path, &text, msg, n);

	if (st != HB_OK)
		return st;
	st = hb_preset_load_string(text, path, sc, msg, n);
	free(text);
	return st;
}

/* "KEY=VALUE" applied to sc; the key is trimmed of blanks. */
static int
apply_set(struct hb_scene *sc, const char *arg, char *msg, size_t n)
{
	struct hb_scene_error err;
	char key[128], m[512];
	const char *eq = strchr(arg, '='), *k0 = arg, *k1;

	if (eq == NULL)
		return hb_status_set(msg, n, HB_EINVAL, "--set '%s': expected KEY=VALUE, e.g. "
		    "--set law.c=0.4 or --set initial.x0='40 um'", arg);
	k1 = eq;
	while (k0 < k1 && isspace((unsigned char)*k0))
		k0++;
	while (k1 > k0 && isspace((unsigned char)k1[-1]))
		k1--;
	if (k1 == k0 || (size_t)(k1 - k0) >= sizeof key)
		return hb_status_set(msg, n, HB_EINVAL, "--set '%s': expected KEY=VALUE with a key "
		    "such as law.c, body1.R, initial.x0, run.rtol, scene.law", arg);
	memcpy(key, k0, (size_t)(k1 - k0));
	key[k1 - k0] = '\0';
	if (hb_scene_set_text(sc, key, eq + 1, &err) != HB_OK) {
		/* a long argument is shown by its start, so that the reason stays in sight */
		int shown = strlen(arg) > 72 ? 60 : 72;
		return hb_status_set(msg, n, HB_EINVAL, "--set %.*s%s: %s", shown, arg,
		    strlen(arg) > 72 ? "..." : "", hb_scene_error_str(&err, m, sizeof m));
	}
	return HB_OK;
}

/*
 * Loads path (read once), applies sets, validates; the text read goes to
 * *text when asked.  With br, [branch N] sections are read into *br
 * (preset_branch.c) on top of the scene with its sets; else refused.
 */
static int
open_text(const char *path, const char *const *sets, int nsets, struct hb_scene *sc,
          char **text, struct hb_branch **br, size_t *nbr, char *msg, size_t n)
{
	char m[512], *buf = NULL;
	struct preset_entry *e = NULL;
	int ne = 0;
	int st = read_file(path, &buf, msg, n);

	if (st == HB_OK)
		st = preset_load_text(buf, path, sc, br != NULL ? &e : NULL, &ne, msg, n);
	for (int i = 0; st == HB_OK && i < nsets; i++)
		st = apply_set(sc, sets[i], msg, n);
	if (st == HB_OK && (st = hb_scene_validate(sc, m, sizeof m)) != HB_OK)
		hb_status_set(msg, n, st, "%s: %s", path, m);
	if (st == HB_OK && br != NULL)
		st = preset_branches_read(e, ne, path, sc, br, nbr, msg, n);
	preset_entries_free(e, ne);
	if (st == HB_OK && text != NULL)
		*text = buf;
	else
		free(buf);
	return st;
}

int
hb_preset_open(const char *path, const char *const *sets, int nsets, struct hb_scene *sc,
            char *msg, size_t n)
{
	return open_text(path, sets, nsets, sc, NULL, NULL, NULL, msg, n);
}

/*
 * Resolves preset NAME into path (pn bytes); on failure a status whose
 * message names the preset (the resolver's message names it too: a long
 * name is shown by its start here).
 */
static int
resolve_named(const char *name, char *path, size_t pn, char *msg, size_t n)
{
	char m[4096];
	int st;

	m[0] = '\0';
	if ((st = hb_preset_resolve(name, path, pn, m, sizeof m)) != HB_OK)
		return hb_status_set(msg, n, st, "preset '%.*s%s': %s", strlen(name) > 72 ? 60 : 72,
		    name, strlen(name) > 72 ? "..." : "", m[0] ? m : "not found");
	return HB_OK;
}

int
hb_preset_open_named(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                     char *path, size_t pn, char *msg, size_t n)
{
	return hb_preset_open_text(name, sets, nsets, sc, path, pn, NULL, msg, n);
}

int
hb_preset_open_text(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                    char *path, size_t pn, char **text, char *msg, size_t n)
{
	int st = resolve_named(name, path, pn, msg, n);

	return st != HB_OK ? st : open_text(path, sets, nsets, sc, text, NULL, NULL, msg, n);
}

int
hb_preset_open_branched(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                        struct hb_branch **br, size_t *nbr, char *path, size_t pn, char *msg,
                        size_t n)
{
	int st;

	*br = NULL;
	*nbr = 0;
	st = resolve_named(name, path, pn, msg, n);
	return st != HB_OK ? st : open_text(path, sets, nsets, sc, NULL, br, nbr, msg, n);
}
