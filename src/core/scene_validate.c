/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_validate.c - checking a whole scene against the admissible ranges
 * of the key table and of the law's parameters, and the constraints between
 * values (see scene.h).  The error is data: the key at fault, its value and
 * the accepted range.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "scene_override.h"

/* Checks number v of key against r; vs is written with dim. */
static int
check_value(const char *key, double v, const struct hb_unit_range *r, struct hb_unit_dim dim,
            const struct hb_unit_dim *rdim, const char *what, struct hb_scene_error *err)
{
	char vs[64];

	if (hb_units_in_range(v, r))
		return HB_OK;
	hb_units_format(v, dim, 6, vs, sizeof vs);
	return scene_error_range(err, key, r, rdim, "%s %s is out of range", what, vs);
}

/* The values of the table that this scene uses. */
static int
check_table(const struct hb_scene *sc, struct hb_scene_error *err)
{
	const char *base = (const char *)sc;
	int st;

	for (int i = 0; i < scene_nkeydefs; i++) {
		const struct scene_keydef *kd = &scene_keydefs[i];
		double v;

		if (!scene_keydef_present(sc, kd) || (kd->special == SP_RAMP && !sc->loads.ramp))
			continue;
		switch (kd->store) {
		case ST_DOUBLE:
			v = *(const double *)(base + kd->off);
			st = check_value(kd->key, v, &kd->range, *kd->dim, kd->dim, "value", err);
			break;
		case ST_LONG:
		case ST_INT:
			v = kd->store == ST_LONG ? (double)*(const long *)(base + kd->off)
			                         : (double)*(const int *)(base + kd->off);
			st = check_value(kd->key, v, &kd->range, hb_unit_none, NULL, "value", err);
			break;
		case ST_LAW:
			st = sc->law == NULL ? scene_error_set(err, kd->key, NULL, "no contact law")
			                     : HB_OK;
			break;
		case ST_STEPPER:
			st = sc->run.stepper < 0 || sc->run.stepper >= HB_STEPPER_COUNT
			    ? scene_error_set(err, kd->key, NULL, "value %d is out of range",
			          sc->run.stepper) : HB_OK;
			break;
		case ST_REDUCE:
			st = sc->run.reduce < 0 || sc->run.reduce > HB_REDUCE_ALL
			    ? scene_error_set(err, kd->key, NULL, "value %d is out of range",
			          sc->run.reduce) : HB_OK;
			break;
		default:
			st = HB_OK;
			break;
		}
		if (st != HB_OK)
			return st;
	}
	return HB_OK;
}

