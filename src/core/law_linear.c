/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_linear.c - the clamped linear law of the non-uniqueness example
 * (paper eq. nonuniq_law, n_z = 0):
 *
 *     Phi(x_c, v_c) = k min(x_c, 0)
 *
 * with k > 0 in N/m.  Its k is a plain spring constant, not a Hertzian
 * coefficient, so it is never derived from the materials (k_hertz = NULL).
 *
 * Rule R1: with ext = 1 the law is continued to x_c > 0 by Phi = k x_c
 * (adhesive); with ext = 0 it is the paper's law as written, clamped at 0,
 * which is what the solution chi^d of the example needs.  The kink is at
 * x_c = 0 (only with ext = 0).
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_common.h"
#include "law_terms.h"

enum { K = LAW_LINEAR_K, NPAR = LAW_LINEAR_NPAR };

static const struct hb_law_param linear_params[NPAR] = {
	[K] = { "k", { .kg = 1, .s = -2 }, LAW_RANGE_POSITIVE, 1e5, 0,
	        "spring constant, N/m (the paper's example of non-uniqueness at a separation); never derived from materials" },
};

static double
linear_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_linear_phi(par, ext, xc, z, v);
}

/* Columns (x_c, v). */
static void
linear_jac(const double *par, int ext, double xc, const double *z, double v,
           double *dphi, double *dpsi)
{
	(void)z;
	(void)v;
	(void)dpsi;
	law_linear_dphi(par, ext, xc, dphi);
}

const struct hb_law_type hb_law_linear = {
	.name = "linear",
	.title = "Clamped linear (non-uniqueness example)",
	.description = "Linear spring k min(x_c, 0) of the paper's example of non-uniqueness at a separation; continued "
	               "to x_c > 0 as k x_c (adhesive, rule R1), or clamped as "
	               "written when ext = 0",
	.n_z = 0,
	.n_params = NPAR,
	.params = linear_params,
	.n_kinks = 1,
	.phi = linear_phi,
	.psi = NULL,
	.jac = linear_jac,
	.kinks = law_kinks_xc,     /* g = {x_c} */
	.check = NULL,
	.k_hertz = NULL,
};
