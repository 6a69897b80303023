/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_bwmcl.c - the Bouc-Wen-Maxwell collision law (paper example ex:bwm,
 * eqs. bwm_psi1, bwm_psi2 and bwm_phi; n_z = 2):
 *
 *     Phi    = alpha k z2|z2|^(p-1) + (1 - alpha) k z1|z1|^(p-1)
 *     Psi_2  = v - Phi / c
 *     Psi_1  = A Psi_2 - beta z1|z1|^(n-1) |Psi_2| - gamma |z1|^n Psi_2
 *
 * with z1 = z_c1 (the hysteretic displacement, dz1/dt = Psi_1), z2 = z_c2
 * (the deflection of the spring branches, dz2/dt = Psi_2), k, A, c > 0,
 * alpha in (0, 1), beta >= 0, gamma in [-beta, beta] and n, p >= 1.  The
 * branches of eq. bwshc_phi are in series with a linear dashpot c, whose
 * deflection is x_c - z2.
 *
 * Rule R1: Phi depends on the internal state only, never on x_c, so it
 * needs no continuation to x_c > 0 and `ext` has no effect.  Kinks: z1 and
 * z2 (the powers) and Psi_2 (|Psi_2| in Psi_1).
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_common.h"
#include "law_terms.h"

static const struct hb_law_param bwmcl_params[LAW_BW_NPAR] = {
	LAW_BW_PARAMS(2.138e8, 5e7, 5e7, "Phi of the BWMCL", "Psi_1 of the BWMCL",
	    "Bouc-Wen gain A: dz1/dt = A dz2/dt while z1 is small (Psi_1 of the BWMCL)",
	    "exponent of both spring branches; 3/2 is Hertz's"),
	[LAW_BW_C] = { "c", { .kg = 1, .s = -1 }, LAW_RANGE_POSITIVE, 4.4e3, 0,
	        "Maxwell dashpot in series, N s/m; sets the sinking rate m g / c (Table 1 of the paper)" },
};

/* Eq. bwm_phi: the elastic branch deflects by z2, the hysteretic one by z1. */
static double
bwmcl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_bwmcl_phi(par, ext, xc, z, v);
}

/* dz[0] = Psi_1 (for z_c1), dz[1] = Psi_2 (for z_c2). */
static void
bwmcl_psi(const double *par, int ext, double xc, const double *z, double v,
          double *dz)
{
	double psi2 = v - bwmcl_phi(par, ext, xc, z, v) / par[LAW_BW_C];

	dz[0] = law_bw_rate(par, z[0], psi2);
	dz[1] = psi2;
}

/*
 * Columns (x_c, z1, z2, v); dpsi rows (Psi_1, Psi_2).  Psi_1 depends on the
 * state through Psi_2 as well as through z1 directly:
 *     dPsi_1/dw = (A - beta z1|z1|^(n-1) sgn(Psi_2) - gamma |z1|^n) dPsi_2/dw
 *                 + [w = z1] (-beta n|z1|^(n-1) |Psi_2|
 *                             - gamma n z1|z1|^(n-2) Psi_2).
 */
/* Psi with the sign of Psi_2 in |Psi_2| given (kink g[2]). */
static void
bwmcl_psi_mode(const double *par, int ext, double xc, const double *z, double v, int sign,
               double *dz)
{
	law_bwmcl_psi_mode(par, ext, xc, z, v, sign, dz);
}

static void
bwmcl_jac(const double *par, int ext, double xc, const double *z, double v,
          double *dphi, double *dpsi)
{
	double c = par[LAW_BW_C], z1 = z[0], psi2, g1;

	law_bwmcl_dphi(par, z, dphi);
	if (dpsi == NULL)
		return;

	psi2 = v - bwmcl_phi(par, ext, xc, z, v) / c;
	dpsi[4] = 0.0;
	dpsi[5] = -dphi[1] / c;
	dpsi[6] = -dphi[2] / c;
	dpsi[7] = 1.0;

	g1 = law_bw_rate_dw(par, z1, psi2);
	dpsi[0] = 0.0;
	dpsi[1] = g1 * dpsi[5] + law_bw_rate_dz(par, z1, psi2);
	dpsi[2] = g1 * dpsi[6];
	dpsi[3] = g1;
}

/* g = {z1, z2, Psi_2}. */
static void
bwmcl_kinks(const double *par, int ext, double xc, const double *z, double v,
            double *g)
{
	law_bwmcl_kinks(par, ext, xc, z, v, g);
}

const struct hb_law_type hb_law_bwmcl = {
	.name = "bwmcl",
	.title = "Bouc-Wen-Maxwell (BWMCL)",
	.description = "Elastic and Bouc-Wen hysteretic Hertz branches in series "
	               "with a linear dashpot c; Phi depends on z only, so x_c > 0 "
	               "needs no continuation and ext has no effect (rule R1)",
	.n_z = 2,
	.n_params = LAW_BW_NPAR,
	.params = bwmcl_params,
	.n_kinks = 3,
	.phi = bwmcl_phi,
	.psi = bwmcl_psi,
	.jac = bwmcl_jac,
	.kinks = bwmcl_kinks,
	.psi_mode = bwmcl_psi_mode, /* |Psi_2| as a mode */
	.mode_kink = 2,
	.check = law_bw_check,     /* gamma in [-beta, beta] */
	.k_hertz = law_bw_k_hertz, /* k_H / (alpha + (1 - alpha) A^p) */
};
