/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_override.h - the keys of one body or one interface of a chain
 * (private to the engine; scene.h: struct hb_scene_overrides):
 *
 *     body.I.E  body.I.nu  body.I.rho  body.I.R  body.I.mass  body.I.F
 *     interface.K.law  interface.K.extension  interface.K.PARAM
 *     initial.body.I.v  initial.body.I.gap
 *
 * In a preset they are the sections [body.I] and [interface.K] and the
 * keys body.I.v, body.I.gap of [initial].  hb_scene_set_text/_number,
 * hb_scene_get, hb_scene_check, the sweep's read-back, the panel and the
 * preset writer reach them through these functions.
 */
#ifndef HYBOUNCE_SCENE_OVERRIDE_H
#define HYBOUNCE_SCENE_OVERRIDE_H

#include <stddef.h>

#include "hybounce/scene.h"
#include "hybounce/units.h"

struct textbuf;

/* 1 if key has the form of an override key (its name may still be unknown). */
int
scene_override_is_key(const char *key);

/* 1 if section is [body.I] or [interface.K] of a preset. */
int
scene_override_is_section(const char *section);

/*
 * Sets an override from text (num NULL) or from a number (SI).  On error
 * the scene is unchanged and err names the key and what is accepted.
 */
int
scene_override_set(struct hb_scene *sc, const char *key, const char *text, const double *num,
                   struct hb_scene_error *err);

/* The typed value of an override key as it applies (overridden or the chain's). */
int
scene_override_get(const struct hb_scene *sc, const char *key, struct hb_scene_keyinfo *out,
                   struct hb_scene_error *err);

/* As scene_key_value (scene_keys.h) for an override key. */
int
scene_override_value(const struct hb_scene *sc, const char *key, double *num, const char **word);

/* The overrides checked against the chain: indices, ranges, materials, laws. */
int
scene_override_check(const struct hb_scene *sc, struct hb_scene_error *err);

/*
 * Appends what belongs to preset section `section` ("initial": its body.I.*
 * keys) or, for section NULL, the [body.I] and [interface.K] sections.
 */
void
scene_override_write(const struct hb_scene *sc, const char *section, struct textbuf *o);

/* The key of override i of the scene, into buf (for the panel). */
void
scene_override_key(const struct hb_scene *sc, int i, char *buf, size_t n);

/* Preset order of an entry of an override section: law/extension 0, exponents 1, the rest 2. */
int
scene_override_pass(const struct hb_scene *sc, const char *section, const char *name);

/* ---------------------------------------------------------------- */
/* Shared by scene_override.c, scene_override_check.c, scene_override_text.c */

/* The highest index a key may name (chain.n is at most 1000). */
#define SCENE_OVERRIDE_MAX_INDEX 1000

/* A number an override of a body (body.I.*) or of its initial state (initial.body.I.*) holds. */
struct scene_override_field {
	const char *name;
	const struct hb_unit_dim *dim;
	struct hb_unit_range range;
	const char *help;
};

/* The fields of HB_OVERRIDE_BODY or HB_OVERRIDE_INITIAL (*n of them), and one by name (or NULL). */
const struct scene_override_field *
scene_override_fields(int kind, int *n);
const struct scene_override_field *
scene_override_field(int kind, const char *name);

/* "none", "adhesive": an extension by its value. */
extern const char *const scene_override_ext_words[2];

/* The index in sc->over.o of (kind, index, name), or -1. */
int
scene_override_find(const struct hb_scene *sc, int kind, int index, const char *name);

/* Interface k's law, and its parameters before any derivation into par (may be NULL). */
const struct hb_law_type *
scene_override_iface_law(const struct hb_scene *sc, int k, double *par);

/* The index of law parameter name (exact), or -1. */
int
scene_override_param(const struct hb_law_type *law, const char *name);

/* "law, extension, k, p ...": the names interface keys of law accept. */
void
scene_override_iface_accepted(const struct hb_law_type *law, char *buf, size_t n);

/* HB_OK when (kind, index) is in the chain, else HB_EINVAL with err naming the range. */
int
scene_override_index_check(const struct hb_scene *sc, const char *key, int kind, int index,
                           struct hb_scene_error *err);

/* The refusal of a typed stiffness that interface k derives. */
int
scene_override_derived_error(struct hb_scene_error *err, const char *key, int k);

/* The man page's items of [body.I] and [interface.K] (section NULL) or of [initial]'s body.I.*. */
void
scene_override_mdoc(struct textbuf *t, const char *section);

#endif
