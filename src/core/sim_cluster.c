/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster.c - a chain's interfaces in contact, integrated together
 * (docs/chains.md section 8, points 1-4).
 *
 * The interfaces in contact (q_k = 1) split the bodies into clusters:
 * maximal runs of bodies joined by interfaces in contact, with the floor
 * when its interface is in contact.  Every interface in contact carries a
 * block (x_c, v, z..., W, J_Fc, J_Fe) in one ODE, integrated in scaled
 * variables by the engine's driver (sim.c, sim_locate.c) with the scene's
 * stepper (rk8pd by default, bsimp once stiff under auto):
 *
 *     x_c,k' = v_k,   z_k' = Psi_k,   W_k' = Phi_k v_k,   J_Fc,k' = -Phi_k,
 *     J_Fe,k' = F_e,r,k,
 *     v_k' = F_c,k (1/m_lo + 1/m_hi) - F_c,k+1 / m_hi - F_c,k-1 / m_lo + a_hi - a_lo
 *
 * with F_c,j = -q_j Phi_j (0 for an interface in flight), so that the
 * neighbours' terms are present only within a cluster.  The gap is
 * x_k = x_e,k + x_c,k (x_e,k its gap at the commencement).  Each cluster's
 * centre of mass moves under its loads alone, in closed form (a cluster on
 * the floor has its bodies placed from the floor up instead); its bodies
 * are placed from it and from its gaps where a sample needs them.  Bodies
 * in no cluster fly on their parabolas (sim_chain.c).
 *
 * Watched along a step, interface by interface in increasing k: for one
 * in contact the indicator of its flow set -min(Phi_k, v_k) (an event),
 * its law's switching functions (kinks: the step ends there and the
 * stepper restarts), v_k (the extremum of x_c,k) and dPhi_k/dt (that of
 * F_c,k, its neighbours' forces in dv_k/dt); for one in flight
 * next to a cluster the indicator max(x_k, v_k) of its gap (an event).
 * A crossing is located by the engine's driver as a two-body contact's
 * (sim_locate.c); the earliest wins, the lowest k on a tie.  A gap between two
 * flying bodies closes at a time known in closed form when the interval
 * begins: it is a target of the steps.  An event ends the interval at the
 * bracket's end in D, and the jump (sim_record.c) rebuilds the clusters;
 * the next interval takes any interface already in D at once, the lowest
 * k first (docs/chains.md section 3).
 *
 * The work of a step is linear in the number of interfaces in contact and
 * of watched gaps, not in N; rebuilding the clusters after a jump scans
 * the gaps of flying bodies once (their closing times).
 */
#include "sim_impl.h"
#include "sim_cluster_law.h"
#include "sim_iface.h"

#define GROW(p, cap, n)                                                                 \
	((n) <= (cap) ? 0 : grow_to((void **)&(p), &(cap), (n), sizeof *(p)))

static int
grow_to(void **p, int *cap, int n, size_t sz)
{
	int c = *cap > 0 ? *cap : 8;
	void *q;

	while (c < n)
		c *= 2;
	q = realloc(*p, (size_t)c * sz);
	if (q == NULL)
		return HB_ENOMEM;
	*p = q;
	*cap = c;
	return 0;
}

/* Index into ifc of the interface below body i (-1: none), and above it (-1: none). */
static inline int
if_below(const struct hb_sim *s, int i)
{
	int k = i - s->k0;

	return k >= 0 ? k : -1;
}

static inline int
if_above(const struct hb_sim *s, int i)
{
	int k = i + 1 - s->k0;

	return k < s->nif ? k : -1;
}

void
hbs_cluster_free(struct hb_sim *s)
{
	struct clusters *c = &s->cx;

	free(c->act);
	free(c->cl);
	free(c->wif);
	free(c->fkind);
	free(c->fif);
	free(c->by);
	free(c->bu);
	memset(c, 0, sizeof *c);
}

/*
 * The bodies of cluster C at t, with its interfaces' gaps and relative
 * velocities (x_e + x_c, v) read from the scaled state u: into by[], bu[]
 * at the bodies' indices.  Without the floor, the bodies' offsets from the
 * lowest one are summed up the cluster and moved so that their centre of
 * mass is the cluster's; on the floor they are summed from the floor.
 */
static void
cluster_bodies(const struct hb_sim *s, const struct cluster *C, double t, const double *u)
{
	const struct clusters *c = &s->cx;
	double r = 0.0, w = 0.0, mr = 0.0, mw = 0.0, y0, u0;
	int i;

	c->by[C->b0] = 0.0;
	c->bu[C->b0] = 0.0;
	for (i = C->b0; i < C->b1; i++) {
		const struct iface *I = &s->ifc[if_above(s, i)];
		double x = I->xe + u[I->off] * s->scale[I->off], v = u[I->off + 1] * s->scale[I->off + 1];

		r += s->body[i].up + x + s->body[i + 1].dn;
		w += v;
		c->by[i + 1] = r;
		c->bu[i + 1] = w;
	}
	if (C->floor) {
		const struct iface *I = &s->ifc[if_below(s, C->b0)];

		y0 = I->xe + u[I->off] * s->scale[I->off] + s->body[C->b0].dn;
		u0 = u[I->off + 1] * s->scale[I->off + 1];
	} else {
		double tau = t - C->t0;

		for (i = C->b0; i <= C->b1; i++) {
			mr += s->body[i].m * c->by[i];
			mw += s->body[i].m * c->bu[i];
		}
		y0 = C->y0 + tau * (C->u0 + 0.5 * C->a * tau) - mr / C->M;
		u0 = C->u0 + C->a * tau - mw / C->M;
	}
	for (i = C->b0; i <= C->b1; i++) {
		c->by[i] += y0;
		c->bu[i] += u0;
	}
}

/* Body i at t: from the scratch when it is in a cluster (filled for this state), else its parabola. */
static inline void
body_state(const struct hb_sim *s, int i, double t, double *y, double *u)
{
	if (s->body[i].cl >= 0) {
		*y = s->cx.by[i];
		*u = s->cx.bu[i];
	} else {
		hbs_body_now(&s->body[i], t, y, u);
	}
}

/* Gap and relative velocity of interface I from the bodies' states (scratch filled). */
static void
gap_of(const struct hb_sim *s, const struct iface *I, double t, double *x, double *v)
{
	double yh, uh, yl, ul;

	body_state(s, I->hi, t, &yh, &uh);
	if (I->lo < 0) {
		*x = yh - s->body[I->hi].dn;
		*v = uh;
		return;
	}
	body_state(s, I->lo, t, &yl, &ul);
	*x = (yh - s->body[I->hi].dn) - (yl + s->body[I->lo].up);
	*v = uh - ul;
}

/*
 * The right-hand side: the forces of every interface in contact first,
 * then each block's derivatives (scaled as they are written).  A trial
 * stage that is not finite returns GSL_FAILURE (the evolver halves the step).
 */
int
hbs_cluster_rhs(double t, const double u[], double du[], void *params)
{
	struct hb_sim *s = params;
	const struct clusters *c = &s->cx;
	const double *sc = s->scale, *is = s->iscale;
	double bad = 0.0;
	int p, i;

	(void)t;
	s->st.rhs++;
	for (p = 0; p < c->nact; p++)
		hbs_cluster_law(&s->ifc[c->act[p]], u, sc, 0);
#define PUT(k, val) (du[k] = (val) * is[k], bad += 0.0 * du[k])
	for (p = 0; p < c->nact; p++) {
		int k = c->act[p];
		const struct iface *I = &s->ifc[k];
		int o = I->off, nz = I->law->n_z;
		double v = u[o + 1] * sc[o + 1], phi = I->tphi, acc;

		acc = -phi * (I->ilo + I->ihi) + I->arel;
		if (k > 0 && s->ifc[k - 1].off >= 0)
			acc += s->ifc[k - 1].tphi * I->ilo;
		if (k + 1 < s->nif && s->ifc[k + 1].off >= 0)
			acc += s->ifc[k + 1].tphi * I->ihi;
		PUT(o, v);
		PUT(o + 1, acc);
		if (nz) {
			double z[HB_LAW_MAX_Z], dz[HB_LAW_MAX_Z];

			for (i = 0; i < nz; i++)
				z[i] = u[o + 2 + i] * sc[o + 2 + i];
			if (I->msign)
				I->law->psi_mode(I->par, I->ext, u[o] * sc[o], z, v, I->msign, dz);
			else
				I->law->psi(I->par, I->ext, u[o] * sc[o], z, v, dz);
			for (i = 0; i < nz; i++)
				PUT(o + 2 + i, dz[i]);
		}
		PUT(o + 2 + nz, phi * v);
		PUT(o + 3 + nz, -phi);
		PUT(o + 4 + nz, I->Fer);
	}
#undef PUT
	if (bad != 0.0 || isnan(bad))
		return GSL_FAILURE;
	return GSL_SUCCESS;
}

/* Phi of interface I (in contact) at the clusters' scaled state u. */
static inline double
iface_phi(const struct hb_sim *s, const struct iface *I, const double *u)
{
	int o = I->off, nz = I->law->n_z, i;
	double z[HB_LAW_MAX_Z];

	for (i = 0; i < nz; i++)
		z[i] = u[o + 2 + i] * s->scale[o + 2 + i];
	return hbs_iface_phi(I, u[o] * s->scale[o], nz ? z : NULL, u[o + 1] * s->scale[o + 1]);
}

/* Interface I's (x_c, z, v), unscaled from u; z zero past its n_z. */
static inline void
iface_state(const struct hb_sim *s, const struct iface *I, const double *u, double *xc, double *z,
            double *v)
{
	int o = I->off, nz = I->law->n_z, i;

	for (i = 0; i < HB_LAW_MAX_Z; i++)
		z[i] = i < nz ? u[o + 2 + i] * s->scale[o + 2 + i] : 0.0;
	*xc = u[o] * s->scale[o];
	*v = u[o + 1] * s->scale[o + 1];
}

/*
 * dv/dt of interface k from its Phi (phi; 0 in flight) and its neighbours'
 * k - 1 (plo) and k + 1 (phi_hi), these read only where they are in
 * contact.
 */
static inline double
iface_vdot(const struct hb_sim *s, int k, double phi, double plo, double phi_hi)
{
	const struct iface *I = &s->ifc[k];
	double vdot = -phi * (I->ilo + I->ihi) + I->arel;

	if (k > 0 && s->ifc[k - 1].off >= 0)
		vdot += plo * I->ilo;
	if (k + 1 < s->nif && s->ifc[k + 1].off >= 0)
		vdot += phi_hi * I->ihi;
	return vdot;
}

/*
 * dPhi/dt of interface k (its minimum is F_c's maximum), with this step's
 * mode of Psi, from the Phi of k (phi) and of its neighbours (iface_vdot).
 */
static inline double
iface_dphidt(const struct hb_sim *s, int k, double xc, const double *z, double v, double phi, double plo,
             double phi_hi)
{
	return hbs_iface_dphidt(&s->ifc[k], xc, z, v, iface_vdot(s, k, phi, plo, phi_hi), s->ifc[k].msign);
}

/*
 * The watched functions at (t, u), interface by interface in increasing
 * k (see the header comment); their kinds and interfaces were laid out by
 * setup.  Fills the clusters' bodies in the scratch when gaps are watched.
 * With rate not NULL, each event's indicator's rate (one-sided where it
 * has a corner) into rate[] at its index, NAN at the others' (the dip
 * test, sim_locate.c).
 */
void
hbs_cluster_watch(struct hb_sim *s, double t, const double *u, double *f, double *rate)
{
	struct clusters *c = &s->cx;
	int n = 0, p, w, i;

	if (c->nwatch > 0)
		for (i = 0; i < c->ncl; i++)
			cluster_bodies(s, &c->cl[i], t, u);
	for (p = 0; p < c->nact; p++) { /* the forces first: dPhi/dt needs the neighbours' */
		struct iface *I = &s->ifc[c->act[p]];

		I->tphi = iface_phi(s, I, u);
	}
	for (p = 0, w = 0; p < c->nact || w < c->nwatch;) {
		if (w >= c->nwatch || (p < c->nact && c->act[p] < c->wif[w])) {
			int k = c->act[p++];
			const struct iface *I = &s->ifc[k];
			int nk = I->law->n_kinks && s->sc.run.kinks ? I->law->n_kinks : 0;
			double z[HB_LAW_MAX_Z], xc, v;

			iface_state(s, I, u, &xc, z, &v);
			f[n++] = -fmin(I->tphi, v);
			if (nk) {
				hbs_iface_kinks(I, xc, z, v, &f[n]);
				n += nk;
			}
			f[n++] = v;
			{
				double plo = k > 0 ? s->ifc[k - 1].tphi : 0.0;
				double phi_hi = k + 1 < s->nif ? s->ifc[k + 1].tphi : 0.0;
				double vdot = iface_vdot(s, k, I->tphi, plo, phi_hi);

				f[n++] = hbs_iface_dphidt(I, xc, z, v, vdot, I->msign);
				if (rate != NULL) {
					for (i = I->fo + 1; i < n; i++)
						rate[i] = NAN;
					rate[I->fo] = I->tphi < v ? -f[n - 1] : -vdot;
				}
			}
		} else {
			int k = c->wif[w++];
			double x, v;

			gap_of(s, &s->ifc[k], t, &x, &v);
			/*
			 * No dip test for a gap: touching beads' gaps read 0 at both
			 * ends of a step and dip by the rounding of their
			 * displacements (1e-21 m) as a wave's precursor nears; such a
			 * crossing is taken where a step's end shows it.
			 */
			if (rate != NULL)
				rate[n] = NAN;
			f[n++] = fmax(x, v);
		}
	}
}

/*
 * Watched function fi alone at (t, u): the same double as
 * hbs_cluster_watch's f[fi], from the state of its interface (and of its
 * neighbours in contact for dPhi/dt, of the clusters its gap's bodies are
 * in for a gap) only.  The root finder asks one function many times.
 */
double
hbs_cluster_watch_one(struct hb_sim *s, double t, const double *u, int fi)
{
	struct clusters *c = &s->cx;
	int k = c->fif[fi], j;
	const struct iface *I = &s->ifc[k];
	double z[HB_LAW_MAX_Z], xc, v;

	if (I->off < 0) { /* a gap in flight next to a cluster */
		double x, w;
		int bl = I->lo >= 0 ? s->body[I->lo].cl : -1, bh = s->body[I->hi].cl;

		if (bh >= 0)
			cluster_bodies(s, &c->cl[bh], t, u);
		if (bl >= 0 && bl != bh)
			cluster_bodies(s, &c->cl[bl], t, u);
		gap_of(s, I, t, &x, &w);
		return fmax(x, w);
	}
	switch (c->fkind[fi]) {
	case FUN_EVENT:
		return -fmin(iface_phi(s, I, u), u[I->off + 1] * s->scale[I->off + 1]);
	case FUN_XCMAX:
		return u[I->off + 1] * s->scale[I->off + 1];
	case FUN_KINK: {
		double g[HB_LAW_MAX_KINKS];

		for (j = 1; c->fkind[fi - j] == FUN_KINK; j++) /* its index among its interface's */
			;
		iface_state(s, I, u, &xc, z, &v);
		hbs_iface_kinks(I, xc, z, v, g);
		return g[j - 1];
	}
	default: /* FUN_FCMAX */
		iface_state(s, I, u, &xc, z, &v);
		return iface_dphidt(s, k, xc, z, v, iface_phi(s, I, u),
		                    k > 0 && s->ifc[k - 1].off >= 0 ? iface_phi(s, &s->ifc[k - 1], u) : 0.0,
		                    k + 1 < s->nif && s->ifc[k + 1].off >= 0 ? iface_phi(s, &s->ifc[k + 1], u)
		                                                             : 0.0);
	}
}

/* Copies the ODE's state at t into the interfaces in contact and the watched gaps. */
void
hbs_cluster_unpack(struct hb_sim *s, double t, const double *u)
{
	struct clusters *c = &s->cx;
	int p, i;

	s->t = t;
	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];
		int o = I->off, nz = I->law->n_z;

		I->xc = u[o] * s->scale[o];
		I->v = u[o + 1] * s->scale[o + 1];
		I->x = I->xe + I->xc;
		for (i = 0; i < nz; i++)
			I->z[i] = u[o + 2 + i] * s->scale[o + 2 + i];
		I->W = u[o + 2 + nz] * s->scale[o + 2 + nz];
		I->JFc = u[o + 3 + nz] * s->scale[o + 3 + nz];
		I->JFe = u[o + 4 + nz] * s->scale[o + 4 + nz];
		I->Wc = I->Wc0 - I->W;
		if (fabs(I->xc) > I->xcmax)
			I->xcmax = fabs(I->xc);
		{
			double Fc = -I->law->phi(I->par, I->ext, I->xc, nz ? I->z : NULL, I->v);

			if (Fc > I->Fcmax)
				I->Fcmax = Fc;
		}
	}
	if (c->nwatch > 0) {
		for (i = 0; i < c->ncl; i++)
			cluster_bodies(s, &c->cl[i], t, u);
		for (i = 0; i < c->nwatch; i++) {
			struct iface *I = &s->ifc[c->wif[i]];

			gap_of(s, I, t, &I->x, &I->v);
		}
	}
}

