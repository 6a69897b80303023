/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_num.c - the numerical error of a fit's estimates (fit.h:
 * hb_fit_options.numerical): how far the estimates move when the runs are
 * made at the tighter tolerance of an error estimate (error.h:
 * hb_error_tighten, rk8pd at a hundredth of run.rtol).
 *
 * The residuals are evaluated once more at the estimates, with the
 * tighter runs; their change dr moves the least-squares solution by the
 * Gauss-Newton step from there,
 *
 *     du = -(J^T J)^-1 J^T dr,   dtheta = T du   (T = d theta / d u),
 *
 * J the Jacobian at the estimates (the one the standard errors come
 * from).  One evaluation of the data's runs, not a fit: and, unlike the
 * difference of two fits, the step does not hold the solver's own
 * stopping tolerance (xtol), which would be as large as what is measured.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "hybounce/error.h"
#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"

int
fit_numerical(const struct hb_scene *sc, const struct hb_fit_data *d, int jobs,
              const struct fit_param *fp, int np, const double *u, const gsl_matrix *J,
              const gsl_vector *f, const double *meas, const double *sd, double *dtheta,
              double *rtol, long *runs, double *cpu, double *span, char *msg, size_t n)
{
	size_t npts = J->size1;
	double T[HB_FIT_MAX_FREE * HB_FIT_MAX_FREE], th[HB_FIT_MAX_FREE], g[HB_FIT_MAX_FREE];
	double du[HB_FIT_MAX_FREE];
	struct hb_scene tight = *sc;
	gsl_matrix *C = NULL;
	double *y = NULL;
	int fail = 0, rc;

	for (int i = 0; i < np; i++)
		dtheta[i] = NAN;
	(void)hb_error_tighten(&tight);
	*rtol = tight.run.rtol;
	if ((rc = fit_param_apply(&tight, fp, np, u, th, T, msg, n)) != HB_OK)
		return rc;
	y = malloc((npts > 0 ? npts : 1) * sizeof *y);
	C = gsl_matrix_alloc((size_t)np, (size_t)np);
	if (y == NULL || C == NULL) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	if ((rc = fit_eval(&tight, 1, d, jobs, NAN, y, &fail, runs, cpu, span, msg, n)) != HB_OK)
		goto out;
	if (fail) {
		char m[512];

		snprintf(m, sizeof m, "%s", msg != NULL ? msg : "");
		rc = hb_status_set(msg, n, HB_ENUMERIC, "the runs at rtol %.3g (rk8pd) failed at the "
		                   "estimates: %.400s", tight.run.rtol, m);
		goto out;
	}
	if (gsl_multifit_nlinear_covar(J, 0.0, C) != GSL_SUCCESS) {
		rc = hb_status_set(msg, n, HB_ENUMERIC, "the Jacobian at the estimates is singular");
		goto out;
	}
	/* g = J^T dr, dr the change of every residual */
	for (int j = 0; j < np; j++)
		g[j] = 0;
	for (size_t k = 0; k < npts; k++) {
		double dr = (y[k] - meas[k]) / sd[k] - gsl_vector_get(f, k);

		for (int j = 0; j < np; j++)
			g[j] += gsl_matrix_get(J, k, (size_t)j) * dr;
	}
	for (int i = 0; i < np; i++) {
		du[i] = 0;
		for (int j = 0; j < np; j++)
			du[i] -= gsl_matrix_get(C, (size_t)i, (size_t)j) * g[j];
	}
	for (int i = 0; i < np; i++) {
		double acc = 0;

		for (int j = 0; j < np; j++)
			acc += T[i * np + j] * du[j];
		dtheta[i] = fabs(acc);
	}
	rc = HB_OK;
out:
	gsl_matrix_free(C);
	free(y);
	return rc;
}
