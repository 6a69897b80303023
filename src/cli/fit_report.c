/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_report.c - what `hybounce fit` says of a fit: the text report on
 * stdout (points, degrees of freedom, cost, reduced chi-square and the test
 * of the stated noise, AIC and BIC, estimates with standard errors and 95%
 * intervals, parameters at a bound, correlations, residuals), the verdict
 * (credible or the reasons why not) and the same as JSON for --report.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "fit_cmd.h"

#define PROG "hybounce"

/* The form of AIC and BIC, in words (fit.h, hb_fit_stats). */
static const char *
ic_form(const struct hb_fit_stats *st)
{
	return st->noise_stated
	    ? "least squares with known variance (the stated sd): AIC = cost + 2P, "
	      "BIC = cost + P ln N"
	    : "least squares with unknown variance: AIC = N ln(cost/N) + 2P, "
	      "BIC = N ln(cost/N) + P ln N";
}

int
fit_num_flagged(const struct hb_fit_result *r, int i)
{
	return r->num_on && isfinite(r->num_err[i]) && isfinite(r->se[i]) &&
	       r->num_err[i] > HB_FIT_NUM_RATIO * r->se[i];
}

int
fit_verdict(const struct hb_fit_result *r, const struct hb_fit_stats *st, double max_rse,
            struct fit_verdict *v)
{
	memset(v, 0, sizeof *v);
	if (r->reason > HB_FIT_CONVERGED_COST) {
		snprintf(v->reason[v->n++], sizeof v->reason[0], "not converged: %.500s", r->why);
	}
	for (int i = 0; i < r->np && v->n < FIT_VERDICT_MAX; i++) {
		if (st->rel_se[i] <= max_rse)
			continue;
		snprintf(v->reason[v->n++], sizeof v->reason[0], "the standard error of %s is %.3g "
		         "of its value, above %g (--max-relative-se): the data do not determine it",
		         r->key[i], st->rel_se[i], max_rse);
	}
	for (int i = 0; i < r->np && v->n < FIT_VERDICT_MAX; i++) {
		if (!fit_num_flagged(r, i))
			continue;
		snprintf(v->reason[v->n++], sizeof v->reason[0], "the numerical error of %s is "
		         "%.3g, not well below its standard error %.3g (above %g of it): the "
		         "tolerance, not the data, limits the estimate; expected a smaller run.rtol",
		         r->key[i], r->num_err[i], r->se[i], HB_FIT_NUM_RATIO);
	}
	if (v->n < FIT_VERDICT_MAX && (st->noise == HB_FIT_NOISE_ABOVE
	                               || st->noise == HB_FIT_NOISE_BELOW)) {
		snprintf(v->reason[v->n++], sizeof v->reason[0], "%s: reduced chi-square %.3g, "
		         "P(chi-square with %ld dof %s cost) = %.3g, below %g/2 (two-sided test at %g)%s",
		         hb_fit_noise_str(st->noise), st->chi2_red, st->dof,
		         st->noise == HB_FIT_NOISE_ABOVE ? ">=" : "<=",
		         st->noise == HB_FIT_NOISE_ABOVE ? st->p_above : st->p_below,
		         st->level, st->level,
		         st->noise == HB_FIT_NOISE_ABOVE
		         ? ": the law does not explain the data, or the sd understate the noise"
		         : ": the sd overstate the noise, so the standard errors are too large");
	}
	v->status = v->n > 0 ? 1 : 0;
	return v->status;
}

