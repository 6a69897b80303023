/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_common.h - what the contact laws (src/core/law_*.c) share: parameter
 * descriptors, rule R1, the Bouc-Wen terms and the shared callbacks of
 * law_common.c (private to the engine).
 *
 * Parameter rows.  A row that means the same in several laws (the Hertz
 * stiffness k, the exponent p, the Hunt-Crossley damping c, the Bouc-Wen
 * A, alpha, beta, gamma, n) is written once here as a macro; a law's table
 * supplies only what differs (default, help text, equation label).
 *
 * Rule R1 (law.h).  law_ext_clamped() is the one test of the clamp: with
 * ext = 0 and x_c > 0, Phi(x_c, z, v) = Phi(0, z, v), so a law evaluates
 * its formula at law_ext_x(ext, x_c) and its partials in x_c are 0 there
 * (law_ext_dx); with ext = 1 the formula continues itself (adhesive).
 *
 * The helpers keep the operations and their order of the formulas they
 * replace, so every law gives the same doubles to the last bit.
 */
#ifndef HYBOUNCE_LAW_COMMON_H
#define HYBOUNCE_LAW_COMMON_H

#include <math.h>
#include <stddef.h>

#include "hybounce/law.h"

#include "law_pow.h"

/* Dimensions (struct hb_unit_dim) used by several tables. */
#define LAW_DIM_NONE    { 0 }
#define LAW_DIM_K_HERTZ { .kg = 1, .m = 1, .s = -2, .mp = -1 } /* N m^-p */
#define LAW_DIM_C_HC    { .kg = 1, .s = -1, .mp = -1 }         /* N s m^(-p-1) */
#define LAW_DIM_PER_M_N { .mn = -1 }                           /* m^-n */

/* Admissible ranges: lo, hi, lo_open, hi_open of struct hb_law_param. */
#define LAW_RANGE_POSITIVE 0, HUGE_VAL, 1, 0         /* (0, inf) */
#define LAW_RANGE_NONNEG   0, HUGE_VAL, 0, 0         /* [0, inf) */
#define LAW_RANGE_EXPONENT 1, 1e12, 0, 0             /* [1, 1e12]: far past any contact law (every power of such an exponent over- or underflows) */
#define LAW_RANGE_FRACTION 0, 1, 1, 1                /* (0, 1) */
#define LAW_RANGE_ANY      -HUGE_VAL, HUGE_VAL, 0, 0 /* no bound */

/* The stiffness k > 0 of a Hertz-type term k x|x|^(p-1), N m^-p. */
#define LAW_PARAM_K(def, help) \
	{ "k", LAW_DIM_K_HERTZ, LAW_RANGE_POSITIVE, (def), HB_LAW_PARAM_STIFFNESS, help }

/* The exponent p >= 1 of the Hertz-type terms, 3/2 by default. */
#define LAW_PARAM_P(help) \
	{ "p", LAW_DIM_NONE, LAW_RANGE_EXPONENT, 1.5, HB_LAW_PARAM_EXPONENT_P, help }

/* The Hunt-Crossley damping c >= 0 of a term c|x|^p v; table: its number in the paper. */
#define LAW_PARAM_C_HC(def, table) \
	{ "c", LAW_DIM_C_HC, LAW_RANGE_NONNEG, (def), 0, \
	  "Hunt-Crossley damping c|x|^p v, N s m^(-p-1) (Table " table " of the paper)" }

/*
 * The Bouc-Wen laws (BWSHCCL, BWMCL) share their parameter layout: the
 * elastic and hysteretic Hertz branches (k, alpha, p), the Bouc-Wen model
 * of the hysteretic displacement (A, beta, gamma, n) and a damping c whose
 * kind differs.  law_bw_* below read par[] by this layout.
 */
enum {
	LAW_BW_K,
	LAW_BW_A,
	LAW_BW_ALPHA,
	LAW_BW_BETA,
	LAW_BW_GAMMA,
	LAW_BW_N,
	LAW_BW_P,
	LAW_BW_C,
	LAW_BW_NPAR,
};

/*
 * The rows LAW_BW_K .. LAW_BW_P of a Bouc-Wen table (the law adds
 * LAW_BW_C).  phi_eq and psi_eq name the law's Phi and its Bouc-Wen
 * equation for the reader ("Psi of the BWSHCCL"); a_help and p_help the help of A and p.
 */
#define LAW_BW_PARAMS(k_def, beta_def, gamma_def, phi_eq, psi_eq, a_help, p_help) \
	[LAW_BW_K] = LAW_PARAM_K(k_def, "stiffness of both branches, N m^-p; " \
	                         "derived from the materials by Hertz contact theory"), \
	[LAW_BW_A] = { "A", LAW_DIM_NONE, LAW_RANGE_POSITIVE, 1.0, 0, a_help }, \
	[LAW_BW_ALPHA] = { "alpha", LAW_DIM_NONE, LAW_RANGE_FRACTION, 0.35, 0, \
	        "share of the elastic branch; 1 - alpha is hysteretic (" phi_eq ")" }, \
	[LAW_BW_BETA] = { "beta", LAW_DIM_PER_M_N, LAW_RANGE_NONNEG, (beta_def), 0, \
	        "Bouc-Wen beta, m^-n: shapes the hysteresis loop (" psi_eq ")" }, \
	[LAW_BW_GAMMA] = { "gamma", LAW_DIM_PER_M_N, LAW_RANGE_ANY, (gamma_def), \
	        HB_LAW_PARAM_CHECKED, \
	        "Bouc-Wen gamma, m^-n, in [-beta, beta] (" psi_eq ")" }, \
	[LAW_BW_N] = { "n", LAW_DIM_NONE, LAW_RANGE_EXPONENT, 2.0, HB_LAW_PARAM_EXPONENT_N, \
	        "Bouc-Wen exponent n: sharpness of the yield (" psi_eq ")" }, \
	[LAW_BW_P] = LAW_PARAM_P(p_help)

