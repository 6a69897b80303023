/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_chain.c - the chain a scene describes (docs/chains.md section 1):
 * its bodies, from the bottom up, and its interfaces, each bound to its law
 * and with its effective mass; the bodies' positions, velocities and loads
 * at the current state; whether a run goes on with a new scene from its
 * current state (else it begins again), its flying bodies settled first.
 *
 * The two-body scenes are two chains:
 *  - the full system H_f: N = 2 bodies, no floor, interface 1 between them;
 *    chain body 1 (below) is the scene's body 2, chain body 2 (above) the
 *    scene's body 1 (the paper's body 1 is the upper one);
 *  - the reduced system H_r: N = 1 body on the floor, interface 0.
 * Their state is the interface's (x, v, ...) and the centre of mass
 * (x_m, v_m), as today; their bodies' positions (measured so that the gap
 * is their difference, as the paper's x and x_m are) and velocities follow
 * on request.
 *
 * A [chain] scene has chain.n bodies of body 1's mass and radius, with the
 * scene's law at every interface.  Each body's (y, u) is kept at the time
 * tb it is of and moves on its parabola from there (sim_flight.c), so
 * that a flight or a step touches only the bodies it concerns; one
 * interface at a time is in contact, integrated as the two-body contact
 * (s->I, its effective mass and F_e,r) with its pair's centre of mass in
 * closed form from the commencement, its two bodies set from them at
 * every sample; another interface closing meanwhile stops the run.
 */
#include "sim_impl.h"
#include "scene_chain.h"

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

/* F_e,r of a two-body scene's interface: the scene's loads (ramps included). */
static double
scene_Fer(const struct hb_sim *s, const struct iface *I, double t)
{
	(void)I;
	return hb_scene_Fer(&s->sc, t);
}

/* F_e,r of a chain's interface: constant. */
static double
chain_Fer(const struct hb_sim *s, const struct iface *I, double t)
{
	(void)s;
	(void)t;
	return I->Fer;
}

/* Binds interface I (number k) of a chain scene: the bodies it joins, its mass and F_e,r. */
static void
bind_chain_iface(struct hb_sim *s, struct iface *I, int k)
{
	const struct hb_scene *sc = &s->sc;

	I->lo = k - 1;
	I->hi = k;
	if (I->lo < 0) {
		I->m = sc->d.m1;
		I->Fer = s->body[0].Fe;
		I->wlo = 0.0;
		I->whi = 1.0;
	} else {
		const struct body *lo = &s->body[I->lo], *hi = &s->body[I->hi];

		I->m = lo->m * hi->m / (lo->m + hi->m);
		I->wlo = lo->m / (lo->m + hi->m);
		I->whi = hi->m / (lo->m + hi->m);
		I->Fer = I->wlo * hi->Fe - I->whi * lo->Fe; /* (m_lo F_hi - m_hi F_lo) / (m_lo + m_hi) */
	}
	I->ihi = 1.0 / s->body[I->hi].m;
	I->ilo = I->lo < 0 ? 0.0 : 1.0 / s->body[I->lo].m;
	I->arel = s->body[I->hi].a - (I->lo < 0 ? 0.0 : s->body[I->lo].a);
}

