/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_law.c - the contact laws (src/core/law*.c): eq. vanishing, the
 * partial derivatives against central differences, rule R1 (ext), the
 * registry, the parameter ranges and checks (and the rows the laws share),
 * known values and the switching functions.
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/law.h"
#include "hybounce/status.h"
#include "testutil.h"

#define NLAWS 5

static const double vs[] = { -2.385, -0.01, 0.0, 0.37, 5.1 };
#define NV (sizeof vs / sizeof vs[0])

/* Parameter sets: the defaults, then each law with other exponents. */
static void
set_par(const struct hb_law_type *law, double *par, const char *name, double v)
{
	int i = hb_law_param_index(law, name);

	cr_assert(i >= 0, "%s has no parameter %s", law->name, name);
	par[i] = v;
}

static int
has_param(const struct hb_law_type *law, const char *name)
{
	return hb_law_param_index(law, name) >= 0;
}

/*
 * Variant v of the law's parameters: 0 the defaults, then other exponents
 * (p, n in {1, 2, 2.7, 1.3, 3.1}) and, for the Bouc-Wen laws, gamma != beta
 * and A != 1, so that every fast path and the generic pow path is run.
 */
enum { NVARIANT = 5 };

static void
variant(const struct hb_law_type *law, int v, double *par)
{
	static const double ps[NVARIANT] = { 1.5, 1.0, 2.0, 2.7, 1.3 };
	static const double ns[NVARIANT] = { 2.0, 1.0, 3.1, 2.0, 1.7 };

	hb_law_defaults(law, par);
	if (v == 0)
		return;
	if (has_param(law, "p"))
		set_par(law, par, "p", ps[v]);
	if (has_param(law, "n"))
		set_par(law, par, "n", ns[v]);
	if (has_param(law, "gamma")) {
		int ib = hb_law_param_index(law, "beta");
		set_par(law, par, "gamma", v % 2 ? -0.4 * par[ib] : 0.7 * par[ib]);
		set_par(law, par, "A", v % 2 ? 1.3 : 0.8);
	}
}

Test(law, vanishing)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS], z[HB_LAW_MAX_Z] = { 0, 0 };

	for (int i = 0; ls[i] != NULL; i++)
		for (int var = 0; var < NVARIANT; var++) {
			variant(ls[i], var, par);
			for (int ext = 0; ext <= 1; ext++)
				for (size_t j = 0; j < NV; j++) {
					double f = ls[i]->phi(par, ext, 0.0, z, vs[j]);
					cr_assert(f == 0.0, "%s var %d ext %d: Phi(0, 0, %g) = %g",
					    ls[i]->name, var, ext, vs[j], f);
				}
		}
}

/* States (x_c, z1, z2, v) away from the kinks, of the scale of a contact. */
static const double states[][4] = {
	{ -1.37e-4, -0.83e-4, -1.12e-4, -0.413 },
	{ -2.91e-5, -3.3e-5, 1.7e-5, 0.267 },
	{ -4.4e-4, 2.2e-4, -3.9e-4, 1.93 },
	{ 3.1e-5, 1.05e-4, 0.61e-4, 0.052 },
	{ 7.7e-6, -2.4e-5, 4.9e-5, -1.21 },
	{ -6.1e-4, -5.2e-4, -5.8e-4, -0.0071 },
};
#define NSTATE (sizeof states / sizeof states[0])

/* Column scales for (x_c, z..., v). */
static double
col_scale(const struct hb_law_type *law, int j)
{
	return j == law->n_z + 1 ? 1.0 : 1e-4;
}

/* w = (x_c, z..., v) packed. */
static double
eval_phi(const struct hb_law_type *law, const double *par, int ext, const double *w)
{
	return law->phi(par, ext, w[0], w + 1, w[law->n_z + 1]);
}

static void
eval_psi(const struct hb_law_type *law, const double *par, int ext, const double *w,
         double *dz)
{
	law->psi(par, ext, w[0], w + 1, w[law->n_z + 1], dz);
}

/*
 * 1 if a switching function is within 5e-6 of zero at w: the differences
 * below step 1e-10 in x_c and z and 1e-6 in v, so this keeps every stencil
 * on one side of every kink.
 */
