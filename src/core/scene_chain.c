/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * A chain scene's bodies and interfaces, one at a time (scene_chain.h).
 *
 * A uniform chain: every body is the scene's body 1, every interface has
 * the scene's law, the striker (body n) moves at striker.v, the bodies are
 * chain.spacing apart.  The overrides of the scene (scene.h: body.I.*,
 * interface.K.*, initial.body.I.*) replace what they name for one body or
 * one interface.  An interface's stiffness is derived, as the scene's is
 * (hb_scene_derive: eq. k_hertz from k_H = 4/3 E* sqrt(R_e)), from ITS two
 * bodies: the upper one in the role of the paper's body 1, the lower one
 * (or the floor, the scene's body 2) in that of its body 2; so that the
 * uniform chain gets the scene's k to the bit, with the same expressions.
 */
#include "scene_chain.h"

#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* The override of kind/index/name, or NULL. */
static const struct hb_scene_override *
find(const struct hb_scene *sc, int kind, int index, const char *name)
{
	for (int i = 0; i < sc->over.n && i < HB_SCENE_MAX_OVERRIDES; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		if (o->kind == kind && o->index == index && strcmp(o->name, name) == 0)
			return o;
	}
	return NULL;
}

int
scene_chain_body_full(const struct hb_scene *sc, int i, struct scene_chain_bodyx *b)
{
	const struct hb_scene_body *b1 = &sc->body[0];
	const struct hb_scene_override *E, *nu, *rho, *R, *mass, *F, *v, *gap;
	int I = i + 1;

	if (sc->chain.n <= 0 || i < 0 || i >= sc->chain.n)
		return HB_EINVAL;
	memset(b, 0, sizeof *b);
	E = find(sc, HB_OVERRIDE_BODY, I, "E");
	nu = find(sc, HB_OVERRIDE_BODY, I, "nu");
	rho = find(sc, HB_OVERRIDE_BODY, I, "rho");
	R = find(sc, HB_OVERRIDE_BODY, I, "R");
	mass = find(sc, HB_OVERRIDE_BODY, I, "mass");
	F = find(sc, HB_OVERRIDE_BODY, I, "F");
	v = find(sc, HB_OVERRIDE_INITIAL, I, "v");
	gap = find(sc, HB_OVERRIDE_INITIAL, I, "gap");

	b->has_material = b1->has_material || (E != NULL && nu != NULL);
	b->half = !b1->has_material && (E != NULL) != (nu != NULL);
	b->E = E != NULL ? E->value : b1->E;
	b->nu = nu != NULL ? nu->value : b1->nu;
	b->R = R != NULL ? R->value : b1->R;
	b->both = rho != NULL && mass != NULL;
	if (mass != NULL) {
		b->mass_given = 1;
		b->mass = mass->value;
		b->rho = 0;
	} else if (rho != NULL || (R != NULL && !b1->mass_given)) {
		b->rho = rho != NULL ? rho->value : b1->rho;
		b->mass = b->rho > 0 && isfinite(b->R) ? 4.0 / 3.0 * M_PI * b->R * b->R * b->R * b->rho
		                                       : NAN;
	} else { /* body 1's mass, as the scene derived it */
		b->mass_given = b1->mass_given;
		b->rho = b1->mass_given ? 0 : b1->rho;
		b->mass = sc->d.m1;
	}
	b->F = F != NULL ? F->value : 0.0;
	b->v0 = v != NULL ? v->value : i == sc->chain.n - 1 ? sc->chain.v : 0.0;
	b->gap = gap != NULL ? gap->value : i == 0 && !sc->chain.floor ? 0.0 : sc->chain.spacing;
	return HB_OK;
}

int
scene_chain_body(const struct hb_scene *sc, int i, struct scene_chain_body *out)
{
	struct scene_chain_bodyx b;

	if (scene_chain_body_full(sc, i, &b) != HB_OK)
		return HB_EINVAL;
	out->m = b.mass;
	out->R = isfinite(b.R) ? b.R : 0.0;
	out->F = -out->m * sc->loads.g;
	if (b.F != 0.0)
		out->F += b.F;
	out->v0 = b.v0;
	out->gap = b.gap;
	return HB_OK;
}

int
scene_chain_iface_full(const struct hb_scene *sc, int k, struct scene_chain_iface *out,
                       int *derivable, int *floorless)
{
	const struct hb_scene_override *law, *ext;
	struct scene_chain_bodyx hi, lo;
	int ki, lo_mat;
	double Estar, Re, kH;

	*derivable = *floorless = 0;
	if (sc->chain.n <= 0 || k < !sc->chain.floor || k >= sc->chain.n)
		return HB_EINVAL;
	law = find(sc, HB_OVERRIDE_IFACE, k, "law");
	ext = find(sc, HB_OVERRIDE_IFACE, k, "extension");
	out->law = sc->law;
	memcpy(out->par, sc->par, sizeof out->par);
	if (law != NULL && law->value >= 0) {
		const struct hb_law_type *const *list = hb_law_list();
		int n = 0;
		while (list[n] != NULL)
			n++;
		if ((int)law->value < n && list[(int)law->value] != sc->law) {
			out->law = list[(int)law->value];
			memset(out->par, 0, sizeof out->par);
			hb_law_defaults(out->law, out->par);
		}
	}
	out->ext = ext != NULL ? ext->value != 0 : sc->ext;
	for (int i = 0; i < sc->over.n && i < HB_SCENE_MAX_OVERRIDES; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		int pi;
		if (o->kind != HB_OVERRIDE_IFACE || o->index != k)
			continue;
		pi = hb_law_param_index(out->law, o->name);
		if (pi >= 0 && strcmp(out->law->params[pi].name, o->name) == 0)
			out->par[pi] = o->value;
	}

	/* the stiffness from the pair: the upper body as the paper's body 1 */
	ki = -1;
	for (int i = 0; out->law != NULL && i < out->law->n_params; i++)
		if (out->law->params[i].flags & HB_LAW_PARAM_STIFFNESS) {
			ki = i;
			break;
		}
	if (ki < 0 || out->law->k_hertz == NULL)
		return HB_OK;
	if (scene_chain_body_full(sc, k, &hi) != HB_OK)
		return HB_EINVAL;
	if (k == 0) { /* the floor: the scene's body 2 */
		const struct hb_scene_body *f = &sc->body[1];
		memset(&lo, 0, sizeof lo);
		lo.E = f->E;
		lo.nu = f->nu;
		lo.R = f->R;
		lo_mat = f->has_material;
	} else {
		if (scene_chain_body_full(sc, k - 1, &lo) != HB_OK)
			return HB_EINVAL;
		lo_mat = lo.has_material;
	}
	if (!hi.has_material || !lo_mat) {
		*floorless = k == 0 && hi.has_material && sc->d.k_derived &&
		    find(sc, HB_OVERRIDE_IFACE, 0, out->law->params[ki].name) == NULL;
		return HB_OK;
	}
	Estar = 1.0 / ((1.0 - hi.nu * hi.nu) / hi.E + (1.0 - lo.nu * lo.nu) / lo.E);
	Re = 1.0 / (1.0 / hi.R + 1.0 / lo.R);
	kH = 4.0 / 3.0 * Estar * sqrt(Re);
	if (isfinite(kH) && kH > 0) {
		out->par[ki] = out->law->k_hertz(out->par, kH);
		*derivable = 1;
	}
	return HB_OK;
}

int
scene_chain_iface(const struct hb_scene *sc, int k, struct scene_chain_iface *out)
{
	int derivable, floorless;

	return scene_chain_iface_full(sc, k, out, &derivable, &floorless);
}
