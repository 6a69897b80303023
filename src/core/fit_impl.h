/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_impl.h - declarations shared by fit.c, fit_eval.c, fit_lin.c and fit_param.c
 * (not part of the API).
 */
#ifndef HYBOUNCE_FIT_IMPL_H
#define HYBOUNCE_FIT_IMPL_H

#include <stddef.h>

#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include "hybounce/fit.h"

/* A free parameter: the key, its range and its transform theta(u). */
struct fit_param {
	char key[48];
	double lo, hi;  /* admissible range (open); infinite for none */
	int beta;       /* gamma: index of beta in the law's table (theta = beta tanh u), else -1 */
	double u0;      /* u of the start */
	double k;       /* (lo, hi): the logistic's rate, 1 or less (see fit.h) */
};

/*
 * fit_data.c.  fit_data_check: the invariant of fit_data.c (0, or
 * HB_EINVAL with "SOURCE: ..." in msg).  fit_data_one_trial: d->n rows as
 * one trial (trial_row, file_row allocated; HB_ENOMEM).  fit_points: the
 * data points in the order of fit_result.point and of fit_eval's output
 * (pt may be NULL: measured, sd, row, obs, trial, index), pidx[ob * d->n +
 * row] the point of each value (SIZE_MAX for none; may be NULL), *scaled 1
 * when a column has no sd (may be NULL); returns the number of points.
 */
int
fit_data_check(struct hb_fit_data *d, char *msg, size_t n);
int
fit_data_one_trial(struct hb_fit_data *d);
size_t
fit_points(const struct hb_fit_data *d, struct hb_fit_point *pt, size_t *pidx, int *scaled);

int
fit_param_init(const struct hb_scene *sc, const char *key, struct fit_param *fp,
               char *msg, size_t n);

int
fit_param_apply(struct hb_scene *sc, const struct fit_param *fp, int np, const double *u,
                double *th, double *T, char *msg, size_t n);

/*
 * Simulates the data's observables for nsc scenes at once (the runs on
 * `jobs` threads): out[s * hb_fit_npoints(d) + k] for scene s.  A run that
 * fails, or a sequence with fewer collisions than the data, sets
 * fail[s] = 1 (may be NULL) and, for the first such scene, the message; its
 * missing values are filled with `penalty` (NAN for none).  Adds the runs
 * made to *runs, their CPU seconds to *cpu and the wall time they would
 * take had each thread a core of its own to *span (each may be NULL).
 * Returns 0, or HB_ENOMEM.
 */
int
fit_eval(const struct hb_scene *sc, int nsc, const struct hb_fit_data *d, int jobs,
         double penalty, double *out, int *fail, long *runs, double *cpu, double *span,
         char *msg, size_t n);

/*
 * fit_lin.c: from the Jacobian J (n residuals x P free parameters) at the
 * estimates.  fit_identifiability: the condition number of J with unit
 * columns into *cond, and the parameters of its weakest direction into
 * names when that is below 1e-4 of the strongest (or a column is zero: a
 * parameter with no effect); returns 1 when not identifiable.
 * fit_gn_decrease: what a Gauss-Newton step from there would remove from
 * the cost |f|^2, f^T J (J^T J)^-1 J^T f (NAN if it cannot be computed).
 */
int
fit_identifiability(const gsl_matrix *J, const struct fit_param *fp, int np, double *cond,
                    char *names, size_t nn);
double
fit_gn_decrease(const gsl_matrix *J, const gsl_vector *f);

/*
 * fit_num.c: the numerical error of the estimates at u (see there): the
 * runs of the data at hb_error_tighten's tolerance (its rtol into *rtol),
 * the change of the residuals f (J, f: at u) carried through J into
 * |dtheta| (np values; NAN on failure).  Returns HB_OK, or HB_ENUMERIC
 * (a tighter run failed, J singular) / HB_ENOMEM with msg.
 */
int
fit_numerical(const struct hb_scene *sc, const struct hb_fit_data *d, int jobs,
              const struct fit_param *fp, int np, const double *u, const gsl_matrix *J,
              const gsl_vector *f, const double *meas, const double *sd, double *dtheta,
              double *rtol, long *runs, double *cpu, double *span, char *msg, size_t n);

/* The context of the solver's callbacks (fit_resid.c), held in struct hb_fit (fit.c). */
struct fit_ctx {
	const struct hb_scene *sc;
	const struct hb_fit_data *d;
	const struct fit_param *fp;
	int np;
	size_t npts;
	int jobs;
	double *meas, *sd;    /* per point */
	double h_rel;         /* finite-difference step, relative */
	long runs;
	/* the last f evaluation, reused by df at the same x */
	double *last_u, *last_r;
	int have_last;
	struct hb_scene *scs;    /* np + 1 scenes */
	double *y;            /* (np + 1) * npts simulated values */
	int *fail;
	/*
	 * Jacobian columns run beside an evaluation of f on cores that would
	 * wait otherwise (see fit_resid_f): columns 0 .. spec_n - 1 at spec_u.
	 */
	int cores;            /* threads the runs may use (jobs resolved) */
	int spec_n;
	double *spec_u, *spec_y;  /* np; np * npts */
	int *spec_fail;           /* np */
	long per;             /* runs per scene: trials, or drops */
	double cpu, span;     /* CPU seconds of every run; their span on the threads */
};

/* Simulates the scenes for parameter vectors u[0..ns-1] into c->y. */
int
fit_eval_many(struct fit_ctx *c, const double *const *u, int ns, char *msg, size_t n);

/* GSL's residual function f at x and its Jacobian J (params: struct fit_ctx). */
int
fit_resid_f(const gsl_vector *x, void *params, gsl_vector *f);
int
fit_resid_df(const gsl_vector *x, void *params, gsl_matrix *J);

/* Standard errors and correlations of theta at u from J into r (see fit_resid.c). */
void
fit_errors(const gsl_matrix *J, struct fit_ctx *c, const double *u, struct hb_fit_result *r);

#endif
