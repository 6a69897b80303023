/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit.c - nonlinear least squares over runs of the simulator (GSL
 * gsl_multifit_nlinear, trust region): the residuals are
 *
 *     r_k(u) = (y_k(theta(u)) - y_k^meas) / sd_k,   cost = sum_k r_k^2,
 *
 * y_k the simulated observables (fit_eval.c) and theta(u) the transform
 * that keeps each free parameter in its range (fit_param.c).  The Jacobian
 * is taken by forward differences in u, all P perturbed runs at once on
 * the worker threads.  Identifiability and the decrease left are read from
 * the Jacobian at the estimates (fit_lin.c).
 *
 * The residuals, their Jacobian and the standard errors are computed in
 * fit_resid.c; this file holds the fit in progress (struct hb_fit).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"
#include "cnum.h"

static const char *const reasons[] = {
	[HB_FIT_CONVERGED_STEP] = "converged (the step became small)",
	[HB_FIT_CONVERGED_GRAD] = "converged (the gradient became small)",
	[HB_FIT_CONVERGED_COST] = "converged (the cost stopped decreasing)",
	[HB_FIT_MAXITER] = "stopped at the iteration cap",
	[HB_FIT_NOPROGRESS] = "stopped: no step lowered the cost",
	[HB_FIT_SINGULAR] = "stopped: singular Jacobian",
	[HB_FIT_FAILED] = "stopped: runs failed",
	[HB_FIT_RUNNING] = "running",
};

const char *
hb_fit_reason_str(int reason)
{
	return reason >= 0 && reason <= HB_FIT_RUNNING ? reasons[reason] : "?";
}

void
hb_fit_result_free(struct hb_fit_result *r)
{
	if (r == NULL)
		return;
	free(r->point);
	r->point = NULL;
	r->npoints = 0;
}

/* The fit in progress (fit.h): the solver, its callbacks' context, the result so far. */
struct hb_fit {
	struct fit_ctx c;             /* c.sc -> scene, c.fp -> fp */
	struct hb_scene scene;
	struct fit_param fp[HB_FIT_MAX_FREE];
	gsl_multifit_nlinear_fdf fdf;
	gsl_multifit_nlinear_workspace *w;
	double xtol, gtol, ftol;
	int max_iter;
	void (*progress)(void *ctx, int iter, double cost, long runs);
	void *pctx;
	int done;
	struct hb_fit_result r;          /* keys, starts, points (start values), cost0; reason */
	/* the numerical error (fit_num.c), made once when the fit has stopped */
	int numerical, num_done;
	double num_err[HB_FIT_MAX_FREE], num_rtol;
	char num_why[256];
};

void
hb_fit_free(struct hb_fit *f)
{
	if (f == NULL)
		return;
	if (f->w != NULL)
		gsl_multifit_nlinear_free(f->w);
	free(f->c.meas);
	free(f->c.sd);
	free(f->c.last_u);
	free(f->c.last_r);
	free(f->c.scs);
	free(f->c.y);
	free(f->c.fail);
	free(f->c.spec_u);
	free(f->c.spec_y);
	free(f->c.spec_fail);
	free(f->r.point);
	free(f);
}

