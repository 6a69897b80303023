/*
 * A chain scene's bodies and interfaces, one at a time (scene_chain.h).
 * A uniform chain: every body is the scene's body 1, every interface has
 * the scene's law, the striker (body n) moves at striker.v.
 */
#include "scene_chain.h"

#include <math.h>
#include <string.h>

int
scene_chain_body(const struct hb_scene *sc, int i, struct scene_chain_body *out)
{
	if (sc->chain.n <= 0 || i < 0 || i >= sc->chain.n)
		return HB_EINVAL;
	out->m = sc->d.m1;
	out->R = isfinite(sc->body[0].R) ? sc->body[0].R : 0.0;
	out->F = -out->m * sc->loads.g;
	out->v0 = i == sc->chain.n - 1 ? sc->chain.v : 0.0;
	out->gap = i == 0 && !sc->chain.floor ? 0.0 : sc->chain.spacing;
	return HB_OK;
}

int
scene_chain_iface(const struct hb_scene *sc, int k, struct scene_chain_iface *out)
{
	if (sc->chain.n <= 0 || k < !sc->chain.floor || k >= sc->chain.n)
		return HB_EINVAL;
	out->law = sc->law;
	memcpy(out->par, sc->par, sizeof out->par);
	out->ext = sc->ext;
	return HB_OK;
}
