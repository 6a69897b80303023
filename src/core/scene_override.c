/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_override.c - the keys of one body or one interface of a chain
 * (scene_override.h): parsing "body.I.NAME", "interface.K.NAME" and
 * "initial.body.I.NAME", storing them in the scene's table of overrides,
 * their typed values, their checks against the chain, and their preset
 * text.  What each resolves to for body i or interface k is
 * scene_chain.c's (the engine reads only that).
 */
#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_chain.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

#define INF HUGE_VAL

#define MAX_INDEX SCENE_OVERRIDE_MAX_INDEX

static const struct scene_override_field body_fields[] = {
	{ "E", &hb_unit_pressure, { 0, INF, 1, 1, 0 }, "Young's modulus of this body" },
	{ "nu", &hb_unit_none, { -1, 0.5, 1, 1, 0 }, "Poisson's ratio of this body" },
	{ "rho", &hb_unit_density, { 0, INF, 1, 1, 0 }, "density of this body; m = 4/3 pi R^3 rho" },
	{ "R", &hb_unit_length, { 0, INF, 1, 1, 0 }, "radius of this body (its mass follows unless given)" },
	{ "mass", &hb_unit_mass, { 0, INF, 1, 1, 0 }, "mass of this body, given (forgets rho)" },
	{ "F", &hb_unit_force, { -INF, INF, 1, 1, 0 },
	  "constant force on this body along n1, besides gravity" },
};
static const struct scene_override_field initial_fields[] = {
	{ "v", &hb_unit_velocity, { -1e5, 1e5, 0, 0, 0 }, "initial velocity of this body" },
	{ "gap", &hb_unit_length, { 0, 1e6, 0, 0, 0 },
	  "initial gap below this body (to the body below, or the floor); 0: touching" },
};
#define NBODY (int)(sizeof body_fields / sizeof body_fields[0])
#define NINIT (int)(sizeof initial_fields / sizeof initial_fields[0])

const struct scene_override_field *
scene_override_fields(int kind, int *n)
{
	*n = kind == HB_OVERRIDE_BODY ? NBODY : NINIT;
	return kind == HB_OVERRIDE_BODY ? body_fields : initial_fields;
}

const char *const scene_override_ext_words[2] = { "none", "adhesive" };

/* Parses KEY into kind, index and name; 0, or -1 if it is no override key. */
static int
parse(const char *key, int *kind, int *index, char *name, size_t n)
{
	const char *p;
	char *end;
	long i;

	if (key == NULL)
		return -1;
	if (strncmp(key, "initial.body.", 13) == 0) {
		*kind = HB_OVERRIDE_INITIAL;
		p = key + 13;
	} else if (strncmp(key, "body.", 5) == 0) {
		*kind = HB_OVERRIDE_BODY;
		p = key + 5;
	} else if (strncmp(key, "interface.", 10) == 0) {
		*kind = HB_OVERRIDE_IFACE;
		p = key + 10;
	} else
		return -1;
	if (!isdigit((unsigned char)*p))
		return -1;
	i = strtol(p, &end, 10);
	if (*end != '.' || end - p > 4 || i > MAX_INDEX)
		return -1;
	if (strlen(end + 1) >= n || end[1] == '\0')
		return -1;
	*index = (int)i;
	snprintf(name, n, "%s", end + 1);
	return 0;
}

int
scene_override_is_key(const char *key)
{
	int kind, index;
	char name[16];

	return parse(key, &kind, &index, name, sizeof name) == 0;
}

int
scene_override_is_section(const char *section)
{
	char key[64];

	snprintf(key, sizeof key, "%s.x", section);
	return strncmp(section, "initial", 7) != 0 && scene_override_is_key(key);
}

const struct scene_override_field *
scene_override_field(int kind, const char *name)
{
	const struct scene_override_field *f = kind == HB_OVERRIDE_BODY ? body_fields : initial_fields;
	int nf = kind == HB_OVERRIDE_BODY ? NBODY : NINIT;

	for (int i = 0; i < nf; i++)
		if (strcmp(f[i].name, name) == 0)
			return &f[i];
	return NULL;
}