struct hb_fit *
hb_fit_new(const struct hb_scene *sc, const struct hb_fit_data *d, const struct hb_fit_options *o,
        char *msg, size_t n)
{
	gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
	struct hb_fit *f;
	struct hb_fit_result *r;
	struct fit_ctx *c;
	double u[HB_FIT_MAX_FREE];
	int np = o->nkeys;
	size_t npts = hb_fit_npoints(d);
	gsl_vector_view xv;

	if (np < 1 || np > HB_FIT_MAX_FREE) {
		hb_status_set(msg, n, HB_EINVAL, "--free: %d keys; accepted: 1 to %d", np, HB_FIT_MAX_FREE);
		return NULL;
	}
	if ((f = calloc(1, sizeof *f)) == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	r = &f->r;
	c = &f->c;
	f->scene = *sc;
	for (int i = 0; i < np; i++) {
		if (fit_param_init(sc, o->keys[i], &f->fp[i], msg, n) != HB_OK)
			goto fail;
		for (int j = 0; j < i; j++)
			if (strcmp(o->keys[i], o->keys[j]) == 0) {
				hb_status_set(msg, n, HB_EINVAL, "--free: %s given twice; accepted: each "
				              "key once", o->keys[i]);
				goto fail;
			}
		snprintf(r->key[i], sizeof r->key[i], "%s", o->keys[i]);
		u[i] = f->fp[i].u0;
		hb_fit_key_get(sc, o->keys[i], &r->start[i], msg, n);
	}
	if (npts < (size_t)np) {
		hb_status_set(msg, n, HB_EINVAL, "%s: %zu data point%s cannot determine %d "
		    "parameters; accepted: at least as many points as free keys", d->source, npts,
		    npts == 1 ? "" : "s", np);
		goto fail;
	}
	/* a height is (e v_i)^2 / (2 g): free flight under gravity alone */
	if (d->kind == HB_FIT_HEIGHTS && (!(sc->loads.g > 0) || sc->loads.F1 != 0
	                                  || sc->loads.F2 != 0 || sc->loads.ramp)) {
		cnum_snprintf(msg, n, "%s: rebound heights need a flight under gravity alone (the "
		    "apex is v^2 / (2 g)); the scene has loads.g = %g m/s^2%s; accepted: loads.g > "
		    "0 and no other load (--set loads.g=9.81)", d->source, sc->loads.g,
		    sc->loads.F1 != 0 || sc->loads.F2 != 0 || sc->loads.ramp
		    ? " and another load" : "");
		goto fail;
	}
	f->xtol = o->xtol > 0 ? o->xtol : 1e-8;
	f->gtol = o->gtol > 0 ? o->gtol : 1e-10;
	f->ftol = o->ftol > 0 ? o->ftol : 1e-12;
	f->max_iter = o->max_iter > 0 ? o->max_iter : 100;
	f->numerical = o->numerical;
	f->progress = o->progress;
	f->pctx = o->ctx;
	r->np = np;
	r->npoints = npts;
	c->sc = &f->scene;
	c->d = d;
	c->fp = f->fp;
	c->np = np;
	c->npts = npts;
	c->jobs = o->jobs;
	/*
	 * The difference step: the square root of the run's relative error,
	 * but never below 1e-6.  A simulated impact time is not a smooth
	 * function of the parameters below the integrator's error (a change
	 * of the step sequence moves it by about that error), and at rtol
	 * 3e-14 a step of 1.7e-7 turned that noise into a Jacobian from which
	 * no step lowered the cost (tests/test_fit.c, bwmcl_sequence_noisy,
	 * with dop853 at 3e-14); at 1e-6 every fit test passes with rk8pd at
	 * 1e-12 and with dop853 at 3e-14.
	 */
	c->h_rel = sqrt(fmax(sc->run.rtol, 1e-12));
	r->point = calloc(npts, sizeof *r->point);
	c->meas = malloc(npts * sizeof(double));
	c->sd = malloc(npts * sizeof(double));
	c->last_u = malloc(HB_FIT_MAX_FREE * sizeof(double));
	c->last_r = malloc(npts * sizeof(double));
	c->scs = malloc((size_t)(np + 1) * sizeof *c->scs);
	c->y = malloc((size_t)(np + 1) * npts * sizeof(double));
	c->fail = malloc((size_t)(np + 1) * sizeof(int));
	c->spec_u = malloc((size_t)np * sizeof(double));
	c->spec_y = malloc((size_t)np * npts * sizeof(double));
	c->spec_fail = malloc((size_t)np * sizeof(int));
	c->per = d->kind == HB_FIT_DROPS ? (long)d->n : (long)d->ntrials;
	c->cores = o->jobs;
	if (c->cores <= 0) {
		long nc = sysconf(_SC_NPROCESSORS_ONLN);

		c->cores = nc > 0 ? (int)nc : 1;
	}
	if (r->point == NULL || c->meas == NULL || c->sd == NULL || c->last_u == NULL
	    || c->last_r == NULL || c->scs == NULL || c->y == NULL || c->fail == NULL
	    || c->spec_u == NULL || c->spec_y == NULL || c->spec_fail == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto fail;
	}
	fit_points(d, r->point, NULL, &r->sd_scaled);
	for (size_t k = 0; k < npts; k++) {
		c->meas[k] = r->point[k].measured;
		c->sd[k] = r->point[k].sd;
	}

	/* The start: every run must succeed, or the fit has nothing to go on. */
	{
		const double *up = u;
		char m[384];
		int st;

		if ((st = fit_eval_many(c, &up, 1, m, sizeof m)) != HB_OK) {
			hb_status_set(msg, n, st, "the start: %s", m);
			goto fail;
		}
		if (c->fail[0]) {
			hb_status_set(msg, n, HB_EINVAL, "at the start: %s; accepted: a start whose "
			    "run reproduces the data's collisions (choose it with --set)", m);
			goto fail;
		}
		for (size_t k = 0; k < npts; k++) {
			r->point[k].start = c->y[k];
			r->cost0 += pow((c->y[k] - c->meas[k]) / c->sd[k], 2);
		}
	}
	f->fdf.f = fit_resid_f;
	f->fdf.df = fit_resid_df;
	f->fdf.fvv = NULL;
	f->fdf.n = npts;
	f->fdf.p = (size_t)np;
	f->fdf.params = c;
	par.trs = gsl_multifit_nlinear_trs_lm;
	par.scale = gsl_multifit_nlinear_scale_more;
	par.solver = gsl_multifit_nlinear_solver_qr;
	f->w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, npts, (size_t)np);
	if (f->w == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto fail;
	}
	xv = gsl_vector_view_array(u, (size_t)np);
	gsl_multifit_nlinear_init(&xv.vector, &f->fdf, f->w);
	/* A Jacobian singular at the start: no iteration can tell the keys apart. */
	if (fit_identifiability(gsl_multifit_nlinear_jac(f->w), f->fp, np, &r->cond, r->unident,
	                    sizeof r->unident)) {
		r->reason = HB_FIT_SINGULAR;
		f->done = 1;
	}
	return f;
fail:
	hb_fit_free(f);
	return NULL;
}

