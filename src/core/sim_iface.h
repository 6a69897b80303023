/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_iface.h - the terms of one interface's contact that both systems
 * the driver steps watch with (private to the engine): Phi, the law's
 * switching functions, dPhi/dt, the mode a step begins in, and the
 * contact's block of the flow's Jacobian.  The pair's watched functions
 * (sim_watch.c) and a chain's clusters' (sim_cluster.c) call them for
 * each interface in contact, as do both Jacobians (sim_flow.c,
 * sim_cluster_stiff.c); inline, as they are evaluated at every step and
 * every trial of a location.
 */
#ifndef HYBOUNCE_SIM_IFACE_H
#define HYBOUNCE_SIM_IFACE_H

#include "sim_impl.h"
#include "law_terms.h"

/*
 * The law's terms the watched functions need: inline for the engine's own laws
 * (law_terms.h, the functions their tables call), through the table for a
 * host's law (W_HOST).
 */
enum wlaw { W_HOST, W_SHCCL, W_BWSHCCL, W_BWMCL, W_HERTZ, W_LINEAR };

static inline enum wlaw
wlaw_of(const struct hb_law_type *law)
{
	if (law == &hb_law_bwshccl)
		return W_BWSHCCL;
	if (law == &hb_law_bwmcl)
		return W_BWMCL;
	if (law == &hb_law_shccl)
		return W_SHCCL;
	if (law == &hb_law_hertz)
		return W_HERTZ;
	return law == &hb_law_linear ? W_LINEAR : W_HOST;
}

/* Phi of interface I (per interface: both systems watch with it) */
static inline double
hbs_iface_phi(const struct iface *I, double xc, const double *z, double v)
{
	switch (wlaw_of(I->law)) {
	case W_SHCCL: return law_shccl_phi(I->par, I->ext, xc, z, v);
	case W_BWSHCCL: return law_bwshccl_phi(I->par, I->ext, xc, z, v);
	case W_BWMCL: return law_bwmcl_phi(I->par, I->ext, xc, z, v);
	case W_HERTZ: return law_hertz_phi(I->par, I->ext, xc, z, v);
	case W_LINEAR: return law_linear_phi(I->par, I->ext, xc, z, v);
	default: return I->law->phi(I->par, I->ext, xc, z, v);
	}
}

/* its switching functions into g */
static inline void
hbs_iface_kinks(const struct iface *I, double xc, const double *z, double v, double *g)
{
	switch (wlaw_of(I->law)) {
	case W_SHCCL:
	case W_HERTZ:
	case W_LINEAR: g[0] = xc; break; /* law_kinks_xc */
	case W_BWSHCCL: law_bwshccl_kinks(xc, z, v, g); break;
	case W_BWMCL: law_bwmcl_kinks(I->par, I->ext, xc, z, v, g); break;
	default: I->law->kinks(I->par, I->ext, xc, z, v, g); break;
	}
}

/*
 * dPhi/dt of interface I along its flow, with v' = vdot and Psi in mode
 * msign (0: Psi's own doubles; the pair watches with 0, a chain's
 * clusters with the step's frozen mode): the function whose minimum is
 * F_c's maximum.  Psi's partials are not needed.
 */
static inline double
hbs_iface_dphidt(const struct iface *I, double xc, const double *z, double v, double vdot, int msign)
{
	double dphi[HB_LAW_MAX_Z + 2], dz[HB_LAW_MAX_Z], dpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)], d;
	int i, nz = I->law->n_z;

	switch (wlaw_of(I->law)) {
	case W_SHCCL: law_shccl_dphi(I->par, I->ext, xc, v, dphi); break;
	case W_BWSHCCL:
		law_bwshccl_dphi(I->par, I->ext, xc, z, v, dphi);
		law_bwshccl_psi_mode(I->par, I->ext, xc, z, v, msign, dz); /* sign 0: Psi's doubles */
		break;
	case W_BWMCL:
		law_bwmcl_dphi(I->par, z, dphi);
		law_bwmcl_psi_mode(I->par, I->ext, xc, z, v, msign, dz);
		break;
	case W_HERTZ: law_hertz_dphi(I->par, I->ext, xc, dphi); break;
	case W_LINEAR: law_linear_dphi(I->par, I->ext, xc, dphi); break;
	default:
		I->law->jac(I->par, I->ext, xc, z, v, dphi, nz ? dpsi : NULL);
		if (nz && msign)
			I->law->psi_mode(I->par, I->ext, xc, z, v, msign, dz);
		else if (nz)
			I->law->psi(I->par, I->ext, xc, z, v, dz);
		break;
	}
	d = dphi[0] * v + dphi[nz + 1] * vdot;
	for (i = 0; i < nz; i++)
		d += dphi[1 + i] * dz[i];
	return d;
}

/*
 * Kinks as modes, per interface (both systems): the sign of the law's
 * |w| term (law_type.psi_mode) frozen for a step is the sign of its
 * switching function at the step's start (0: the law has no mode, or
 * run.kinks is off).
 */
static inline int
hbs_iface_mode(const struct hb_sim *s, const struct iface *I, double xc, const double *z, double v)
{
	double g[HB_LAW_MAX_KINKS];
	int k = I->law->mode_kink;

	if (!I->law->psi_mode || !s->sc.run.kinks)
		return 0;
	I->law->kinks(I->par, I->ext, xc, z, v, g);
	return g[k] > 0 ? 1 : (g[k] < 0 ? -1 : 0);
}

/* Where interface I's contact block sits in a flow's state: the rows (and columns) of its terms. */
struct jrows {
	int ixc, iv, iz, iW, iJc;
};

/*
 * Interface I's contact block of the Jacobian of the flow (both
 * systems' Jacobians, for bsimp), unscaled, from Phi and its partials
 * dphi (columns x_c, z..., v) and Psi's dpsi at the state (v its relative
 * velocity): dx_c'/dv = 1; the v row -dphi vnum / vden (the pair's 1 / m,
 * a chain's 1 / m_lo + 1 / m_hi over 1); the z rows dpsi; the W row
 * dphi v (+ Phi in column v); the J_Fc row -dphi.  Each entry once,
 * through put (the pair's sets it, a chain's scales and adds it); the
 * neighbours' forces in a chain's v rows are the chain's own.
 */
static inline void
hbs_iface_jac_block(const struct iface *I, const struct jrows *r, double v, double phi, const double *dphi,
                    const double *dpsi, double vnum, double vden,
                    void (*put)(void *ctx, int row, int col, double val), void *ctx)
{
	int nz = I->law->n_z, col[HB_LAW_MAX_Z + 2], i, k;

	col[0] = r->ixc;
	for (i = 0; i < nz; i++)
		col[1 + i] = r->iz + i;
	col[nz + 1] = r->iv;
	put(ctx, r->ixc, r->iv, 1.0);
	for (k = 0; k < nz + 2; k++) {
		put(ctx, r->iv, col[k], -dphi[k] * vnum / vden);
		put(ctx, r->iW, col[k], k == nz + 1 ? dphi[k] * v + phi : dphi[k] * v);
		put(ctx, r->iJc, col[k], -dphi[k]);
		for (i = 0; i < nz; i++)
			put(ctx, r->iz + i, col[k], dpsi[i * (nz + 2) + k]);
	}
}

#endif
