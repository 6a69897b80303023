/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_keys.c - the table of scene keys (see scene_keys.h and scene.h):
 * every key's unit, range, default, meaning, and how it is stored; a key's
 * row, body, section and presence in a scene.  A value as text is in
 * scene_keys_text.c, the typed access (hb_scene_get) in scene_keyinfo.c,
 * errors as data in scene_error.c.
 */
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"

#define OFF(f) offsetof(struct hb_scene, f)
#define SIZE(f) sizeof ((struct hb_scene *)0)->f
#define INF HUGE_VAL

/* Ranges: lo, hi, lo_open, hi_open, whole. */
#define R_POS      { 0, INF, 1, 1, 0 }   /* (0, inf) */
#define R_POS_INF  { 0, INF, 1, 0, 0 }   /* (0, inf]: inf allowed */
#define R_NONNEG   { 0, INF, 0, 1, 0 }   /* [0, inf) */
#define R_ANY      { -INF, INF, 1, 1, 0 }
#define R_NONE     { 0, 0, 0, 0, 0 }
#define R_NU       { -1, 0.5, 1, 1, 0 }  /* (-1, 0.5) */
#define R_TOL      { 0, 1, 1, 1, 0 }     /* (0, 1) */
/*
 * Bounds on the initial state and on gravity: wide beyond any impact this
 * model describes (100 km/s is above meteorite speeds, 10^7 m/s^2 about an
 * ultracentrifuge's; the forces F1, F2 are held to the same acceleration by
 * hb_scene_check), and narrow enough that a flight's x, v and v^2 stay
 * far from overflowing a double (1e300 m/s is refused, not run into NaN).
 */
#define R_GAP      { 0, 1e6, 0, 0, 0 }   /* [0, 1000 km] */
#define R_POSITION { -1e6, 1e6, 0, 0, 0 } /* [-1000 km, 1000 km] */
#define R_SPEED    { -1e5, 1e5, 0, 0, 0 } /* [-100 km/s, 100 km/s] */
#define R_GRAVITY  { -SCENE_ACCEL_MAX, SCENE_ACCEL_MAX, 0, 0, 0 } /* [-1e7, 1e7] m/s^2 */
#define NUM(key, panel, label, dim, range, def, field, sp, help) \
	{ key, panel, label, ST_DOUBLE, &dim, range, def, NULL, OFF(field), 0, sp, help }
#define TXT(key, panel, label, store, def, field, size, help) \
	{ key, panel, label, store, NULL, R_NONE, NAN, def, OFF(field), size, SP_NONE, help }