int
hb_fit_iterate(struct hb_fit *f)
{
	struct hb_fit_result *r = &f->r;
	int info = 0, s;
	gsl_vector *fv;
	double cost;

	if (f->done)
		return 1;
	s = gsl_multifit_nlinear_iterate(f->w);
	fv = gsl_multifit_nlinear_residual(f->w);
	r->iter = (int)gsl_multifit_nlinear_niter(f->w);
	gsl_blas_ddot(fv, fv, &cost);
	if (f->progress != NULL)
		f->progress(f->pctx, r->iter, cost, f->c.runs);
	if (s == GSL_ENOPROG) {
		/*
		 * No trial step lowered the cost.  Where the Gauss-Newton step
		 * would lower it by less than ftol of itself, this is the
		 * minimum to the noise of the runs (a simulated value moves by
		 * the integrator's error as the step sequence changes): the cost
		 * stopped decreasing.  Otherwise the solver is stuck.
		 */
		double left = fit_gn_decrease(gsl_multifit_nlinear_jac(f->w), fv);

		r->reason = left <= f->ftol * cost ? HB_FIT_CONVERGED_COST : HB_FIT_NOPROGRESS;
		f->done = 1;
	} else if (s != GSL_SUCCESS) {
		r->reason = HB_FIT_FAILED;
		snprintf(r->why, sizeof r->why, "%s", gsl_strerror(s));
		f->done = 1;
	} else if (gsl_multifit_nlinear_test(f->xtol, f->gtol, f->ftol, &info, f->w)
	           == GSL_SUCCESS) {
		r->reason = info == 1 ? HB_FIT_CONVERGED_STEP : info == 2
		    ? HB_FIT_CONVERGED_GRAD : HB_FIT_CONVERGED_COST;
		f->done = 1;
	} else if (r->iter >= f->max_iter) {
		r->reason = HB_FIT_MAXITER;
		f->done = 1;
	}
	if (f->done && r->reason != HB_FIT_FAILED
	    && fit_identifiability(gsl_multifit_nlinear_jac(f->w), f->fp, f->c.np, &r->cond,
	                       r->unident, sizeof r->unident))
		r->reason = HB_FIT_SINGULAR;
	return f->done;
}

