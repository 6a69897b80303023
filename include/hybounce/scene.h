/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene.h - everything a run needs: bodies and materials, the derived
 * values, the contact law and its parameters, the applied loads, the initial
 * state and the run settings.  Plain data the caller fills in (transparent,
 * like gsl_odeiv2_system); all values SI.
 *
 * The system is chosen from the bodies, never set by hand: when body 2 has
 * infinite mass (an obstacle: R2 = inf and no density, or mass = inf) the
 * scene is the reduced system H_r, otherwise the full system H_f (paper
 * eqs. Hr_f .. Hr_init and H_f .. H_init).
 *
 * Derived values (E*, R_e, m1, m2, m, eta, k_H and k by eq. k_hertz) are
 * computed by hb_scene_derive() and are never typed: k is typed only when a
 * body has no material (E, nu) or the law has no k_hertz (clamped linear).
 *
 * Keys.  Every typed value has a key "section.name" (e.g. "law.c",
 * "body1.R", "initial.x0", "run.rtol") used by presets, by --set and by the
 * explorer's parameter panel; hb_scene_set() parses "VALUE [UNIT]" for a key.
 * One table (src/core/scene_keys.c, with the law's parameter table) holds
 * each key's unit, range, default, meaning and how it is read and printed.
 *
 * Errors as data.  hb_scene_set_text(), hb_scene_set_number() and hb_scene_check()
 * fill a struct hb_scene_error: the key, what is wrong and what is accepted
 * (with the range as numbers when it is one); hb_scene_error_str() writes it
 * as "KEY: WHAT; accepted: ACCEPTED".  hb_scene_set() and hb_scene_validate() are
 * the same with the message written out.
 */
#ifndef HB_SCENE_H
#define HB_SCENE_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>

#include "law.h"
#include "units.h"

enum hb_scene_system { HB_SCENE_REDUCED = 0, HB_SCENE_FULL = 1 };

enum hb_scene_stepper {
	HB_STEPPER_RK8PD = 0, /* default: explicit Dormand-Prince 8(9) */
	HB_STEPPER_RKF45,
	HB_STEPPER_RKCK,
	HB_STEPPER_MSBDF,     /* implicit, uses the law's Jacobian */
	HB_STEPPER_RK4IMP,
	HB_STEPPER_BSIMP,
	HB_STEPPER_AUTO,      /* dop853, then bsimp for contacts once one is found stiff */
	HB_STEPPER_DOP853,    /* explicit Dormand-Prince 8(5,3) with dense output (the engine's own) */
	HB_STEPPER_VERN98,    /* explicit Verner 9(8), 16 stages (the engine's own) */
	HB_STEPPER_COUNT
};

/* Reductions of DESIGN.md section 3 (all on by default; the bench turns them off). */
enum {
	HB_REDUCE_FLIGHT = 1,  /* closed-form flight when F_er is constant on the interval */
	HB_REDUCE_CONTACT = 2, /* integrate (x_c, v, z_c) in contact and recover x = x_e + x_c */
	HB_REDUCE_COM = 4,     /* centre of mass in closed form, not integrated */
	HB_REDUCE_ALL = 7,
};

struct hb_scene_body {
	char name[64];
	int has_material; /* E and nu given */
	double E, nu;     /* Pa, 1 */
	double rho;       /* kg/m^3; 0 when not given */
	double R;         /* m; INFINITY for a flat (half-space) */
	double mass;      /* kg: given, or 4/3 pi R^3 rho (derived); INFINITY for an obstacle */
	int mass_given;   /* 1 if mass was typed rather than derived */
};

struct hb_scene_loads {
	double g;         /* gravity, m/s^2, acting along -n1 on both bodies: F_ei += -m_i g */
	double F1, F2;    /* constant forces on body 1 and body 2 along n1, N */
	int ramp;         /* 1: the S-ramp loads of the second study, eqs. u_1 and u_2 */
	double Fe0;       /* N */
	double Te, Ts;    /* s */
};

struct hb_scene_initial {
	double x0, v0;    /* relative displacement (>= 0) and velocity */
	double xm0, vm0;  /* centre of mass (full system only) */
};

struct hb_scene_run {
	double T;         /* end of ordinary time, s */
	long J;           /* jump cap */
	int stepper;      /* enum hb_scene_stepper */
	double rtol;      /* relative tolerance */
	double atol;      /* absolute tolerance, relative to each component's scale */
	double h_max;     /* largest step inside a contact, s; 0: none */
	long max_samples; /* arc memory bound: thinning starts beyond this */
	int chatter;      /* most jumps allowed at one instant of ordinary time */
	int reduce;       /* REDUCE_* flags */
	int kinks;        /* 1: steps end on the law's and the loads' kinks (DESIGN.md 4a) */
	int limits;       /* 1: refuse a stepper at a tolerance where its global error is
	                   * more than 10 x rk8pd's on the paper's studies (0: only to measure it) */
	double max_indent; /* a chain's: largest indentation, a fraction of the smaller radius */
	int chain_limits; /* a chain's model limits (docs/chains.md 6): HB_CHAIN_LIMITS_* */
};

/* What a chain does where it leaves its model's limits (run.chain_limits). */
enum { HB_CHAIN_LIMITS_STOP = 0, HB_CHAIN_LIMITS_WARN = 1 };

/*
 * A chain of n bodies on the axis (docs/chains.md): n = 0 for the
 * two-body scene.  Every body is body 1 of the scene and every interface
 * has the scene's law, but where the overrides (struct hb_scene_overrides)
 * say otherwise; body 1 is the lowest, body n (the striker) the highest.
 */
struct hb_scene_chain {
	int n;            /* bodies; 0: not a chain */
	int floor;        /* 1: a fixed obstacle below body 1 (interface 0) */
	double spacing;   /* gap between neighbours (and body 1 and the floor), m */
	double v;         /* the striker's (body n's) initial velocity, m/s */
};

/*
 * What differs from the uniform chain for one body or one interface
 * (docs/chains.md section 7): the keys "body.I.NAME" (I = 1..n: E, nu, rho,
 * R, mass, F), "interface.K.NAME" (law, extension, or a parameter of that
 * interface's law) and "initial.body.I.NAME" (v, gap), read and written by
 * hb_scene_set()/hb_scene_get() like every key.  They are kept in a table of
 * fixed size inside the scene, so that a scene stays a plain value copied
 * by assignment; a scene holds at most HB_SCENE_MAX_OVERRIDES of them.
 */
enum { HB_SCENE_MAX_OVERRIDES = 64 };

enum hb_scene_override_kind {
	HB_OVERRIDE_NONE = 0,
	HB_OVERRIDE_BODY,    /* body.I.NAME */
	HB_OVERRIDE_IFACE,   /* interface.K.NAME */
	HB_OVERRIDE_INITIAL, /* initial.body.I.NAME */
};

struct hb_scene_override {
	int kind;         /* enum hb_scene_override_kind */
	int index;        /* body I (1 = the lowest .. n) or interface K (0 = the floor's) */
	char name[16];    /* "R", "F", "law", "c", "v" ... */
	double value;     /* SI; law: its index in hb_law_list(); extension: 1 adhesive, 0 none */
};

struct hb_scene_overrides {
	int n;
	struct hb_scene_override o[HB_SCENE_MAX_OVERRIDES]; /* o[n..] zero */
};

struct hb_scene_derived {
	int system;       /* enum hb_scene_system */
	double Estar;     /* Pa; NAN when a body has no material */
	double Re;        /* m */
	double m1, m2;    /* kg (m2 = INFINITY in the reduced system) */
	double m;         /* effective mass m1 m2 / (m1 + m2) */
	double eta, etac; /* m1/(m1+m2), m2/(m1+m2) (full system) */
	double kH;        /* 4/3 E* sqrt(R_e) */
	int k_derived;    /* 1 if law k comes from k_H by eq. k_hertz */
};

struct hb_scene {
	char name[96];          /* short title */
	char description[256];  /* one or two sentences */
	struct hb_scene_body body[2];
	const struct hb_law_type *law;
	double par[HB_LAW_MAX_PARAMS]; /* law parameters, in the law's table order */
	int ext;                /* rule R1: 1 adhesive continuation (default), 0 clamped */
	struct hb_scene_loads loads;
	struct hb_scene_initial init;
	struct hb_scene_run run;
	struct hb_scene_chain chain;
	struct hb_scene_derived d; /* filled by hb_scene_derive() */
	struct hb_scene_overrides over; /* a chain's bodies and interfaces that differ */
};

/* An error of a key, as data. */
struct hb_scene_error {
	char key[48];        /* "law.alpha"; "" when no key is concerned */
	char what[256];      /* "value 1.2 is out of range" */
	char accepted[192];  /* "(0, 1)", "rk8pd, rkf45, ..."; "" if none */
	int has_range;       /* 1: range holds the accepted numbers */
	struct hb_unit_range range;
};

/* "KEY: WHAT; accepted: ACCEPTED" into buf; returns buf. */
char *
hb_scene_error_str(const struct hb_scene_error *e, char *buf, size_t n);

/* A valid neutral scene: a steel ball dropped on a Hertz elastic flat. */
void
hb_scene_defaults(struct hb_scene *sc);

/*
 * Computes the derived values (and k when derivable).  Returns 0, or
 * HB_EINVAL with a message when they cannot be computed (e.g. no mass).
 */
int
hb_scene_derive(struct hb_scene *sc, char *msg, size_t n);

/*
 * Checks every value against the paper's admissible ranges (alpha in (0,1),
 * gamma in [-beta, beta], n, p >= 1, masses and stiffnesses > 0, x0 >= 0,
 * tolerances > 0 ...).  Returns 0, or HB_EINVAL with "KEY: value V is out
 * of range; accepted: RANGE" in msg.  Calls hb_scene_derive() first.
 */
int
hb_scene_validate(struct hb_scene *sc, char *msg, size_t n);

/*
 * Sets key ("law.c", "body1.E", "initial.x0", "run.stepper", "scene.law",
 * "scene.extension" ...) from text with an optional unit.  Setting
 * "scene.law" loads the new law's defaults.  Checks the unit and the range
 * of that one value; on error nothing changes and HB_EINVAL is returned
 * with a message naming the key and what is accepted.
 */
int
hb_scene_set(struct hb_scene *sc, const char *key, const char *text, char *msg, size_t n);

/* The same with the error as data (err may be NULL). */
int
hb_scene_set_text(struct hb_scene *sc, const char *key, const char *text, struct hb_scene_error *err);

/* Sets a number (SI) or whole-number key from a double; same checks. */
int
hb_scene_set_number(struct hb_scene *sc, const char *key, double v, struct hb_scene_error *err);

/* hb_scene_validate() with the error as data (err may be NULL). */
int
hb_scene_check(struct hb_scene *sc, struct hb_scene_error *err);

enum hb_scene_key_kind {
	HB_SCENE_KEY_NUMBER, /* a real number with a unit */
	HB_SCENE_KEY_WHOLE,  /* a whole number */
	HB_SCENE_KEY_TEXT,   /* free text */
	HB_SCENE_KEY_CHOICE, /* one of choices[] */
};

/* One row of the parameter panel, and the typed value of a key. */
struct hb_scene_keyinfo {
	char key[48];       /* "law.alpha" */
	char section[16];   /* "bodies", "derived", "law", "loads", "initial", "run" */
	char label[32];     /* "alpha" / "E (body 1)" */
	char value[64];     /* for display, with unit: "0.35", "200 GPa"; "-" not given */
	char range[64];     /* accepted range for display, e.g. "(0, 1)" */
	char help[128];
	int readonly;       /* derived values */
	char edit[64];      /* the value as text that reads back exactly ("20 mm") */
	/* Typed: */
	int kind;           /* enum hb_scene_key_kind */
	double number;      /* NUMBER, WHOLE: the SI value; NAN when not given */
	struct hb_unit_dim dim;/* NUMBER: its dimension (law exponents applied) */
	char unit[32];      /* NUMBER: the SI unit ("N s m^-5/2"; "" dimensionless) */
	struct hb_unit_range limits; /* NUMBER, WHOLE: the admissible range */
	const char *choices[16];  /* CHOICE: the accepted texts */
	int nchoices;
	int choice;         /* CHOICE: index of the current value in choices */
};

/*
 * The typed value of any key (also those the panel hides: F2 in the
 * reduced system, law.k when derived ...).  Returns 0, or HB_EINVAL with
 * err filled for an unknown key.
 */
int
hb_scene_get(const struct hb_scene *sc, const char *key, struct hb_scene_keyinfo *out,
          struct hb_scene_error *err);

/*
 * The typed row of parameter i of a law at its defaults (number = the
 * law's default, unit at the default exponents), for references such as
 * --list-laws.  Returns 0, or HB_EINVAL for a bad i.
 */
int
hb_scene_law_param_info(const struct hb_law_type *law, int i, struct hb_scene_keyinfo *out);

/* Number of rows (depends on law and system). */
int
hb_scene_nkeys(const struct hb_scene *sc);

/* Fills row i (0 <= i < hb_scene_nkeys). Returns 0 or HB_EINVAL for a bad i. */
int
hb_scene_key(const struct hb_scene *sc, int i, struct hb_scene_keyinfo *out);

/* Applied loads at time t: F_e1, F_e2 (body 2 ignored in the reduced system). */
void
hb_scene_loads_at(const struct hb_scene *sc, double t, double *Fe1, double *Fe2);

/* F_er(t) (paper eq. u): F_e1 in the reduced system. */
double
hb_scene_Fer(const struct hb_scene *sc, double t);

/*
 * Times in (t0, t1) where the loads have a kink (T_s, T_e of the ramp),
 * ascending, at most max.  Returns the count.
 */
int
hb_scene_load_kinks(const struct hb_scene *sc, double t0, double t1, double *out, int max);

/* 1 if F_er is constant on [t0, t1]. */
int
hb_scene_Fer_constant(const struct hb_scene *sc, double t0, double t1);

/*
 * Closed-form flight increments under F_er alone (no contact force):
 *     dx = int_{t0}^{t1} (t1 - s) F_er(s) ds / m,  dv = int_{t0}^{t1} F_er(s) ds / m.
 */
void
hb_scene_flight_increment(const struct hb_scene *sc, double t0, double t1, double *dx, double *dv);

/* Centre of mass x_m(t), v_m(t) in closed form (eq. com); 0 in the reduced system. */
void
hb_scene_com(const struct hb_scene *sc, double t, double *xm, double *vm);

/* Name of a stepper ("rk8pd" ...) and lookup by name (-1 if unknown). */
const char *
hb_scene_stepper_name(int stepper);
int
hb_scene_stepper_find(const char *name);

HB_END_DECLS

#endif