void
fit_report_print(const struct hb_fit_result *r, const struct hb_fit_data *d,
                 const struct hb_fit_stats *st, int quiet)
{
	int p = r->np;

	printf("stopped     %s after %d iteration%s, %ld runs\n", r->why, r->iter,
	    r->iter == 1 ? "" : "s", r->runs);
	printf("cost        %.6g at the start, %.6g at the estimates (sum of squared "
	       "residuals / sd, %zu points)\n", r->cost0, r->cost, r->npoints);
	printf("dof         %zu points - %d free parameter%s = %ld degrees of freedom\n",
	    st->n, st->p, st->p == 1 ? "" : "s", st->dof);
	printf("chi-square  reduced %.4g (cost / dof); ", st->chi2_red);
	if (st->noise == HB_FIT_NOISE_UNSTATED)
		printf("%s\n", st->noise_stated ? "no test: no degrees of freedom left"
		       : "no test: the data carry no sd (the residual variance scales the errors)");
	else
		printf("stated noise: %s (P(chi2 <= cost) = %.3g, P(chi2 >= cost) = %.3g; "
		       "two-sided test at %g)\n", hb_fit_noise_str(st->noise), st->p_below,
		       st->p_above, st->level);
	printf("AIC, BIC    %.6g, %.6g (%s)\n", st->aic, st->bic, ic_form(st));
	printf("\nestimates   (SI units; standard errors %s; 95%% interval: t with %ld dof, "
	       "%.4g se)\n", r->sd_scaled
	    ? "scaled by the residual variance cost/(N-P): the data carry no sd"
	    : "from the data's standard deviations", st->dof, st->t95);
	printf("  %-14s %14s %16s %12s %9s %13s %13s %11s  %s\n", "key", "start", "estimate",
	    "std error", "relative", "95% low", "95% high", "numerical", "unit");
	for (int i = 0; i < p; i++) {
		struct hb_scene_keyinfo ki;

		if (hb_scene_get(&r->fitted, r->key[i], &ki, NULL) != HB_OK)
			ki.unit[0] = '\0';
		printf("  %-14s %14.6g %16.9g %12.3g %9.2g %13.6g %13.6g %11.2g  %s%s%s\n", r->key[i],
		    r->start[i], r->value[i], r->se[i], st->rel_se[i], st->lo95[i], st->hi95[i],
		    r->num_on ? r->num_err[i] : NAN, ki.unit, st->at_bound[i] < 0
		    ? "  AT LOWER BOUND" : st->at_bound[i] > 0 ? "  AT UPPER BOUND" : "",
		    fit_num_flagged(r, i) ? "  NUMERICAL ERROR NOT WELL BELOW SE" : "");
	}
	if (r->num_on && r->num_why[0] != '\0')
		printf("  numerical: no estimate: %s\n", r->num_why);
	else if (r->num_on)
		printf("  numerical: how far each estimate moves when the runs are made at rtol "
		       "%.3g (rk8pd; the residuals at the estimates through the Jacobian); "
		       "at most %g x the standard error is well below it\n", r->num_rtol,
		       HB_FIT_NUM_RATIO);
	for (int i = 0; i < p; i++)
		if (st->at_bound[i] != 0)
			printf("  %s is at the %s bound of its range: its standard error and interval "
			       "do not describe it\n", r->key[i], st->at_bound[i] < 0 ? "lower" : "upper");
	if (p > 1) {
		printf("\ncorrelation\n  %-14s", "");
		for (int j = 0; j < p; j++)
			printf(" %10.10s", r->key[j]);
		printf("\n");
		for (int i = 0; i < p; i++) {
			printf("  %-14s", r->key[i]);
			for (int j = 0; j < p; j++)
				printf(" %10.4f", r->corr[i * HB_FIT_MAX_FREE + j]);
			printf("\n");
		}
	}
	if (quiet)
		return;
	printf("\nresiduals   (%s)\n", d->kind == HB_FIT_SEQUENCE ? d->ntrials > 1
	    ? "t_e: time since the trial's first impact; i: the impact" : "t_e: time since the first impact"
	    : d->kind == HB_FIT_HEIGHTS ? "h: the apex after impact i - 1, from rest at the row's h_0"
	    : "one run per drop");
	if (d->kind == HB_FIT_SEQUENCE && d->ntrials <= 1)
		printf("  %4s %4s %-6s %16s %16s %12s %10s\n", "pt", "row", "obs", "measured",
		    "simulated", "sd", "resid/sd");
	else
		printf("  %4s %4s %5s %3s %-6s %16s %16s %12s %10s\n", "pt", "row", "trial", "i",
		    "obs", "measured", "simulated", "sd", "resid/sd");
	for (size_t k = 0; k < r->npoints; k++) {
		const struct hb_fit_point *pt = &r->point[k];

		if (d->kind == HB_FIT_SEQUENCE && d->ntrials <= 1)
			printf("  %4zu %4zu %-6s %16.9g %16.9g %12.3g %10.3g\n", k, pt->row + 1,
			    hb_fit_obs_name(pt->obs), pt->measured, pt->simulated, pt->sd, pt->resid);
		else
			printf("  %4zu %4zu %5zu %3zu %-6s %16.9g %16.9g %12.3g %10.3g\n", k, pt->row + 1,
			    pt->trial + 1, pt->index, hb_fit_obs_name(pt->obs), pt->measured,
			    pt->simulated, pt->sd, pt->resid);
	}
	fit_plot(stdout, r, d);
}