/* The clusters' bodies set to their state at s->t (a sample, a jump). */
void
hbs_cluster_sync(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int i, b;

	if (c->nact == 0 || c->dim == 0)
		return;
	for (i = 0; i < c->ncl; i++) {
		const struct cluster *C = &c->cl[i];

		cluster_bodies(s, C, s->t, s->u);
		for (b = C->b0; b <= C->b1; b++)
			hbs_body_set(&s->body[b], s->t, c->by[b], c->bu[b]);
	}
}

/*
 * After a jump of s->I (its bodies are at s->t, synced by the pre-jump
 * sample): the interfaces in contact, the clusters, their centres of mass
 * and the watched gaps again.  The ODE's blocks are laid out by the next
 * setup.
 */
int
hbs_cluster_jumped(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int ia = s->ia, p, i;

	c->dim = 0; /* the ODE's layout is the next setup's */

	if (s->I->q) { /* insert ia */
		if (GROW(c->act, c->capact, c->nact + 1))
			return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters");
		for (p = c->nact; p > 0 && c->act[p - 1] > ia; p--)
			c->act[p] = c->act[p - 1];
		c->act[p] = ia;
		c->nact++;
	} else {
		for (p = 0; p < c->nact && c->act[p] != ia; p++)
			;
		for (; p + 1 < c->nact; p++)
			c->act[p] = c->act[p + 1];
		c->nact--;
	}
	/* the bodies of the old clusters leave them (their state is at s->t) */
	for (i = 0; i < c->ncl; i++)
		for (p = c->cl[i].b0; p <= c->cl[i].b1; p++)
			s->body[p].cl = -1;
	c->ncl = 0;
	c->nwatch = 0;
	for (p = 0; p < c->nact;) {
		const struct iface *I = &s->ifc[c->act[p]];
		struct cluster *C;
		int q = p, b;

		while (q + 1 < c->nact && c->act[q + 1] == c->act[q] + 1)
			q++;
		if (GROW(c->cl, c->capcl, c->ncl + 1))
			return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters");
		C = &c->cl[c->ncl];
		C->floor = I->lo < 0;
		C->b0 = C->floor ? 0 : I->lo;
		C->b1 = s->ifc[c->act[q]].hi;
		C->M = C->y0 = C->u0 = C->a = 0.0;
		C->t0 = s->t;
		for (b = C->b0; b <= C->b1; b++) {
			double y, u;
			const struct body *B = &s->body[b];

			hbs_body_now(B, s->t, &y, &u);
			hbs_body_set(&s->body[b], s->t, y, u);
			s->body[b].cl = c->ncl;
			C->M += B->m;
			C->y0 += B->m * y;
			C->u0 += B->m * u;
			C->a += B->Fe;
		}
		C->y0 /= C->M;
		C->u0 /= C->M;
		C->a /= C->M;
		c->ncl++;
		p = q + 1;
	}
	for (i = 0; i < s->nif; i++)
		s->ifc[i].watch = 0;
	for (i = 0; i < c->ncl; i++) {
		const struct cluster *C = &c->cl[i];
		int lo = C->floor ? -1 : if_below(s, C->b0), hi = if_above(s, C->b1);

		if (lo >= 0 && !s->ifc[lo].watch) {
			s->ifc[lo].watch = 1;
			if (GROW(c->wif, c->capwif, c->nwatch + 1))
				return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters");
			c->wif[c->nwatch++] = lo;
		}
		if (hi >= 0) {
			s->ifc[hi].watch = 1;
			if (GROW(c->wif, c->capwif, c->nwatch + 1))
				return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters");
			c->wif[c->nwatch++] = hi;
		}
	}
	if (s->I->q)
		s->I->xe = s->I->x; /* its gap at the commencement */
	return 0;
}
