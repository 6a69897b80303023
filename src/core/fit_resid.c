/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_resid.c - the residuals of a fit (fit.c) and their Jacobian, as the
 * callbacks of GSL's solver, and the standard errors at the estimates:
 *
 *     r_k(u) = (y_k(theta(u)) - y_k^meas) / sd_k,
 *
 * the Jacobian by forward differences in u, all P perturbed runs at once
 * on the worker threads.  The covariance of u is (J^T J)^-1 (times
 * cost / (N - P) when the data carry no standard deviations), that of
 * theta is T C T^T with T = d theta / d u (first-order propagation).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"

#define FIT_FAIL_RESID 1e6      /* residual of a point whose run failed */

int
fit_eval_many(struct fit_ctx *c, const double *const *u, int ns, char *msg, size_t n)
{
	double th[HB_FIT_MAX_FREE];

	for (int s = 0; s < ns; s++) {
		c->scs[s] = *c->sc;
		if (fit_param_apply(&c->scs[s], c->fp, c->np, u[s], th, NULL, msg, n) != HB_OK)
			return HB_EINVAL;
	}
	return fit_eval(c->scs, ns, c->d, c->jobs, NAN, c->y, c->fail, &c->runs, &c->cpu,
	                &c->span, msg, n);
}

/* Residuals of simulated values y (scene s) into r. */
static void
resid_of(const struct fit_ctx *c, const double *y, int failed, double *r)
{
	for (size_t k = 0; k < c->npts; k++)
		r[k] = failed || !isfinite(y[k]) ? FIT_FAIL_RESID : (y[k] - c->meas[k]) / c->sd[k];
}

/* u0 moved by the difference step of column j into uj; returns the step as represented. */
static double
fd_point(const struct fit_ctx *c, const double *u0, int j, double *uj)
{
	memcpy(uj, u0, (size_t)c->np * sizeof *uj);
	uj[j] += c->h_rel * fmax(fabs(u0[j]), 1);
	/* the step as represented, so the quotient uses the exact difference */
	return uj[j] - u0[j];
}

/*
 * f at x.  With more than one core, P mod cores Jacobian columns at x run
 * beside it: GSL asks for the Jacobian at x next whenever it accepts the
 * step, and then finds them done, so that the rest of the columns fill
 * every core (P = 1 on 2 cores: f and the column together, one run's time
 * for an accepted iteration instead of two).  More would not shorten the
 * iteration and would cost CPU at every rejected step, whose columns are
 * wasted (runs at a rejected point are often the slow ones).  The values
 * are those fit_resid_df would compute (each run is independent and
 * deterministic), so the result does not depend on the cores, to the bit;
 * runs counts the runs the fit used, not those wasted.
 */
int
fit_resid_f(const gsl_vector *x, void *params, gsl_vector *f)
{
	struct fit_ctx *c = params;
	double u[HB_FIT_MAX_FREE + 1][HB_FIT_MAX_FREE];
	const double *up[HB_FIT_MAX_FREE + 1];
	int ns = 1 + (c->cores > 1 ? c->np % c->cores : 0);
	char m[256];

	for (int j = 0; j < c->np; j++)
		u[0][j] = gsl_vector_get(x, (size_t)j);
	up[0] = u[0];
	for (int s = 1; s < ns; s++) {
		fd_point(c, u[0], s - 1, u[s]);
		up[s] = u[s];
	}
	c->spec_n = 0;
	if (fit_eval_many(c, up, ns, m, sizeof m) != HB_OK)
		for (int s = 0; s < ns; s++)
			c->fail[s] = 1;
	c->runs -= (long)(ns - 1) * c->per; /* counted when used */
	resid_of(c, c->y, c->fail[0], f->data);
	if (ns > 1) {
		memcpy(c->spec_u, u[0], (size_t)c->np * sizeof *c->spec_u);
		memcpy(c->spec_y, c->y + c->npts, (size_t)(ns - 1) * c->npts * sizeof *c->spec_y);
		memcpy(c->spec_fail, c->fail + 1, (size_t)(ns - 1) * sizeof *c->spec_fail);
		c->spec_n = ns - 1;
	}
	memcpy(c->last_u, u[0], (size_t)c->np * sizeof u[0][0]);
	memcpy(c->last_r, f->data, c->npts * sizeof *c->last_r);
	c->have_last = 1;
	return GSL_SUCCESS;
}

