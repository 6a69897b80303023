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
void
hbs_snap_stick(struct hb_sim *s, double *u)
{
	struct phase *p = s->cur;
	const struct layout *L = &p->L;
	double y[MAXDIM], eta = fmax(64 * DBL_EPSILON, 100 * fmax(s->sc.run.rtol, s->sc.run.atol)), phi, v;
	double z[HB_LAW_MAX_Z] = { 0 };
	int i;

	v = u[L->iv] * s->scale[L->iv];
	if (!(v > 0 && v <= eta * s->vmax))
		return;
	hbs_unscale(p, u, y);
	for (i = 0; i < s->I->law->n_z; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, v);
	if (phi > 0 && phi <= eta * s->I->Fcmax)
		u[L->iv] = 0.0;
}

/*
 * The noise of v at a scaled state: NOISE times the tolerance the control
 * allows it (atol + rtol |u_v| of its scale).
 */
enum { NOISE = 100 };

static double
v_noise(const struct hb_sim *s, const double *u)
{
	int iv = s->cur->L.iv;

	return NOISE * s->scale[iv] * (s->sc.run.atol + s->sc.run.rtol * fabs(u[iv]));
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
int
hbs_snap_separation(struct hb_sim *s, double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct iface *I = s->I;
	double z[HB_LAW_MAX_Z] = { 0 }, dphi[HB_LAW_MAX_Z + 2], phi, v, xc, vn, dv;
	int nz = I->law->n_z, i;

	if (!p->q)
		return 0;
	/* unscaled as hbs_unscale does, only the components read, v first */
	v = u[L->iv] * s->scale[L->iv];
	if (!(v > 0))
		return 0;
	xc = u[L->ixc] * s->scale[L->ixc];
	for (i = 0; i < nz; i++)
		z[i] = u[L->iz + i] * s->scale[L->iz + i];
	phi = phi_at(s, xc, z, v);
	if (!(phi > 0))
		return 0;
	I->law->jac(I->par, I->ext, xc, z, v, dphi, NULL);
	dv = dphi[nz + 1];
	if (!(dv > 0) || phi > dv * v_noise(s, u))
		return 0;
	vn = v - phi / dv;
	for (i = 0; i < 8 && phi_at(s, xc, z, vn) > 0; i++)
		vn -= ldexp(fabs(vn) * DBL_EPSILON, i);
	if (phi_at(s, xc, z, vn) > 0)
		return 0;
	u[L->iv] = vn * s->iscale[L->iv];
	return 1;
}

/* Does the step from the scaled state u begin on Phi = 0 to the noise, receding? */
int
hbs_hugging(struct hb_sim *s, const double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct iface *I = s->I;
	double z[HB_LAW_MAX_Z] = { 0 }, dphi[HB_LAW_MAX_Z + 2], phi, v, xc;
	int nz = I->law->n_z, i;

	if (!p->q)
		return 0;
	/* unscaled as hbs_unscale does, only the components read, v first */
	v = u[L->iv] * s->scale[L->iv];
	if (!(v > 0))
		return 0;
	xc = u[L->ixc] * s->scale[L->ixc];
	for (i = 0; i < nz; i++)
		z[i] = u[L->iz + i] * s->scale[L->iz + i];
	phi = phi_at(s, xc, z, v);
	I->law->jac(I->par, I->ext, xc, z, v, dphi, NULL);
	return dphi[nz + 1] > 0 && fabs(phi) <= dphi[nz + 1] * v_noise(s, u);
}