#define BODY(i, defname, defrho, defR, massrange, masshelp)                                           \
	TXT("body" #i ".name", "bodies", "name (body " #i ")", ST_STRING, defname,            \
	    body[i - 1].name, SIZE(body[0].name), "name of body " #i),                        \
	NUM("body" #i ".E", "bodies", "E (body " #i ")", hb_unit_pressure, R_POS, 200e9,         \
	    body[i - 1].E, SP_MATERIAL, "Young's modulus of body " #i),                       \
	NUM("body" #i ".nu", "bodies", "nu (body " #i ")", hb_unit_none,                         \
	    R_NU, 0.3, body[i - 1].nu, SP_MATERIAL,      \
	    "Poisson's ratio of body " #i),                                                   \
	NUM("body" #i ".rho", "bodies", "rho (body " #i ")", hb_unit_density, R_POS, defrho,     \
	    body[i - 1].rho, SP_RHO, "density of body " #i "; m = 4/3 pi R^3 rho"),           \
	NUM("body" #i ".R", "bodies", "R (body " #i ")", hb_unit_length, R_POS_INF, defR,        \
	    body[i - 1].R, SP_NONE, "radius of body " #i "; inf for a flat"),                 \
	NUM("body" #i ".mass", "bodies", "mass (body " #i ")", hb_unit_mass, R_##massrange, NAN,     \
	    body[i - 1].mass, SP_MASS, masshelp)

const struct scene_keydef scene_keydefs[] = {
	TXT("scene.name", "scene", "name", ST_STRING, "steel ball on a steel flat", name,
	    SIZE(name), "short title of the scene"),
	TXT("scene.description", "scene", "description", ST_STRING,
	    "A steel ball dropped on a Hertz elastic steel flat (the neutral default scene).",
	    description, SIZE(description), "one or two sentences: what the scene shows"),
	TXT("scene.law", "law", "law", ST_LAW, "hertz", law, 0,
	    "contact law; changing it loads the law's defaults"),
	TXT("scene.extension", "law", "extension", ST_EXT, "adhesive", ext, 0,
	    "rule R1: adhesive continuation to x_c > 0, or none (clamped)"),

	BODY(1, "steel ball", 7800, 0.020, POS,
	     "mass of body 1: given, or derived from rho and R"),
	BODY(2, "steel flat", NAN, INF, POS_INF,
	     "mass of body 2: given (inf: a fixed obstacle), or derived from rho and R"),

	NUM("loads.g", "loads", "g", hb_unit_accel, R_GRAVITY, 9.81, loads.g, SP_NONE,
	    "gravity along -n1 on both bodies: F_ei += -m_i g"),
	NUM("loads.F1", "loads", "F1", hb_unit_force, R_ANY, 0, loads.F1, SP_NONE,
	    "constant force on body 1 along n1, |F1| <= 1e7 m/s^2 times m1"),
	NUM("loads.F2", "loads", "F2", hb_unit_force, R_ANY, 0, loads.F2, SP_FULL,
	    "constant force on body 2 along n1 (full system), |F2| <= 1e7 m/s^2 times m2"),
	TXT("loads.ramp", "loads", "ramp", ST_BOOL, "no", loads.ramp, 0,
	    "the S-ramp loads F_e1(t), F_e2(t) of the second study: yes or no"),
	NUM("loads.F_e0", "loads", "F_e0", hb_unit_force, R_NONNEG, 0, loads.Fe0, SP_RAMP,
	    "ramp: force drawing the bodies together, from F_e0 to 2 F_e0"),
	NUM("loads.T_e", "loads", "T_e", hb_unit_time, R_POS, 0.2, loads.Te, SP_RAMP,
	    "ramp: duration of the growth of the drawing force"),
	NUM("loads.T_s", "loads", "T_s", hb_unit_time, R_POS, 0.1, loads.Ts, SP_RAMP,
	    "ramp: time in which the centre of mass is brought to rest"),

	NUM("initial.x0", "initial", "x0", hb_unit_length, R_GAP, 0.010, init.x0, SP_NONE,
	    "initial gap (relative displacement), >= 0"),
	NUM("initial.v0", "initial", "v0", hb_unit_velocity, R_SPEED, 0, init.v0, SP_NONE,
	    "initial relative velocity (negative: approaching)"),
	NUM("initial.x_m0", "initial", "x_m0", hb_unit_length, R_POSITION, 0, init.xm0, SP_FULL,
	    "initial position of the centre of mass (full system)"),
	NUM("initial.v_m0", "initial", "v_m0", hb_unit_velocity, R_SPEED, 0, init.vm0, SP_FULL,
	    "initial velocity of the centre of mass (full system)"),

	{ "chain.n", "chain", "n", ST_INT, NULL, { 0, 1000, 0, 0, 1 }, 0, NULL, OFF(chain.n), 0,
	  SP_CHAIN, "bodies of a chain, each body 1, with the law between neighbours; 0: the two-body scene" },
	{ "chain.floor", "chain", "floor", ST_BOOL, NULL, R_NONE, NAN, "no", OFF(chain.floor), 0,
	  SP_CHAIN, "a fixed obstacle below body 1 of the chain (interface 0): yes or no" },
	NUM("chain.spacing", "chain", "spacing", hb_unit_length, R_NONNEG, 0.001, chain.spacing, SP_CHAIN,
	    "gap between neighbours (and between body 1 and the floor); 0: touching"),
	NUM("striker.v", "chain", "striker v", hb_unit_velocity, R_SPEED, 0, chain.v, SP_CHAIN,
	    "initial velocity of body n, the striker (negative: towards body n - 1)"),

	NUM("run.T", "run", "T", hb_unit_time, R_POS, 0.2, run.T, SP_NONE, "end of ordinary time"),
	{ "run.J", "run", "J", ST_LONG, NULL, { 1, 1e18, 0, 0, 1 }, 100000, NULL, OFF(run.J), 0,
	  SP_NONE, "jump cap" },
	TXT("run.stepper", "run", "stepper", ST_STEPPER, "rk8pd", run.stepper, 0,
	    "stepper: rk8pd, dop853 (with dense output), vern98 (Verner's 9(8)), rkf45, rkck, "
	    "msbdf, rk4imp, bsimp, "
	    "or auto (rk8pd, then bsimp for the contacts once one is found stiff)"),
	NUM("run.rtol", "run", "rtol", hb_unit_none, R_TOL, 1e-10,
	    run.rtol, SP_NONE, "relative tolerance of the integrator"),
	NUM("run.atol", "run", "atol", hb_unit_none, R_TOL, 1e-10,
	    run.atol, SP_NONE, "absolute tolerance, relative to each component's scale"),
	NUM("run.h_max", "run", "h_max", hb_unit_time, R_NONNEG, 0, run.h_max, SP_NONE,
	    "largest step inside a contact; 0: none"),
	{ "run.max_samples", "run", "max_samples", ST_LONG, NULL, { 1024, 1e18, 0, 0, 1 }, 262144,
	  NULL, OFF(run.max_samples), 0, SP_NONE, "arc memory bound: thinning starts beyond this" },
	{ "run.chatter", "run", "chatter", ST_INT, NULL, { 2, INT_MAX, 0, 0, 1 }, 4, NULL,
	  OFF(run.chatter), 0, SP_NONE, "most jumps allowed at one instant of ordinary time" },
	TXT("run.reductions", "run", "reductions", ST_REDUCE, "all", run.reduce, 0,
	    "closed forms used: all, none, or a comma list of flight, contact, com"),
	TXT("run.kinks", "run", "kinks", ST_BOOL, "yes", run.kinks, 0,
	    "end steps on the kinks of the law and the loads (no: only to measure their effect)"),
	TXT("run.limits", "run", "limits", ST_BOOL, "yes", run.limits, 0,
	    "refuse a stepper at a tolerance where its global error on the paper's studies is "
	    "more than 10 x rk8pd's (no: run it anyway, only to measure it)"),
	NUM("run.max_indent", "run", "max_indent", hb_unit_none, R_TOL, 0.1, run.max_indent, SP_CHAIN,
	    "a chain's largest indentation (or overlap), a fraction of the smaller radius of its two bodies"),
	{ "run.chain_limits", "run", "chain_limits", ST_STOPWARN, NULL, R_NONE, NAN, "stop",
	  OFF(run.chain_limits), 0, SP_CHAIN, "where a chain passes run.max_indent, or bodies that are "
	  "not neighbours overlap: stop the run, or warn (note it and go on)" },
};
const int scene_nkeydefs = (int)(sizeof scene_keydefs / sizeof scene_keydefs[0]);

const struct scene_keydef *
scene_keydef_find(const char *key)
{
	for (int i = 0; i < scene_nkeydefs; i++) /* the first letter before the whole key */
		if (scene_keydefs[i].key[0] == key[0] && strcmp(scene_keydefs[i].key, key) == 0)
			return &scene_keydefs[i];
	return NULL;
}

int
scene_keydef_body(const struct scene_keydef *kd)
{
	if (strncmp(kd->key, "body", 4) == 0 && (kd->key[4] == '1' || kd->key[4] == '2'))
		return kd->key[4] - '1';
	return -1;
}

const char *
scene_keydef_section(const struct scene_keydef *kd, char *buf, size_t n)
{
	const char *dot = strchr(kd->key, '.');

	snprintf(buf, n, "%.*s", (int)(dot - kd->key), kd->key);
	return buf;
}

int
scene_keydef_present(const struct hb_scene *sc, const struct scene_keydef *kd)
{
	int b = scene_keydef_body(kd);

	if (kd->special == SP_CHAIN)
		return sc->chain.n > 0;
	if (b < 0)
		return 1;
	switch (kd->special) {
	case SP_MATERIAL: return sc->body[b].has_material;
	case SP_RHO: return !sc->body[b].mass_given && sc->body[b].rho != 0;
	case SP_MASS: return sc->body[b].mass_given;
	default: return 1;
	}
}

int
scene_stiffness_index(const struct hb_law_type *law)
{
	if (law == NULL)
		return -1;
	for (int i = 0; i < law->n_params; i++)
		if (law->params[i].flags & HB_LAW_PARAM_STIFFNESS)
			return i;
	return -1;
}

struct hb_unit_dim
scene_lawpar_dim(const struct hb_scene *sc, int i)
{
	return hb_units_resolve(sc->law->params[i].dim, hb_law_exponent_p(sc->law, sc->par),
	    hb_law_exponent_n(sc->law, sc->par));
}