int
scene_override_find(const struct hb_scene *sc, int kind, int index, const char *name)
{
	for (int i = 0; i < sc->over.n; i++)
		if (sc->over.o[i].kind == kind && sc->over.o[i].index == index &&
		    strcmp(sc->over.o[i].name, name) == 0)
			return i;
	return -1;
}

static void
ovr_remove(struct hb_scene *sc, int i)
{
	memmove(&sc->over.o[i], &sc->over.o[i + 1], (size_t)(sc->over.n - i - 1) * sizeof sc->over.o[0]);
	sc->over.n--;
	memset(&sc->over.o[sc->over.n], 0, sizeof sc->over.o[0]);
}

/* Interface k's law and parameters before any derivation (no chain needed). */
const struct hb_law_type *
scene_override_iface_law(const struct hb_scene *sc, int k, double *par)
{
	const struct hb_law_type *law = sc->law;
	int li = scene_override_find(sc, HB_OVERRIDE_IFACE, k, "law");

	if (par != NULL)
		memcpy(par, sc->par, sizeof sc->par);
	if (li >= 0) {
		const struct hb_law_type *const *list = hb_law_list();
		int v = (int)sc->over.o[li].value, nl = 0;
		while (list[nl] != NULL)
			nl++;
		if (v >= 0 && v < nl && list[v] != sc->law) {
			law = list[v];
			if (par != NULL) {
				memset(par, 0, sizeof sc->par);
				hb_law_defaults(law, par);
			}
		}
	}
	for (int i = 0; par != NULL && i < sc->over.n; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		int pi = o->kind == HB_OVERRIDE_IFACE && o->index == k ? hb_law_param_index(law, o->name)
		                                                         : -1;
		if (pi >= 0 && strcmp(law->params[pi].name, o->name) == 0)
			par[pi] = o->value;
	}
	return law;
}

/* The law parameter index of name in law (exact name), or -1. */
int
scene_override_param(const struct hb_law_type *law, const char *name)
{
	int i = law != NULL ? hb_law_param_index(law, name) : -1;

	return i >= 0 && strcmp(law->params[i].name, name) == 0 ? i : -1;
}

/* "k, c, p" of a law, or the names an interface accepts. */
void
scene_override_iface_accepted(const struct hb_law_type *law, char *buf, size_t n)
{
	size_t l;

	snprintf(buf, n, "law, extension");
	for (int i = 0; law != NULL && i < law->n_params; i++) {
		l = strlen(buf);
		snprintf(buf + l, n - l, ", %s", law->params[i].name);
	}
}

static void
fields_accepted(int kind, char *buf, size_t n)
{
	const struct scene_override_field *f = kind == HB_OVERRIDE_BODY ? body_fields : initial_fields;
	int nf = kind == HB_OVERRIDE_BODY ? NBODY : NINIT;
	size_t l;

	buf[0] = '\0';
	for (int i = 0; i < nf; i++) {
		l = strlen(buf);
		snprintf(buf + l, n - l, "%s%s.%s", i ? ", " : "",
		    kind == HB_OVERRIDE_BODY ? "body.I" : "initial.body.I", f[i].name);
	}
}

/* Stores value for (kind, index, name); a new entry needs room. */
static int
store(struct hb_scene *sc, const char *key, int kind, int index, const char *name, double value,
      struct hb_scene_error *err)
{
	int i = scene_override_find(sc, kind, index, name);

	if (i < 0) {
		char acc[160];
		if (sc->over.n >= HB_SCENE_MAX_OVERRIDES) {
			snprintf(acc, sizeof acc, "at most %d keys of single bodies and interfaces; give "
			    "the values most of them share in [body1], [law] and [chain]",
			    HB_SCENE_MAX_OVERRIDES);
			return scene_error_set(err, key, acc, "too many overrides: the scene holds %d",
			    sc->over.n);
		}
		i = sc->over.n++;
		memset(&sc->over.o[i], 0, sizeof sc->over.o[i]);
		sc->over.o[i].kind = kind;
		sc->over.o[i].index = index;
		snprintf(sc->over.o[i].name, sizeof sc->over.o[i].name, "%s", name);
	}
	sc->over.o[i].value = value;
	return HB_OK;
}

