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
#include "hybounce/status.h"

#include "law_pow.h"

enum { K, A, ALPHA, BETA, GAMMA, N, P, C, NPAR };

static const struct law_param bwshccl_params[NPAR] = {
	[K] = { "k", { .kg = 1, .m = 1, .s = -2, .mp = -1 },
	        0, HUGE_VAL, 1, 0, 7.095e7, LAW_PARAM_STIFFNESS,
	        "stiffness of both branches, N m^-p; derived by eq. k_hertz from the materials" },
	[A] = { "A", { 0 }, 0, HUGE_VAL, 1, 0, 1.0, 0,
	        "Bouc-Wen gain A: dz/dt = A v while z is small (eq. bwshc_psi)" },
	[ALPHA] = { "alpha", { 0 }, 0, 1, 1, 1, 0.35, 0,
	        "share of the elastic branch; 1 - alpha is hysteretic (eq. bwshc_phi)" },
	[BETA] = { "beta", { .mn = -1 }, 0, HUGE_VAL, 0, 0, 2.409e8, 0,
	        "Bouc-Wen beta, m^-n: shapes the hysteresis loop (eq. bwshc_psi)" },
	[GAMMA] = { "gamma", { .mn = -1 }, -HUGE_VAL, HUGE_VAL, 0, 0, 2.409e8, 0,
	        "Bouc-Wen gamma, m^-n, in [-beta, beta] (eq. bwshc_psi)" },
	[N] = { "n", { 0 }, 1, HUGE_VAL, 0, 0, 2.0, LAW_PARAM_EXPONENT_N,
	        "Bouc-Wen exponent n: sharpness of the yield (eq. bwshc_psi)" },
	[P] = { "p", { 0 }, 1, HUGE_VAL, 0, 0, 1.5, LAW_PARAM_EXPONENT_P,
	        "exponent of both branches and of the damping; 3/2 is Hertz's" },
	[C] = { "c", { .kg = 1, .s = -1, .mp = -1 },
	        0, HUGE_VAL, 0, 0, 2.5e7, 0,
	        "Hunt-Crossley damping c|x|^p v, N s m^(-p-1) (table tab:two)" },
};

static double
bwshccl_phi(const double *par, int ext, double xc, const double *z, double v)
{
	double k = par[K], alpha = par[ALPHA], p = par[P];

	if (!ext && xc > 0)
		xc = 0.0;
	return alpha * k * spow(xc, p) + (1.0 - alpha) * k * spow(z[0], p)
	    + par[C] * apow(xc, p) * v;
}

static void
bwshccl_psi(const double *par, int ext, double xc, const double *z, double v,
            double *dz)
{
	double n = par[N];

	(void)ext;
	(void)xc;
	dz[0] = par[A] * v - par[BETA] * spow(z[0], n) * fabs(v)
	    - par[GAMMA] * apow(z[0], n) * v;
}

/* Columns (x_c, z, v); dpsi is one row. */
static void
bwshccl_jac(const double *par, int ext, double xc, const double *z, double v,
            double *dphi, double *dpsi)
{
	double k = par[K], alpha = par[ALPHA], p = par[P], n = par[N];
	double c = par[C], beta = par[BETA], gamma = par[GAMMA];
	double zz = z[0];

	if (!ext && xc > 0) {
		dphi[0] = 0.0;
		dphi[2] = 0.0;
	} else {
		dphi[0] = alpha * k * dspow(xc, p) + c * dapow(xc, p) * v;
		dphi[2] = c * apow(xc, p);
	}
	dphi[1] = (1.0 - alpha) * k * dspow(zz, p);

	if (dpsi == NULL)
		return;
	dpsi[0] = 0.0;
	dpsi[1] = -beta * dspow(zz, n) * fabs(v) - gamma * dapow(zz, n) * v;
	dpsi[2] = par[A] - beta * spow(zz, n) * dabs1(v) - gamma * apow(zz, n);
}

/* g = {x_c, z, v}. */
static void
bwshccl_kinks(const double *par, int ext, double xc, const double *z,
              double v, double *g)
{
	(void)par;
	(void)ext;
	g[0] = xc;
	g[1] = z[0];
	g[2] = v;
}

/* Rejects |gamma| > beta (eq. bwshc_psi requires gamma in [-beta, beta]). */
static int
bwshccl_check(const double *par, char *msg, size_t n)
{
	double beta = par[BETA], gamma = par[GAMMA];

	if (gamma >= -beta && gamma <= beta)
		return HB_OK;
	return status_set(msg, n, HB_EINVAL,
	    "gamma = %g must lie in [-beta, beta] = [%g, %g]", gamma, -beta, beta);
}

/* Eq. k_hertz: k = k_H / (alpha + (1 - alpha) A^p). */
static double
bwshccl_k_hertz(const double *par, double kH)
{
	double alpha = par[ALPHA];

	return kH / (alpha + (1.0 - alpha) * apow(par[A], par[P]));
}

const struct law_type law_bwshccl = {
	.name = "bwshccl",
	.title = "Bouc-Wen-Simon-Hunt-Crossley (BWSHCCL)",
	.description = "Elastic and Bouc-Wen hysteretic Hertz branches with "
	               "Hunt-Crossley damping; continued to x_c > 0 by the same "
	               "formulas (adhesive, rule R1), or clamped at x_c = 0 when "
	               "ext = 0",
	.n_z = 1,
	.n_params = NPAR,
	.params = bwshccl_params,
	.n_kinks = 3,
	.phi = bwshccl_phi,
	.psi = bwshccl_psi,
	.jac = bwshccl_jac,
	.kinks = bwshccl_kinks,
	.check = bwshccl_check,
	.k_hertz = bwshccl_k_hertz,
};