static int
near_kink(const struct hb_law_type *law, const double *par, int ext, const double *w)
{
	double g[HB_LAW_MAX_KINKS];

	law->kinks(par, ext, w[0], w + 1, w[law->n_z + 1], g);
	for (int i = 0; i < law->n_kinks; i++)
		if (fabs(g[i]) < 5e-6)
			return 1;
	return 0;
}

/*
 * Compares the row an[0 .. m-1] with central differences fd: with column
 * scales s_j, |fd_j - an_j| s_j <= tol (sum |an_j| s_j + tiny).
 */
static void
compare_row(const struct hb_law_type *law, const char *what, int var, int ext,
            int st, const double *an, const double *fd, double tiny)
{
	int m = law->n_z + 2;
	double norm = tiny;

	for (int j = 0; j < m; j++)
		norm += fabs(an[j]) * col_scale(law, j);
	for (int j = 0; j < m; j++) {
		double err = fabs(fd[j] - an[j]) * col_scale(law, j);
		cr_assert(isfinite(an[j]), "%s %s: non-finite partial", law->name, what);
		cr_assert(err <= 1e-6 * norm,
		    "%s %s var %d ext %d state %d col %d: analytic %.10g, fd %.10g",
		    law->name, what, var, ext, st, j, an[j], fd[j]);
	}
}

Test(law, jacobian_finite_differences)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS];
	int checked = 0;

	for (int i = 0; ls[i] != NULL; i++) {
		const struct hb_law_type *law = ls[i];
		int m = law->n_z + 2, nz = law->n_z;

		for (int var = 0; var < NVARIANT; var++) {
			variant(law, var, par);
			for (int ext = 0; ext <= 1; ext++)
				for (size_t st = 0; st < NSTATE; st++) {
					double w[HB_LAW_MAX_Z + 2], dphi[HB_LAW_MAX_Z + 2];
					double dpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];
					double fphi[HB_LAW_MAX_Z + 2];
					double fpsi[HB_LAW_MAX_Z][HB_LAW_MAX_Z + 2];
					double h0 = 1e-6;

					w[0] = states[st][0];
					for (int k = 0; k < nz; k++)
						w[1 + k] = states[st][1 + k];
					w[m - 1] = states[st][3];
					if (near_kink(law, par, ext, w))
						continue;
					law->jac(par, ext, w[0], w + 1, w[m - 1], dphi,
					    nz > 0 ? dpsi : NULL);
					for (int j = 0; j < m; j++) {
						double wp[HB_LAW_MAX_Z + 2], wm[HB_LAW_MAX_Z + 2];
						double h = h0 * col_scale(law, j);
						double dzp[HB_LAW_MAX_Z], dzm[HB_LAW_MAX_Z];

						memcpy(wp, w, sizeof w);
						memcpy(wm, w, sizeof w);
						wp[j] += h;
						wm[j] -= h;
						fphi[j] = (eval_phi(law, par, ext, wp)
						    - eval_phi(law, par, ext, wm)) / (2 * h);
						if (nz == 0)
							continue;
						eval_psi(law, par, ext, wp, dzp);
						eval_psi(law, par, ext, wm, dzm);
						for (int r = 0; r < nz; r++)
							fpsi[r][j] = (dzp[r] - dzm[r]) / (2 * h);
					}
					compare_row(law, "dphi", var, ext, (int)st, dphi, fphi,
					    1e-30);
					for (int r = 0; r < nz; r++)
						compare_row(law, "dpsi", var, ext, (int)st,
						    dpsi + r * m, fpsi[r], 1e-30);
					checked++;
				}
		}
	}
	/* Most combinations must have been away from kinks. */
	cr_assert(checked >= NLAWS * NVARIANT * 2 * 4, "only %d states checked", checked);
}