int
fit_resid_df(const gsl_vector *x, void *params, gsl_matrix *J)
{
	struct fit_ctx *c = params;
	double u[HB_FIT_MAX_FREE + 1][HB_FIT_MAX_FREE], h[HB_FIT_MAX_FREE];
	const double *up[HB_FIT_MAX_FREE + 1];
	double *r0, *r1;
	int base, same = c->have_last, have = c->spec_n, ns = 0;
	char m[256];

	for (int j = 0; j < c->np; j++) {
		u[0][j] = gsl_vector_get(x, (size_t)j);
		same = same && c->last_u[j] == u[0][j];
	}
	for (int j = 0; j < c->np; j++)
		if (c->spec_u[j] != u[0][j])
			have = 0;
	if (!same)
		have = 0; /* the columns ran beside the f at last_u */
	base = same ? 0 : 1; /* f at x is known when GSL evaluated it last */
	for (int j = 0; j < c->np; j++)
		h[j] = fd_point(c, u[0], j, u[j + 1]);
	/* the columns not run beside f, and f when it is not known */
	if (base)
		up[ns++] = u[0];
	for (int j = have; j < c->np; j++)
		up[ns++] = u[j + 1];
	if (ns > 0 && fit_eval_many(c, up, ns, m, sizeof m) != HB_OK)
		for (int s = 0; s < ns; s++)
			c->fail[s] = 1;
	c->runs += (long)have * c->per;
	r0 = malloc(2 * c->npts * sizeof *r0);
	if (r0 == NULL)
		return GSL_ENOMEM;
	r1 = r0 + c->npts;
	if (same)
		memcpy(r0, c->last_r, c->npts * sizeof *r0);
	else
		resid_of(c, c->y, c->fail[0], r0);
	for (int j = 0; j < c->np; j++) {
		if (j < have) {
			resid_of(c, c->spec_y + (size_t)j * c->npts, c->spec_fail[j], r1);
		} else {
			int s = j - have + base;

			resid_of(c, c->y + (size_t)s * c->npts, c->fail[s], r1);
		}
		for (size_t k = 0; k < c->npts; k++)
			gsl_matrix_set(J, k, (size_t)j, (r1[k] - r0[k]) / h[j]);
	}
	free(r0);
	return GSL_SUCCESS;
}

/* Standard errors and correlations of theta at u from J (see the top). */
void
fit_errors(const gsl_matrix *J, struct fit_ctx *c, const double *u, struct hb_fit_result *r)
{
	int p = c->np;
	gsl_matrix *C = gsl_matrix_alloc((size_t)p, (size_t)p);
	double T[HB_FIT_MAX_FREE * HB_FIT_MAX_FREE], th[HB_FIT_MAX_FREE], s2 = 1;
	double cov[HB_FIT_MAX_FREE * HB_FIT_MAX_FREE];
	struct hb_scene tmp = *c->sc;
	char m[256];

	for (int i = 0; i < p; i++)
		r->se[i] = NAN;
	for (int i = 0; i < p * p; i++)
		r->corr[i] = NAN;
	if (C == NULL || fit_param_apply(&tmp, c->fp, p, u, th, T, m, sizeof m) != HB_OK
	    || gsl_multifit_nlinear_covar(J, 0.0, C) != GSL_SUCCESS) {
		gsl_matrix_free(C);
		return;
	}
	if (r->sd_scaled && c->npts > (size_t)p)
		s2 = r->cost / (double)(c->npts - (size_t)p);
	for (int i = 0; i < p; i++)
		for (int j = 0; j < p; j++) {
			double acc = 0;

			for (int a = 0; a < p; a++)
				for (int b = 0; b < p; b++)
					acc += T[i * p + a] * gsl_matrix_get(C, (size_t)a, (size_t)b)
					    * T[j * p + b];
			cov[i * p + j] = s2 * acc;
		}
	for (int i = 0; i < p; i++)
		r->se[i] = sqrt(cov[i * p + i]);
	for (int i = 0; i < p; i++)
		for (int j = 0; j < p; j++)
			r->corr[i * HB_FIT_MAX_FREE + j] = cov[i * p + j] / (r->se[i] * r->se[j]);
	gsl_matrix_free(C);
}