int
hbs_chain_bind(struct hb_sim *s)
{
	const struct hb_scene *sc = &s->sc;
	int chain = sc->chain.n > 0;
	int full = sc->d.system == HB_SCENE_FULL;
	int nbody = chain ? sc->chain.n : full ? 2 : 1;
	int k0 = chain ? !sc->chain.floor : full ? 1 : 0;
	int i;
	struct iface *I;

	if (grow((void **)&s->body, &s->capbody, nbody, sizeof *s->body) ||
	    grow((void **)&s->ifc, &s->capif, nbody - k0, sizeof *s->ifc))
		return HB_ENOMEM;
	s->chain = chain;
	s->nbody = nbody;
	s->k0 = k0;
	s->nif = nbody - k0;
	for (i = 0; i < nbody; i++) { /* the bodies' states are kept: only their constants change */
		struct body *b = &s->body[i];
		struct scene_chain_body cb;

		if (chain) {
			if (scene_chain_body(sc, i, &cb) != HB_OK)
				return HB_EINVAL;
			b->m = cb.m;
			b->l = cb.R;
			b->Fe = cb.F;
			b->a = cb.F / cb.m;
			continue;
		}
		b->m = i == 0 ? (full ? sc->d.m2 : sc->d.m1) : sc->d.m1;
		b->l = 0.0;
		b->a = -sc->loads.g;
		b->Fe = -b->m * sc->loads.g;
	}
	for (i = 0; i < s->nif; i++) {
		I = &s->ifc[i];
		I->Fer_at = chain ? chain_Fer : scene_Fer;
		if (chain) {
			struct scene_chain_iface ci;

			if (scene_chain_iface(sc, k0 + i, &ci) != HB_OK)
				return HB_EINVAL;
			I->law = ci.law;
			memcpy(I->parv, ci.par, sizeof I->parv);
			I->par = I->parv; /* set again at every bind: the array may have moved */
			I->ext = ci.ext;
			bind_chain_iface(s, I, k0 + i);
			continue;
		}
		I->law = sc->law;
		I->par = sc->par;
		I->ext = sc->ext;
		I->lo = full ? 0 : -1;
		I->hi = full ? 1 : 0;
		I->m = sc->d.m; /* m_lo m_hi / (m_lo + m_hi), as the scene derived it (m_hi on the floor) */
	}
	if (s->ia < 0 || s->ia >= s->nif)
		s->ia = s->nif - 1;
	s->I = &s->ifc[s->ia]; /* the arrays may have moved */
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

/* Gap and relative velocity of interface I at t from the bodies' parabolas. */
static void
gap_at(const struct hb_sim *s, const struct iface *I, double t, double *x, double *v)
{
	const struct body *hi = &s->body[I->hi];
	double yh, uh;

	hbs_body_now(hi, t, &yh, &uh);
	if (I->lo < 0) {
		*x = yh - hi->dn;
		*v = uh;
	} else {
		const struct body *lo = &s->body[I->lo];
		double yl, ul;

		hbs_body_now(lo, t, &yl, &ul);
		*x = (yh - hi->dn) - (yl + lo->up);
		*v = uh - ul;
	}
}

int
hbs_bodies_sync(struct hb_sim *s)
{
	if (s->chain)
		hbs_cluster_sync(s);
	return 0;
}

void
hbs_body_at(const struct hb_sim *s, int i, double *y, double *u)
{
	const struct hb_scene *sc = &s->sc;
	const struct iface *I = &s->ifc[0];

	if (s->chain) {
		hbs_body_now(&s->body[i], s->t, y, u);
		*y += s->body[i].y0;
	} else if (s->nbody == 1) {
		*y = I->x;
		*u = I->v;
	} else if (i == I->hi) {
		*y = s->xm + sc->d.etac * I->x;
		*u = s->vm + sc->d.etac * I->v;
	} else {
		*y = s->xm - sc->d.eta * I->x;
		*u = s->vm - sc->d.eta * I->v;
	}
}

/* Makes interface number i (index into ifc) the one the flow interval is about. */
void
hbs_chain_activate(struct hb_sim *s, int i)
{
	s->ia = i;
	s->I = &s->ifc[i];
}

/*
 * The chain's state at t = 0: bodies spaced from the floor (or from 0) up,
 * the striker moving.  A body's y is its displacement from there (y0), and
 * a gap the difference of two displacements plus the gap at t = 0: a
 * position in metres along a chain of 1,000 beads would carry the rounding
 * of its length (1e-16 m), and touching beads at rest would overlap by it.
 */
void
hbs_chain_reset(struct hb_sim *s)
{
	const struct hb_scene *sc = &s->sc;
	double y = 0.0;
	int i;

	for (i = 0; i < s->nbody; i++) {
		struct body *b = &s->body[i];
		struct scene_chain_body cb;

		scene_chain_body(sc, i, &cb); /* cannot fail: hbs_chain_bind took every body */
		if (i == 0)
			y = sc->chain.floor ? b->l + cb.gap : 0.0;
		else
			y += s->body[i - 1].l + cb.gap + b->l;
		hbs_body_set(b, 0.0, 0.0, cb.v0);
		b->y0 = y;
		b->dn = i == 0 && !sc->chain.floor ? 0.0 : -cb.gap;
		b->up = 0.0;
		b->u0 = cb.v0;
	}
	for (i = 0; i < s->nif; i++) {
		struct iface *J = &s->ifc[i];

		memset(&J->q, 0, sizeof *J - offsetof(struct iface, q));
		J->over = J->msign = J->mforce = 0;
		gap_at(s, J, 0.0, &J->x, &J->v);
	}
	hbs_chain_activate(s, s->nif - 1);
	s->xm = s->vm = 0.0;
	for (i = 0; i < s->nbody; i++)
		s->body[i].cl = -1;
	for (i = 0; i < s->nif; i++)
		s->ifc[i].off = -1;
	s->cx.nact = s->cx.ncl = s->cx.nwatch = s->cx.dim = 0;
	s->h = 0.0;
	s->nlim = 0;
	s->limnote[0] = '\0';
}

/* x_m, v_m: the centre of mass of s->I's pair from the bodies (0 on the floor). */
void
hbs_chain_pair_com(struct hb_sim *s)
{
	const struct iface *I = s->I;

	double yl, ul, yh, uh;

	if (I->lo < 0) {
		s->xm = s->vm = 0.0;
		return;
	}
	hbs_body_now(&s->body[I->lo], s->t, &yl, &ul);
	hbs_body_now(&s->body[I->hi], s->t, &yh, &uh);
	s->xm = I->wlo * yl + I->whi * yh;
	s->vm = I->wlo * ul + I->whi * uh;
}

/* Gap and relative velocity of interface i at t, for the flight (sim_flight.c). */
void
hbs_chain_gap(const struct hb_sim *s, int i, double t, double *x, double *v)
{
	gap_at(s, &s->ifc[i], t, x, v);
}

/* The bodies of interface i set to their state at t (where a flight's event places them). */
void
hbs_chain_settle(struct hb_sim *s, int i, double t)
{
	const struct iface *J = &s->ifc[i];
	double y, u;

	hbs_body_now(&s->body[J->hi], t, &y, &u);
	hbs_body_set(&s->body[J->hi], t, y, u);
	if (J->lo >= 0) {
		hbs_body_now(&s->body[J->lo], t, &y, &u);
		hbs_body_set(&s->body[J->lo], t, y, u);
	}
}

/*
 * A chain's run goes on with scene nsc from its current state unless that
 * changes what the state was computed from or what is in contact (as the
 * two-body scenes' rule): the number of bodies, the floor, the system, any
 * body's initial velocity, gap or radius (its position at t = 0), the mass
 * or load of a body in contact, or the law or extension of an interface in
 * contact.  Then 0: the run begins again from t = 0.
 */
int
hbs_chain_continues(const struct hb_sim *s, const struct hb_scene *nsc)
{
	const struct hb_scene *o = &s->sc;
	int i;

	if (nsc->chain.n != o->chain.n || nsc->chain.floor != o->chain.floor ||
	    nsc->d.system != o->d.system || memcmp(&nsc->init, &o->init, sizeof nsc->init) != 0)
		return 0;
	for (i = 0; i < s->nbody; i++) {
		struct scene_chain_body a, b;

		if (scene_chain_body(o, i, &a) != HB_OK || scene_chain_body(nsc, i, &b) != HB_OK)
			return 0;
		if (a.v0 != b.v0 || a.gap != b.gap || a.R != b.R)
			return 0;
		if (s->body[i].cl >= 0 && (a.m != b.m || a.F != b.F))
			return 0;
	}
	for (i = 0; i < s->nif; i++) {
		struct scene_chain_iface a, b;

		if (!s->ifc[i].q)
			continue;
		if (scene_chain_iface(o, s->k0 + i, &a) != HB_OK ||
		    scene_chain_iface(nsc, s->k0 + i, &b) != HB_OK || a.law != b.law || a.ext != b.ext)
			return 0;
	}
	return 1;
}

/*
 * Before a chain's bodies take new constants: each flying body's (y, u)
 * moved to the current t on its parabola, so that a new acceleration acts
 * from now on (a body in contact keeps its mass and load).
 */
void
hbs_chain_settle_flying(struct hb_sim *s)
{
	for (int i = 0; i < s->nbody; i++) {
		double y, u;

		if (s->body[i].cl >= 0)
			continue;
		hbs_body_now(&s->body[i], s->t, &y, &u);
		hbs_body_set(&s->body[i], s->t, y, u);
	}
}

int
hb_sim_nbodies(const struct hb_sim *s)
{
	return s->nbody;
}

int
hb_sim_body(const struct hb_sim *s, int i, struct hb_sim_body *out)
{
	if (i < 0 || i >= s->nbody)
		return HB_EINVAL;
	out->m = s->body[i].m;
	out->R = s->body[i].l;
	hbs_body_at(s, i, &out->y, &out->u);
	return HB_OK;
}