/* Partials are finite at x = 0, z = 0 for every exponent >= 1. */
Test(law, jacobian_finite_at_origin)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS], z[HB_LAW_MAX_Z] = { 0, 0 };
	double dphi[HB_LAW_MAX_Z + 2], dpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)], dz[HB_LAW_MAX_Z];

	for (int i = 0; ls[i] != NULL; i++) {
		const struct hb_law_type *law = ls[i];
		int m = law->n_z + 2;

		for (int var = 0; var < NVARIANT; var++) {
			variant(law, var, par);
			for (int ext = 0; ext <= 1; ext++)
				for (size_t j = 0; j < NV; j++) {
					law->jac(par, ext, 0.0, z, vs[j], dphi, dpsi);
					for (int c = 0; c < m; c++)
						cr_assert(isfinite(dphi[c]), "%s dphi[%d]", law->name, c);
					for (int c = 0; c < law->n_z * m; c++)
						cr_assert(isfinite(dpsi[c]), "%s dpsi[%d]", law->name, c);
					if (law->psi != NULL) {
						law->psi(par, ext, 0.0, z, vs[j], dz);
						for (int c = 0; c < law->n_z; c++)
							cr_assert(isfinite(dz[c]), "%s psi", law->name);
					}
				}
		}
	}
}

/* The p = 1 derivative of x|x|^0 at 0 is k, not 0 (pow(0, 0) = 1). */
Test(law, hertz_p1_slope_at_origin)
{
	double par[HB_LAW_MAX_PARAMS], dphi[2];

	hb_law_defaults(&hb_law_hertz, par);
	par[hb_law_param_index(&hb_law_hertz, "p")] = 1.0;
	hb_law_hertz.jac(par, 1, 0.0, NULL, 0.3, dphi, NULL);
	cr_assert_float_eq(dphi[0], par[0], 1e-9 * par[0]);
}

Test(law, rule_r1_adhesive_continuation)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS], z[HB_LAW_MAX_Z] = { 0, 0 };
	static const double xs[] = { 1e-9, 3.7e-7, 2.1e-5 };
	static const double vp[] = { 0.0, 0.37, 5.1 };

	for (int i = 0; ls[i] != NULL; i++) {
		if (ls[i] == &hb_law_bwmcl)
			continue;
		for (int var = 0; var < NVARIANT; var++) {
			variant(ls[i], var, par);
			for (size_t a = 0; a < 3; a++)
				for (size_t b = 0; b < 3; b++) {
					double f = ls[i]->phi(par, 1, xs[a], z, vp[b]);
					cr_assert(f > 0.0, "%s: Phi(%g, 0, %g) = %g is not > 0",
					    ls[i]->name, xs[a], vp[b], f);
				}
		}
	}
}

Test(law, rule_r1_clamped)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS];

	for (int i = 0; ls[i] != NULL; i++)
		for (int var = 0; var < NVARIANT; var++) {
			variant(ls[i], var, par);
			for (size_t st = 0; st < NSTATE; st++) {
				const double *s = states[st];
				double x = fabs(s[0]) + 1e-7;
				double f = ls[i]->phi(par, 0, x, s + 1, s[3]);
				double f0 = ls[i]->phi(par, 0, 0.0, s + 1, s[3]);
				double f0e = ls[i]->phi(par, 1, 0.0, s + 1, s[3]);
				cr_assert(f == f0, "%s: clamped Phi(%g) = %g != Phi(0) = %g",
				    ls[i]->name, x, f, f0);
				cr_assert(f0 == f0e, "%s: ext changes Phi at x_c = 0",
				    ls[i]->name);
			}
		}
}

/*
 * Rule R1 for the partials, exactly: where a law is clamped (ext = 0,
 * x_c > 0) its partial in x_c is 0 and every other partial is the one at
 * x_c = 0 (the x_c column itself has a kink at 0, so it is not compared).
 */
Test(law, rule_r1_clamped_jacobian)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS];

	for (int i = 0; ls[i] != NULL; i++) {
		const struct hb_law_type *law = ls[i];
		int m = law->n_z + 2;

		for (int var = 0; var < NVARIANT; var++) {
			variant(law, var, par);
			for (size_t st = 0; st < NSTATE; st++) {
				const double *s = states[st];
				double x = fabs(s[0]) + 1e-7;
				double d[HB_LAW_MAX_Z + 2], d0[HB_LAW_MAX_Z + 2];
				double p[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];
				double p0[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];

				law->jac(par, 0, x, s + 1, s[3], d, p);
				law->jac(par, 0, 0.0, s + 1, s[3], d0, p0);
				cr_assert(d[0] == 0.0, "%s var %d state %zu: dPhi/dx_c = %g "
				    "where clamped", law->name, var, st, d[0]);
				for (int c = 1; c < m; c++)
					cr_assert(d[c] == d0[c], "%s var %d state %zu: dphi[%d] "
					    "%g != %g at x_c = 0", law->name, var, st, c, d[c],
					    d0[c]);
				for (int c = 0; c < law->n_z * m; c++)
					cr_assert(p[c] == p0[c], "%s var %d state %zu: dpsi[%d] "
					    "%g != %g at x_c = 0", law->name, var, st, c, p[c],
					    p0[c]);
			}
		}
	}
}