/* The law's parameters, each in its range, then the law's own check. */
static int
check_law(const struct hb_scene *sc, struct hb_scene_error *err)
{
	const struct hb_law_type *law = sc->law;
	char lm[256], key[48], vs[64];
	int st;

	for (int i = 0; i < law->n_params; i++) {
		const struct hb_law_param *pp = &law->params[i];
		struct hb_unit_range r = hb_law_param_range(pp);
		int derived = (pp->flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived;

		snprintf(key, sizeof key, "law.%s", pp->name);
		st = check_value(key, sc->par[i], &r, scene_lawpar_dim(sc, i), NULL,
		    derived ? "derived value" : "value", err);
		if (st != HB_OK) {
			if (derived && err != NULL) {
				size_t l = strlen(err->accepted);
				snprintf(err->accepted + l, sizeof err->accepted - l,
				    " (check the materials)");
			}
			return st;
		}
	}
	if (law->check != NULL && law->check(sc->par, lm, sizeof lm) != HB_OK) {
		int pi = 0;
		for (int i = 0; i < law->n_params; i++)
			if (law->params[i].flags & HB_LAW_PARAM_CHECKED) {
				pi = i;
				break;
			}
		snprintf(key, sizeof key, "law.%s", law->params[pi].name);
		hb_units_format(sc->par[pi], scene_lawpar_dim(sc, pi), 6, vs, sizeof vs);
		return scene_error_set(err, key, lm, "value %s is out of range", vs);
	}
	return HB_OK;
}

/*
 * The weight m g of each moving body is a finite force: 1e308 kg under
 * gravity is refused here, naming the mass, rather than failing the run on
 * an overflowing flight.
 */
static int
check_weight(const struct hb_scene *sc, struct hb_scene_error *err)
{
	for (int b = 0; b < 2; b++) {
		double m = b == 0 ? sc->d.m1 : sc->d.m2;
		char ms[64], lim[96], gs[64];
		if (b == 1 && (sc->d.system != HB_SCENE_FULL || isinf(m)))
			continue; /* body 2 fixed, or its load not applied */
		if (isfinite(m * sc->loads.g))
			continue;
		hb_units_format(m, hb_unit_mass, 4, ms, sizeof ms);
		hb_units_format(sc->loads.g, hb_unit_accel, 4, gs, sizeof gs);
		hb_units_format(DBL_MAX / fabs(sc->loads.g), hb_unit_mass, 4, lim, sizeof lim);
		snprintf(lim + strlen(lim), sizeof lim - strlen(lim), " or less at g = %s", gs);
		return scene_error_set(err, b == 0 ? "body1.mass" : "body2.mass", lim,
		    "its weight m g (%s times %s) overflows a double", ms, gs);
	}
	return HB_OK;
}

/*
 * The constant forces may not accelerate a body beyond SCENE_ACCEL_MAX,
 * the bound of g: a force of 1e300 N is refused, naming the range of
 * forces that mass accepts, rather than run into a meaningless flight.
 */
static int
check_forces(const struct hb_scene *sc, struct hb_scene_error *err)
{
	for (int b = 0; b < 2; b++) {
		double m = b == 0 ? sc->d.m1 : sc->d.m2, F = b == 0 ? sc->loads.F1 : sc->loads.F2;
		char ms[64];
		if (b == 1 && (sc->d.system != HB_SCENE_FULL || isinf(m)))
			continue; /* body 2 fixed, or its load not applied */
		if (fabs(F) <= SCENE_ACCEL_MAX * m)
			continue;
		struct hb_unit_range r = { -SCENE_ACCEL_MAX * m, SCENE_ACCEL_MAX * m, 0, 0, 0 };
		hb_units_format(m, hb_unit_mass, 4, ms, sizeof ms);
		return scene_error_range(err, b == 0 ? "loads.F1" : "loads.F2", &r, &hb_unit_force,
		    "it would accelerate body %d (%s) beyond %g m/s^2", b + 1, ms, SCENE_ACCEL_MAX);
	}
	return HB_OK;
}

/*
 * What a chain runs with in this version: constant loads (gravity, no
 * ramp), every closed form, bodies apart at the start (touching bodies
 * would be several contacts at once), at least one interface.
 */
static int
check_chain(const struct hb_scene *sc, struct hb_scene_error *err)
{
	if (sc->chain.n <= 0)
		return HB_OK;
	if (sc->chain.n < 2 && !sc->chain.floor)
		return scene_error_set(err, "chain.n", "2 or more bodies, or chain.floor = yes",
		    "a chain of one body without a floor has no interface");
	if (sc->loads.ramp)
		return scene_error_set(err, "loads.ramp", "no", "a chain's loads are constant");
	if (sc->loads.F1 != 0 || sc->loads.F2 != 0)
		return scene_error_set(err, sc->loads.F1 != 0 ? "loads.F1" : "loads.F2", "0 N",
		    "a chain's load is gravity alone");
	if (sc->run.reduce != HB_REDUCE_ALL)
		return scene_error_set(err, "run.reductions", "all",
		    "a chain's flights and centres of mass are always in closed form");
	return HB_OK;
}

int
hb_scene_check(struct hb_scene *sc, struct hb_scene_error *err)
{
	static const struct hb_unit_range m1 = { 0, HUGE_VAL, 1, 1, 0 }, m2 = { 0, HUGE_VAL, 1, 0, 0 };
	char key[32];
	int st;

	if (sc->law == NULL)
		return scene_error_set(err, "scene.law", NULL, "no contact law");
	if ((st = check_table(sc, err)) != HB_OK)
		return st;
	if ((st = scene_check_stepper(sc, err)) != HB_OK)
		return st;
	if (sc->loads.ramp) { /* the ramp needs a drawing force: F_e0 > 0 */
		static const struct hb_unit_range fe0 = { 0, HUGE_VAL, 1, 1, 0 };
		if ((st = check_value("loads.F_e0", sc->loads.Fe0, &fe0, hb_unit_force, &hb_unit_force,
		    "value", err)) != HB_OK)
			return st;
	}
	for (int b = 0; b < 2; b++) {
		const struct hb_scene_body *bd = &sc->body[b];
		if (!bd->mass_given && !(bd->rho > 0 && isfinite(bd->R)) && !(b == 1 && isinf(bd->R))) {
			snprintf(key, sizeof key, "%s", b == 0 ? "body1.mass" : "body2.mass");
			return scene_error_set(err, key,
			    b == 1 ? "a mass, or rho with a finite R (or R = inf: a fixed obstacle)"
			           : "a mass, or rho with a finite R", "body %d has no mass", b + 1);
		}
	}
	hb_scene_derive(sc, NULL, 0);
	if ((st = check_value("body1.mass", sc->d.m1, &m1, hb_unit_mass, &hb_unit_mass, "value", err)))
		return st;
	if ((st = check_value("body2.mass", sc->d.m2, &m2, hb_unit_mass, &hb_unit_mass, "value", err)))
		return st;
	if ((st = check_weight(sc, err)) != HB_OK)
		return st;
	if ((st = check_forces(sc, err)) != HB_OK)
		return st;
	if ((st = check_chain(sc, err)) != HB_OK)
		return st;
	if ((st = scene_override_check(sc, err)) != HB_OK)
		return st;
	return check_law(sc, err);
}

int
hb_scene_validate(struct hb_scene *sc, char *msg, size_t n)
{
	struct hb_scene_error e;
	int st = hb_scene_check(sc, &e);

	if (st != HB_OK && msg != NULL && n > 0)
		hb_scene_error_str(&e, msg, n);
	return st;
}
