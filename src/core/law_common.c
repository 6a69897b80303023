/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_common.c - the callbacks of struct hb_law_type that several laws share
 * (declared in law_common.h): the kink at x_c = 0, k = k_H, and the
 * Bouc-Wen check and k_hertz.
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"
#include "hybounce/status.h"

#include "law_common.h"

/*
 * Switching function of a law whose only kink is at x_c = 0 (the clamp of
 * rule R1 with ext = 0, and |x_c|^p): g[0] = x_c.
 */
void
law_kinks_xc(const double *par, int ext, double xc, const double *z, double v,
             double *g)
{
	(void)par;
	(void)ext;
	(void)z;
	(void)v;
	g[0] = xc;
}

/* k = k_H, for a law whose elastic term is the Hertzian relation itself. */
double
law_k_hertz_identity(const double *par, double kH)
{
	(void)par;
	return kH;
}

/*
 * Checks a Bouc-Wen parameter set (layout LAW_BW_*): eqs. bwshc_psi and
 * bwm_psi1 require gamma in [-beta, beta].  Returns 0, or HB_EINVAL with
 * the accepted range in msg (size n).
 */
int
law_bw_check(const double *par, char *msg, size_t n)
{
	double beta = par[LAW_BW_BETA], gamma = par[LAW_BW_GAMMA];

	if (gamma >= -beta && gamma <= beta)
		return HB_OK;
	return hb_status_set(msg, n, HB_EINVAL,
	    "gamma = %g must lie in [-beta, beta] = [%g, %g]", gamma, -beta, beta);
}

/*
 * Eq. k_hertz for a Bouc-Wen law (layout LAW_BW_*): the k whose two
 * branches together match the Hertz coefficient kH,
 * k = k_H / (alpha + (1 - alpha) A^p).
 */
double
law_bw_k_hertz(const double *par, double kH)
{
	double alpha = par[LAW_BW_ALPHA];

	return kH / (alpha + (1.0 - alpha) * apow(par[LAW_BW_A], par[LAW_BW_P]));
}
