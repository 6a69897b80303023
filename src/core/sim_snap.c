/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_snap.c - states on the boundary of C to the precision of the
 * computation: round-off at a sticking contact, and the separation that
 * rounding cannot fake (see sim.c for the method).
 */
#include "sim_impl.h"

/*
 * Round-off at a sticking contact.  When the force and the velocity both
 * decay towards zero without changing sign (a Maxwell element with c below
 * sqrt(k m)/2), the computed values eventually wander about zero at the
 * level of round-off and may both turn positive, which would be read as a
 * separation.  A state whose v and Phi are both positive but below
 * eta = 100 max(rtol, atol) of the contact's largest |v| and F_c (the noise
 * of the integration, whose components are controlled to atol of their
 * scales) is on
 * the boundary of C to the precision of the computation: its v is set to 0,
 * which keeps it in C (rule R2) and changes it by less than the tolerance.
 */
/* Where an interface's block lies in a scaled state: its x_c, v and first z. */
struct blk {
	int ixc, iv, iz;
};

/* Interface I's x_c and z in u, unscaled as hbs_unscale does. */
static inline double
blk_state(const struct hb_sim *s, const struct iface *I, struct blk b, const double *u, double *z)
{
	int i;

	for (i = 0; i < I->law->n_z; i++)
		z[i] = u[b.iz + i] * s->scale[b.iz + i];
	return u[b.ixc] * s->scale[b.ixc];
}

/* The pair's block, and a chain's interface's (sim_cluster.c: x_c, v, z... at its offset). */
static inline struct blk
pair_blk(const struct hb_sim *s)
{
	const struct layout *L = &s->cur->L;

	return (struct blk){ L->ixc, L->iv, L->iz };
}

static inline struct blk
chain_blk(const struct iface *I)
{
	return (struct blk){ I->off, I->off + 1, I->off + 2 };
}

static ALWAYS_INLINE void
stick(struct hb_sim *s, const struct iface *I, struct blk b, double vmax, double *u)
{
	double eta = fmax(64 * DBL_EPSILON, 100 * fmax(s->sc.run.rtol, s->sc.run.atol)), phi, v, xc;
	double z[HB_LAW_MAX_Z] = { 0 };

	v = u[b.iv] * s->scale[b.iv];
	if (!(v > 0 && v <= eta * vmax))
		return;
	xc = blk_state(s, I, b, u, z);
	phi = I->law->phi(I->par, I->ext, xc, z, v);
	if (phi > 0 && phi <= eta * I->Fcmax)
		u[b.iv] = 0.0;
}

/*
 * A chain's interfaces are snapped where their law has an internal state
 * (a Maxwell element, BWMCL and BWSHCCL: the sticking the snap is for).
 * An elastic or SHCCL contact in a chain may end with v and Phi both at
 * the level of round-off, in a wave's tail where touching beads part:
 * that is a separation (the gap opens), not a contact sticking, and the
 * snap would hold such a pair in contact, its gap open by femtometres,
 * to the run's end.  The pair's interface is snapped whatever its law.
 */
void
hbs_snap_stick(struct hb_sim *s, double *u)
{
	if (s->chain) {
		for (int p = 0; p < s->cx.nact; p++) {
			const struct iface *I = &s->ifc[s->cx.act[p]];

			if (I->law->n_z > 0)
				stick(s, I, chain_blk(I), I->vmax, u);
		}
		return;
	}
	stick(s, s->I, pair_blk(s), s->vmax, u);
}

/*
 * The noise of v at a scaled state: NOISE times the tolerance the control
 * allows it (atol + rtol |u_v| of its scale).
 */
enum { NOISE = 100 };

