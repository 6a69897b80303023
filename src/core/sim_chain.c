/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_chain.c - the chain a scene describes (docs/chains.md section 1):
 * its bodies, from the bottom up, and its interfaces, each bound to its law
 * and with its effective mass; the bodies' positions, velocities and loads
 * at the current state.
 *
 * Today's scenes are two chains:
 *  - the full system H_f: N = 2 bodies, no floor, interface 1 between them;
 *    chain body 1 (below) is the scene's body 2, chain body 2 (above) the
 *    scene's body 1 (the paper's body 1 is the upper one);
 *  - the reduced system H_r: N = 1 body on the floor, interface 0.
 * Their positions are measured so that the gap is their difference (the
 * half-lengths are taken into the positions: l = 0), as the paper's x and
 * x_m are.
 */
#include "sim_impl.h"

/* Grows *p (of *cap elements of size sz) to n elements, zeroing the new ones. */
static int
grow(void **p, int *cap, int n, size_t sz)
{
	void *q;

	if (n <= *cap)
		return 0;
	q = realloc(*p, (size_t)n * sz);
	if (q == NULL)
		return HB_ENOMEM;
	memset((char *)q + (size_t)*cap * sz, 0, (size_t)(n - *cap) * sz);
	*p = q;
	*cap = n;
	return 0;
}

int
hbs_chain_bind(struct hb_sim *s)
{
	const struct hb_scene *sc = &s->sc;
	int full = sc->d.system == HB_SCENE_FULL;
	int nbody = full ? 2 : 1, k0 = full ? 1 : 0;
	struct iface *I;

	if (grow((void **)&s->body, &s->capbody, nbody, sizeof *s->body) ||
	    grow((void **)&s->ifc, &s->capif, nbody - k0, sizeof *s->ifc))
		return HB_ENOMEM;
	s->nbody = nbody;
	s->k0 = k0;
	s->nif = nbody - k0;
	memset(s->body, 0, (size_t)nbody * sizeof *s->body);
	I = &s->ifc[0];
	if (full) {
		s->body[0].m = sc->d.m2;
		s->body[1].m = sc->d.m1;
		I->lo = 0;
		I->hi = 1;
	} else {
		s->body[0].m = sc->d.m1;
		I->lo = -1;
		I->hi = 0;
	}
	I->law = sc->law;
	I->par = sc->par;
	I->ext = sc->ext;
	I->m = sc->d.m; /* m_lo m_hi / (m_lo + m_hi), as the scene derived it (m_hi on the floor) */
	s->I = I;
	return 0;
}

void
hbs_chain_free(struct hb_sim *s)
{
	free(s->body);
	free(s->ifc);
	s->body = NULL;
	s->ifc = NULL;
	s->capbody = s->capif = 0;
}

void
hbs_bodies_sync(struct hb_sim *s)
{
	const struct hb_scene *sc = &s->sc;
	const struct iface *I = &s->ifc[0];
	double F1, F2;

	hb_scene_loads_at(sc, s->t, &F1, &F2);
	if (s->nbody == 2) {
		struct body *lo = &s->body[I->lo], *hi = &s->body[I->hi];

		hi->y = s->xm + sc->d.etac * I->x;
		hi->u = s->vm + sc->d.etac * I->v;
		lo->y = s->xm - sc->d.eta * I->x;
		lo->u = s->vm - sc->d.eta * I->v;
		hi->Fe = F1;
		lo->Fe = F2;
	} else {
		s->body[0].y = I->x;
		s->body[0].u = I->v;
		s->body[0].Fe = F1;
	}
}
