/*
 * scene.c - defaults, derived values, validation, the key table, and the
 * applied loads of a scene (see scene.h).
 *
 * Keys.  One table serves scene_set() (presets, --set, the parameter panel)
 * and scene_key() (the panel's rows).  A key is "section.name": scene.*,
 * body1.*, body2.*, law.<param of the current law>, loads.*, initial.*,
 * run.*; the panel also shows read-only derived.* rows.  Every message of
 * scene_set() and scene_validate() begins with "KEY: ", so that a preset
 * reader can replace it with "FILE:LINE: [section] name: ".
 *
 * Bodies.  A body is given by its material (E and nu) or not, and by its
 * mass or by rho and R.  Typing E or nu marks the body as having a
 * material; typing mass makes the mass given (and forgets rho); typing rho
 * makes the mass derived again.  A body 2 of infinite mass (mass = inf, or
 * R = inf without rho) is an obstacle: the reduced system.
 *
 * Loads (paper, second study, eqs. ramp .. u_2), generalised by constant
 * forces F1, F2 and gravity g along -n1:
 *     S(w) = 0 (w < 0), (1 - cos pi w)/2 (0 <= w <= 1), 1 (w > 1)
 *     a(t) = v_m0 / T_s S'(t / T_s)
 *     F_e1 = F1 - m1 g - ramp (F_e0 (1 + S(t/T_e)) + m1 a(t))
 *     F_e2 = F2 - m2 g + ramp (F_e0 (1 + S(t/T_e)) - m2 a(t))
 * whence, in the full system, exactly (gravity and a(t) cancel):
 *     F_er = (m2 F_e1 - m1 F_e2)/(m1 + m2) = eta_c F1 - eta F2 - ramp F_e0 (1 + S(t/T_e))
 * and in the reduced system F_er = F_e1.
 */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---------------------------------------------------------------- */
/* Steppers */

static const char *const stepper_names[STEPPER_COUNT] = {
	"rk8pd", "rkf45", "rkck", "msbdf", "rk4imp", "bsimp", "auto", "dop853",
};

const char *
scene_stepper_name(int stepper)
{
	if (stepper < 0 || stepper >= STEPPER_COUNT)
		return "?";
	return stepper_names[stepper];
}

int
scene_stepper_find(const char *name)
{
	if (name == NULL)
		return -1;
	for (int i = 0; i < STEPPER_COUNT; i++)
		if (strcmp(stepper_names[i], name) == 0)
			return i;
	return -1;
}

/* ---------------------------------------------------------------- */
/* Defaults and derived values */

static void
body_steel(struct scene_body *b, const char *name, double R, double rho)
{
	memset(b, 0, sizeof *b);
	snprintf(b->name, sizeof b->name, "%s", name);
	b->has_material = 1;
	b->E = 200e9;
	b->nu = 0.3;
	b->rho = rho;
	b->R = R;
	b->mass = 0;
	b->mass_given = 0;
}

/*
 * A neutral valid scene: a steel ball (R = 20 mm) dropped from 10 mm on a
 * Hertz elastic steel flat of infinite mass, under gravity.
 */
void
scene_defaults(struct scene *sc)
{
	memset(sc, 0, sizeof *sc);
	snprintf(sc->name, sizeof sc->name, "%s", "steel ball on a steel flat");
	snprintf(sc->description, sizeof sc->description, "%s",
	    "A steel ball dropped on a Hertz elastic steel flat (the neutral default scene).");
	body_steel(&sc->body[0], "steel ball", 0.020, 7800);
	body_steel(&sc->body[1], "steel flat", INFINITY, 0);
	sc->law = &law_hertz;
	law_defaults(sc->law, sc->par);
	sc->ext = 1;
	sc->loads.g = 9.81;
	sc->loads.F1 = 0;
	sc->loads.F2 = 0;
	sc->loads.ramp = 0;
	sc->loads.Fe0 = 0;
	sc->loads.Te = 0.2;
	sc->loads.Ts = 0.1;
	sc->init.x0 = 0.010;
	sc->init.v0 = 0;
	sc->init.xm0 = 0;
	sc->init.vm0 = 0;
	sc->run.T = 0.2;
	sc->run.J = 100000;
	sc->run.stepper = STEPPER_DOP853;
	sc->run.rtol = 1e-10;
	sc->run.atol = 1e-10;
	sc->run.h_max = 0;
	sc->run.max_samples = 262144;
	sc->run.chatter = 4;
	sc->run.reduce = REDUCE_ALL;
	sc->run.kinks = 1;
	scene_derive(sc, NULL, 0);
}

/* Index of the law's stiffness parameter, or -1. */
static int
stiffness_index(const struct law_type *law)
{
	if (law == NULL)
		return -1;
	for (int i = 0; i < law->n_params; i++)
		if (law->params[i].flags & LAW_PARAM_STIFFNESS)
			return i;
	return -1;
}

/* The mass of body i: given, or 4/3 pi R^3 rho, or INFINITY for an obstacle. */
static int
body_mass(const struct scene_body *b, int i, double *mass, char *msg, size_t n)
{
	if (b->mass_given) {
		*mass = b->mass;
		return HB_OK;
	}
	if (b->rho > 0 && isfinite(b->R)) {
		*mass = 4.0 / 3.0 * M_PI * b->R * b->R * b->R * b->rho;
		return HB_OK;
	}
	if (i == 1 && isinf(b->R)) {
		*mass = INFINITY;
		return HB_OK;
	}
	return status_set(msg, n, HB_EINVAL,
	    "body%d.mass: body %d has no mass; accepted: a mass, or rho with a finite R%s", i + 1,
	    i + 1, i == 1 ? " (or R = inf: a fixed obstacle)" : "");
}

/*
 * Computes E*, R_e, m1, m2, m, eta, k_H and, when the law has k_hertz and
 * both bodies have materials, k by eq. k_hertz (written into the law's
 * stiffness parameter).  The system is the reduced one when body 2 has
 * infinite mass.
 */
