/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_set.c - reading one value of a scene by its key (see scene.h):
 * text with an optional unit, or a number, checked against the key's row
 * of the table (scene_keys.c) or the law's parameter table.  On error the
 * scene is unchanged and the error names the key and what is accepted.
 *
 * Bodies: typing E or nu gives the body a material; typing mass makes the
 * mass given (and forgets rho); typing rho makes the mass derived again.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "scene_override.h"
#include "cnum.h"

/* Trims leading and trailing blanks of text into buf. */
static int
trim_copy(const char *text, char *buf, size_t n)
{
	size_t len;

	while (isspace((unsigned char)*text))
		text++;
	len = strlen(text);
	while (len > 0 && isspace((unsigned char)text[len - 1]))
		len--;
	if (len >= n)
		return -1;
	memcpy(buf, text, len);
	buf[len] = '\0';
	return 0;
}

/* "a number with a unit of U (SI prefixes allowed), or a plain number in U" */
static void
unit_accepted(struct hb_unit_dim dim, char *buf, size_t n)
{
	char u[48];

	hb_units_dim_str(dim, u, sizeof u);
	if (u[0] == '\0')
		snprintf(buf, n, "a plain number");
	else
		snprintf(buf, n, "a number with a unit of %s (SI prefixes allowed), or a plain "
		    "number in %s", u, u);
}

/* The body flags that typing a value of kd sets. */
/*
 * What a table key accepts, as text: numbers with their unit, whole
 * numbers, or the list of choices.
 */
static void
keydef_accepted(const struct scene_keydef *kd, char *acc, size_t n)
{
	const char *ch[16];
	int nc;
	size_t l = 0;

	switch (kd->store) {
	case ST_STRING:
		snprintf(acc, n, "printable text");
		return;
	case ST_DOUBLE:
		unit_accepted(*kd->dim, acc, n);
		return;
	case ST_LONG:
	case ST_INT:
		snprintf(acc, n, "a whole number");
		return;
	default:
		break;
	}
	acc[0] = '\0';
	nc = scene_keydef_choices(kd, ch, 16);
	for (int i = 0; i < nc && i < 16 && l < n; i++) {
		if (kd->store == ST_REDUCE && i >= 2)
			break;
		snprintf(acc + l, n - l, "%s%s", i ? ", " : "", ch[i]);
		l = strlen(acc);
	}
	if (kd->store == ST_REDUCE && l < n)
		snprintf(acc + l, n - l, ", or a comma list of flight, contact, com");
	if (kd->store == ST_BOOL && l < n)
		snprintf(acc + l, n - l, ", 1, 0");
}

static void
body_typed(struct hb_scene *sc, const struct scene_keydef *kd)
{
	int b = scene_keydef_body(kd);

	if (b < 0)
		return;
	if (kd->special == SP_MATERIAL)
		sc->body[b].has_material = 1;
	else if (kd->special == SP_RHO)
		sc->body[b].mass_given = 0;
	else if (kd->special == SP_MASS) {
		sc->body[b].mass_given = 1;
		sc->body[b].rho = 0;
	}
}

/*
 * Stores number v (SI) into key of tmp after checking its range; text is
 * the value as typed, for the message (NULL: print v).
 */
static int
store_number(struct hb_scene *tmp, const char *key, double v, const char *text,
             struct hb_scene_error *err)
{
	const struct scene_keydef *kd = NULL;
	struct hb_unit_range r;
	char vs[64];

	if (strncmp(key, "law.", 4) == 0) {
		int i = hb_law_param_index(tmp->law, key + 4);

		r = hb_law_param_range(&tmp->law->params[i]);
		if (hb_units_in_range(v, &r)) {
			tmp->par[i] = v;
			return HB_OK;
		}
	} else {
		kd = scene_keydef_find(key);
		if (hb_units_in_range(v, &kd->range)) {
			switch (kd->store) {
			case ST_DOUBLE: *(double *)((char *)tmp + kd->off) = v; break;
			case ST_LONG: *(long *)((char *)tmp + kd->off) = (long)v; break;
			case ST_INT: *(int *)((char *)tmp + kd->off) = (int)v; break;
			default: break;
			}
			body_typed(tmp, kd);
			return HB_OK;
		}
		r = kd->range;
	}
	/* refused: the message shows the value as typed (no text: %.17g of v),
	 * formatted here only, not on every accepted value */
	if (text == NULL)
		cnum_snprintf(vs, sizeof vs, "%.17g", v);
	else
		snprintf(vs, sizeof vs, "%s", text);
	return scene_error_range(err, key, &r, kd != NULL ? kd->dim : NULL,
	                         "value %s is out of range", vs);
}

/*
 * The key's row or law parameter: checks that key names a value that can
 * be typed in tmp; *kd is NULL for a law parameter (index *li).
 */
static int
key_lookup(const struct hb_scene *tmp, const char *key, const struct scene_keydef **kd, int *li,
           struct hb_scene_error *err)
{
	int st, ro;

	*kd = NULL;
	*li = -1;
	if (key == NULL)
		return scene_error_set(err, "", NULL, "no key");
	if (strncmp(key, "derived.", 8) == 0)
		return scene_error_set(err, key, "the keys of the sections scene, body1, body2, law, loads, "
		    "initial and run (PRESETS in hybounce(1); hybounce --list-laws)",
		    "derived values are computed, never typed");
	if ((st = scene_key_resolve(tmp, key, kd, li, &ro, err)) != HB_OK)
		return st;
	if (ro)
		return scene_error_set(err, key, "no value",
		    "%s is derived from the materials by Hertz contact theory; give masses instead of "
		    "materials to type it", key);
	return HB_OK;
}