/* Reads text or *num for a number of dimension dim and range r. */
static int
read_number(const char *key, const char *text, const double *num, struct hb_unit_dim dim,
            const struct hb_unit_range *r, const struct hb_unit_dim *rdim, double *v,
            struct hb_scene_error *err)
{
	char m[256], vs[64], u[48];

	if (num != NULL) {
		*v = *num;
		cnum_snprintf(vs, sizeof vs, "%.17g", *v);
	} else {
		if (text == NULL)
			return scene_error_set(err, key, NULL, "no value");
		while (isspace((unsigned char)*text))
			text++;
		if (hb_units_parse(text, dim, v, m, sizeof m) != HB_OK) {
			char acc[192];
			hb_units_dim_str(dim, u, sizeof u);
			if (u[0] == '\0')
				snprintf(acc, sizeof acc, "a plain number");
			else
				snprintf(acc, sizeof acc, "a number with a unit of %s (SI prefixes "
				    "allowed), or a plain number in %s", u, u);
			return scene_error_set(err, key, acc, "%s", m);
		}
		snprintf(vs, sizeof vs, "%.60s", text);
		for (size_t l = strlen(vs); l > 0 && isspace((unsigned char)vs[l - 1]); l--)
			vs[l - 1] = '\0';
	}
	if (!hb_units_in_range(*v, r))
		return scene_error_range(err, key, r, rdim, "value %s is out of range", vs);
	return HB_OK;
}

/* Reads a choice word of text (leading and trailing blanks ignored) into w. */
static void
word_of(const char *text, char *w, size_t n)
{
	size_t l;

	while (isspace((unsigned char)*text))
		text++;
	snprintf(w, n, "%s", text);
	l = strlen(w);
	while (l > 0 && isspace((unsigned char)w[l - 1]))
		w[--l] = '\0';
}

/* Interface k's stiffness is derived: typing it is refused. */
int
scene_override_derived_error(struct hb_scene_error *err, const char *key, int k)
{
	char pair[48];

	if (k == 0)
		snprintf(pair, sizeof pair, "the floor (body2) and body 1");
	else
		snprintf(pair, sizeof pair, "bodies %d and %d", k, k + 1);
	return scene_error_set(err, key, "no value (give masses instead of materials to type it)",
	    "derived from the materials of %s by Hertz contact theory", pair);
}

int
scene_override_set(struct hb_scene *sc, const char *key, const char *text, const double *num,
                   struct hb_scene_error *err)
{
	struct hb_scene tmp;
	int kind, index, st;
	char name[16], acc[192];
	double v;

	if (parse(key, &kind, &index, name, sizeof name) != 0)
		return scene_error_set(err, key, NULL, "unknown key");
	if (sc->chain.n > 0 && (st = scene_override_index_check(sc, key, kind, index, err)) != HB_OK)
		return st; /* (a preset's chain.n comes after its [body.I]: checked as a whole then) */
	if (kind != HB_OVERRIDE_IFACE) {
		const struct scene_override_field *f = scene_override_field(kind, name);
		if (f == NULL) {
			fields_accepted(kind, acc, sizeof acc);
			return scene_error_set(err, key, acc, "unknown key");
		}
		if (index < 1) {
			snprintf(acc, sizeof acc, "%s.1 .. %s.%d", kind == HB_OVERRIDE_BODY ? "body" :
			    "initial.body", kind == HB_OVERRIDE_BODY ? "body" : "initial.body", MAX_INDEX);
			return scene_error_set(err, key, acc, "bodies are numbered from 1 (the lowest)");
		}
		if ((st = read_number(key, text, num, *f->dim, &f->range, f->dim, &v, err)) != HB_OK)
			return st;
		tmp = *sc;
		if (kind == HB_OVERRIDE_BODY && strcmp(name, "mass") == 0) {
			int r = scene_override_find(&tmp, kind, index, "rho");
			if (r >= 0)
				ovr_remove(&tmp, r);
		} else if (kind == HB_OVERRIDE_BODY && strcmp(name, "rho") == 0) {
			int r = scene_override_find(&tmp, kind, index, "mass");
			if (r >= 0)
				ovr_remove(&tmp, r);
		}
		if ((st = store(&tmp, key, kind, index, name, v, err)) != HB_OK)
			return st;
		*sc = tmp;
		return HB_OK;
	}