int
scene_derive(struct scene *sc, char *msg, size_t n)
{
	struct scene_derived *d = &sc->d;
	const struct scene_body *b1 = &sc->body[0], *b2 = &sc->body[1];
	double m1 = NAN, m2 = NAN;
	int st, ki;

	st = body_mass(b1, 0, &m1, msg, n);
	if (st == HB_OK)
		st = body_mass(b2, 1, &m2, msg, n);
	if (st != HB_OK)
		return st;
	sc->body[0].mass = m1;
	sc->body[1].mass = m2;
	d->m1 = m1;
	if (isinf(m2)) {
		d->system = SCENE_REDUCED;
		d->m2 = INFINITY;
		d->m = m1;
		d->eta = 0;  /* the limits of m1/(m1+m2) and m2/(m1+m2) as m2 -> inf */
		d->etac = 1;
	} else {
		d->system = SCENE_FULL;
		d->m2 = m2;
		d->m = m1 * m2 / (m1 + m2);
		d->eta = m1 / (m1 + m2);
		d->etac = 1.0 - d->eta;
	}
	if (b1->has_material && b2->has_material)
		d->Estar = 1.0 / ((1.0 - b1->nu * b1->nu) / b1->E + (1.0 - b2->nu * b2->nu) / b2->E);
	else
		d->Estar = NAN;
	d->Re = 1.0 / (1.0 / b1->R + 1.0 / b2->R);
	d->kH = 4.0 / 3.0 * d->Estar * sqrt(d->Re);
	d->k_derived = 0;
	ki = stiffness_index(sc->law);
	if (sc->law != NULL && sc->law->k_hertz != NULL && ki >= 0 && b1->has_material &&
	    b2->has_material && isfinite(d->kH) && d->kH > 0) {
		sc->par[ki] = sc->law->k_hertz(sc->par, d->kH);
		d->k_derived = 1;
	}
	return HB_OK;
}

/* ---------------------------------------------------------------- */
/* The key table */

enum ktype {
	K_DOUBLE, K_LONG, K_INT, K_STRING, K_LAW, K_EXT, K_STEPPER, K_BOOL, K_REDUCE,
};

enum kspecial { SP_NONE, SP_MATERIAL, SP_RHO, SP_MASS, SP_FULL };

struct keydef {
	const char *key;
	const char *section; /* panel section */
	const char *label;
	int type;
	const struct unit_dim *dim;
	double lo, hi;
	int lo_open, hi_open;
	size_t off;
	size_t size;         /* strings */
	int special;
	const char *help;
};

#define OFF(f) offsetof(struct scene, f)
#define INF HUGE_VAL

