/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_panel.c - the rows of the explorer's parameter panel (see
 * scene.h): the keys of the table and the law's parameters by panel
 * section, with read-only rows of the derived values (E*, R_e, masses,
 * k_H, k, the static indentation).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "scene_override.h"

/* ---------------------------------------------------------------- */
/* Panel rows */

enum derived_id { D_ESTAR, D_RE, D_M1, D_M2, D_M, D_ETA, D_KH, D_K, D_XCS, D_COUNT };

struct row {
	int kind;   /* 0 key, 1 law parameter, 2 derived, 3 a chain's override (id: its index) */
	const struct scene_keydef *kd;
	int id;
};

static double
xcs(const struct hb_scene *sc)
{
	double f = sc->d.m * sc->loads.g / sc->d.kH;

	return pow(f, 1.0 / hb_law_exponent_p(sc->law, sc->par));
}

/* Lists the rows of the panel; returns the count (at most max). */
static int
rows_list(const struct hb_scene *sc, struct row *rows, int max)
{
	static const char *const order[] = { "bodies", "derived", "law", "chain", "loads", "initial",
		"run" };
	int nr = 0, full = sc->d.system == HB_SCENE_FULL;

#define PUSH(k, d, i) do { if (nr < max) { rows[nr].kind = (k); rows[nr].kd = (d); \
	rows[nr].id = (i); } nr++; } while (0)
	for (size_t s = 0; s < sizeof order / sizeof order[0]; s++) {
		if (strcmp(order[s], "derived") == 0) {
			int hasmat = sc->body[0].has_material && sc->body[1].has_material;
			if (hasmat) {
				PUSH(2, NULL, D_ESTAR);
				PUSH(2, NULL, D_RE);
			}
			PUSH(2, NULL, D_M1);
			if (full)
				PUSH(2, NULL, D_M2);
			PUSH(2, NULL, D_M);
			if (full)
				PUSH(2, NULL, D_ETA);
			if (hasmat && isfinite(sc->d.kH)) {
				PUSH(2, NULL, D_KH);
				if (sc->d.k_derived)
					PUSH(2, NULL, D_K);
				if (sc->loads.g > 0 && isfinite(xcs(sc)))
					PUSH(2, NULL, D_XCS);
			}
			continue;
		}
		for (int i = 0; i < scene_nkeydefs; i++) {
			const struct scene_keydef *kd = &scene_keydefs[i];
			if (strcmp(kd->panel, order[s]) != 0)
				continue;
			if ((kd->special == SP_FULL && !full) || (kd->special == SP_CHAIN && !sc->chain.n))
				continue;
			PUSH(0, kd, 0);
		}
		if (strcmp(order[s], "chain") == 0 && sc->chain.n > 0) /* body.I.*, interface.K.* */
			for (int i = 0; i < sc->over.n; i++)
				PUSH(3, NULL, i);
		if (strcmp(order[s], "law") == 0 && sc->law != NULL) {
			for (int i = 0; i < sc->law->n_params; i++) {
				if ((sc->law->params[i].flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived)
					continue;
				PUSH(1, NULL, i);
			}
		}
	}
#undef PUSH
	return nr;
}

int
hb_scene_nkeys(const struct hb_scene *sc)
{
	return rows_list(sc, NULL, 0);
}

static void
derived_row(const struct hb_scene *sc, int id, struct hb_scene_keyinfo *o)
{
	static const struct {
		const char *key, *label, *help;
		const struct hb_unit_dim *dim;
	} dr[D_COUNT] = {
		[D_ESTAR] = { "derived.Estar", "E*", "effective modulus ((1-nu1^2)/E1 + (1-nu2^2)/E2)^-1", &hb_unit_pressure },
		[D_RE] = { "derived.Re", "R_e", "effective radius (1/R1 + 1/R2)^-1", &hb_unit_length },
		[D_M1] = { "derived.m1", "m1", "mass of body 1", &hb_unit_mass },
		[D_M2] = { "derived.m2", "m2", "mass of body 2", &hb_unit_mass },
		[D_M] = { "derived.m", "m", "effective mass m1 m2/(m1 + m2)", &hb_unit_mass },
		[D_ETA] = { "derived.eta", "eta", "m1/(m1 + m2)", &hb_unit_none },
		[D_KH] = { "derived.kH", "k_H", "Hertz coefficient 4/3 E* sqrt(R_e)", NULL },
		[D_K] = { "derived.k", "k", "stiffness, from the materials by Hertz contact theory", NULL },
		[D_XCS] = { "derived.xcs", "x_c^s", "static Hertz indentation (m g / k_H)^(1/p)", &hb_unit_length },
	};
	double v = 0;
	struct hb_unit_dim dim = hb_unit_none;

	snprintf(o->key, sizeof o->key, "%s", dr[id].key);
	snprintf(o->section, sizeof o->section, "derived");
	snprintf(o->label, sizeof o->label, "%s", dr[id].label);
	snprintf(o->help, sizeof o->help, "%s", dr[id].help);
	snprintf(o->range, sizeof o->range, "derived");
	o->readonly = 1;
	o->kind = HB_SCENE_KEY_NUMBER;
	if (dr[id].dim != NULL)
		dim = *dr[id].dim;
	switch (id) {
	case D_ESTAR: v = sc->d.Estar; break;
	case D_RE: v = sc->d.Re; break;
	case D_M1: v = sc->d.m1; break;
	case D_M2: v = sc->d.m2; break;
	case D_M: v = sc->d.m; break;
	case D_ETA: v = sc->d.eta; break;
	case D_KH:
	case D_K: {
		int ki = scene_stiffness_index(sc->law);
		struct hb_unit_dim kd = { 1, 1, -2, -1, 0 };
		if (ki >= 0)
			kd = sc->law->params[ki].dim;
		dim = hb_units_resolve(kd, hb_law_exponent_p(sc->law, sc->par),
		    hb_law_exponent_n(sc->law, sc->par));
		v = id == D_KH ? sc->d.kH : (ki >= 0 ? sc->par[ki] : NAN);
		break;
	}
	case D_XCS: v = xcs(sc); break;
	default: break;
	}
	o->number = v;
	o->dim = dim;
	hb_units_dim_str(dim, o->unit, sizeof o->unit);
	hb_units_format(v, dim, 4, o->value, sizeof o->value);
}

int
hb_scene_key(const struct hb_scene *sc, int i, struct hb_scene_keyinfo *out)
{
	struct row rows[128 + HB_SCENE_MAX_OVERRIDES];
	int nr = rows_list(sc, rows, 128 + HB_SCENE_MAX_OVERRIDES);

	if (i < 0 || i >= nr || i >= 128 + HB_SCENE_MAX_OVERRIDES)
		return HB_EINVAL;
	memset(out, 0, sizeof *out);
	if (rows[i].kind == 3) {
		char key[64];
		scene_override_key(sc, rows[i].id, key, sizeof key);
		return scene_override_get(sc, key, out, NULL);
	}
	if (rows[i].kind == 2) {
		derived_row(sc, rows[i].id, out);
		return HB_OK;
	}
	if (rows[i].kind == 1)
		return scene_key_info_law(sc, rows[i].id, out);
	return scene_key_info(sc, rows[i].kd, out);
}