/*
 * The two Bouc-Wen laws share their parameter layout (the shared check and
 * k_hertz read par[] by it) and the meaning of the rows k .. p: same
 * dimension, range and flags; only defaults and help differ.
 */
Test(law, bouc_wen_layout)
{
	static const char *const names[] = { "k", "A", "alpha", "beta", "gamma",
	                                     "n", "p", "c" };
	const struct hb_law_type *bw[] = { &hb_law_bwshccl, &hb_law_bwmcl };

	for (int l = 0; l < 2; l++) {
		cr_assert_eq(bw[l]->n_params, 8, "%s", bw[l]->name);
		for (int j = 0; j < 8; j++)
			cr_assert_str_eq(bw[l]->params[j].name, names[j], "%s row %d",
			    bw[l]->name, j);
	}
	for (int j = 0; j < 7; j++) {
		const struct hb_law_param *a = &hb_law_bwshccl.params[j];
		const struct hb_law_param *b = &hb_law_bwmcl.params[j];

		cr_assert(a->dim.kg == b->dim.kg && a->dim.m == b->dim.m
		    && a->dim.s == b->dim.s && a->dim.mp == b->dim.mp
		    && a->dim.mn == b->dim.mn, "%s: dimensions differ", a->name);
		cr_assert(a->lo == b->lo && a->hi == b->hi && a->lo_open == b->lo_open
		    && a->hi_open == b->hi_open, "%s: ranges differ", a->name);
		cr_assert_eq(a->flags, b->flags, "%s: flags differ", a->name);
	}
	/* the shared rows k and p mean the same in SHCCL and Hertz too */
	for (int j = 0; j < 2; j++) {
		const struct hb_law_param *a = &hb_law_shccl.params[j];
		const struct hb_law_param *b = &hb_law_hertz.params[j];

		cr_assert_str_eq(a->name, b->name);
		cr_assert(a->dim.m == b->dim.m && a->dim.mp == b->dim.mp
		    && a->lo == b->lo && a->lo_open == b->lo_open
		    && a->flags == b->flags, "%s: rows differ", a->name);
	}
}

/* BWMCL ignores x_c and ext altogether. */
Test(law, bwmcl_independent_of_x_and_ext)
{
	double par[HB_LAW_MAX_PARAMS], dz0[2], dz1[2];

	hb_law_defaults(&hb_law_bwmcl, par);
	for (size_t st = 0; st < NSTATE; st++) {
		const double *s = states[st];
		double f = hb_law_bwmcl.phi(par, 1, s[0], s + 1, s[3]);

		cr_assert(f == hb_law_bwmcl.phi(par, 0, s[0], s + 1, s[3]));
		cr_assert(f == hb_law_bwmcl.phi(par, 1, -3 * s[0] + 1e-4, s + 1, s[3]));
		hb_law_bwmcl.psi(par, 0, s[0], s + 1, s[3], dz0);
		hb_law_bwmcl.psi(par, 1, 2.5e-3, s + 1, s[3], dz1);
		cr_assert(dz0[0] == dz1[0] && dz0[1] == dz1[1]);
	}
}