static const struct keydef keys[] = {
	{ "scene.name", "scene", "name", K_STRING, NULL, 0, 0, 0, 0, OFF(name),
	  sizeof ((struct scene *)0)->name, SP_NONE, "short title of the scene" },
	{ "scene.description", "scene", "description", K_STRING, NULL, 0, 0, 0, 0,
	  OFF(description), sizeof ((struct scene *)0)->description, SP_NONE,
	  "one or two sentences: what the scene shows" },
	{ "scene.law", "law", "law", K_LAW, NULL, 0, 0, 0, 0, OFF(law), 0, SP_NONE,
	  "contact law; changing it loads the law's defaults" },
	{ "scene.extension", "law", "extension", K_EXT, NULL, 0, 0, 0, 0, OFF(ext), 0, SP_NONE,
	  "rule R1: adhesive continuation to x_c > 0, or none (clamped)" },

#define BODY(i, s)                                                                          \
	{ "body" #i ".name", "bodies", "name (body " #i ")", K_STRING, NULL, 0, 0, 0, 0,        \
	  OFF(body[i - 1].name), sizeof ((struct scene *)0)->body[0].name, SP_NONE,             \
	  "name of body " #i },                                                                 \
	{ "body" #i ".E", "bodies", "E (body " #i ")", K_DOUBLE, &UNIT_PRESSURE, 0, INF, 1, 1,   \
	  OFF(body[i - 1].E), 0, SP_MATERIAL, "Young's modulus of body " #i },                  \
	{ "body" #i ".nu", "bodies", "nu (body " #i ")", K_DOUBLE, &UNIT_NONE, -1, 0.5, 1, 1,    \
	  OFF(body[i - 1].nu), 0, SP_MATERIAL, "Poisson's ratio of body " #i },                 \
	{ "body" #i ".rho", "bodies", "rho (body " #i ")", K_DOUBLE, &UNIT_DENSITY, 0, INF, 1,   \
	  1, OFF(body[i - 1].rho), 0, SP_RHO, "density of body " #i "; m = 4/3 pi R^3 rho" },   \
	{ "body" #i ".R", "bodies", "R (body " #i ")", K_DOUBLE, &UNIT_LENGTH, 0, INF, 1, 0,     \
	  OFF(body[i - 1].R), 0, SP_NONE, "radius of body " #i "; inf for a flat" },            \
	{ "body" #i ".mass", "bodies", "mass (body " #i ")", K_DOUBLE, &UNIT_MASS, 0, INF, 1,    \
	  0, OFF(body[i - 1].mass), 0, SP_MASS, s }
	BODY(1, "mass of body 1: given, or derived from rho and R"),
	BODY(2, "mass of body 2: given (inf: a fixed obstacle), or derived from rho and R"),
#undef BODY

	{ "loads.g", "loads", "g", K_DOUBLE, &UNIT_ACCEL, -INF, INF, 1, 1, OFF(loads.g), 0,
	  SP_NONE, "gravity along -n1 on both bodies: F_ei += -m_i g" },
	{ "loads.F1", "loads", "F1", K_DOUBLE, &UNIT_FORCE, -INF, INF, 1, 1, OFF(loads.F1), 0,
	  SP_NONE, "constant force on body 1 along n1" },
	{ "loads.F2", "loads", "F2", K_DOUBLE, &UNIT_FORCE, -INF, INF, 1, 1, OFF(loads.F2), 0,
	  SP_FULL, "constant force on body 2 along n1 (full system)" },
	{ "loads.ramp", "loads", "ramp", K_BOOL, NULL, 0, 0, 0, 0, OFF(loads.ramp), 0, SP_NONE,
	  "the S-ramp loads of the second study (eqs. u_1, u_2): yes or no" },
	{ "loads.F_e0", "loads", "F_e0", K_DOUBLE, &UNIT_FORCE, 0, INF, 0, 1, OFF(loads.Fe0), 0,
	  SP_NONE, "ramp: force drawing the bodies together, from F_e0 to 2 F_e0" },
	{ "loads.T_e", "loads", "T_e", K_DOUBLE, &UNIT_TIME, 0, INF, 1, 1, OFF(loads.Te), 0,
	  SP_NONE, "ramp: duration of the growth of the drawing force" },
	{ "loads.T_s", "loads", "T_s", K_DOUBLE, &UNIT_TIME, 0, INF, 1, 1, OFF(loads.Ts), 0,
	  SP_NONE, "ramp: time in which the centre of mass is brought to rest" },

	{ "initial.x0", "initial", "x0", K_DOUBLE, &UNIT_LENGTH, 0, INF, 0, 1, OFF(init.x0), 0,
	  SP_NONE, "initial gap (relative displacement), >= 0" },
	{ "initial.v0", "initial", "v0", K_DOUBLE, &UNIT_VELOCITY, -INF, INF, 1, 1,
	  OFF(init.v0), 0, SP_NONE, "initial relative velocity (negative: approaching)" },
	{ "initial.x_m0", "initial", "x_m0", K_DOUBLE, &UNIT_LENGTH, -INF, INF, 1, 1,
	  OFF(init.xm0), 0, SP_FULL, "initial position of the centre of mass (full system)" },
	{ "initial.v_m0", "initial", "v_m0", K_DOUBLE, &UNIT_VELOCITY, -INF, INF, 1, 1,
	  OFF(init.vm0), 0, SP_FULL, "initial velocity of the centre of mass (full system)" },

	{ "run.T", "run", "T", K_DOUBLE, &UNIT_TIME, 0, INF, 1, 1, OFF(run.T), 0, SP_NONE,
	  "end of ordinary time" },
	{ "run.J", "run", "J", K_LONG, NULL, 1, 1e18, 0, 0, OFF(run.J), 0, SP_NONE,
	  "jump cap" },
	{ "run.stepper", "run", "stepper", K_STEPPER, NULL, 0, 0, 0, 0, OFF(run.stepper), 0,
	  SP_NONE, "stepper: dop853 (with dense output), rk8pd, rkf45, rkck, msbdf, rk4imp, "
	  "bsimp, or auto (dop853, then bsimp for the contacts once one is found stiff)" },
	{ "run.rtol", "run", "rtol", K_DOUBLE, &UNIT_NONE, 0, 1, 1, 1, OFF(run.rtol), 0,
	  SP_NONE, "relative tolerance of the integrator" },
	{ "run.atol", "run", "atol", K_DOUBLE, &UNIT_NONE, 0, 1, 1, 1, OFF(run.atol), 0,
	  SP_NONE, "absolute tolerance, relative to each component's scale" },
	{ "run.h_max", "run", "h_max", K_DOUBLE, &UNIT_TIME, 0, INF, 0, 1, OFF(run.h_max), 0,
	  SP_NONE, "largest step inside a contact; 0: none" },
	{ "run.max_samples", "run", "max_samples", K_LONG, NULL, 1024, 1e18, 0, 0,
	  OFF(run.max_samples), 0, SP_NONE, "arc memory bound: thinning starts beyond this" },
	{ "run.chatter", "run", "chatter", K_INT, NULL, 2, INT_MAX, 0, 0, OFF(run.chatter), 0,
	  SP_NONE, "most jumps allowed at one instant of ordinary time" },
	{ "run.reductions", "run", "reductions", K_REDUCE, NULL, 0, 0, 0, 0, OFF(run.reduce), 0,
	  SP_NONE, "all, none, or a comma list of flight, contact, com" },
	{ "run.kinks", "run", "kinks", K_BOOL, NULL, 0, 0, 0, 0, OFF(run.kinks), 0, SP_NONE,
	  "end steps on the kinks of the law and the loads (no: only to measure their effect)" },
};
#define NKEYS (sizeof keys / sizeof keys[0])

static const struct keydef *
keydef_find(const char *key)
{
	for (size_t i = 0; i < NKEYS; i++)
		if (strcmp(keys[i].key, key) == 0)
			return &keys[i];
	return NULL;
}

/* "(0, 1)", "[0, inf)", "(0, inf]", "any" */
static void
range_str(double lo, double hi, int lo_open, int hi_open, const struct unit_dim *dim,
          char *buf, size_t n)
{
	char l[32], h[32], u[48] = "";

	if (lo == -INF && hi == INF && lo_open && hi_open) {
		snprintf(buf, n, "any finite value");
		return;
	}
	if (isinf(lo))
		snprintf(l, sizeof l, "%sinf", lo < 0 ? "-" : "");
	else
		snprintf(l, sizeof l, "%.6g", lo);
	if (isinf(hi))
		snprintf(h, sizeof h, "%sinf", hi < 0 ? "-" : "");
	else
		snprintf(h, sizeof h, "%.6g", hi);
	if (dim != NULL)
		units_dim_str(*dim, u, sizeof u);
	snprintf(buf, n, "%c%s, %s%c%s%s", lo_open ? '(' : '[', l, h, hi_open ? ')' : ']',
	    u[0] ? " " : "", u);
}

static int
in_range(double v, double lo, double hi, int lo_open, int hi_open)
{
	if (isnan(v))
		return 0;
	if (lo_open ? !(v > lo) : !(v >= lo))
		return 0;
	if (hi_open ? !(v < hi) : !(v <= hi))
		return 0;
	return 1;
}

static double
exponent_p(const struct scene *sc)
{
	return sc->law != NULL ? law_exponent_p(sc->law, sc->par) : 1;
}

static double
exponent_n(const struct scene *sc)
{
	return sc->law != NULL ? law_exponent_n(sc->law, sc->par) : 1;
}

static struct unit_dim
lawpar_dim(const struct scene *sc, int i)
{
	return units_resolve(sc->law->params[i].dim, exponent_p(sc), exponent_n(sc));
}

/* Formats a value of a double key for messages and the panel. */
static void
value_str(double v, struct unit_dim dim, char *buf, size_t n)
{
	units_format(v, dim, 6, buf, n);
}

static void
law_names(char *buf, size_t n)
{
	const struct law_type *const *l = law_list();

	buf[0] = '\0';
	for (int i = 0; l[i] != NULL; i++) {
		size_t len = strlen(buf);
		snprintf(buf + len, n - len, "%s%s", i ? ", " : "", l[i]->name);
	}
}

static int
parse_bool(const char *t, int *out)
{
	static const char *const yes[] = { "yes", "1", "true", "on" };
	static const char *const no[] = { "no", "0", "false", "off" };

	for (size_t i = 0; i < 4; i++) {
		if (strcasecmp(t, yes[i]) == 0)
			return *out = 1, 0;
		if (strcasecmp(t, no[i]) == 0)
			return *out = 0, 0;
	}
	return -1;
}

static int
parse_reduce(const char *t, int *out)
{
	char buf[128];
	char *tok, *save = NULL;
	int r = 0;

	if (strcasecmp(t, "all") == 0)
		return *out = REDUCE_ALL, 0;
	if (strcasecmp(t, "none") == 0)
		return *out = 0, 0;
	if (strlen(t) >= sizeof buf)
		return -1;
	strcpy(buf, t);
	for (tok = strtok_r(buf, ", \t", &save); tok != NULL; tok = strtok_r(NULL, ", \t", &save)) {
		if (strcasecmp(tok, "flight") == 0)
			r |= REDUCE_FLIGHT;
		else if (strcasecmp(tok, "contact") == 0)
			r |= REDUCE_CONTACT;
		else if (strcasecmp(tok, "com") == 0)
			r |= REDUCE_COM;
		else
			return -1;
	}
	*out = r;
	return 0;
}

static void
reduce_str(int r, char *buf, size_t n)
{
	if ((r & REDUCE_ALL) == REDUCE_ALL) {
		snprintf(buf, n, "all");
		return;
	}
	if (r == 0) {
		snprintf(buf, n, "none");
		return;
	}
	snprintf(buf, n, "%s%s%s%s%s", r & REDUCE_FLIGHT ? "flight" : "",
	    (r & REDUCE_FLIGHT) && (r & (REDUCE_CONTACT | REDUCE_COM)) ? "," : "",
	    r & REDUCE_CONTACT ? "contact" : "",
	    (r & REDUCE_CONTACT) && (r & REDUCE_COM) ? "," : "",
	    r & REDUCE_COM ? "com" : "");
}

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

/* Parses a whole number (integers or "1e5"). */
static int
parse_count(const char *key, const char *text, double *v, char *msg, size_t n)
{
	char m[200];

	if (units_parse(text, UNIT_NONE, v, m, sizeof m) != HB_OK)
		return status_set(msg, n, HB_EINVAL, "%s: %s; accepted: a whole number", key, m);
	if (*v != floor(*v))
		return status_set(msg, n, HB_EINVAL, "%s: '%s' is not a whole number", key, text);
	return HB_OK;
}

/* "KEY: MESSAGE; accepted: a number in UNIT" */
static int
unit_error(const char *key, const char *m, struct unit_dim dim, char *msg, size_t n)
{
	char u[64];

	units_dim_str(dim, u, sizeof u);
	if (u[0] == '\0')
		return status_set(msg, n, HB_EINVAL, "%s: %s; accepted: a plain number", key, m);
	return status_set(msg, n, HB_EINVAL,
	    "%s: %s; accepted: a number with a unit of %s (SI prefixes allowed), or a plain "
	    "number in %s", key, m, u, u);
}

int
scene_set(struct scene *sc, const char *key, const char *text, char *msg, size_t n)
{
	struct scene tmp = *sc;
	const struct keydef *kd;
	char t[512], m[256], r[96];
	double v;

	if (key == NULL || text == NULL)
		return status_set(msg, n, HB_EINVAL, "no key or value");
	if (trim_copy(text, t, sizeof t) != 0)
		return status_set(msg, n, HB_EINVAL, "%s: value too long", key);
	scene_derive(&tmp, NULL, 0);

	if (strncmp(key, "law.", 4) == 0) {
		int i = law_param_index(tmp.law, key + 4);
		const struct law_param *pp;
		struct unit_dim dim;

		if (tmp.law == NULL || i < 0 || strcmp(tmp.law->params[i].name, key + 4) != 0)
			return status_set(msg, n, HB_EINVAL, "%s: unknown key for law %s", key,
			    tmp.law != NULL ? tmp.law->name : "(none)");
		pp = &tmp.law->params[i];
		if ((pp->flags & LAW_PARAM_STIFFNESS) && tmp.d.k_derived)
			return status_set(msg, n, HB_EINVAL,
			    "%s: %s is derived from the materials by eq. k_hertz; give masses "
			    "instead of materials to type it; accepted: no value", key, key);
		dim = lawpar_dim(&tmp, i);
		if (units_parse(t, dim, &v, m, sizeof m) != HB_OK)
			return unit_error(key, m, dim, msg, n);
		if (!isfinite(v) || !in_range(v, pp->lo, pp->hi, pp->lo_open, pp->hi_open)) {
			range_str(pp->lo, pp->hi, pp->lo_open || isinf(pp->lo),
			    pp->hi_open || isinf(pp->hi), NULL, r, sizeof r);
			return status_set(msg, n, HB_EINVAL,
			    "%s: value %s is out of range; accepted: %s", key, t, r);
		}
		tmp.par[i] = v;
		scene_derive(&tmp, NULL, 0);
		*sc = tmp;
		return HB_OK;
	}
	if (strncmp(key, "derived.", 8) == 0)
		return status_set(msg, n, HB_EINVAL,
		    "%s: derived values are computed, never typed", key);

	kd = keydef_find(key);
	if (kd == NULL)
		return status_set(msg, n, HB_EINVAL, "%s: unknown key", key);
	if (t[0] == '\0' && kd->type != K_STRING)
		return status_set(msg, n, HB_EINVAL, "%s: empty value", key);

	char *base = (char *)&tmp;
	switch (kd->type) {
	case K_STRING:
		for (const char *c = t; *c; c++)
			if ((unsigned char)*c < 0x20 || *c == 0x7f)
				return status_set(msg, n, HB_EINVAL,
				    "%s: control characters are not accepted", key);
		for (const char *c = t + 1; *c; c++)
			if ((*c == ';' || *c == '#') && isspace((unsigned char)c[-1]))
				return status_set(msg, n, HB_EINVAL,
				    "%s: ' %c' would start a comment in a preset; accepted: text "
				    "without a space before ';' or '#'", key, *c);
		if (strlen(t) >= kd->size)
			return status_set(msg, n, HB_EINVAL,
			    "%s: too long; accepted: at most %zu bytes", key, kd->size - 1);
		memcpy(base + kd->off, t, strlen(t) + 1);
		break;
	case K_LAW: {
		const struct law_type *law = law_find(t);
		if (law == NULL) {
			law_names(r, sizeof r);
			return status_set(msg, n, HB_EINVAL,
			    "%s: unknown law '%s'; accepted: %s", key, t, r);
		}
		if (law != tmp.law) {
			tmp.law = law;
			memset(tmp.par, 0, sizeof tmp.par);
			law_defaults(law, tmp.par);
		}
		break;
	}
	case K_EXT:
		if (strcasecmp(t, "adhesive") == 0)
			tmp.ext = 1;
		else if (strcasecmp(t, "none") == 0 || strcasecmp(t, "clamped") == 0)
			tmp.ext = 0;
		else
			return status_set(msg, n, HB_EINVAL,
			    "%s: '%s' is not an extension; accepted: adhesive, none", key, t);
		break;
	case K_STEPPER: {
		int s = scene_stepper_find(t);
		if (s < 0)
			return status_set(msg, n, HB_EINVAL,
			    "%s: unknown stepper '%s'; accepted: dop853, rk8pd, rkf45, rkck, "
			    "msbdf, rk4imp, bsimp, auto", key, t);
		tmp.run.stepper = s;
		break;
	}
	case K_BOOL: {
		int b;
		if (parse_bool(t, &b) != 0)
			return status_set(msg, n, HB_EINVAL,
			    "%s: '%s' is not yes or no; accepted: yes, no, 1, 0", key, t);
		*(int *)(base + kd->off) = b;
		break;
	}
	case K_REDUCE: {
		int rr;
		if (parse_reduce(t, &rr) != 0)
			return status_set(msg, n, HB_EINVAL,
			    "%s: '%s' is not a reduction list; accepted: all, none, or a comma "
			    "list of flight, contact, com", key, t);
		tmp.run.reduce = rr;
		break;
	}
	case K_LONG:
	case K_INT: {
		int st = parse_count(key, t, &v, msg, n);
		if (st != HB_OK)
			return st;
		if (!in_range(v, kd->lo, kd->hi, kd->lo_open, kd->hi_open)) {
			if (kd->type == K_INT)
				snprintf(r, sizeof r, "whole numbers >= %g", kd->lo);
			else
				snprintf(r, sizeof r, "whole numbers >= %g", kd->lo);
			return status_set(msg, n, HB_EINVAL,
			    "%s: value %s is out of range; accepted: %s", key, t, r);
		}
		if (kd->type == K_INT)
			*(int *)(base + kd->off) = (int)v;
		else
			*(long *)(base + kd->off) = (long)v;
		break;
	}
	case K_DOUBLE:
		if (units_parse(t, *kd->dim, &v, m, sizeof m) != HB_OK)
			return unit_error(key, m, *kd->dim, msg, n);
		if (!in_range(v, kd->lo, kd->hi, kd->lo_open, kd->hi_open)) {
			range_str(kd->lo, kd->hi, kd->lo_open, kd->hi_open, kd->dim, r, sizeof r);
			return status_set(msg, n, HB_EINVAL,
			    "%s: value %s is out of range; accepted: %s", key, t, r);
		}
		*(double *)(base + kd->off) = v;
		if (kd->special != SP_NONE && kd->special != SP_FULL) {
			int bi = key[4] == '1' ? 0 : 1;
			struct scene_body *b = &tmp.body[bi];
			if (kd->special == SP_MATERIAL)
				b->has_material = 1;
			else if (kd->special == SP_RHO)
				b->mass_given = 0;
			else if (kd->special == SP_MASS) {
				b->mass_given = 1;
				b->rho = 0;
			}
		}
		break;
	default:
		return status_set(msg, n, HB_EINVAL, "%s: unknown key", key);
	}
	scene_derive(&tmp, NULL, 0);
	*sc = tmp;
	return HB_OK;
}

/* ---------------------------------------------------------------- */
/* Validation */

static int
check_double(const char *key, double v, double lo, double hi, int lo_open, int hi_open,
             struct unit_dim dim, char *msg, size_t n)
{
	char vs[64], r[96];

	if (in_range(v, lo, hi, lo_open, hi_open))
		return HB_OK;
	value_str(v, dim, vs, sizeof vs);
	range_str(lo, hi, lo_open, hi_open, &dim, r, sizeof r);
	return status_set(msg, n, HB_EINVAL, "%s: value %s is out of range; accepted: %s", key,
	    vs, r);
}

/*
 * Checks every value against the paper's admissible ranges; derives first.
 * Returns 0 or HB_EINVAL with "KEY: value V is out of range; accepted: R".
 */
int
scene_validate(struct scene *sc, char *msg, size_t n)
{
	int st;
	char lm[256];

	if (sc->law == NULL)
		return status_set(msg, n, HB_EINVAL, "scene.law: no contact law");
	for (int i = 0; i < 2; i++) {
		const struct scene_body *b = &sc->body[i];
		char key[32];

		if (b->has_material) {
			snprintf(key, sizeof key, "body%d.E", i + 1);
			if ((st = check_double(key, b->E, 0, INF, 1, 1, UNIT_PRESSURE, msg, n)))
				return st;
			snprintf(key, sizeof key, "body%d.nu", i + 1);
			if ((st = check_double(key, b->nu, -1, 0.5, 1, 1, UNIT_NONE, msg, n)))
				return st;
		}
		if (!b->mass_given && b->rho != 0) {
			snprintf(key, sizeof key, "body%d.rho", i + 1);
			if ((st = check_double(key, b->rho, 0, INF, 1, 1, UNIT_DENSITY, msg, n)))
				return st;
		}
		snprintf(key, sizeof key, "body%d.R", i + 1);
		if ((st = check_double(key, b->R, 0, INF, 1, 0, UNIT_LENGTH, msg, n)))
			return st;
		if (b->mass_given) {
			snprintf(key, sizeof key, "body%d.mass", i + 1);
			if ((st = check_double(key, b->mass, 0, INF, 1, i == 0, UNIT_MASS, msg, n)))
				return st;
		}
	}
	st = scene_derive(sc, msg, n);
	if (st != HB_OK)
		return st;
	if ((st = check_double("body1.mass", sc->d.m1, 0, INF, 1, 1, UNIT_MASS, msg, n)))
		return st;
	if ((st = check_double("body2.mass", sc->d.m2, 0, INF, 1, 0, UNIT_MASS, msg, n)))
		return st;

	for (int i = 0; i < sc->law->n_params; i++) {
		const struct law_param *pp = &sc->law->params[i];
		char key[48];

		snprintf(key, sizeof key, "law.%s", pp->name);
		if (!isfinite(sc->par[i]) || law_param_check(pp, sc->par[i], lm, sizeof lm)) {
			if (isfinite(pp->lo) || isfinite(pp->hi) || !isfinite(sc->par[i])) {
				char r[96], vs[64];
				range_str(pp->lo, pp->hi, pp->lo_open || isinf(pp->lo),
				    pp->hi_open || isinf(pp->hi), NULL, r, sizeof r);
				value_str(sc->par[i], lawpar_dim(sc, i), vs, sizeof vs);
				if ((pp->flags & LAW_PARAM_STIFFNESS) && sc->d.k_derived)
					return status_set(msg, n, HB_EINVAL,
					    "%s: derived value %s is out of range; accepted: %s "
					    "(check the materials)", key, vs, r);
				return status_set(msg, n, HB_EINVAL,
				    "%s: value %s is out of range; accepted: %s", key, vs, r);
			}
		}
	}
	if (sc->law->check != NULL && sc->law->check(sc->par, lm, sizeof lm) != HB_OK) {
		/* Name the key after the parameter the law's message begins with. */
		char name[32] = "";
		size_t k = 0;
		while (k + 1 < sizeof name && (isalnum((unsigned char)lm[k]) || lm[k] == '_')) {
			name[k] = lm[k];
			k++;
		}
		name[k] = '\0';
		int pi = law_param_index(sc->law, name);
		char vs[64];
		if (pi < 0) {
			pi = 0;
			snprintf(name, sizeof name, "%s", sc->law->params[0].name);
		}
		value_str(sc->par[pi], lawpar_dim(sc, pi), vs, sizeof vs);
		return status_set(msg, n, HB_EINVAL, "law.%s: value %s is out of range; accepted: %s",
		    name, vs, lm);
	}

	const struct scene_loads *L = &sc->loads;
	if ((st = check_double("loads.g", L->g, -INF, INF, 1, 1, UNIT_ACCEL, msg, n)))
		return st;
	if ((st = check_double("loads.F1", L->F1, -INF, INF, 1, 1, UNIT_FORCE, msg, n)))
		return st;
	if ((st = check_double("loads.F2", L->F2, -INF, INF, 1, 1, UNIT_FORCE, msg, n)))
		return st;
	if (L->ramp) {
		if ((st = check_double("loads.F_e0", L->Fe0, 0, INF, 1, 1, UNIT_FORCE, msg, n)))
			return st;
		if ((st = check_double("loads.T_e", L->Te, 0, INF, 1, 1, UNIT_TIME, msg, n)))
			return st;
		if ((st = check_double("loads.T_s", L->Ts, 0, INF, 1, 1, UNIT_TIME, msg, n)))
			return st;
	}
	const struct scene_initial *I = &sc->init;
	if ((st = check_double("initial.x0", I->x0, 0, INF, 0, 1, UNIT_LENGTH, msg, n)))
		return st;
	if ((st = check_double("initial.v0", I->v0, -INF, INF, 1, 1, UNIT_VELOCITY, msg, n)))
		return st;
	if ((st = check_double("initial.x_m0", I->xm0, -INF, INF, 1, 1, UNIT_LENGTH, msg, n)))
		return st;
	if ((st = check_double("initial.v_m0", I->vm0, -INF, INF, 1, 1, UNIT_VELOCITY, msg, n)))
		return st;
	const struct scene_run *R = &sc->run;
	if ((st = check_double("run.T", R->T, 0, INF, 1, 1, UNIT_TIME, msg, n)))
		return st;
	if (R->J < 1)
		return status_set(msg, n, HB_EINVAL,
		    "run.J: value %ld is out of range; accepted: whole numbers >= 1", R->J);
	if (R->stepper < 0 || R->stepper >= STEPPER_COUNT)
		return status_set(msg, n, HB_EINVAL,
		    "run.stepper: value %d is out of range; accepted: dop853, rk8pd, rkf45, "
		    "rkck, msbdf, rk4imp, bsimp, auto", R->stepper);
	if ((st = check_double("run.rtol", R->rtol, 0, 1, 1, 1, UNIT_NONE, msg, n)))
		return st;
	if ((st = check_double("run.atol", R->atol, 0, 1, 1, 1, UNIT_NONE, msg, n)))
		return st;
	if ((st = check_double("run.h_max", R->h_max, 0, INF, 0, 1, UNIT_TIME, msg, n)))
		return st;
	if (R->max_samples < 1024)
		return status_set(msg, n, HB_EINVAL,
		    "run.max_samples: value %ld is out of range; accepted: whole numbers >= 1024",
		    R->max_samples);
	if (R->chatter < 2)
		return status_set(msg, n, HB_EINVAL,
		    "run.chatter: value %d is out of range; accepted: whole numbers >= 2",
		    R->chatter);
	if (R->reduce < 0 || R->reduce > REDUCE_ALL)
		return status_set(msg, n, HB_EINVAL,
		    "run.reductions: value %d is out of range; accepted: all, none, or a comma "
		    "list of flight, contact, com", R->reduce);
	return HB_OK;
}

/* ---------------------------------------------------------------- */
/* Panel rows */

enum derived_id { D_ESTAR, D_RE, D_M1, D_M2, D_M, D_ETA, D_KH, D_K, D_XCS, D_COUNT };

struct row {
	int kind;   /* 0 key, 1 law parameter, 2 derived */
	const struct keydef *kd;
	int id;
};

static double
xcs(const struct scene *sc)
{
	double f = sc->d.m * sc->loads.g / sc->d.kH;

	return pow(f, 1.0 / exponent_p(sc));
}

/* Lists the rows of the panel; returns the count (at most max). */
static int
rows_list(const struct scene *sc, struct row *rows, int max)
{
	static const char *const order[] = { "bodies", "derived", "law", "loads", "initial", "run" };
	int nr = 0, full = sc->d.system == SCENE_FULL;

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
		for (size_t i = 0; i < NKEYS; i++) {
			const struct keydef *kd = &keys[i];
			if (strcmp(kd->section, order[s]) != 0)
				continue;
			if (kd->special == SP_FULL && !full)
				continue;
			PUSH(0, kd, 0);
		}
		if (strcmp(order[s], "law") == 0 && sc->law != NULL) {
			for (int i = 0; i < sc->law->n_params; i++) {
				if ((sc->law->params[i].flags & LAW_PARAM_STIFFNESS) && sc->d.k_derived)
					continue;
				PUSH(1, NULL, i);
			}
		}
	}
#undef PUSH
	return nr;
}

int
scene_nkeys(const struct scene *sc)
{
	return rows_list(sc, NULL, 0);
}

static void
derived_row(const struct scene *sc, int id, struct scene_keyinfo *o)
{
	static const struct {
		const char *key, *label, *help;
		const struct unit_dim *dim;
	} dr[D_COUNT] = {
		[D_ESTAR] = { "derived.Estar", "E*", "effective modulus ((1-nu1^2)/E1 + (1-nu2^2)/E2)^-1", &UNIT_PRESSURE },
		[D_RE] = { "derived.Re", "R_e", "effective radius (1/R1 + 1/R2)^-1", &UNIT_LENGTH },
		[D_M1] = { "derived.m1", "m1", "mass of body 1", &UNIT_MASS },
		[D_M2] = { "derived.m2", "m2", "mass of body 2", &UNIT_MASS },
		[D_M] = { "derived.m", "m", "effective mass m1 m2/(m1 + m2)", &UNIT_MASS },
		[D_ETA] = { "derived.eta", "eta", "m1/(m1 + m2)", &UNIT_NONE },
		[D_KH] = { "derived.kH", "k_H", "Hertz coefficient 4/3 E* sqrt(R_e)", NULL },
		[D_K] = { "derived.k", "k", "stiffness by eq. k_hertz", NULL },
		[D_XCS] = { "derived.xcs", "x_c^s", "static Hertz indentation (m g / k_H)^(1/p) (eq. x_static)", &UNIT_LENGTH },
	};
	double v = 0;
	struct unit_dim dim = UNIT_NONE;

	snprintf(o->key, sizeof o->key, "%s", dr[id].key);
	snprintf(o->section, sizeof o->section, "derived");
	snprintf(o->label, sizeof o->label, "%s", dr[id].label);
	snprintf(o->help, sizeof o->help, "%s", dr[id].help);
	snprintf(o->range, sizeof o->range, "derived");
	o->readonly = 1;
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
		int ki = stiffness_index(sc->law);
		struct unit_dim kd = { 1, 1, -2, -1, 0 };
		if (ki >= 0)
			kd = sc->law->params[ki].dim;
		dim = units_resolve(kd, exponent_p(sc), exponent_n(sc));
		v = id == D_KH ? sc->d.kH : (ki >= 0 ? sc->par[ki] : NAN);
		break;
	}
	case D_XCS: v = xcs(sc); break;
	default: break;
	}
	units_format(v, dim, 4, o->value, sizeof o->value);
}

int
scene_key(const struct scene *sc, int i, struct scene_keyinfo *out)
{
	struct row rows[128];
	int nr = rows_list(sc, rows, 128);

	if (i < 0 || i >= nr || i >= 128)
		return HB_EINVAL;
	memset(out, 0, sizeof *out);
	if (rows[i].kind == 2) {
		derived_row(sc, rows[i].id, out);
		return HB_OK;
	}
	if (rows[i].kind == 1) {
		const struct law_param *pp = &sc->law->params[rows[i].id];
		snprintf(out->key, sizeof out->key, "law.%s", pp->name);
		snprintf(out->section, sizeof out->section, "law");
		snprintf(out->label, sizeof out->label, "%s", pp->name);
		units_format(sc->par[rows[i].id], lawpar_dim(sc, rows[i].id), 4, out->value,
		    sizeof out->value);
		range_str(pp->lo, pp->hi, pp->lo_open || isinf(pp->lo), pp->hi_open || isinf(pp->hi),
		    NULL, out->range, sizeof out->range);
		snprintf(out->help, sizeof out->help, "%s", pp->help ? pp->help : "");
		out->readonly = 0;
		return HB_OK;
	}
	const struct keydef *kd = rows[i].kd;
	const char *base = (const char *)sc;
	snprintf(out->key, sizeof out->key, "%s", kd->key);
	snprintf(out->section, sizeof out->section, "%s", kd->section);
	snprintf(out->label, sizeof out->label, "%s", kd->label);
	snprintf(out->help, sizeof out->help, "%s", kd->help);
	switch (kd->type) {
	case K_STRING:
		snprintf(out->value, sizeof out->value, "%s", base + kd->off);
		snprintf(out->range, sizeof out->range, "text");
		break;
	case K_LAW:
		snprintf(out->value, sizeof out->value, "%s", sc->law ? sc->law->name : "");
		law_names(out->range, sizeof out->range);
		break;
	case K_EXT:
		snprintf(out->value, sizeof out->value, "%s", sc->ext ? "adhesive" : "none");
		snprintf(out->range, sizeof out->range, "adhesive, none");
		break;
	case K_STEPPER:
		snprintf(out->value, sizeof out->value, "%s", scene_stepper_name(sc->run.stepper));
		snprintf(out->range, sizeof out->range, "rk8pd rkf45 rkck msbdf rk4imp bsimp auto dop853");
		break;
	case K_BOOL:
		snprintf(out->value, sizeof out->value, "%s", *(const int *)(base + kd->off) ? "yes" : "no");
		snprintf(out->range, sizeof out->range, "yes, no");
		break;
	case K_REDUCE:
		reduce_str(sc->run.reduce, out->value, sizeof out->value);
		snprintf(out->range, sizeof out->range, "all, none, flight,contact,com");
		break;
	case K_LONG:
		snprintf(out->value, sizeof out->value, "%ld", *(const long *)(base + kd->off));
		snprintf(out->range, sizeof out->range, ">= %g", kd->lo);
		break;
	case K_INT:
		snprintf(out->value, sizeof out->value, "%d", *(const int *)(base + kd->off));
		snprintf(out->range, sizeof out->range, ">= %g", kd->lo);
		break;
	case K_DOUBLE: {
		double v = *(const double *)(base + kd->off);
		int bi = strncmp(kd->key, "body", 4) == 0 ? kd->key[4] - '1' : -1;
		if (bi >= 0 && kd->special == SP_MATERIAL && !sc->body[bi].has_material)
			snprintf(out->value, sizeof out->value, "-");
		else if (bi >= 0 && kd->special == SP_RHO && (sc->body[bi].mass_given || v == 0))
			snprintf(out->value, sizeof out->value, "-");
		else
			units_format(v, *kd->dim, 4, out->value, sizeof out->value);
		if (bi >= 0 && kd->special == SP_MASS && !sc->body[bi].mass_given)
			snprintf(out->help, sizeof out->help, "derived from rho and R (type a mass to give it)");
		range_str(kd->lo, kd->hi, kd->lo_open, kd->hi_open, kd->dim, out->range,
		    sizeof out->range);
		break;
	}
	default:
		break;
	}
	return HB_OK;
}

/* ---------------------------------------------------------------- */
/* Loads */

static double
ramp_S(double w)
{
	if (w < 0)
		return 0;
	if (w > 1)
		return 1;
	return 0.5 * (1.0 - cos(M_PI * w));
}

static double
ramp_Sd(double w)
{
	if (w < 0 || w > 1)
		return 0;
	return 0.5 * M_PI * sin(M_PI * w);
}

/* The drawing force of the ramp, F_e0 (1 + S(t/T_e)). */
static double
ramp_draw(const struct scene *sc, double t)
{
	return sc->loads.Fe0 * (1.0 + ramp_S(t / sc->loads.Te));
}

/* a(t) = v_m0 / T_s S'(t / T_s) (eq. a_of_t). */
static double
ramp_a(const struct scene *sc, double t)
{
	return sc->init.vm0 / sc->loads.Ts * ramp_Sd(t / sc->loads.Ts);
}

void
scene_loads_at(const struct scene *sc, double t, double *Fe1, double *Fe2)
{
	const struct scene_loads *L = &sc->loads;
	double m1 = sc->d.m1, m2 = sc->d.m2;
	double f1 = L->F1 - m1 * L->g, f2 = 0;

	if (L->ramp)
		f1 -= ramp_draw(sc, t) + m1 * ramp_a(sc, t);
	if (sc->d.system == SCENE_FULL) {
		f2 = L->F2 - m2 * L->g;
		if (L->ramp)
			f2 += ramp_draw(sc, t) - m2 * ramp_a(sc, t);
	}
	if (Fe1 != NULL)
		*Fe1 = f1;
	if (Fe2 != NULL)
		*Fe2 = f2;
}

/* The constant part of F_er. */
static double
fer_const(const struct scene *sc)
{
	if (sc->d.system == SCENE_FULL)
		return sc->d.etac * sc->loads.F1 - sc->d.eta * sc->loads.F2;
	return sc->loads.F1 - sc->d.m1 * sc->loads.g;
}

double
scene_Fer(const struct scene *sc, double t)
{
	double f = fer_const(sc);

	if (sc->loads.ramp) {
		f -= ramp_draw(sc, t);
		if (sc->d.system != SCENE_FULL)
			f -= sc->d.m1 * ramp_a(sc, t);
	}
	return f;
}

int
scene_load_kinks(const struct scene *sc, double t0, double t1, double *out, int max)
{
	double k[2];
	int nk = 0, cnt = 0;

	if (!sc->loads.ramp)
		return 0;
	k[0] = sc->loads.Te;
	k[1] = sc->loads.Ts;
	if (k[1] < k[0]) {
		double tt = k[0];
		k[0] = k[1];
		k[1] = tt;
	}
	nk = k[0] == k[1] ? 1 : 2;
	for (int i = 0; i < nk; i++)
		if (k[i] > t0 && k[i] < t1 && cnt < max)
			out[cnt++] = k[i];
	return cnt;
}

int
scene_Fer_constant(const struct scene *sc, double t0, double t1)
{
	(void)t1;
	if (!sc->loads.ramp)
		return 1;
	if (t0 < sc->loads.Te)
		return 0;
	/* In the reduced system the m1 a(t) term is present until T_s. */
	if (sc->d.system != SCENE_FULL && sc->init.vm0 != 0 && t0 < sc->loads.Ts)
		return 0;
	return 1;
}

/*
 * For one piece [a, b] and f(s) = cos(w s) (sine = 0) or sin(w s)
 * (sine = 1), writes I0 = int_a^b f and I1 = int_a^b (b - s) f, in forms
 * free of cancellation for short pieces: with u = b - s and h = b - a,
 *     I1 = cos(w b) Ic + sin(w b) Is            (cosine)
 *     I1 = sin(w b) Ic - cos(w b) Is            (sine)
 *     Ic = int_0^h u cos(w u) du,  Is = int_0^h u sin(w u) du
 * summed as series when w h < 1.
 */
static void
piece_trig(double w, double a, double b, int sine, double *I0, double *I1)
{
	double h = b - a, th = w * h, Ic, Is, mid = 0.5 * w * (a + b);
	double sh = sin(0.5 * th);

	if (fabs(th) < 1.0) {
		/* th^2 sum (-1)^(k+1) th^(2k-2) (2k-1)/(2k)!, th^3 sum (-1)^(k+1) th^(2k-2) 2k/(2k+1)! */
		double sc_ = 0, ss = 0, pw = 1, fc = 2, fs = 6; /* (2k)!, (2k+1)! at k = 1 */
		for (int k = 1; k <= 12; k++) {
			double sg = (k % 2) ? 1 : -1;
			sc_ += sg * pw * (2 * k - 1) / fc;
			ss += sg * pw * (2 * k) / fs;
			pw *= th * th;
			fc *= (2 * k + 1) * (2 * k + 2);
			fs *= (2 * k + 2) * (2 * k + 3);
		}
		Ic = h * h * sc_;
		Is = h * h * th * ss;
	} else {
		Ic = (th * sin(th) - 2.0 * sh * sh) / (w * w);
		Is = (sin(th) - th * cos(th)) / (w * w);
	}
	if (!sine) {
		*I0 = 2.0 * cos(mid) * sh / w;   /* (sin wb - sin wa)/w */
		*I1 = cos(w * b) * Ic + sin(w * b) * Is;
	} else {
		*I0 = 2.0 * sin(mid) * sh / w;   /* (cos wa - cos wb)/w */
		*I1 = sin(w * b) * Ic - cos(w * b) * Is;
	}
}

/*
 * The integrals of F_er over a piece [a, b] on which it is smooth:
 * I0 = int_a^b F_er, I1 = int_a^b (b - s) F_er(s) ds.
 */
static void
fer_piece(const struct scene *sc, double a, double b, double *I0, double *I1)
{
	double h = b - a, c = fer_const(sc), J0, J1;
	double mid = 0.5 * (a + b);

	*I0 = 0;
	*I1 = 0;
	if (sc->loads.ramp) {
		double Te = sc->loads.Te, Fe0 = sc->loads.Fe0;
		/* F_e0 (1 + S(s/T_e)): F_e0 before 0, 2 F_e0 after T_e,
		 * 3/2 F_e0 - F_e0/2 cos(pi s/T_e) between. */
		if (mid < 0)
			c -= Fe0;
		else if (mid > Te)
			c -= 2 * Fe0;
		else {
			c -= 1.5 * Fe0;
			piece_trig(M_PI / Te, a, b, 0, &J0, &J1);
			*I0 += 0.5 * Fe0 * J0;
			*I1 += 0.5 * Fe0 * J1;
		}
		if (sc->d.system != SCENE_FULL && mid > 0 && mid < sc->loads.Ts) {
			/* m1 a(s) = m1 v_m0 / T_s (pi/2) sin(pi s / T_s) */
			double Ts = sc->loads.Ts, A = sc->d.m1 * sc->init.vm0 / Ts * 0.5 * M_PI;
			piece_trig(M_PI / Ts, a, b, 1, &J0, &J1);
			*I0 -= A * J0;
			*I1 -= A * J1;
		}
	}
	*I0 += c * h;
	*I1 += c * h * h / 2;
}

void
scene_flight_increment(const struct scene *sc, double t0, double t1, double *dx, double *dv)
{
	double cuts[4], x = 0, v = 0, a = t0;
	int nc = 0;

	if (sc->loads.ramp) {
		double k[3] = { 0, sc->loads.Te, sc->loads.Ts };
		for (int i = 0; i < 3; i++)
			if (k[i] > t0 && k[i] < t1)
				cuts[nc++] = k[i];
		for (int i = 1; i < nc; i++)
			for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; j--) {
				double tt = cuts[j];
				cuts[j] = cuts[j - 1];
				cuts[j - 1] = tt;
			}
	}
	cuts[nc++] = t1;
	for (int i = 0; i < nc; i++) {
		double b = cuts[i], I0, I1;
		if (b <= a)
			continue;
		fer_piece(sc, a, b, &I0, &I1);
		v += I0;
		x += (t1 - b) * I0 + I1;
		a = b;
	}
	*dx = x / sc->d.m;
	*dv = v / sc->d.m;
}

/*
 * Eq. com in closed form: dv_m/dt = (F_e1 + F_e2)/(m1 + m2)
 *     = (F1 + F2)/(m1 + m2) - g - ramp a(t),
 * so v_m = v_m0 + c t - ramp v_m0 S(t/T_s) and
 * x_m = x_m0 + v_m0 t + c t^2/2 - ramp v_m0 int_0^t S(s/T_s) ds.
 */
void
scene_com(const struct scene *sc, double t, double *xm, double *vm)
{
	double c, x, v;

	if (sc->d.system != SCENE_FULL) {
		*xm = 0;
		*vm = 0;
		return;
	}
	c = (sc->loads.F1 + sc->loads.F2) / (sc->d.m1 + sc->d.m2) - sc->loads.g;
	x = sc->init.xm0 + sc->init.vm0 * t + 0.5 * c * t * t;
	v = sc->init.vm0 + c * t;
	if (sc->loads.ramp && t > 0) {
		double Ts = sc->loads.Ts, iS;
		if (t <= Ts)
			iS = 0.5 * t - Ts / (2.0 * M_PI) * sin(M_PI * t / Ts);
		else
			iS = 0.5 * Ts + (t - Ts);
		x -= sc->init.vm0 * iS;
		v -= sc->init.vm0 * ramp_S(t / Ts);
	}
	*xm = x;
	*vm = v;
}
