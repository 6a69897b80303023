/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_defaults.c - the default scene (from the key table) and the derived
 * values of a scene (see scene.h); the names of the steppers:
 * scene_stepper.c.
 *
 * Bodies.  A body is given by its material (E and nu) or not, and by its
 * mass or by rho and R.  A body 2 of infinite mass (mass = inf, or R = inf
 * without rho) is an obstacle: the reduced system.
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"

#include "scene_keys.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---------------------------------------------------------------- */
/* Defaults and derived values */

/*
 * A neutral valid scene: a steel ball (R = 20 mm) dropped from 10 mm on a
 * Hertz elastic steel flat of infinite mass, under gravity.  Every value
 * is the default of its row in the key table (scene_keys.c).
 */
void
hb_scene_defaults(struct hb_scene *sc)
{
	char *base = (char *)sc;

	memset(sc, 0, sizeof *sc);
	for (int i = 0; i < scene_nkeydefs; i++) {
		const struct scene_keydef *kd = &scene_keydefs[i];
		int b = scene_keydef_body(kd), v = 0;

		switch (kd->store) {
		case ST_DOUBLE:
			if (isnan(kd->def))
				break; /* not given: no density, or a derived mass */
			*(double *)(base + kd->off) = kd->def;
			if (b >= 0 && kd->special == SP_MATERIAL)
				sc->body[b].has_material = 1;
			break;
		case ST_LONG:
			*(long *)(base + kd->off) = (long)kd->def;
			break;
		case ST_INT:
			*(int *)(base + kd->off) = (int)kd->def;
			break;
		case ST_STRING:
			snprintf(base + kd->off, kd->size, "%s", kd->deftext);
			break;
		case ST_LAW:
			scene_keydef_read_choice(kd, kd->deftext, &v);
			sc->law = hb_law_list()[v];
			hb_law_defaults(sc->law, sc->par);
			break;
		default:
			scene_keydef_read_choice(kd, kd->deftext, &v);
			*(int *)(base + kd->off) = v;
			break;
		}
	}
	hb_scene_derive(sc, NULL, 0);
}

/* The mass of body i: given, or 4/3 pi R^3 rho, or INFINITY for an obstacle. */
static int
body_mass(const struct hb_scene_body *b, int i, double *mass, char *msg, size_t n)
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
	return hb_status_set(msg, n, HB_EINVAL,
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
hb_scene_derive(struct hb_scene *sc, char *msg, size_t n)
{
	struct hb_scene_derived *d = &sc->d;
	/* in a chain every body is body 1: its interfaces are body 1 on body 1 */
	const struct hb_scene_body *b1 = &sc->body[0], *b2 = sc->chain.n > 0 ? b1 : &sc->body[1];
	double m1 = NAN, m2 = NAN;
	int st, ki;

	st = body_mass(b1, 0, &m1, msg, n);
	if (st == HB_OK)
		st = sc->chain.n > 0 ? (m2 = m1, HB_OK) : body_mass(b2, 1, &m2, msg, n);
	if (st != HB_OK)
		return st;
	sc->body[0].mass = m1;
	if (sc->chain.n == 0)
		sc->body[1].mass = m2;
	d->m1 = m1;
	if (isinf(m2)) {
		d->system = HB_SCENE_REDUCED;
		d->m2 = INFINITY;
		d->m = m1;
		d->eta = 0;  /* the limits of m1/(m1+m2) and m2/(m1+m2) as m2 -> inf */
		d->etac = 1;
	} else {
		d->system = HB_SCENE_FULL;
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
	ki = scene_stiffness_index(sc->law);
	if (sc->law != NULL && sc->law->k_hertz != NULL && ki >= 0 && b1->has_material &&
	    b2->has_material && isfinite(d->kH) && d->kH > 0) {
		sc->par[ki] = sc->law->k_hertz(sc->par, d->kH);
		d->k_derived = 1;
	}
	return HB_OK;
}

