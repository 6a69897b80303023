/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_keyinfo.c - the typed access to a scene's keys (hb_scene_get,
 * scene_keys.h): a key resolved to its row of the table or to a law
 * parameter, its value as a number or a choice, and its typed row (kind,
 * unit, range, the value shown and the value to edit, the choices, help).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/law.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "scene_override.h"
#include "cnum.h"

/* Fills the typed part and the display strings of a table key. */
static void
info_keydef(const struct hb_scene *sc, const struct scene_keydef *kd, struct hb_scene_keyinfo *o)
{
	const char *base = (const char *)sc;

	snprintf(o->key, sizeof o->key, "%s", kd->key);
	snprintf(o->section, sizeof o->section, "%s", kd->panel);
	snprintf(o->label, sizeof o->label, "%s", kd->label);
	snprintf(o->help, sizeof o->help, "%s", kd->help);
	o->number = NAN;
	switch (kd->store) {
	case ST_STRING:
		o->kind = HB_SCENE_KEY_TEXT;
		snprintf(o->value, sizeof o->value, "%s", base + kd->off);
		snprintf(o->edit, sizeof o->edit, "%s", base + kd->off);
		snprintf(o->range, sizeof o->range, "text");
		break;
	case ST_LONG:
	case ST_INT:
		o->kind = HB_SCENE_KEY_WHOLE;
		o->number = kd->store == ST_LONG ? (double)*(const long *)(base + kd->off)
		                                  : (double)*(const int *)(base + kd->off);
		o->limits = kd->range;
		cnum_snprintf(o->value, sizeof o->value, "%.0f", o->number);
		cnum_snprintf(o->edit, sizeof o->edit, "%.0f", o->number);
		hb_units_range_str(&kd->range, NULL, o->range, sizeof o->range);
		break;
	case ST_DOUBLE: {
		int b = scene_keydef_body(kd);
		o->kind = HB_SCENE_KEY_NUMBER;
		o->dim = *kd->dim;
		hb_units_dim_str(o->dim, o->unit, sizeof o->unit);
		o->limits = kd->range;
		hb_units_range_str(&kd->range, kd->dim, o->range, sizeof o->range);
		o->number = *(const double *)(base + kd->off);
		if (b >= 0 && !scene_keydef_present(sc, kd) && kd->special != SP_MASS)
			o->number = NAN; /* no material, or no density */
		if (isnan(o->number))
			snprintf(o->value, sizeof o->value, "-");
		else {
			hb_units_format(o->number, o->dim, 4, o->value, sizeof o->value);
			hb_units_format_exact(o->number, o->dim, o->edit, sizeof o->edit);
		}
		if (b >= 0 && kd->special == SP_MASS && !sc->body[b].mass_given)
			snprintf(o->help, sizeof o->help, "derived from rho and R (type a mass to give it)");
		break;
	}
	default: {
		const char *cur = scene_keydef_choice(sc, kd);
		size_t l = 0;
		o->kind = HB_SCENE_KEY_CHOICE;
		o->nchoices = scene_keydef_choices(kd, o->choices, 16);
		if (o->nchoices > 16)
			o->nchoices = 16;
		o->choice = -1;
		o->range[0] = '\0';
		for (int i = 0; i < o->nchoices; i++) {
			if (strcmp(o->choices[i], cur) == 0)
				o->choice = i;
			if (kd->store != ST_REDUCE || i < 2) {
				snprintf(o->range + l, sizeof o->range - l, "%s%s", i ? ", " : "",
				    o->choices[i]);
				l = strlen(o->range);
			}
		}
		if (kd->store == ST_REDUCE)
			snprintf(o->range + l, sizeof o->range - l, ", flight,contact,com");
		snprintf(o->value, sizeof o->value, "%s", cur);
		snprintf(o->edit, sizeof o->edit, "%s", cur);
		break;
	}
	}
}

