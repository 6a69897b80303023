/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_keys.h - the table of scene keys (private to the engine).
 *
 * One row per typed key other than the law's parameters (whose rows are the
 * law's own table, struct hb_law_param): where the value is stored, how it is
 * read and printed, its unit, admissible range, default, panel section,
 * label and meaning.  hb_scene_defaults(), hb_scene_set(), hb_scene_validate(), the
 * panel rows (hb_scene_key), the preset reader and writer and the man page's
 * PRESETS section all read this table (scene_keys.c).
 */
#ifndef HYBOUNCE_SCENE_KEYS_H
#define HYBOUNCE_SCENE_KEYS_H

#include <stddef.h>

#include "hybounce/scene.h"
#include "hybounce/units.h"

/*
 * The greatest acceleration a load may give, m/s^2: the bound of loads.g,
 * and of F1/m1 and F2/m2 (about an ultracentrifuge's; see scene_keys.c).
 */
#define SCENE_ACCEL_MAX 1e7

/* How a value is stored in struct hb_scene, and so read and printed. */
enum scene_store {
	ST_DOUBLE,  /* double, "VALUE [UNIT]" */
	ST_LONG,    /* long, a whole number */
	ST_INT,     /* int, a whole number */
	ST_STRING,  /* char[size] */
	ST_LAW,     /* const struct hb_law_type *: a law name */
	ST_EXT,     /* int: adhesive | none */
	ST_STEPPER, /* int: a stepper name */
	ST_BOOL,    /* int: yes | no */
	ST_REDUCE,  /* int: REDUCE_* flags, all | none | a comma list */
	ST_STOPWARN, /* int: stop | warn (HB_CHAIN_LIMITS_*) */
};

/* What else a value means (SP_FULL and SP_RAMP: when it is shown and checked). */
enum scene_special {
	SP_NONE,
	SP_MATERIAL, /* E, nu: typing one gives the body a material */
	SP_RHO,      /* typing it makes the mass derived again */
	SP_MASS,     /* typing it makes the mass given (and forgets rho) */
	SP_FULL,     /* used by the full system only */
	SP_RAMP,     /* used only with loads.ramp = yes */
	SP_CHAIN,    /* shown and written only for a chain (chain.n >= 1) */
};

struct scene_keydef {
	const char *key;     /* "body1.E" */
	const char *panel;   /* panel section: "bodies", "law", "loads", "initial", "run" */
	const char *label;   /* "E (body 1)" */
	int store;           /* enum scene_store */
	const struct hb_unit_dim *dim; /* ST_DOUBLE */
	struct hb_unit_range range;    /* ST_DOUBLE, ST_LONG, ST_INT */
	double def;          /* default of a number; NAN: not given */
	const char *deftext; /* default of a string or a choice */
	size_t off;          /* offset in struct hb_scene */
	size_t size;         /* ST_STRING: buffer size */
	int special;         /* enum scene_special */
	const char *help;    /* meaning */
};

/* The table, in preset order. */
extern const struct scene_keydef scene_keydefs[];
extern const int scene_nkeydefs;

/*
 * What hb_scene_get finds of a key, without formatting its value: its row in
 * the table (*kd), or for a law parameter *kd NULL and its index *li, with
 * *readonly set where the scene derives it.  HB_OK, or an error naming the
 * keys accepted.
 */
int
scene_key_resolve(const struct hb_scene *sc, const char *key, const struct scene_keydef **kd,
                  int *li, int *readonly, struct hb_scene_error *err);

/*
 * The value of a key as hb_scene_get gives it (its number for a number or
 * a whole number, its choice's text for a choice), without formatting any
 * text: the sweep reads each of its values back this way.  Returns
 * HB_SCENE_KEY_NUMBER, _WHOLE or _CHOICE, or -1 for an unknown, derived
 * (read-only) or free-text key.
 */
int
scene_key_value(const struct hb_scene *sc, const char *key, double *num, const char **word);

/* The row of a key, or NULL. */
const struct scene_keydef *
scene_keydef_find(const char *key);

/* The body (0, 1) a key belongs to, or -1. */
int
scene_keydef_body(const struct scene_keydef *kd);

/* The preset section of a key ("body1"), into buf. */
const char *
scene_keydef_section(const struct scene_keydef *kd, char *buf, size_t n);

/*
 * 1 if the key holds a value in this scene (written in a preset, validated;
 * SP_RAMP values are written always and validated with the ramp on).
 */
int
scene_keydef_present(const struct hb_scene *sc, const struct scene_keydef *kd);

/* The choices of a choice key (law, extension, stepper, yes/no, reductions). */
int
scene_keydef_choices(const struct scene_keydef *kd, const char **out, int max);

/*
 * Reads a choice ("adhesive", "yes", "flight,com", a law name ...) into *v
 * (for ST_LAW the index in hb_law_list()).  Returns 0, or -1 if not accepted.
 */
int
scene_keydef_read_choice(const struct scene_keydef *kd, const char *text, int *v);

/* The current value of a choice key as its choice's text. */
const char *
scene_keydef_choice(const struct hb_scene *sc, const struct scene_keydef *kd);

/* The value printed so that it reads back exactly ("%.17g UNIT", a name ...). */
void
scene_keydef_print(const struct hb_scene *sc, const struct scene_keydef *kd, char *buf, size_t n);

/* The resolved unit of law parameter i in this scene (p and n applied). */
struct hb_unit_dim
scene_lawpar_dim(const struct hb_scene *sc, int i);

/* The index of the law's stiffness parameter, or -1. */
int
scene_stiffness_index(const struct hb_law_type *law);

/* The typed row of a table key / of law parameter i (HB_EINVAL: no such). */
int
scene_key_info(const struct hb_scene *sc, const struct scene_keydef *kd, struct hb_scene_keyinfo *out);
int
scene_key_info_law(const struct hb_scene *sc, int i, struct hb_scene_keyinfo *out);

/*
 * run.stepper at run.rtol against the measured limits of each stepper
 * (scene_limits.c): HB_OK, or HB_EINVAL with err naming the stepper, the
 * tolerance and what is accepted.  Nothing is refused when run.limits = no.
 */
int
scene_check_stepper(const struct hb_scene *sc, struct hb_scene_error *err);

/* Fills an error (what: printf format); returns HB_EINVAL. */
int
scene_error_set(struct hb_scene_error *e, const char *key, const char *accepted,
                const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* The same with a range (and unit) as the accepted values. */
int
scene_error_range(struct hb_scene_error *e, const char *key, const struct hb_unit_range *r,
                  const struct hb_unit_dim *dim, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

#endif