	/* an interface: its law, its extension, or a parameter of its law */
	if (strcmp(name, "law") == 0 || strcmp(name, "extension") == 0) {
		char w[64];
		int c = -1;
		if (num != NULL)
			return scene_error_set(err, key, NULL, "not a number key");
		if (text == NULL)
			return scene_error_set(err, key, NULL, "no value");
		word_of(text, w, sizeof w);
		if (name[0] == 'l') {
			const struct hb_law_type *const *l = hb_law_list();
			size_t al = 0;
			acc[0] = '\0';
			for (int i = 0; l[i] != NULL; i++) {
				if (cnum_casecmp(l[i]->name, w) == 0)
					c = i;
				snprintf(acc + al, sizeof acc - al, "%s%s", i ? ", " : "", l[i]->name);
				al = strlen(acc);
			}
		} else {
			snprintf(acc, sizeof acc, "adhesive, none");
			if (cnum_casecmp(w, "adhesive") == 0)
				c = 1;
			else if (cnum_casecmp(w, "none") == 0 || cnum_casecmp(w, "clamped") == 0)
				c = 0;
		}
		if (c < 0)
			return scene_error_set(err, key, acc, "'%s' is not accepted", w);
		tmp = *sc;
		if (name[0] == 'l' && scene_override_iface_law(&tmp, index, NULL) != hb_law_list()[c]) {
			/* a new law starts from its defaults (or the scene's values of it) */
			for (int i = tmp.over.n - 1; i >= 0; i--) {
				const struct hb_scene_override *o = &tmp.over.o[i];
				if (o->kind == HB_OVERRIDE_IFACE && o->index == index &&
				    strcmp(o->name, "law") != 0 && strcmp(o->name, "extension") != 0)
					ovr_remove(&tmp, i);
			}
		}
		if ((st = store(&tmp, key, kind, index, name, c, err)) != HB_OK)
			return st;
		*sc = tmp;
		return HB_OK;
	}
	{
		double par[HB_LAW_MAX_PARAMS];
		const struct hb_law_type *law = scene_override_iface_law(sc, index, par);
		int pi = scene_override_param(law, name);
		struct hb_unit_range r;
		struct hb_unit_dim dim;

		if (pi < 0) {
			scene_override_iface_accepted(law, acc, sizeof acc);
			return scene_error_set(err, key, acc, "unknown key for interface %d (law %s)",
			    index, law != NULL ? law->name : "(none)");
		}
		if ((law->params[pi].flags & HB_LAW_PARAM_STIFFNESS) && sc->chain.n > 0) {
			struct scene_chain_iface ci;
			int dv = 0, fl;
			if (scene_chain_iface_full(sc, index, &ci, &dv, &fl) == HB_OK && dv)
				return scene_override_derived_error(err, key, index);
		}
		r = hb_law_param_range(&law->params[pi]);
		dim = hb_units_resolve(law->params[pi].dim, hb_law_exponent_p(law, par),
		    hb_law_exponent_n(law, par));
		if ((st = read_number(key, text, num, dim, &r, NULL, &v, err)) != HB_OK)
			return st;
		tmp = *sc;
		if ((st = store(&tmp, key, kind, index, name, v, err)) != HB_OK)
			return st;
		*sc = tmp;
		return HB_OK;
	}
}

