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
#include "hybounce/status.h"

#include "law_pow.h"

enum { K, A, ALPHA, BETA, GAMMA, N, P, C, NPAR };

static const struct law_param bwmcl_params[NPAR] = {
	[K] = { "k", { .kg = 1, .m = 1, .s = -2, .mp = -1 },
	        0, HUGE_VAL, 1, 0, 2.138e8, LAW_PARAM_STIFFNESS,
	        "stiffness of both branches, N m^-p; derived by eq. k_hertz from the materials" },
	[A] = { "A", { 0 }, 0, HUGE_VAL, 1, 0, 1.0, 0,
	        "Bouc-Wen gain A: dz1/dt = A dz2/dt while z1 is small (eq. bwm_psi1)" },
	[ALPHA] = { "alpha", { 0 }, 0, 1, 1, 1, 0.35, 0,
	        "share of the elastic branch; 1 - alpha is hysteretic (eq. bwm_phi)" },
	[BETA] = { "beta", { .mn = -1 }, 0, HUGE_VAL, 0, 0, 5e7, 0,
	        "Bouc-Wen beta, m^-n: shapes the hysteresis loop (eq. bwm_psi1)" },
	[GAMMA] = { "gamma", { .mn = -1 }, -HUGE_VAL, HUGE_VAL, 0, 0, 5e7, 0,
	        "Bouc-Wen gamma, m^-n, in [-beta, beta] (eq. bwm_psi1)" },
	[N] = { "n", { 0 }, 1, HUGE_VAL, 0, 0, 2.0, LAW_PARAM_EXPONENT_N,
	        "Bouc-Wen exponent n: sharpness of the yield (eq. bwm_psi1)" },
	[P] = { "p", { 0 }, 1, HUGE_VAL, 0, 0, 1.5, LAW_PARAM_EXPONENT_P,
	        "exponent of both spring branches; 3/2 is Hertz's" },
	[C] = { "c", { .kg = 1, .s = -1 }, 0, HUGE_VAL, 1, 0, 4.4e3, 0,
	        "Maxwell dashpot in series, N s/m; sets the sinking rate m g / c (table tab:one)" },
};

static double
bwmcl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	double k = par[K], alpha = par[ALPHA], p = par[P];

	(void)ext;
	(void)xc;
	(void)v;
	return alpha * k * spow(z[1], p) + (1.0 - alpha) * k * spow(z[0], p);
}

/* dz[0] = Psi_1 (for z_c1), dz[1] = Psi_2 (for z_c2). */
static void
bwmcl_psi(const double *par, int ext, double xc, const double *z, double v,
          double *dz)
{
	double n = par[N];
	double psi2 = v - bwmcl_phi(par, ext, xc, z, v) / par[C];

	dz[0] = par[A] * psi2 - par[BETA] * spow(z[0], n) * fabs(psi2)
	    - par[GAMMA] * apow(z[0], n) * psi2;
	dz[1] = psi2;
}

/*
 * Columns (x_c, z1, z2, v); dpsi rows (Psi_1, Psi_2).  Psi_1 depends on the
 * state through Psi_2 as well as through z1 directly:
 *     dPsi_1/dw = (A - beta z1|z1|^(n-1) sgn(Psi_2) - gamma |z1|^n) dPsi_2/dw
 *                 + [w = z1] (-beta n|z1|^(n-1) |Psi_2|
 *                             - gamma n z1|z1|^(n-2) Psi_2).
 */
static void
bwmcl_jac(const double *par, int ext, double xc, const double *z, double v,
          double *dphi, double *dpsi)
{
	double k = par[K], alpha = par[ALPHA], p = par[P], n = par[N];
	double c = par[C], beta = par[BETA], gamma = par[GAMMA];
	double z1 = z[0], psi2, g1, h1;

	dphi[0] = 0.0;
	dphi[1] = (1.0 - alpha) * k * dspow(z1, p);
	dphi[2] = alpha * k * dspow(z[1], p);
	dphi[3] = 0.0;
	if (dpsi == NULL)
		return;

	psi2 = v - bwmcl_phi(par, ext, xc, z, v) / c;
	dpsi[4] = 0.0;
	dpsi[5] = -dphi[1] / c;
	dpsi[6] = -dphi[2] / c;
	dpsi[7] = 1.0;

	g1 = par[A] - beta * spow(z1, n) * dabs1(psi2) - gamma * apow(z1, n);
	h1 = -beta * dspow(z1, n) * fabs(psi2) - gamma * dapow(z1, n) * psi2;
	dpsi[0] = 0.0;
	dpsi[1] = g1 * dpsi[5] + h1;
	dpsi[2] = g1 * dpsi[6];
	dpsi[3] = g1;
}

/* g = {z1, z2, Psi_2}. */
static void
bwmcl_kinks(const double *par, int ext, double xc, const double *z, double v,
            double *g)
{
	g[0] = z[0];
	g[1] = z[1];
	g[2] = v - bwmcl_phi(par, ext, xc, z, v) / par[C];
}

/* Rejects |gamma| > beta (eq. bwm_psi1 requires gamma in [-beta, beta]). */
static int
bwmcl_check(const double *par, char *msg, size_t n)
{
	double beta = par[BETA], gamma = par[GAMMA];

	if (gamma >= -beta && gamma <= beta)
		return HB_OK;
	return status_set(msg, n, HB_EINVAL,
	    "gamma = %g must lie in [-beta, beta] = [%g, %g]", gamma, -beta, beta);
}

/* Eq. k_hertz: k = k_H / (alpha + (1 - alpha) A^p). */
static double
bwmcl_k_hertz(const double *par, double kH)
{
	double alpha = par[ALPHA];

	return kH / (alpha + (1.0 - alpha) * apow(par[A], par[P]));
}

const struct law_type law_bwmcl = {
	.name = "bwmcl",
	.title = "Bouc-Wen-Maxwell (BWMCL)",
	.description = "Elastic and Bouc-Wen hysteretic Hertz branches in series "
	               "with a linear dashpot c; Phi depends on z only, so x_c > 0 "
	               "needs no continuation and ext has no effect (rule R1)",
	.n_z = 2,
	.n_params = NPAR,
	.params = bwmcl_params,
	.n_kinks = 3,
	.phi = bwmcl_phi,
	.psi = bwmcl_psi,
	.jac = bwmcl_jac,
	.kinks = bwmcl_kinks,
	.check = bwmcl_check,
	.k_hertz = bwmcl_k_hertz,
};