/*
 * Rule R1: 1 where the law is clamped (ext = 0 and x_c > 0), 0 where its
 * formula holds (x_c <= 0, or the adhesive continuation of ext = 1).
 */
static inline int
law_ext_clamped(int ext, double xc)
{
	return !ext && xc > 0;
}

/* Rule R1: the x_c a law's formula is evaluated at, min(x_c, 0) if clamped. */
static inline double
law_ext_x(int ext, double xc)
{
	return law_ext_clamped(ext, xc) ? 0.0 : xc;
}

/*
 * Rule R1 for a partial derivative in x_c: d (the formula's partial at
 * x_c) where the formula holds, 0 where the law is clamped (Phi does not
 * change with x_c there).
 */
static inline double
law_ext_dx(int ext, double xc, double d)
{
	return law_ext_clamped(ext, xc) ? 0.0 : d;
}

/*
 * Partials of a Hertz spring with Hunt-Crossley damping in x_c,
 *     kx x|x|^(p-1) + c|x|^p v    (x = x_c),
 * under rule R1: *dx = d/dx_c, *dv = d/dv; both are 0 where the law is
 * clamped (the term is constant, and c|0|^p = 0).
 */
static inline void
law_hc_jac(int ext, double kx, double c, double p, double xc, double v,
           double *dx, double *dv)
{
	if (law_ext_clamped(ext, xc)) {
		*dx = 0.0;
		*dv = 0.0;
		return;
	}
	*dx = kx * dspow(xc, p) + c * dapow(xc, p) * v;
	*dv = c * apow(xc, p);
}

/*
 * The two Hertz branches of a Bouc-Wen law (eqs. bwshc_phi, bwm_phi),
 *     alpha k e|e|^(p-1) + (1 - alpha) k h|h|^(p-1),
 * with e the deflection of the elastic branch and h that of the
 * hysteretic one.
 */
static inline double
law_bw_springs_p(const double *par, double e, double h, double p)
{
	double k = par[LAW_BW_K], alpha = par[LAW_BW_ALPHA];

	return alpha * k * spow(e, p) + (1.0 - alpha) * k * spow(h, p);
}

/* ... with the exponent p of par (the _p form takes it as an argument: a constant where inlined). */
static inline double
law_bw_springs(const double *par, double e, double h)
{
	return law_bw_springs_p(par, e, h, par[LAW_BW_P]);
}

/*
 * The Bouc-Wen rate of the hysteretic displacement z driven by the rate w
 * (eqs. bwshc_psi with w = v_c, bwm_psi1 with w = Psi_2):
 *     A w - beta z|z|^(n-1) |w| - gamma |z|^n w.
 */
static inline double
law_bw_rate(const double *par, double z, double w)
{
	double n = par[LAW_BW_N];

	return par[LAW_BW_A] * w - par[LAW_BW_BETA] * spow(z, n) * fabs(w)
	    - par[LAW_BW_GAMMA] * apow(z, n) * w;
}

/*
 * law_bw_rate on a mode: |w| replaced by sign * w (sign = +1 or -1), or
 * |w| itself when sign = 0 (then the same doubles as law_bw_rate).
 */
static inline double
law_bw_rate_mode_n(const double *par, double z, double w, int sign, double n)
{
	double aw = sign ? (double)sign * w : fabs(w);

	return par[LAW_BW_A] * w - par[LAW_BW_BETA] * spow(z, n) * aw
	    - par[LAW_BW_GAMMA] * apow(z, n) * w;
}

/* ... with the exponent n of par. */
static inline double
law_bw_rate_mode(const double *par, double z, double w, int sign)
{
	return law_bw_rate_mode_n(par, z, w, sign, par[LAW_BW_N]);
}

/* d/dz of law_bw_rate: -beta n|z|^(n-1) |w| - gamma n z|z|^(n-2) w. */
static inline double
law_bw_rate_dz(const double *par, double z, double w)
{
	double n = par[LAW_BW_N];

	return -par[LAW_BW_BETA] * dspow(z, n) * fabs(w)
	    - par[LAW_BW_GAMMA] * dapow(z, n) * w;
}

/*
 * d/dw of law_bw_rate: A - beta z|z|^(n-1) sgn(w) - gamma |z|^n (at the
 * kink w = 0 the left derivative).
 */
static inline double
law_bw_rate_dw(const double *par, double z, double w)
{
	double n = par[LAW_BW_N];

	return par[LAW_BW_A] - par[LAW_BW_BETA] * spow(z, n) * dabs1(w)
	    - par[LAW_BW_GAMMA] * apow(z, n);
}

/*
 * Callbacks of struct hb_law_type shared by several laws (law_common.c).
 */

/* kinks of a law whose only kink is at x_c = 0: g = {x_c}. */
void
law_kinks_xc(const double *par, int ext, double xc, const double *z, double v,
             double *g);

/* k_hertz of a law whose elastic term is the Hertzian relation: k = k_H. */
double
law_k_hertz_identity(const double *par, double kH);

/* check of a Bouc-Wen law: rejects gamma outside [-beta, beta]. */
int
law_bw_check(const double *par, char *msg, size_t n);

/* k_hertz of a Bouc-Wen law, eq. k_hertz: k = k_H / (alpha + (1 - alpha) A^p). */
double
law_bw_k_hertz(const double *par, double kH);

#endif