/* The index range of the chain's bodies or interfaces, for messages; 0 if index is in it. */
int
scene_override_index_check(const struct hb_scene *sc, const char *key, int kind, int index,
            struct hb_scene_error *err)
{
	char acc[96];
	int n = sc->chain.n, k0 = !sc->chain.floor;

	if (n <= 0)
		return scene_error_set(err, key, "chain.n of 1 or more (a [chain] scene)",
		    "only a chain has numbered bodies and interfaces");
	if (kind == HB_OVERRIDE_IFACE) {
		if (index >= k0 && index < n)
			return HB_OK;
		snprintf(acc, sizeof acc, "interface.%d .. interface.%d%s", k0, n - 1,
		    k0 ? " (interface.0 with chain.floor = yes)" : "");
		return scene_error_set(err, key, acc, "the chain of %d bod%s has no interface %d", n,
		    n == 1 ? "y" : "ies", index);
	}
	if (index >= 1 && index <= n)
		return HB_OK;
	snprintf(acc, sizeof acc, "body.1 .. body.%d", n);
	return scene_error_set(err, key, acc, "the chain has %d bod%s", n, n == 1 ? "y" : "ies");
}

int
scene_override_get(const struct hb_scene *sc, const char *key, struct hb_scene_keyinfo *o,
                   struct hb_scene_error *err)
{
	int kind, index, st;
	char name[16], acc[192];

	memset(o, 0, sizeof *o);
	if (parse(key, &kind, &index, name, sizeof name) != 0)
		return scene_error_set(err, key, NULL, "unknown key");
	if ((st = scene_override_index_check(sc, key, kind, index, err)) != HB_OK)
		return st;
	snprintf(o->key, sizeof o->key, "%s", key);
	snprintf(o->section, sizeof o->section, "chain");
	if (kind != HB_OVERRIDE_IFACE) {
		const struct scene_override_field *f = scene_override_field(kind, name);
		struct scene_chain_bodyx b;
		if (f == NULL) {
			fields_accepted(kind, acc, sizeof acc);
			return scene_error_set(err, key, acc, "unknown key");
		}
		scene_chain_body_full(sc, index - 1, &b);
		o->kind = HB_SCENE_KEY_NUMBER;
		o->dim = *f->dim;
		o->limits = f->range;
		hb_units_dim_str(o->dim, o->unit, sizeof o->unit);
		hb_units_range_str(&f->range, f->dim, o->range, sizeof o->range);
		snprintf(o->label, sizeof o->label, "%s (body %d)", name, index);
		snprintf(o->help, sizeof o->help, "%s%s", f->help,
		    scene_override_find(sc, kind, index, name) < 0 ? " (the chain's: type one to override)" : "");
		switch (name[0]) { /* E, nu, rho, R, mass, F; v, gap */
		case 'E': o->number = b.has_material ? b.E : NAN; break;
		case 'n': o->number = b.has_material ? b.nu : NAN; break;
		case 'r': o->number = b.rho > 0 ? b.rho : NAN; break;
		case 'R': o->number = b.R; break;
		case 'm': o->number = b.mass; break;
		case 'F': o->number = b.F; break;
		case 'v': o->number = b.v0; break;
		case 'g': o->number = b.gap; break;
		default: o->number = NAN; break;
		}
	} else if (strcmp(name, "law") == 0 || strcmp(name, "extension") == 0) {
		struct scene_chain_iface ci;
		const char *cur;
		int dv, fl;
		scene_chain_iface_full(sc, index, &ci, &dv, &fl);
		o->kind = HB_SCENE_KEY_CHOICE;
		snprintf(o->label, sizeof o->label, "%s (interface %d)", name, index);
		if (name[0] == 'l') {
			const struct hb_law_type *const *l = hb_law_list();
			cur = ci.law->name;
			for (int i = 0; l[i] != NULL && i < 16; i++)
				o->choices[o->nchoices++] = l[i]->name;
			snprintf(o->help, sizeof o->help, "contact law of interface %d; changing it "
			    "starts from that law's values", index);
		} else {
			cur = scene_override_ext_words[ci.ext != 0];
			o->choices[o->nchoices++] = scene_override_ext_words[1];
			o->choices[o->nchoices++] = scene_override_ext_words[0];
			snprintf(o->help, sizeof o->help, "rule R1 of interface %d: adhesive or none", index);
		}
		o->choice = -1;
		for (int i = 0; i < o->nchoices; i++) {
			size_t l = strlen(o->range);
			if (strcmp(o->choices[i], cur) == 0)
				o->choice = i;
			snprintf(o->range + l, sizeof o->range - l, "%s%s", i ? ", " : "", o->choices[i]);
		}
		snprintf(o->value, sizeof o->value, "%s", cur);
		snprintf(o->edit, sizeof o->edit, "%s", cur);
		return HB_OK;
	} else {
		struct scene_chain_iface ci;
		int dv, fl, pi;
		scene_chain_iface_full(sc, index, &ci, &dv, &fl);
		pi = scene_override_param(ci.law, name);
		if (pi < 0) {
			scene_override_iface_accepted(ci.law, acc, sizeof acc);
			return scene_error_set(err, key, acc, "unknown key for interface %d (law %s)",
			    index, ci.law->name);
		}
		o->kind = HB_SCENE_KEY_NUMBER;
		o->dim = hb_units_resolve(ci.law->params[pi].dim, hb_law_exponent_p(ci.law, ci.par),
		    hb_law_exponent_n(ci.law, ci.par));
		hb_units_dim_str(o->dim, o->unit, sizeof o->unit);
		o->limits = hb_law_param_range(&ci.law->params[pi]);
		hb_units_range_str(&o->limits, NULL, o->range, sizeof o->range);
		o->number = ci.par[pi];
		o->readonly = dv && (ci.law->params[pi].flags & HB_LAW_PARAM_STIFFNESS);
		snprintf(o->label, sizeof o->label, "%s (interface %d)", name, index);
		snprintf(o->help, sizeof o->help, "%s", o->readonly
		    ? "derived from the materials of its two bodies by Hertz contact theory"
		    : ci.law->params[pi].help ? ci.law->params[pi].help : "");
	}
	if (isnan(o->number))
		snprintf(o->value, sizeof o->value, "-");
	else {
		hb_units_format(o->number, o->dim, 4, o->value, sizeof o->value);
		hb_units_format_exact(o->number, o->dim, o->edit, sizeof o->edit);
	}
	return HB_OK;
}

