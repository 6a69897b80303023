/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_keys.c - the table of scene keys and the typed access to them (see
 * scene_keys.h and scene.h): every key's unit, range, default, meaning,
 * and how it is read and printed; hb_scene_get(), errors as data, and the
 * PRESETS reference of the man page generated from the table.
 */
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "scene_override.h"
#include "cnum.h"

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

static const char *const ext_names[] = { "none", "adhesive" };
static const char *const bool_names[] = { "no", "yes" };
/* Every reduction set, by its flags (HB_REDUCE_FLIGHT 1, CONTACT 2, COM 4). */
static const char *const reduce_names[] = {
	"none", "flight", "contact", "flight,contact", "com", "flight,com", "contact,com", "all",
};

int
scene_keydef_choices(const struct scene_keydef *kd, const char **out, int max)
{
	int k = 0;

#define ADD(s) do { if (k < max) out[k] = (s); k++; } while (0)
	switch (kd->store) {
	case ST_LAW:
		for (const struct hb_law_type *const *l = hb_law_list(); *l != NULL; l++)
			ADD((*l)->name);
		break;
	case ST_EXT:
		ADD(ext_names[1]);
		ADD(ext_names[0]);
		break;
	case ST_STEPPER:
		for (int i = 0; i < HB_STEPPER_COUNT; i++)
			ADD(hb_scene_stepper_name(i));
		break;
	case ST_BOOL:
		ADD(bool_names[1]);
		ADD(bool_names[0]);
		break;
	case ST_STOPWARN:
		ADD("stop");
		ADD("warn");
		break;
	case ST_REDUCE:
		ADD(reduce_names[7]);
		for (int i = 0; i < 7; i++)
			ADD(reduce_names[i]);
		break;
	default:
		break;
	}
#undef ADD
	return k;
}

int
scene_keydef_read_choice(const struct scene_keydef *kd, const char *t, int *v)
{
	static const char *const yes[] = { "yes", "1", "true", "on" };
	static const char *const no[] = { "no", "0", "false", "off" };

	switch (kd->store) {
	case ST_LAW: {
		const struct hb_law_type *const *l = hb_law_list();
		for (int i = 0; l[i] != NULL; i++)
			if (cnum_casecmp(l[i]->name, t) == 0)
				return *v = i, 0;
		return -1;
	}
	case ST_EXT:
		if (cnum_casecmp(t, "adhesive") == 0)
			return *v = 1, 0;
		if (cnum_casecmp(t, "none") == 0 || cnum_casecmp(t, "clamped") == 0)
			return *v = 0, 0;
		return -1;
	case ST_STEPPER:
		*v = hb_scene_stepper_find(t);
		return *v < 0 ? -1 : 0;
	case ST_BOOL:
		for (int i = 0; i < 4; i++) {
			if (cnum_casecmp(t, yes[i]) == 0)
				return *v = 1, 0;
			if (cnum_casecmp(t, no[i]) == 0)
				return *v = 0, 0;
		}
		return -1;
	case ST_STOPWARN:
		if (cnum_casecmp(t, "stop") == 0)
			return *v = HB_CHAIN_LIMITS_STOP, 0;
		if (cnum_casecmp(t, "warn") == 0)
			return *v = HB_CHAIN_LIMITS_WARN, 0;
		return -1;
	case ST_REDUCE: {
		static const char *const flag[] = { "flight", "contact", "com" };
		int r = 0;
		if (cnum_casecmp(t, "all") == 0)
			return *v = HB_REDUCE_ALL, 0;
		if (cnum_casecmp(t, "none") == 0)
			return *v = 0, 0;
		while (*t) {
			size_t len = strcspn(t, ", \t");
			int f = -1;
			for (int i = 0; i < 3; i++)
				if (strlen(flag[i]) == len && cnum_ncasecmp(t, flag[i], len) == 0)
					f = i;
			if (len > 0 && f < 0)
				return -1;
			if (f >= 0)
				r |= 1 << f;
			t += len;
			t += strspn(t, ", \t");
		}
		return *v = r, 0;
	}
	default:
		return -1;
	}
}

const char *
scene_keydef_choice(const struct hb_scene *sc, const struct scene_keydef *kd)
{
	const char *base = (const char *)sc;
	int v = kd->store == ST_LAW ? 0 : *(const int *)(base + kd->off);

	switch (kd->store) {
	case ST_LAW: return sc->law != NULL ? sc->law->name : "";
	case ST_EXT: return ext_names[v != 0];
	case ST_STEPPER: return hb_scene_stepper_name(v);
	case ST_BOOL: return bool_names[v != 0];
	case ST_REDUCE: return reduce_names[v & HB_REDUCE_ALL];
	case ST_STOPWARN: return v == HB_CHAIN_LIMITS_WARN ? "warn" : "stop";
	default: return "";
	}
}

void
scene_keydef_print(const struct hb_scene *sc, const struct scene_keydef *kd, char *buf, size_t n)
{
	const char *base = (const char *)sc;
	char u[64];

	switch (kd->store) {
	case ST_DOUBLE:
		hb_units_dim_str(*kd->dim, u, sizeof u);
		cnum_snprintf(buf, n, "%.17g%s%s", *(const double *)(base + kd->off), u[0] ? " " : "", u);
		break;
	case ST_LONG:
		snprintf(buf, n, "%ld", *(const long *)(base + kd->off));
		break;
	case ST_INT:
		snprintf(buf, n, "%d", *(const int *)(base + kd->off));
		break;
	case ST_STRING:
		snprintf(buf, n, "%s", base + kd->off);
		break;
	default:
		snprintf(buf, n, "%s", scene_keydef_choice(sc, kd));
		break;
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

/* ---------------------------------------------------------------- */
/* Errors as data */

static int
error_vset(struct hb_scene_error *e, const char *key, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));

static int
error_vset(struct hb_scene_error *e, const char *key, const char *fmt, va_list ap)
{
	if (e == NULL)
		return HB_EINVAL;
	memset(e, 0, sizeof *e);
	snprintf(e->key, sizeof e->key, "%s", key != NULL ? key : "");
	cnum_vsnprintf(e->what, sizeof e->what, fmt, ap);
	return HB_EINVAL;
}

int
scene_error_set(struct hb_scene_error *e, const char *key, const char *accepted,
                const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	error_vset(e, key, fmt, ap);
	va_end(ap);
	if (e != NULL && accepted != NULL)
		snprintf(e->accepted, sizeof e->accepted, "%s", accepted);
	return HB_EINVAL;
}

int
scene_error_range(struct hb_scene_error *e, const char *key, const struct hb_unit_range *r,
                  const struct hb_unit_dim *dim, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	error_vset(e, key, fmt, ap);
	va_end(ap);
	if (e != NULL) {
		e->has_range = 1;
		e->range = *r;
		hb_units_range_str(r, dim, e->accepted, sizeof e->accepted);
	}
	return HB_EINVAL;
}

char *
hb_scene_error_str(const struct hb_scene_error *e, char *buf, size_t n)
{
	snprintf(buf, n, "%s%s%s%s%s", e->key, e->key[0] ? ": " : "", e->what,
	    e->accepted[0] ? "; accepted: " : "", e->accepted);
	return buf;
}

/* ---------------------------------------------------------------- */
/* Typed access */

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