int
hb_fit_result_get(struct hb_fit *f, struct hb_fit_result *out, char *msg, size_t n)
{
	struct hb_fit_result *r = out;
	struct fit_ctx *c = &f->c;
	int np = c->np;
	double u[HB_FIT_MAX_FREE], th[HB_FIT_MAX_FREE];
	gsl_vector *fv = gsl_multifit_nlinear_residual(f->w);

	*r = f->r;
	r->point = malloc(c->npts * sizeof *r->point);
	if (r->point == NULL) {
		r->npoints = 0;
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	memcpy(r->point, f->r.point, c->npts * sizeof *r->point);
	if (!f->done)
		r->reason = HB_FIT_RUNNING;
	/* The best point: GSL's position is the last accepted one. */
	for (int j = 0; j < np; j++)
		u[j] = gsl_vector_get(gsl_multifit_nlinear_position(f->w), (size_t)j);
	r->fitted = f->scene;
	if (fit_param_apply(&r->fitted, f->fp, np, u, th, NULL, msg, n) != HB_OK)
		return HB_EINVAL;
	for (int j = 0; j < np; j++)
		hb_fit_key_get(&r->fitted, r->key[j], &r->value[j], msg, n);
	r->cost = 0;
	for (size_t k = 0; k < c->npts; k++) {
		double rk = gsl_vector_get(fv, k);

		r->point[k].resid = rk;
		r->point[k].simulated = c->meas[k] + rk * c->sd[k];
		r->cost += rk * rk;
	}
	fit_errors(gsl_multifit_nlinear_jac(f->w), c, u, r);
	if (f->numerical && f->done) {
		if (!f->num_done && r->reason == HB_FIT_SINGULAR) {
			for (int j = 0; j < HB_FIT_MAX_FREE; j++)
				f->num_err[j] = NAN;
			snprintf(f->num_why, sizeof f->num_why, "not identifiable (the Jacobian at "
			         "the estimates is singular)");
			f->num_done = 1;
		} else if (!f->num_done) {
			long num_runs = 0;   /* not the fit's: r->runs counts those */

			f->num_why[0] = '\0';
			if (fit_numerical(c->sc, c->d, c->jobs, f->fp, np, u,
			                  gsl_multifit_nlinear_jac(f->w), fv, c->meas, c->sd,
			                  f->num_err, &f->num_rtol, &num_runs, &c->cpu, &c->span,
			                  f->num_why, sizeof f->num_why) == HB_OK)
				f->num_why[0] = '\0';
			f->num_done = 1;
		}
		r->num_on = 1;
		memcpy(r->num_err, f->num_err, sizeof r->num_err);
		r->num_rtol = f->num_rtol;
		snprintf(r->num_why, sizeof r->num_why, "%s", f->num_why);
	}
	if (r->reason == HB_FIT_SINGULAR) {
		for (int j = 0; j < np; j++)
			if (strstr(r->unident, r->key[j]) != NULL)
				r->se[j] = NAN;
		cnum_snprintf(r->why, sizeof r->why, "not identifiable from these data: %s "
		    "(condition number of the scaled Jacobian %.3g)", r->unident, r->cond);
	} else if (r->reason != HB_FIT_FAILED) {
		snprintf(r->why, sizeof r->why, "%s", hb_fit_reason_str(r->reason));
	}
	r->runs = c->runs;
	r->run_cpu = c->cpu;
	r->run_span = c->span;
	r->threads = c->cores;
	return HB_OK;
}

int
hb_fit_run(const struct hb_scene *sc, const struct hb_fit_data *d, const struct hb_fit_options *o,
        struct hb_fit_result *r, char *msg, size_t n)
{
	struct hb_fit *f;
	int st;

	memset(r, 0, sizeof *r);
	if ((f = hb_fit_new(sc, d, o, msg, n)) == NULL)
		return msg != NULL && strstr(msg, "out of memory") != NULL ? HB_ENOMEM : HB_EINVAL;
	while (!hb_fit_iterate(f))
		;
	st = hb_fit_result_get(f, r, msg, n);
	hb_fit_free(f);
	return st;
}

int
hb_fit_simulate(const struct hb_scene *sc, const struct hb_fit_data *d, int jobs, double *out,
             char *msg, size_t n)
{
	int fail = 0;
	long runs = 0;
	int st = fit_eval(sc, 1, d, jobs, NAN, out, &fail, &runs, NULL, NULL, msg, n);

	if (st != HB_OK)
		return st;
	if (fail)
		return HB_ENUMERIC;
	return HB_OK;
}