Test(law, registry)
{
	const struct hb_law_type *const *ls = hb_law_list();
	static const char *names[NLAWS] = { "shccl", "bwshccl", "bwmcl", "hertz", "linear" };
	static const int nz[NLAWS] = { 0, 1, 2, 0, 0 }; /* internal states in the paper */
	int n = 0;

	while (ls[n] != NULL)
		n++;
	cr_assert_eq(n, NLAWS);
	for (int i = 0; i < NLAWS; i++) {
		const struct hb_law_type *law = hb_law_find(names[i]);
		cr_assert_not_null(law, "%s", names[i]);
		cr_assert_str_eq(law->name, names[i]);
		cr_assert_eq(law->n_z, nz[i], "%s has %d internal states, the paper's law %d",
		             names[i], law->n_z, nz[i]);
		cr_assert(law->n_z <= HB_LAW_MAX_Z);
		cr_assert(law->n_params <= HB_LAW_MAX_PARAMS);
		cr_assert(law->n_kinks <= HB_LAW_MAX_KINKS);
		cr_assert((law->n_z == 0) == (law->psi == NULL));
		cr_assert((law->n_kinks == 0) == (law->kinks == NULL));
		cr_assert(law->jac != NULL && law->phi != NULL);
		cr_assert(law->title != NULL && law->description != NULL);
		cr_assert(strstr(law->description, "x_c > 0") != NULL, "%s", law->name);
		for (int j = 0; j < law->n_params; j++)
			cr_assert(law->params[j].help != NULL && law->params[j].help[0] != '\0');
	}
	cr_assert_eq(hb_law_find("BWMCL"), &hb_law_bwmcl);
	cr_assert_eq(hb_law_find("BwShCcL"), &hb_law_bwshccl);
	cr_assert_eq(hb_law_find("Hertz"), &hb_law_hertz);
	cr_assert_null(hb_law_find("bwm"));
	cr_assert_null(hb_law_find("bwmcl "));
	cr_assert_null(hb_law_find(""));
	cr_assert_null(hb_law_find(NULL));
	cr_assert_eq(hb_law_hertz.k_hertz != NULL, 1);
	cr_assert_null(hb_law_linear.k_hertz);
	cr_assert_eq(hb_law_linear.params[0].flags & HB_LAW_PARAM_STIFFNESS, 0);
	cr_assert_eq(hb_law_bwmcl.n_kinks, 3);
	cr_assert_eq(hb_law_bwshccl.n_kinks, 3);
	cr_assert_eq(hb_law_shccl.n_kinks, 1);
}

Test(law, param_index_and_exponents)
{
	double par[HB_LAW_MAX_PARAMS];

	cr_assert_eq(hb_law_param_index(&hb_law_bwmcl, "k"), 0);
	cr_assert_eq(hb_law_param_index(&hb_law_bwmcl, "alpha"), 2);
	cr_assert_eq(hb_law_param_index(&hb_law_bwmcl, "A"), 1);
	cr_assert_eq(hb_law_param_index(&hb_law_bwmcl, "c"), 7);
	cr_assert_eq(hb_law_param_index(&hb_law_bwmcl, "delta"), -1);
	cr_assert_eq(hb_law_param_index(&hb_law_linear, "p"), -1);
	hb_law_defaults(&hb_law_bwshccl, par);
	par[hb_law_param_index(&hb_law_bwshccl, "p")] = 2.25;
	par[hb_law_param_index(&hb_law_bwshccl, "n")] = 1.75;
	cr_assert_eq(hb_law_exponent_p(&hb_law_bwshccl, par), 2.25);
	cr_assert_eq(hb_law_exponent_n(&hb_law_bwshccl, par), 1.75);
	hb_law_defaults(&hb_law_linear, par);
	cr_assert_eq(hb_law_exponent_p(&hb_law_linear, par), 1.0);
	cr_assert_eq(hb_law_exponent_n(&hb_law_linear, par), 1.0);
	hb_law_defaults(&hb_law_shccl, par);
	cr_assert_eq(hb_law_exponent_p(&hb_law_shccl, par), 1.5);
	cr_assert_eq(hb_law_exponent_n(&hb_law_shccl, par), 1.0);
}

Test(law, defaults_valid)
{
	const struct hb_law_type *const *ls = hb_law_list();
	double par[HB_LAW_MAX_PARAMS];
	char msg[128];

	for (int i = 0; ls[i] != NULL; i++) {
		hb_law_defaults(ls[i], par);
		for (int j = 0; j < ls[i]->n_params; j++)
			cr_assert_eq(hb_law_param_check(&ls[i]->params[j], par[j], msg, sizeof msg),
			    HB_OK, "%s.%s: %s", ls[i]->name, ls[i]->params[j].name, msg);
		if (ls[i]->check != NULL)
			cr_assert_eq(ls[i]->check(par, msg, sizeof msg), HB_OK, "%s", msg);
	}
}

