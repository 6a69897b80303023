/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_hertz.c - the Hertz elastic law (n_z = 0):
 *
 *     Phi(x_c, v_c) = k x_c |x_c|^(p - 1)
 *
 * with k > 0 and p >= 1 (p = 3/2 for spheres).  It dissipates nothing, so a
 * collision under it is perfectly elastic; it is the closed-form reference
 * of the test suite.
 *
 * Rule R1: with ext = 1 the same formula continues the law to x_c > 0
 * (adhesive: Phi > 0 there); with ext = 0 it is clamped,
 * Phi(x_c) = Phi(min(x_c, 0)).  The only kink is at x_c = 0 (p = 1 gives a
 * smooth law there, but the clamp of ext = 0 does not).
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_common.h"
#include "law_terms.h"

enum { K = LAW_HERTZ_K, P = LAW_HERTZ_P, NPAR = LAW_HERTZ_NPAR };

static const struct hb_law_param hertz_params[NPAR] = {
	[K] = LAW_PARAM_K(2.138e8, "stiffness of the spring, N m^-p; "
	                  "k = k_H, the Hertz coefficient of the materials"),
	[P] = LAW_PARAM_P("exponent of the spring; 3/2 is Hertz's for spheres"),
};

static double
hertz_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_hertz_phi(par, ext, xc, z, v);
}

/* Columns (x_c, v). */
static void
hertz_jac(const double *par, int ext, double xc, const double *z, double v,
          double *dphi, double *dpsi)
{
	(void)z;
	(void)v;
	(void)dpsi;
	law_hertz_dphi(par, ext, xc, dphi);
}

const struct hb_law_type hb_law_hertz = {
	.name = "hertz",
	.title = "Hertz elastic",
	.description = "Hertz spring k x|x|^(p-1), no dissipation; continued to "
	               "x_c > 0 by the same formula (adhesive, rule R1), or "
	               "clamped at x_c = 0 when ext = 0",
	.n_z = 0,
	.n_params = NPAR,
	.params = hertz_params,
	.n_kinks = 1,
	.phi = hertz_phi,
	.psi = NULL,
	.jac = hertz_jac,
	.kinks = law_kinks_xc,     /* g = {x_c} */
	.check = NULL,
	.k_hertz = law_k_hertz_identity, /* the law is Hertz's relation itself */
};