static double
v_noise(const struct hb_sim *s, struct blk b, const double *u)
{
	return NOISE * s->scale[b.iv] * (s->sc.run.atol + s->sc.run.rtol * fabs(u[b.iv]));
}
/*
 * A separation that rounding cannot fake.  Under heavy damping (SHCCL
 * with c v0 / k beyond about 35) the receding velocity creeps up to the
 * value at which Phi = 0 (k / c for SHCCL) while x_c returns to 0: Phi is
 * then zero to within the integration's noise for the whole restitution,
 * and its computed sign says nothing.  A receding state (v > 0) whose Phi
 * is positive but vanishes within the noise of v (Newton's step on Phi in
 * v, Phi / (dPhi/dv), below v_noise) is on the boundary of C to the
 * precision of the computation: its v is moved by that step (and ulps)
 * until Phi <= 0, so that it stays in C (rule R2).  The contact then ends where Phi turns positive beyond
 * the noise, which is where the exact law ends it (x_c = 0 for SHCCL).
 * Laws whose Phi does not grow with v are left alone.  Returns 1 if the
 * state was moved.
 */
static ALWAYS_INLINE int
separation(struct hb_sim *s, const struct iface *I, struct blk b, double *u)
{
	double z[HB_LAW_MAX_Z] = { 0 }, dphi[HB_LAW_MAX_Z + 2], phi, v, xc, vn, dv;
	int nz = I->law->n_z, i;

	/* unscaled as hbs_unscale does, only the components read, v first */
	v = u[b.iv] * s->scale[b.iv];
	if (!(v > 0))
		return 0;
	xc = blk_state(s, I, b, u, z);
	phi = I->law->phi(I->par, I->ext, xc, z, v);
	if (!(phi > 0))
		return 0;
	I->law->jac(I->par, I->ext, xc, z, v, dphi, NULL);
	dv = dphi[nz + 1];
	if (!(dv > 0) || phi > dv * v_noise(s, b, u))
		return 0;
	vn = v - phi / dv;
	for (i = 0; i < 8 && I->law->phi(I->par, I->ext, xc, z, vn) > 0; i++)
		vn -= ldexp(fabs(vn) * DBL_EPSILON, i);
	if (I->law->phi(I->par, I->ext, xc, z, vn) > 0)
		return 0;
	u[b.iv] = vn * s->iscale[b.iv];
	return 1;
}

int
hbs_snap_separation(struct hb_sim *s, double *u)
{
	int moved = 0;

	if (!s->cur->q)
		return 0;
	if (!s->chain)
		return separation(s, s->I, pair_blk(s), u);
	for (int p = 0; p < s->cx.nact; p++) {
		const struct iface *I = &s->ifc[s->cx.act[p]];

		moved |= separation(s, I, chain_blk(I), u);
	}
	return moved;
}

static ALWAYS_INLINE int
hugging(struct hb_sim *s, const struct iface *I, struct blk b, const double *u)
{
	double z[HB_LAW_MAX_Z] = { 0 }, dphi[HB_LAW_MAX_Z + 2], phi, v, xc;
	int nz = I->law->n_z;

	/* unscaled as hbs_unscale does, only the components read, v first */
	v = u[b.iv] * s->scale[b.iv];
	if (!(v > 0))
		return 0;
	xc = blk_state(s, I, b, u, z);
	phi = I->law->phi(I->par, I->ext, xc, z, v);
	I->law->jac(I->par, I->ext, xc, z, v, dphi, NULL);
	return dphi[nz + 1] > 0 && fabs(phi) <= dphi[nz + 1] * v_noise(s, b, u);
}

/* Does the step from the scaled state u begin on Phi = 0 to the noise, receding (any interface)? */
int
hbs_hugging(struct hb_sim *s, const double *u)
{
	if (!s->cur->q)
		return 0;
	if (!s->chain)
		return hugging(s, s->I, pair_blk(s), u);
	for (int p = 0; p < s->cx.nact; p++) {
		const struct iface *I = &s->ifc[s->cx.act[p]];

		if (hugging(s, I, chain_blk(I), u))
			return 1;
	}
	return 0;
}
