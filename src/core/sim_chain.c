/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_chain.c - the chain a scene describes (docs/chains.md section 1):
 * its bodies, from the bottom up, and its interfaces, each bound to its law
 * and with its effective mass; the bodies' positions, velocities and loads
 * at the current state.
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
 * scene's law at every interface.  Its bodies' (y, u) are canonical in
 * flight (parabolas from the time tb they are of, sim_flight.c); one
 * interface at a time is in contact, integrated as the two-body contact
 * (s->I, its effective mass and F_e,r) with its pair's centre of mass in
 * closed form from the commencement; the bodies are brought to the
 * current time at every sample, and another interface found overlapping
 * then stops the run.
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
		s->body[i].m = chain ? sc->d.m1 : i == 0 ? (full ? sc->d.m2 : sc->d.m1) : sc->d.m1;
		s->body[i].l = chain && isfinite(sc->body[0].R) ? sc->body[0].R : 0.0;
		s->body[i].a = -sc->loads.g;
		s->body[i].Fe = -s->body[i].m * sc->loads.g;
	}
	for (i = 0; i < s->nif; i++) {
		I = &s->ifc[i];
		I->law = sc->law;
		I->par = sc->par;
		I->ext = sc->ext;
		I->Fer_at = chain ? chain_Fer : scene_Fer;
		if (chain) {
			bind_chain_iface(s, I, k0 + i);
			continue;
		}
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

/* Gap and relative velocity of interface I from the bodies' (y, u). */
static void
gap_of(const struct hb_sim *s, const struct iface *I, double *x, double *v)
{
	const struct body *hi = &s->body[I->hi];

	if (I->lo < 0) {
		*x = hi->y - hi->l;
		*v = hi->u;
	} else {
		const struct body *lo = &s->body[I->lo];

		*x = (hi->y - hi->l) - (lo->y + lo->l);
		*v = hi->u - lo->u;
	}
}

/*
 * A chain's bodies at s->t: the two of the interface in contact from its
 * gap and the centre of mass of the pair, every other one by its parabola
 * from the time tb its (y, u) are of; tb becomes s->t.  Another interface
 * overlapping while one is in contact is two contacts at once, which this
 * version does not carry: HB_ENUMERIC, naming them.
 */
static int
chain_sync(struct hb_sim *s)
{
	const struct iface *I = s->I;
	double tau = s->t - s->tb;
	int i;

	for (i = 0; i < s->nbody; i++) {
		struct body *b = &s->body[i];

		b->y = b->y + tau * (b->u + 0.5 * b->a * tau);
		b->u = b->u + b->a * tau;
	}
	s->tb = s->t;
	if (I->q) {
		struct body *hi = &s->body[I->hi];

		if (I->lo < 0) {
			hi->y = I->x + hi->l;
			hi->u = I->v;
		} else {
			struct body *lo = &s->body[I->lo];
			double d = I->x + hi->l + lo->l;

			hi->y = s->xm + I->wlo * d;
			hi->u = s->vm + I->wlo * I->v;
			lo->y = s->xm - I->whi * d;
			lo->u = s->vm - I->whi * I->v;
		}
		for (i = 0; i < s->nif; i++) {
			const struct iface *J = &s->ifc[i];
			double x, v;

			if (J == I)
				continue;
			gap_of(s, J, &x, &v);
			if (x < 0) {
				char why[200];

				snprintf(why, sizeof why, "interface %d (bodies %d and %d) closed while interface "
				         "%d was in contact: a chain carries one contact at a time in this version",
				         s->k0 + i, J->lo + 1, J->hi + 1, s->k0 + s->ia);
				return hbs_fail(s, HB_ENUMERIC, why);
			}
		}
	}
	return 0;
}

int
hbs_bodies_sync(struct hb_sim *s)
{
	return s->chain ? chain_sync(s) : 0;
}

void
hbs_body_at(const struct hb_sim *s, int i, double *y, double *u)
{
	const struct hb_scene *sc = &s->sc;
	const struct iface *I = &s->ifc[0];

	if (s->chain) {
		*y = s->body[i].y;
		*u = s->body[i].u;
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

/* The chain's state at t = 0: bodies spaced from the floor (or from 0) up, the striker moving. */
void
hbs_chain_reset(struct hb_sim *s)
{
	const struct hb_scene *sc = &s->sc;
	double y = 0.0;
	int i;

	for (i = 0; i < s->nbody; i++) {
		struct body *b = &s->body[i];

		if (i == 0)
			y = sc->chain.floor ? b->l + sc->chain.spacing : 0.0;
		else
			y += s->body[i - 1].l + sc->chain.spacing + b->l;
		b->y = y;
		b->u = i == s->nbody - 1 ? sc->chain.v : 0.0;
	}
	s->tb = 0.0;
	for (i = 0; i < s->nif; i++) {
		struct iface *J = &s->ifc[i];

		memset(&J->q, 0, sizeof *J - offsetof(struct iface, q));
		gap_of(s, J, &J->x, &J->v);
	}
	hbs_chain_activate(s, s->nif - 1);
	s->xm = s->vm = 0.0;
}

/*
 * After the jump of s->I: into a contact, the centre of mass of its pair
 * at the commencement, from which it moves under the pair's load alone.
 */
void
hbs_chain_jumped(struct hb_sim *s)
{
	const struct iface *I = s->I;

	if (!I->q) /* a separation: x_m, v_m unchanged (g) */
		return;
	hbs_chain_pair_com(s);
	s->cm_t0 = s->t;
	s->cm_y0 = s->xm;
	s->cm_u0 = s->vm;
	s->cm_a = I->lo < 0 ? 0.0 : I->wlo * s->body[I->lo].a + I->whi * s->body[I->hi].a;
}

/* x_m, v_m: the centre of mass of s->I's pair from the bodies (0 on the floor). */
void
hbs_chain_pair_com(struct hb_sim *s)
{
	const struct iface *I = s->I;

	if (I->lo < 0) {
		s->xm = s->vm = 0.0;
		return;
	}
	s->xm = I->wlo * s->body[I->lo].y + I->whi * s->body[I->hi].y;
	s->vm = I->wlo * s->body[I->lo].u + I->whi * s->body[I->hi].u;
}

/* The centre of mass of the pair in contact at s->t (closed form). */
void
hbs_chain_com(struct hb_sim *s)
{
	double tau = s->t - s->cm_t0;

	if (!s->I->q)
		return;
	s->xm = s->cm_y0 + tau * (s->cm_u0 + 0.5 * s->cm_a * tau);
	s->vm = s->cm_u0 + s->cm_a * tau;
}

/* Gap and relative velocity of interface i, for the flight (sim_flight.c). */
void
hbs_chain_gap(const struct hb_sim *s, int i, double *x, double *v)
{
	gap_of(s, &s->ifc[i], x, v);
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
	hbs_body_at(s, i, &out->y, &out->u);
	return HB_OK;
}
