/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_bwshccl.c - the Bouc-Wen-Simon-Hunt-Crossley collision law (paper
 * example ex:bwshc, eqs. bwshc_psi and bwshc_phi; n_z = 1):
 *
 *     Psi = A v - beta z|z|^(n-1) |v| - gamma |z|^n v
 *     Phi = alpha k x|x|^(p-1) + (1 - alpha) k z|z|^(p-1) + c |x|^p v
 *
 * with x = x_c, z = z_c, v = v_c, k, A > 0, alpha in (0, 1), beta, c >= 0,
 * gamma in [-beta, beta] and n, p >= 1.  The first term is the elastic
 * branch, the second the hysteretic branch (z is a length governed by the
 * Bouc-Wen model), the third the damping of Simon, Hunt and Crossley.
 *
 * Rule R1: with ext = 1 the same formulas continue the law to x_c > 0 (at
 * z = 0 and v >= 0 the force is then positive: adhesive); with ext = 0 the
 * law is clamped, Phi(x, z, v) = Phi(min(x, 0), z, v).  Psi does not depend
 * on x_c.  Kinks: x_c (|x|^p, the clamp), z (|z|^n) and v (|v|).
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_common.h"
#include "law_terms.h"

static const struct hb_law_param bwshccl_params[LAW_BW_NPAR] = {
	LAW_BW_PARAMS(7.095e7, 2.409e8, 2.409e8, "Phi of the BWSHCCL", "Psi of the BWSHCCL",
	    "Bouc-Wen gain A: dz/dt = A v while z is small (Psi of the BWSHCCL)",
	    "exponent of both branches and of the damping; 3/2 is Hertz's"),
	[LAW_BW_C] = LAW_PARAM_C_HC(2.5e7, "2"),
};

/* Eq. bwshc_phi: the branches at (x_c, z), then the damping. */
static double
bwshccl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_bwshccl_phi(par, ext, xc, z, v);
}

/* Eq. bwshc_psi: the Bouc-Wen rate driven by v_c. */
static void
bwshccl_psi(const double *par, int ext, double xc, const double *z, double v,
            double *dz)
{
	(void)ext;
	(void)xc;
	dz[0] = law_bw_rate(par, z[0], v);
}

/* Columns (x_c, z, v); dpsi is one row. */
/* Psi with the sign of v in |v| given (kink g[2]). */
static void
bwshccl_psi_mode(const double *par, int ext, double xc, const double *z, double v, int sign,
                 double *dz)
{
	law_bwshccl_psi_mode(par, ext, xc, z, v, sign, dz);
}

static void
bwshccl_jac(const double *par, int ext, double xc, const double *z, double v,
            double *dphi, double *dpsi)
{
	law_bwshccl_dphi(par, ext, xc, z, v, dphi);
	if (dpsi == NULL)
		return;
	dpsi[0] = 0.0;
	dpsi[1] = law_bw_rate_dz(par, z[0], v);
	dpsi[2] = law_bw_rate_dw(par, z[0], v);
}

/* g = {x_c, z, v}. */
static void
bwshccl_kinks(const double *par, int ext, double xc, const double *z,
              double v, double *g)
{
	(void)par;
	(void)ext;
	law_bwshccl_kinks(xc, z, v, g);
}

const struct hb_law_type hb_law_bwshccl = {
	.name = "bwshccl",
	.title = "Bouc-Wen-Simon-Hunt-Crossley (BWSHCCL)",
	.description = "Elastic and Bouc-Wen hysteretic Hertz branches with "
	               "Hunt-Crossley damping; continued to x_c > 0 by the same "
	               "formulas (adhesive, rule R1), or clamped at x_c = 0 when "
	               "ext = 0",
	.n_z = 1,
	.n_params = LAW_BW_NPAR,
	.params = bwshccl_params,
	.n_kinks = 3,
	.phi = bwshccl_phi,
	.psi = bwshccl_psi,
	.jac = bwshccl_jac,
	.kinks = bwshccl_kinks,
	.psi_mode = bwshccl_psi_mode, /* |v| as a mode */
	.mode_kink = 2,
	.check = law_bw_check,     /* gamma in [-beta, beta] */
	.k_hertz = law_bw_k_hertz, /* k_H / (alpha + (1 - alpha) A^p) */
};
