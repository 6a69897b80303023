/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_lin.c - what the Jacobian J of the residuals at the estimates says
 * (see fit.c): whether the data identify the free parameters, and how much
 * of the cost a Gauss-Newton step could still remove.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "fit_impl.h"

#define FIT_SINGULAR_RATIO 1e-4 /* s_min / s_max below this: not identifiable */

/*
 * Identifiability is read from the singular values of J with its columns
 * scaled to unit norm: a direction whose singular value is below
 * FIT_SINGULAR_RATIO of the largest cannot be told apart by the data within
 * the accuracy of the differences, and its parameters are named.
 */
int
fit_identifiability(const gsl_matrix *J, const struct fit_param *fp, int np, double *cond,
                    char *names, size_t nn)
{
	size_t n = J->size1, p = J->size2;
	gsl_matrix *A, *V;
	gsl_vector *S, *work;
	int bad = 0;

	names[0] = '\0';
	*cond = NAN;
	for (size_t j = 0; j < p; j++) {
		gsl_vector_const_view col = gsl_matrix_const_column(J, j);

		double norm = gsl_blas_dnrm2(&col.vector);

		if (!(norm > 0)) {
			snprintf(names, nn, "%s (no effect on these data)", fp[j].key);
			*cond = INFINITY;
			return 1;
		}
		/* GSL's SVD would not converge, and would say so through its
		 * process-wide error handler: no verdict, as for a failed SVD */
		if (!isfinite(norm))
			return 0;
	}
	if (n < p)
		return 0;
	A = gsl_matrix_alloc(n, p);
	V = gsl_matrix_alloc(p, p);
	S = gsl_vector_alloc(p);
	work = gsl_vector_alloc(p);
	if (A == NULL || V == NULL || S == NULL || work == NULL)
		goto out;
	gsl_matrix_memcpy(A, J);
	for (size_t j = 0; j < p; j++) {
		gsl_vector_view col = gsl_matrix_column(A, j);

		gsl_vector_scale(&col.vector, 1 / gsl_blas_dnrm2(&col.vector));
	}
	if (gsl_linalg_SV_decomp(A, V, S, work) != GSL_SUCCESS)
		goto out;
	*cond = gsl_vector_get(S, 0) / gsl_vector_get(S, p - 1);
	if (gsl_vector_get(S, p - 1) < FIT_SINGULAR_RATIO * gsl_vector_get(S, 0)) {
		bad = 1;
		for (size_t j = 0; j < (size_t)np; j++) {
			size_t len = strlen(names);

			if (fabs(gsl_matrix_get(V, j, p - 1)) > 0.1)
				snprintf(names + len, nn - len, "%s%s", len ? ", " : "", fp[j].key);
		}
	}
out:
	gsl_matrix_free(A);
	gsl_matrix_free(V);
	gsl_vector_free(S);
	gsl_vector_free(work);
	return bad;
}


double
fit_gn_decrease(const gsl_matrix *J, const gsl_vector *f)
{
	size_t p = J->size2;
	gsl_matrix *C = gsl_matrix_alloc(p, p);
	gsl_vector *g = gsl_vector_alloc(p), *Cg = gsl_vector_alloc(p);
	double dec = NAN;

	if (C != NULL && g != NULL && Cg != NULL
	    && gsl_multifit_nlinear_covar(J, 0.0, C) == GSL_SUCCESS
	    && gsl_blas_dgemv(CblasTrans, 1.0, J, f, 0.0, g) == GSL_SUCCESS
	    && gsl_blas_dgemv(CblasNoTrans, 1.0, C, g, 0.0, Cg) == GSL_SUCCESS)
		gsl_blas_ddot(g, Cg, &dec);
	gsl_matrix_free(C);
	gsl_vector_free(g);
	gsl_vector_free(Cg);
	return dec;
}