/* A JSON number that reads back to the same double, or null (NaN, inf). */
static void
jnum(FILE *f, double v)
{
	if (isfinite(v))
		cnum_fprintf(f, "%.17g", v);
	else
		fputs("null", f);
}

/* A JSON string (the control characters escaped). */
static void
jstr(FILE *f, const char *s)
{
	fputc('"', f);
	for (; *s != '\0'; s++) {
		unsigned char c = (unsigned char)*s;

		if (c == '"' || c == '\\')
			fprintf(f, "\\%c", c);
		else if (c < 0x20)
			fprintf(f, "\\u%04x", c);
		else
			fputc(c, f);
	}
	fputc('"', f);
}

void
fit_report_json(FILE *f, const void *ctx)
{
	fit_report_json_object(f, ctx);
	fputc('\n', f);
}

void
fit_report_json_object(FILE *f, const struct fit_report_ctx *c)
{
	const struct hb_fit_result *r = c->r;
	const struct hb_fit_stats *st = c->st;
	int p = r->np;

	fprintf(f, "{\n  \"hybounce\": ");
	jstr(f, HYBOUNCE_VERSION);
	fprintf(f, ",\n  \"preset\": ");
	jstr(f, c->preset);
	if (c->law != NULL) {
		fprintf(f, ",\n  \"law\": ");
		jstr(f, c->law);
	}
	fprintf(f, ",\n  \"data\": ");
	jstr(f, c->data);
	fprintf(f, ",\n  \"kind\": \"%s\",\n  \"trials\": %zu,\n", c->d->kind == HB_FIT_SEQUENCE
	    ? "sequence" : c->d->kind == HB_FIT_HEIGHTS ? "heights" : "drops", c->d->kind
	    == HB_FIT_DROPS ? c->d->n : c->d->ntrials);
	fprintf(f, "  \"stopped\": ");
	jstr(f, r->why);
	fprintf(f, ",\n  \"converged\": %s,\n  \"iterations\": %d,\n  \"runs\": %ld,\n",
	    r->reason <= HB_FIT_CONVERGED_COST && c->sig == 0 ? "true" : "false", r->iter, r->runs);
	fprintf(f, "  \"points\": %zu,\n  \"free_parameters\": %d,\n  \"dof\": %ld,\n",
	    st->n, st->p, st->dof);
	fprintf(f, "  \"cost_start\": ");
	jnum(f, r->cost0);
	fprintf(f, ",\n  \"cost\": ");
	jnum(f, r->cost);
	fprintf(f, ",\n  \"chi2_reduced\": ");
	jnum(f, st->chi2_red);
	fprintf(f, ",\n  \"noise\": {\"stated\": %s, \"test_level\": ", st->noise_stated
	    ? "true" : "false");
	jnum(f, st->level);
	fprintf(f, ", \"p_below\": ");
	jnum(f, st->p_below);
	fprintf(f, ", \"p_above\": ");
	jnum(f, st->p_above);
	fprintf(f, ", \"verdict\": ");
	jstr(f, hb_fit_noise_str(st->noise));
	fprintf(f, "},\n  \"aic\": ");
	jnum(f, st->aic);
	fprintf(f, ",\n  \"bic\": ");
	jnum(f, st->bic);
	fprintf(f, ",\n  \"information_criteria\": ");
	jstr(f, ic_form(st));
	fprintf(f, ",\n  \"t95\": ");
	jnum(f, st->t95);
	fprintf(f, ",\n  \"numerical_rtol\": ");
	jnum(f, r->num_on ? r->num_rtol : NAN);
	if (r->num_on && r->num_why[0] != '\0') {
		fprintf(f, ",\n  \"numerical_failed\": ");
		jstr(f, r->num_why);
	}
	fprintf(f, ",\n  \"parameters\": [\n");
	for (int i = 0; i < p; i++) {
		struct hb_scene_keyinfo ki;

		if (hb_scene_get(&r->fitted, r->key[i], &ki, NULL) != HB_OK)
			ki.unit[0] = '\0';
		fprintf(f, "    {\"key\": ");
		jstr(f, r->key[i]);
		fprintf(f, ", \"unit\": ");
		jstr(f, ki.unit);
		fprintf(f, ", \"start\": ");
		jnum(f, r->start[i]);
		fprintf(f, ", \"value\": ");
		jnum(f, r->value[i]);
		fprintf(f, ", \"se\": ");
		jnum(f, r->se[i]);
		fprintf(f, ", \"relative_se\": ");
		jnum(f, st->rel_se[i]);
		fprintf(f, ", \"numerical_error\": ");
		jnum(f, r->num_on ? r->num_err[i] : NAN);
		fprintf(f, ", \"numerical_well_below_se\": %s", !r->num_on || !isfinite(r->num_err[i])
		    ? "null" : fit_num_flagged(r, i) ? "false" : "true");
		fprintf(f, ", \"ci95\": [");
		jnum(f, st->lo95[i]);
		fprintf(f, ", ");
		jnum(f, st->hi95[i]);
		fprintf(f, "], \"at_bound\": %s}%s\n", st->at_bound[i] < 0 ? "\"lower\""
		    : st->at_bound[i] > 0 ? "\"upper\"" : "null", i + 1 < p ? "," : "");
	}
	fprintf(f, "  ],\n  \"correlation\": [");
	for (int i = 0; i < p; i++) {
		fprintf(f, "%s[", i ? ", " : "");
		for (int j = 0; j < p; j++) {
			if (j)
				fprintf(f, ", ");
			jnum(f, r->corr[i * HB_FIT_MAX_FREE + j]);
		}
		fprintf(f, "]");
	}
	fprintf(f, "],\n  \"credible\": %s,\n  \"reasons\": [", c->status == 0 ? "true" : "false");
	for (int i = 0; i < c->v->n; i++) {
		if (i)
			fprintf(f, ", ");
		jstr(f, c->v->reason[i]);
	}
	fprintf(f, "],\n  \"exit_status\": %d,\n  \"residuals\": [\n", c->status);
	for (size_t k = 0; k < r->npoints; k++) {
		const struct hb_fit_point *pt = &r->point[k];

		fprintf(f, "    {\"row\": %zu, \"trial\": %zu, \"index\": %zu, \"observable\": "
		    "\"%s\", \"measured\": ", pt->row + 1, pt->trial + 1, pt->index,
		    hb_fit_obs_name(pt->obs));
		jnum(f, pt->measured);
		fprintf(f, ", \"simulated\": ");
		jnum(f, pt->simulated);
		fprintf(f, ", \"sd\": ");
		jnum(f, pt->sd);
		fprintf(f, ", \"resid\": ");
		jnum(f, pt->resid);
		fprintf(f, "}%s\n", k + 1 < r->npoints ? "," : "");
	}
	fprintf(f, "  ]\n}");
}