int
scene_override_value(const struct hb_scene *sc, const char *key, double *num, const char **word)
{
	struct hb_scene_keyinfo ki;

	if (scene_override_get(sc, key, &ki, NULL) != HB_OK || ki.readonly)
		return -1;
	if (ki.kind == HB_SCENE_KEY_CHOICE) {
		if (ki.choice < 0)
			return -1;
		*word = ki.choices[ki.choice];
		return HB_SCENE_KEY_CHOICE;
	}
	*num = ki.number;
	return HB_SCENE_KEY_NUMBER;
}

void
scene_override_key(const struct hb_scene *sc, int i, char *buf, size_t n)
{
	const struct hb_scene_override *o = &sc->over.o[i];

	snprintf(buf, n, "%s%d.%s", o->kind == HB_OVERRIDE_BODY ? "body." : o->kind ==
	    HB_OVERRIDE_IFACE ? "interface." : "initial.body.", o->index, o->name);
}

int
scene_override_pass(const struct hb_scene *sc, const char *section, const char *name)
{
	const struct hb_law_type *law;
	int pi;

	if (strncmp(section, "interface.", 10) != 0)
		return 2;
	if (strcmp(name, "law") == 0 || strcmp(name, "extension") == 0)
		return 0;
	law = scene_override_iface_law(sc, atoi(section + 10), NULL);
	pi = scene_override_param(law, name);
	return pi >= 0 && (law->params[pi].flags & (HB_LAW_PARAM_EXPONENT_P | HB_LAW_PARAM_EXPONENT_N))
	    ? 1 : 2;
}

