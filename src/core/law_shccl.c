/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_shccl.c - the Simon-Hunt-Crossley collision law (n_z = 0):
 *
 *     Phi(x_c, v_c) = k x_c |x_c|^(p - 1) + c |x_c|^p v_c
 *
 * with k > 0, c >= 0 and p >= 1: a Hertz spring with the damping of Simon
 * (1967) and Hunt and Crossley (1975).  The factor |x_c|^p of the damping
 * makes Phi(0, v) = 0 (paper eq. vanishing).  It is BWSHCCL (eq.
 * bwshc_phi) with alpha = 1.
 *
 * Rule R1: with ext = 1 the same formula continues the law to x_c > 0; for
 * v_c >= 0 the force is then positive (adhesive).  With ext = 0,
 * Phi(x_c, v) = Phi(min(x_c, 0), v).  The kink is at x_c = 0.
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_common.h"
#include "law_terms.h"

enum { K = LAW_SHCCL_K, P = LAW_SHCCL_P, C = LAW_SHCCL_C, NPAR = LAW_SHCCL_NPAR };

static const struct hb_law_param shccl_params[NPAR] = {
	[K] = LAW_PARAM_K(4.254e8, "stiffness of the Hertz term, N m^-p; "
	                  "k = k_H, the Hertz coefficient of the materials"),
	[P] = LAW_PARAM_P("exponent of the spring and of the damping; 3/2 is Hertz's"),
	[C] = LAW_PARAM_C_HC(4.3e9, "3"),
};

static double
shccl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_shccl_phi(par, ext, xc, z, v);
}

/* Columns (x_c, v). */
static void
shccl_jac(const double *par, int ext, double xc, const double *z, double v,
          double *dphi, double *dpsi)
{
	(void)z;
	(void)dpsi;
	law_shccl_dphi(par, ext, xc, v, dphi);
}

const struct hb_law_type hb_law_shccl = {
	.name = "shccl",
	.title = "Simon-Hunt-Crossley (SHCCL)",
	.description = "Hertz spring k x|x|^(p-1) with Hunt-Crossley damping "
	               "c|x|^p v; continued to x_c > 0 by the same formula "
	               "(adhesive, rule R1), or clamped at x_c = 0 when ext = 0",
	.n_z = 0,
	.n_params = NPAR,
	.params = shccl_params,
	.n_kinks = 1,
	.phi = shccl_phi,
	.psi = NULL,
	.jac = shccl_jac,
	.kinks = law_kinks_xc,     /* g = {x_c} */
	.check = NULL,
	.k_hertz = law_k_hertz_identity, /* the elastic term is Hertz's relation */
};