int
hb_scene_set_text(struct hb_scene *sc, const char *key, const char *text, struct hb_scene_error *err)
{
	struct hb_scene tmp = *sc;
	const struct scene_keydef *kd;
	char t[512], m[256], acc[192];
	double v;
	int st, li;

	if (scene_override_is_key(key)) /* body.I.*, interface.K.*, initial.body.I.* */
		return scene_override_set(sc, key, text, NULL, err);
	hb_scene_derive(&tmp, NULL, 0);
	if ((st = key_lookup(&tmp, key, &kd, &li, err)) != HB_OK)
		return st;
	if (text == NULL)
		return scene_error_set(err, key, NULL, "no value");
	if (trim_copy(text, t, sizeof t) != 0)
		return scene_error_set(err, key, "at most 511 characters", "value too long");
	if (kd == NULL) { /* a law parameter */
		struct hb_unit_dim dim = scene_lawpar_dim(&tmp, li);
		if (hb_units_parse(t, dim, &v, m, sizeof m) != HB_OK) {
			unit_accepted(dim, acc, sizeof acc);
			return scene_error_set(err, key, acc, "%s", m);
		}
		if ((st = store_number(&tmp, key, v, t, err)) != HB_OK)
			return st;
		hb_scene_derive(&tmp, NULL, 0);
		*sc = tmp;
		return HB_OK;
	}
	if (t[0] == '\0' && kd->store != ST_STRING) {
		keydef_accepted(kd, acc, sizeof acc);
		return scene_error_set(err, key, acc, "empty value");
	}

	char *base = (char *)&tmp;
	switch (kd->store) {
	case ST_STRING:
		for (const char *c = t; *c; c++)
			if ((unsigned char)*c < 0x20 || *c == 0x7f)
				return scene_error_set(err, key, "printable text",
				    "control characters are not accepted");
		for (const char *c = t + 1; *c; c++)
			if ((*c == ';' || *c == '#') && isspace((unsigned char)c[-1]))
				return scene_error_set(err, key,
				    "text without a space before ';' or '#'",
				    "' %c' would start a comment in a preset", *c);
		if (strlen(t) >= kd->size) {
			snprintf(acc, sizeof acc, "at most %zu bytes", kd->size - 1);
			return scene_error_set(err, key, acc, "too long");
		}
		memcpy(base + kd->off, t, strlen(t) + 1);
		break;
	case ST_DOUBLE:
		if (hb_units_parse(t, *kd->dim, &v, m, sizeof m) != HB_OK) {
			unit_accepted(*kd->dim, acc, sizeof acc);
			return scene_error_set(err, key, acc, "%s", m);
		}
		if ((st = store_number(&tmp, key, v, t, err)) != HB_OK)
			return st;
		break;
	case ST_LONG:
	case ST_INT:
		if (hb_units_parse(t, hb_unit_none, &v, m, sizeof m) != HB_OK)
			return scene_error_set(err, key, "a whole number", "%s", m);
		if (v != floor(v))
			return scene_error_set(err, key, "a whole number", "'%s' is not a whole number",
			    t);
		if ((st = store_number(&tmp, key, v, t, err)) != HB_OK)
			return st;
		break;
	default: {
		int c;
		if (scene_keydef_read_choice(kd, t, &c) != 0) {
			keydef_accepted(kd, acc, sizeof acc);
			return scene_error_set(err, key, acc, "'%s' is not accepted", t);
		}
		if (kd->store == ST_LAW) {
			const struct hb_law_type *law = hb_law_list()[c];
			if (law != tmp.law) {
				tmp.law = law;
				memset(tmp.par, 0, sizeof tmp.par);
				hb_law_defaults(law, tmp.par);
			}
		} else
			*(int *)(base + kd->off) = c;
		break;
	}
	}
	hb_scene_derive(&tmp, NULL, 0);
	*sc = tmp;
	return HB_OK;
}

int
hb_scene_set_number(struct hb_scene *sc, const char *key, double v, struct hb_scene_error *err)
{
	struct hb_scene tmp = *sc;
	const struct scene_keydef *kd;
	int st, li;

	if (scene_override_is_key(key))
		return scene_override_set(sc, key, NULL, &v, err);
	hb_scene_derive(&tmp, NULL, 0);
	if ((st = key_lookup(&tmp, key, &kd, &li, err)) != HB_OK)
		return st;
	if (kd != NULL && kd->store != ST_DOUBLE && kd->store != ST_LONG && kd->store != ST_INT)
		return scene_error_set(err, key, NULL, "not a number key");
	if ((st = store_number(&tmp, key, v, NULL, err)) != HB_OK)
		return st;
	hb_scene_derive(&tmp, NULL, 0);
	*sc = tmp;
	return HB_OK;
}

int
hb_scene_set(struct hb_scene *sc, const char *key, const char *text, char *msg, size_t n)
{
	struct hb_scene_error e;
	int st = hb_scene_set_text(sc, key, text, &e);

	if (st != HB_OK && msg != NULL && n > 0)
		hb_scene_error_str(&e, msg, n);
	return st;
}