Test(law, units)
{
	const struct hb_law_param *k = &hb_law_bwshccl.params[0];
	const struct hb_law_param *c = &hb_law_bwshccl.params[7];
	const struct hb_law_param *cm = &hb_law_bwmcl.params[7];
	const struct hb_law_param *b = &hb_law_bwmcl.params[3];

	/* k: N m^-p = kg m^(1-p) s^-2 */
	cr_assert(k->dim.kg == 1 && k->dim.m == 1 && k->dim.s == -2 && k->dim.mp == -1
	    && k->dim.mn == 0);
	/* c: N s m^(-p-1) = kg m^-p s^-1 */
	cr_assert(c->dim.kg == 1 && c->dim.m == 0 && c->dim.s == -1 && c->dim.mp == -1);
	/* c of BWMCL: N s/m = kg s^-1 */
	cr_assert(cm->dim.kg == 1 && cm->dim.m == 0 && cm->dim.s == -1 && cm->dim.mp == 0);
	cr_assert(b->dim.kg == 0 && b->dim.mn == -1 && b->dim.m == 0);
	cr_assert(hb_law_linear.params[0].dim.kg == 1 && hb_law_linear.params[0].dim.s == -2
	    && hb_law_linear.params[0].dim.m == 0 && hb_law_linear.params[0].dim.mp == 0);
}

static void
check_gamma(const struct hb_law_type *law)
{
	double par[HB_LAW_MAX_PARAMS];
	char msg[160];
	int ib = hb_law_param_index(law, "beta"), ig = hb_law_param_index(law, "gamma");

	hb_law_defaults(law, par);
	par[ib] = 2e8;
	par[ig] = -2e8;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_OK);
	par[ig] = 0;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_OK);
	par[ig] = 2.5e8;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "gamma") != NULL && strstr(msg, "[-beta, beta]") != NULL
	    && strstr(msg, "[-2e+08, 2e+08]") != NULL, "message: %s", msg);
	par[ig] = -2.0001e8;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_EINVAL);
	par[ib] = 0;
	par[ig] = 1e-3;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_EINVAL);
	par[ig] = NAN;
	par[ib] = 1;
	cr_assert_eq(law->check(par, msg, sizeof msg), HB_EINVAL);
}

Test(law, check_gamma)
{
	check_gamma(&hb_law_bwshccl);
	check_gamma(&hb_law_bwmcl);
}

static void
expect_reject(const struct hb_law_type *law, const char *name, double value,
              const char *range)
{
	char msg[160] = "";
	int i = hb_law_param_index(law, name);

	cr_assert(i >= 0);
	cr_assert_eq(hb_law_param_check(&law->params[i], value, msg, sizeof msg), HB_EINVAL,
	    "%s.%s = %g accepted", law->name, name, value);
	cr_assert(strstr(msg, name) == msg, "message: %s", msg);
	cr_assert(strstr(msg, range) != NULL, "message '%s' lacks '%s'", msg, range);
}

static void
expect_accept(const struct hb_law_type *law, const char *name, double value)
{
	char msg[160] = "";
	int i = hb_law_param_index(law, name);

	cr_assert_eq(hb_law_param_check(&law->params[i], value, msg, sizeof msg), HB_OK,
	    "%s", msg);
}

Test(law, param_ranges)
{
	char msg[160];
	int ia = hb_law_param_index(&hb_law_bwshccl, "alpha");

	cr_assert_eq(hb_law_param_check(&hb_law_bwshccl.params[ia], 1.2, msg, sizeof msg),
	    HB_EINVAL);
	cr_assert_str_eq(msg, "alpha = 1.2 is out of range; accepted: (0, 1)");
	expect_reject(&hb_law_bwshccl, "alpha", 0.0, "(0, 1)");
	expect_reject(&hb_law_bwmcl, "alpha", 1.0, "(0, 1)");
	expect_reject(&hb_law_bwmcl, "n", 0.5, "[1, 1e+12]");
	expect_reject(&hb_law_shccl, "p", 0.9, "[1, 1e+12]");
	expect_reject(&hb_law_hertz, "k", 0.0, "(0, inf)");
	expect_reject(&hb_law_linear, "k", -3.0, "(0, inf)");
	expect_reject(&hb_law_bwmcl, "c", 0.0, "(0, inf)");
	expect_reject(&hb_law_shccl, "c", -1.0, "[0, inf)");
	expect_reject(&hb_law_bwshccl, "beta", -1.0, "[0, inf)");
	expect_reject(&hb_law_bwshccl, "A", 0.0, "(0, inf)");
	expect_reject(&hb_law_bwshccl, "k", NAN, "(0, inf)");
	expect_reject(&hb_law_bwshccl, "k", HUGE_VAL, "(0, inf)");
	expect_accept(&hb_law_bwshccl, "alpha", 0.999);
	expect_accept(&hb_law_bwshccl, "n", 1.0);
	expect_accept(&hb_law_shccl, "p", 1.0);
	expect_accept(&hb_law_shccl, "c", 0.0);
	expect_accept(&hb_law_bwshccl, "gamma", -3e9);
}