/* Law parameter i is derived by the scene (k from the materials), not typed. */
static int
lawpar_readonly(const struct hb_scene *sc, int i)
{
	return (sc->law->params[i].flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived;
}

/* Fills the row of law parameter i. */
static void
info_lawpar(const struct hb_scene *sc, int i, struct hb_scene_keyinfo *o)
{
	const struct hb_law_param *pp = &sc->law->params[i];

	snprintf(o->key, sizeof o->key, "law.%s", pp->name);
	snprintf(o->section, sizeof o->section, "law");
	snprintf(o->label, sizeof o->label, "%s", pp->name);
	snprintf(o->help, sizeof o->help, "%s", pp->help ? pp->help : "");
	o->kind = HB_SCENE_KEY_NUMBER;
	o->number = sc->par[i];
	o->dim = scene_lawpar_dim(sc, i);
	hb_units_dim_str(o->dim, o->unit, sizeof o->unit);
	o->limits = hb_law_param_range(pp);
	hb_units_format(o->number, o->dim, 4, o->value, sizeof o->value);
	hb_units_format_exact(o->number, o->dim, o->edit, sizeof o->edit);
	hb_units_range_str(&o->limits, NULL, o->range, sizeof o->range);
	o->readonly = lawpar_readonly(sc, i);
}

int
scene_key_info_law(const struct hb_scene *sc, int i, struct hb_scene_keyinfo *out)
{
	memset(out, 0, sizeof *out);
	if (sc->law == NULL || i < 0 || i >= sc->law->n_params)
		return HB_EINVAL;
	info_lawpar(sc, i, out);
	return HB_OK;
}

int
hb_scene_law_param_info(const struct hb_law_type *law, int i, struct hb_scene_keyinfo *out)
{
	struct hb_scene sc;

	memset(out, 0, sizeof *out);
	if (law == NULL || i < 0 || i >= law->n_params)
		return HB_EINVAL;
	memset(&sc, 0, sizeof sc);
	sc.law = law;
	hb_law_defaults(law, sc.par);
	info_lawpar(&sc, i, out);
	return HB_OK;
}

int
scene_key_info(const struct hb_scene *sc, const struct scene_keydef *kd, struct hb_scene_keyinfo *out)
{
	memset(out, 0, sizeof *out);
	info_keydef(sc, kd, out);
	return HB_OK;
}

int
scene_key_resolve(const struct hb_scene *sc, const char *key, const struct scene_keydef **kd,
                  int *li, int *readonly, struct hb_scene_error *err)
{
	*kd = NULL;
	*li = -1;
	*readonly = 0;
	if (key == NULL)
		return scene_error_set(err, "", NULL, "no key");
	if (strncmp(key, "law.", 4) == 0) {
		int i = sc->law != NULL ? hb_law_param_index(sc->law, key + 4) : -1;
		if (i < 0 || strcmp(sc->law->params[i].name, key + 4) != 0) {
			char names[160] = "";
			for (int k = 0; sc->law != NULL && k < sc->law->n_params; k++) {
				size_t l = strlen(names);
				snprintf(names + l, sizeof names - l, "%slaw.%s", k ? ", " : "",
				    sc->law->params[k].name);
			}
			return scene_error_set(err, key, names, "unknown key for law %s",
			    sc->law != NULL ? sc->law->name : "(none)");
		}
		*li = i;
		*readonly = lawpar_readonly(sc, i);
		return HB_OK;
	}
	*kd = scene_keydef_find(key);
	if (*kd == NULL)
		return scene_error_set(err, key, NULL, "unknown key");
	return HB_OK;
}

int
scene_key_value(const struct hb_scene *sc, const char *key, double *num, const char **word)
{
	const struct scene_keydef *kd;
	const char *base = (const char *)sc;
	int li, ro;

	if (scene_override_is_key(key))
		return scene_override_value(sc, key, num, word);
	if (scene_key_resolve(sc, key, &kd, &li, &ro, NULL) != HB_OK || ro)
		return -1;
	if (kd == NULL) {
		*num = sc->par[li];
		return HB_SCENE_KEY_NUMBER;
	}
	switch (kd->store) {
	case ST_STRING:
		return -1;
	case ST_LONG:
	case ST_INT:
		*num = kd->store == ST_LONG ? (double)*(const long *)(base + kd->off)
		                            : (double)*(const int *)(base + kd->off);
		return HB_SCENE_KEY_WHOLE;
	case ST_DOUBLE:
		*num = *(const double *)(base + kd->off);
		/* as info_keydef: no material, or no density */
		if (scene_keydef_body(kd) >= 0 && !scene_keydef_present(sc, kd) &&
		    kd->special != SP_MASS)
			*num = NAN;
		return HB_SCENE_KEY_NUMBER;
	default: {
		const char *cur = scene_keydef_choice(sc, kd), *ch[16];
		int nc = scene_keydef_choices(kd, ch, 16);

		for (int i = 0; i < nc && i < 16; i++)
			if (strcmp(ch[i], cur) == 0) {
				*word = ch[i];
				return HB_SCENE_KEY_CHOICE;
			}
		return -1;
	}
	}
}

int
hb_scene_get(const struct hb_scene *sc, const char *key, struct hb_scene_keyinfo *out,
          struct hb_scene_error *err)
{
	const struct scene_keydef *kd;
	int li, ro, st;

	memset(out, 0, sizeof *out);
	if (scene_override_is_key(key))
		return scene_override_get(sc, key, out, err);
	if ((st = scene_key_resolve(sc, key, &kd, &li, &ro, err)) != HB_OK)
		return st;
	if (kd == NULL)
		info_lawpar(sc, li, out);
	else
		info_keydef(sc, kd, out);
	return HB_OK;
}
