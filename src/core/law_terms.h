/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law_terms.h - the contact laws' Phi and Psi as static inline functions
 * (private to the engine), so that a right-hand side specialised for a law
 * (sim_rhs.c) evaluates them without a call through a pointer.  The tables
 * of src/core/law_*.c call the same functions: one formula per law, the
 * same doubles wherever it is evaluated.  Each law's file describes its
 * formulas; rule R1 and the shared terms are law_common.h's.
 *
 * Psi on a mode (psi_mode, sign = +1 or -1: the law's mode kink frozen on
 * that side) with sign = 0 gives the same doubles as Psi itself.
 */
#ifndef HYBOUNCE_LAW_TERMS_H
#define HYBOUNCE_LAW_TERMS_H

#include "law_common.h"

/* Parameter layouts of the laws that are not Bouc-Wen's (law_common.h has those). */
enum { LAW_SHCCL_K, LAW_SHCCL_P, LAW_SHCCL_C, LAW_SHCCL_NPAR };
enum { LAW_HERTZ_K, LAW_HERTZ_P, LAW_HERTZ_NPAR };
enum { LAW_LINEAR_K, LAW_LINEAR_NPAR };

/* SHCCL: k x_c|x_c|^(p-1) + c|x_c|^p v (law_shccl.c). */
static inline double
law_shccl_phi_p(const double *par, int ext, double xc, double v, double p)
{
	xc = law_ext_x(ext, xc);
	return par[LAW_SHCCL_K] * spow(xc, p) + par[LAW_SHCCL_C] * apow(xc, p) * v;
}

static inline double
law_shccl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	(void)z;
	return law_shccl_phi_p(par, ext, xc, v, par[LAW_SHCCL_P]);
}

/* BWSHCCL: the two Hertz branches and Hunt-Crossley damping (law_bwshccl.c). */
static inline double
law_bwshccl_phi_p(const double *par, int ext, double xc, const double *z, double v, double p)
{
	xc = law_ext_x(ext, xc);
	return law_bw_springs_p(par, xc, z[0], p) + par[LAW_BW_C] * apow(xc, p) * v;
}

static inline double
law_bwshccl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	return law_bwshccl_phi_p(par, ext, xc, z, v, par[LAW_BW_P]);
}

/* BWSHCCL: the Bouc-Wen rate of z driven by v, on a mode (|v| as sign v). */
static inline void
law_bwshccl_psi_mode_n(const double *par, const double *z, double v, int sign, double *dz, double n)
{
	dz[0] = law_bw_rate_mode_n(par, z[0], v, sign, n);
}

static inline void
law_bwshccl_psi_mode(const double *par, int ext, double xc, const double *z, double v, int sign,
                     double *dz)
{
	(void)ext;
	(void)xc;
	law_bwshccl_psi_mode_n(par, z, v, sign, dz, par[LAW_BW_N]);
}

/* BWMCL: the two Hertz branches in series with the dashpot (law_bwmcl.c). */
static inline double
law_bwmcl_phi_p(const double *par, const double *z, double p)
{
	return law_bw_springs_p(par, z[1], z[0], p);
}

static inline double
law_bwmcl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	(void)ext;
	(void)xc;
	(void)v;
	return law_bwmcl_phi_p(par, z, par[LAW_BW_P]);
}

/*
 * BWMCL: Psi_2 = v - Phi/c, and the Bouc-Wen rate of z_1 driven by it, on
 * a mode (|Psi_2|); phi is Phi at (z, v).
 */
static inline void
law_bwmcl_psi_mode_n(const double *par, double phi, double v, const double *z, int sign, double *dz,
                     double n)
{
	double psi2 = v - phi / par[LAW_BW_C];

	dz[0] = law_bw_rate_mode_n(par, z[0], psi2, sign, n);
	dz[1] = psi2;
}

static inline void
law_bwmcl_psi_mode(const double *par, int ext, double xc, const double *z, double v, int sign,
                   double *dz)
{
	law_bwmcl_psi_mode_n(par, law_bwmcl_phi(par, ext, xc, z, v), v, z, sign, dz, par[LAW_BW_N]);
}

/* Hertz: k x_c|x_c|^(p-1) (law_hertz.c). */
static inline double
law_hertz_phi_p(const double *par, int ext, double xc, double p)
{
	return par[LAW_HERTZ_K] * spow(law_ext_x(ext, xc), p);
}

static inline double
law_hertz_phi(const double *par, int ext, double xc, const double *z, double v)
{
	(void)z;
	(void)v;
	return law_hertz_phi_p(par, ext, xc, par[LAW_HERTZ_P]);
}

/* The clamped linear spring: k x_c (law_linear.c). */
static inline double
law_linear_phi(const double *par, int ext, double xc, const double *z, double v)
{
	(void)z;
	(void)v;
	return par[LAW_LINEAR_K] * law_ext_x(ext, xc);
}

/*
 * dPhi, the partials of Phi in (x_c, z_1 .. z_nz, v), as each law's jac
 * gives them (its dphi; the jac of law_*.c calls these).
 */
static inline void
law_shccl_dphi(const double *par, int ext, double xc, double v, double *dphi)
{
	law_hc_jac(ext, par[LAW_SHCCL_K], par[LAW_SHCCL_C], par[LAW_SHCCL_P], xc, v, &dphi[0], &dphi[1]);
}

static inline void
law_bwshccl_dphi(const double *par, int ext, double xc, const double *z, double v, double *dphi)
{
	double k = par[LAW_BW_K], alpha = par[LAW_BW_ALPHA], p = par[LAW_BW_P];

	law_hc_jac(ext, alpha * k, par[LAW_BW_C], p, xc, v, &dphi[0], &dphi[2]);
	dphi[1] = (1.0 - alpha) * k * dspow(z[0], p);
}

static inline void
law_bwmcl_dphi(const double *par, const double *z, double *dphi)
{
	double k = par[LAW_BW_K], alpha = par[LAW_BW_ALPHA], p = par[LAW_BW_P];

	dphi[0] = 0.0;
	dphi[1] = (1.0 - alpha) * k * dspow(z[0], p);
	dphi[2] = alpha * k * dspow(z[1], p);
	dphi[3] = 0.0;
}

static inline void
law_hertz_dphi(const double *par, int ext, double xc, double *dphi)
{
	dphi[0] = law_ext_dx(ext, xc, par[LAW_HERTZ_K] * dspow(xc, par[LAW_HERTZ_P]));
	dphi[1] = 0.0;
}

static inline void
law_linear_dphi(const double *par, int ext, double xc, double *dphi)
{
	dphi[0] = law_ext_dx(ext, xc, par[LAW_LINEAR_K]);
	dphi[1] = 0.0;
}

/* The switching functions of the Bouc-Wen laws (the others': g = {x_c}, law_kinks_xc). */
static inline void
law_bwshccl_kinks(double xc, const double *z, double v, double *g)
{
	g[0] = xc;
	g[1] = z[0];
	g[2] = v;
}

static inline void
law_bwmcl_kinks(const double *par, int ext, double xc, const double *z, double v, double *g)
{
	g[0] = z[0];
	g[1] = z[1];
	g[2] = v - law_bwmcl_phi(par, ext, xc, z, v) / par[LAW_BW_C];
}

#endif