/* BWSHCCL with beta = gamma = 0, A = 1 and z = x is SHCCL. */
Test(law, bwshccl_reduces_to_shccl)
{
	double pb[HB_LAW_MAX_PARAMS], ps[HB_LAW_MAX_PARAMS];
	static const double ps_p[] = { 1.5, 1.0, 2.3 };

	for (size_t q = 0; q < 3; q++) {
		hb_law_defaults(&hb_law_bwshccl, pb);
		hb_law_defaults(&hb_law_shccl, ps);
		pb[hb_law_param_index(&hb_law_bwshccl, "beta")] = 0;
		pb[hb_law_param_index(&hb_law_bwshccl, "gamma")] = 0;
		pb[hb_law_param_index(&hb_law_bwshccl, "A")] = 1;
		pb[hb_law_param_index(&hb_law_bwshccl, "k")] = 1.234e8;
		pb[hb_law_param_index(&hb_law_bwshccl, "p")] = ps_p[q];
		pb[hb_law_param_index(&hb_law_bwshccl, "c")] = 3.21e7;
		ps[hb_law_param_index(&hb_law_shccl, "k")] = 1.234e8;
		ps[hb_law_param_index(&hb_law_shccl, "p")] = ps_p[q];
		ps[hb_law_param_index(&hb_law_shccl, "c")] = 3.21e7;
		for (size_t st = 0; st < NSTATE; st++) {
			double x = -fabs(states[st][0]), v = states[st][3], dz;
			double fb = hb_law_bwshccl.phi(pb, 1, x, &x, v);
			double fs = hb_law_shccl.phi(ps, 1, x, NULL, v);

			cr_assert(fabs(fb - fs) <= 1e-12 * fabs(fs), "p %g state %zu: %.15g vs %.15g",
			    ps_p[q], st, fb, fs);
			/* and z follows x: dz/dt = v */
			hb_law_bwshccl.psi(pb, 1, x, &x, v, &dz);
			cr_assert_eq(dz, v);
		}
	}
}

