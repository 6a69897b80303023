/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_override_check.c - a chain's overrides checked against the chain: indices, laws, materials,
 * masses, forces and each interface's parameters
 * (scene_override.h; the keys themselves are scene_override.c's).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_chain.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

/* ---------------------------------------------------------------- */
/* Checks */

int
scene_override_check(const struct hb_scene *sc, struct hb_scene_error *err)
{
	char key[64], acc[192];
	int st;

	if (sc->over.n == 0 && !(sc->chain.n > 0 && sc->chain.floor))
		return HB_OK;
	for (int i = 0; i < sc->over.n; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		scene_override_key(sc, i, key, sizeof key);
		if ((st = scene_override_index_check(sc, key, o->kind, o->index, err)) != HB_OK)
			return st;
		if (o->kind == HB_OVERRIDE_IFACE && strcmp(o->name, "law") == 0 &&
		    scene_override_iface_law(sc, o->index, NULL)->n_z != sc->law->n_z) {
			/* the engine sizes a contact's state by the scene's law (sim.c) */
			const struct hb_law_type *law = scene_override_iface_law(sc, o->index, NULL);
			size_t l;
			snprintf(acc, sizeof acc, "a law with %d internal state%s, as the scene's %s:",
			    sc->law->n_z, sc->law->n_z == 1 ? "" : "s", sc->law->name);
			for (const struct hb_law_type *const *L = hb_law_list(); *L != NULL; L++)
				if ((*L)->n_z == sc->law->n_z) {
					l = strlen(acc);
					snprintf(acc + l, sizeof acc - l, " %s", (*L)->name);
				}
			return scene_error_set(err, key, acc, "law %s has %d internal state%s and the "
			    "scene's law %s %d: a chain's interfaces carry as many as the scene's law "
			    "in this version", law->name, law->n_z, law->n_z == 1 ? "" : "s",
			    sc->law->name, sc->law->n_z);
		}
		if (o->kind == HB_OVERRIDE_IFACE && strcmp(o->name, "law") != 0 &&
		    strcmp(o->name, "extension") != 0) {
			const struct hb_law_type *law = scene_override_iface_law(sc, o->index, NULL);
			int pi = scene_override_param(law, o->name);
			struct hb_unit_range r;
			if (pi < 0) {
				scene_override_iface_accepted(law, acc, sizeof acc);
				return scene_error_set(err, key, acc, "interface %d's law %s has no "
				    "parameter %s", o->index, law->name, o->name);
			}
			r = hb_law_param_range(&law->params[pi]);
			if (!hb_units_in_range(o->value, &r))
				return scene_error_range(err, key, &r, NULL, "value %.6g is out of range",
				    o->value);
		}
	}
	if (sc->chain.n <= 0)
		return HB_OK;
	/* the bodies that have overrides */
	for (int i = 0; i < sc->over.n; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		struct scene_chain_bodyx b;
		if (o->kind == HB_OVERRIDE_IFACE)
			continue;
		scene_chain_body_full(sc, o->index - 1, &b);
		if (b.half) {
			snprintf(key, sizeof key, "body.%d.%s", o->index,
			    scene_override_find(sc, HB_OVERRIDE_BODY, o->index, "E") >= 0 ? "E" : "nu");
			return scene_error_set(err, key, "both E and nu, or neither",
			    "a material needs both E and nu (body1 has no material to complete it)");
		}
		if (b.both) {
			snprintf(key, sizeof key, "body.%d.mass", o->index);
			return scene_error_set(err, key, "one of them", "give rho (with R) or mass, not both");
		}
		if (!(b.mass > 0) || !isfinite(b.mass)) {
			snprintf(key, sizeof key, "body.%d.mass", o->index);
			return scene_error_set(err, key, "a mass, or rho with a finite R",
			    "body %d has no mass", o->index);
		}
		if (!isfinite(b.mass * sc->loads.g) || fabs(b.F) > SCENE_ACCEL_MAX * b.mass) {
			struct hb_unit_range r = { -SCENE_ACCEL_MAX * b.mass, SCENE_ACCEL_MAX * b.mass, 0, 0, 0 };
			snprintf(key, sizeof key, "body.%d.F", o->index);
			return scene_error_range(err, key, &r, &hb_unit_force,
			    "it would accelerate body %d beyond %g m/s^2", o->index, SCENE_ACCEL_MAX);
		}
	}
	/* the interfaces that have overrides or a neighbour with one, and the floor's */
	for (int k = !sc->chain.floor; k < sc->chain.n; k++) {
		struct scene_chain_iface ci;
		int dv, fl, touched = k == 0;
		char lm[256];
		for (int i = 0; i < sc->over.n && !touched; i++) {
			const struct hb_scene_override *o = &sc->over.o[i];
			touched = o->kind == HB_OVERRIDE_IFACE ? o->index == k
			                                       : o->index == k || o->index == k + 1;
		}
		if (!touched)
			continue;
		scene_chain_iface_full(sc, k, &ci, &dv, &fl);
		if (fl) {
			snprintf(key, sizeof key, "interface.0.%s", ci.law->params[scene_stiffness_index(ci.law)].name);
			return scene_error_set(err, key, "body2.E and body2.nu (the floor's material), or "
			    "this key", "the floor (body2) has no material to derive interface 0's "
			    "stiffness from");
		}
		for (int pi = 0; pi < ci.law->n_params; pi++) {
			struct hb_unit_range r = hb_law_param_range(&ci.law->params[pi]);
			int typed = scene_override_find(sc, HB_OVERRIDE_IFACE, k, ci.law->params[pi].name) >= 0;
			snprintf(key, sizeof key, "interface.%d.%s", k, ci.law->params[pi].name);
			if (typed && dv && (ci.law->params[pi].flags & HB_LAW_PARAM_STIFFNESS))
				return scene_override_derived_error(err, key, k);
			if (!hb_units_in_range(ci.par[pi], &r))
				return scene_error_range(err, key, &r, NULL, "%s %.6g is out of range",
				    dv && (ci.law->params[pi].flags & HB_LAW_PARAM_STIFFNESS)
				    ? "derived value" : "value", ci.par[pi]);
		}
		if (ci.law->check != NULL && ci.law->check(ci.par, lm, sizeof lm) != HB_OK) {
			int pi = 0;
			for (int i = 0; i < ci.law->n_params; i++)
				if (ci.law->params[i].flags & HB_LAW_PARAM_CHECKED) {
					pi = i;
					break;
				}
			snprintf(key, sizeof key, "interface.%d.%s", k, ci.law->params[pi].name);
			return scene_error_set(err, key, lm, "value %.6g is out of range", ci.par[pi]);
		}
	}
	return HB_OK;
}