Test(law, known_values)
{
	double par[HB_LAW_MAX_PARAMS], z[2] = { 0, 0 }, dz[2], g[3];
	double kH = 7.095e7;

	/* eq. k_hertz with A = 1: k = k_H. */
	hb_law_defaults(&hb_law_bwshccl, par);
	cr_assert_float_eq(hb_law_bwshccl.k_hertz(par, kH), kH, 1e-6);
	hb_law_defaults(&hb_law_bwmcl, par);
	cr_assert_float_eq(hb_law_bwmcl.k_hertz(par, kH), kH, 1e-6);
	/* with A = 2, alpha = 0.35, p = 3/2: k_H / (0.35 + 0.65 * 2^1.5). */
	par[hb_law_param_index(&hb_law_bwmcl, "A")] = 2.0;
	assert_rel(hb_law_bwmcl.k_hertz(par, kH), kH / (0.35 + 0.65 * pow(2, 1.5)), 1e-12);
	cr_assert_eq(hb_law_shccl.k_hertz(par, kH), kH);
	hb_law_defaults(&hb_law_bwshccl, par);
	par[hb_law_param_index(&hb_law_bwshccl, "A")] = 0.6;
	par[hb_law_param_index(&hb_law_bwshccl, "alpha")] = 0.2;
	par[hb_law_param_index(&hb_law_bwshccl, "p")] = 2.2;
	assert_rel(hb_law_bwshccl.k_hertz(par, kH), kH / (0.2 + 0.8 * pow(0.6, 2.2)), 1e-12);

	/* BWMCL Psi2 at z = (0, 0) equals v; Psi1 = A v there. */
	hb_law_defaults(&hb_law_bwmcl, par);
	par[hb_law_param_index(&hb_law_bwmcl, "A")] = 1.37;
	for (size_t j = 0; j < NV; j++) {
		hb_law_bwmcl.psi(par, 1, -1e-4, z, vs[j], dz);
		cr_assert_eq(dz[1], vs[j]);
		cr_assert(fabs(dz[0] - 1.37 * vs[j]) <= 1e-15);
	}

	/* Hertz: Phi = k x sqrt|x| at p = 3/2. */
	hb_law_defaults(&hb_law_hertz, par);
	cr_assert(fabs(hb_law_hertz.phi(par, 1, -1e-4, NULL, 0.3) - (-2.138e8 * 1e-6))
	    <= 1e-9);
	/* Linear: k min(x, 0), and k x for x > 0 with ext = 1. */
	hb_law_defaults(&hb_law_linear, par);
	cr_assert_eq(hb_law_linear.phi(par, 0, -2e-3, NULL, 1.0), -200.0);
	cr_assert_eq(hb_law_linear.phi(par, 0, 2e-3, NULL, 1.0), 0.0);
	cr_assert_eq(hb_law_linear.phi(par, 1, 2e-3, NULL, 1.0), 200.0);

	/* BWMCL Phi by hand: z1 = -1e-4, z2 = -4e-4, p = 3/2. */
	hb_law_defaults(&hb_law_bwmcl, par);
	z[0] = -1e-4;
	z[1] = -4e-4;
	{
		double want = -(0.35 * 2.138e8 * 8e-6 + 0.65 * 2.138e8 * 1e-6);
		double f = hb_law_bwmcl.phi(par, 1, 0.0, z, 0.0);
		cr_assert(fabs(f - want) <= 1e-9 * fabs(want), "%g vs %g", f, want);
		/* its kinks: z1, z2, Psi2 = v - Phi/c */
		hb_law_bwmcl.kinks(par, 1, -3e-4, z, 0.25, g);
		cr_assert_eq(g[0], z[0]);
		cr_assert_eq(g[1], z[1]);
		cr_assert(fabs(g[2] - (0.25 - want / 4.4e3)) <= 1e-12);
		hb_law_bwmcl.psi(par, 1, -3e-4, z, 0.25, dz);
		cr_assert_eq(g[2], dz[1]);
	}

	/* BWSHCCL Psi by hand, n = 2: A v - beta z|z| |v| - gamma z^2 v. */
	hb_law_defaults(&hb_law_bwshccl, par);
	z[0] = -2e-5;
	hb_law_bwshccl.psi(par, 1, -3e-5, z, -0.5, dz);
	cr_assert(fabs(dz[0] - (-0.5 - 2.409e8 * (-4e-10) * 0.5 - 2.409e8 * 4e-10 * -0.5))
	    <= 1e-14);
}

Test(law, kinks)
{
	double par[HB_LAW_MAX_PARAMS], g[HB_LAW_MAX_KINKS];
	double z[2] = { -3.3e-5, 1.7e-5 };

	hb_law_defaults(&hb_law_bwshccl, par);
	hb_law_bwshccl.kinks(par, 1, -2.9e-5, z, 0.267, g);
	cr_assert(g[0] == -2.9e-5 && g[1] == z[0] && g[2] == 0.267);
	hb_law_defaults(&hb_law_shccl, par);
	hb_law_shccl.kinks(par, 0, 1.5e-6, NULL, 0.3, g);
	cr_assert_eq(g[0], 1.5e-6);
	hb_law_defaults(&hb_law_hertz, par);
	hb_law_hertz.kinks(par, 1, -7e-6, NULL, 0.3, g);
	cr_assert_eq(g[0], -7e-6);
	hb_law_defaults(&hb_law_linear, par);
	hb_law_linear.kinks(par, 1, 2e-6, NULL, 0.3, g);
	cr_assert_eq(g[0], 2e-6);
}
