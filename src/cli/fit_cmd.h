/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_cmd.h - `hybounce fit`: fit a scene's parameters to measured data
 * (fit_cmd.c), a thin shell over the engine's fit.h and onset.h.
 *
 * Exit status: 0 the fit converged to credible estimates; 1 not credible:
 * stopped without converging
 * (iteration cap, no progress, parameters not identifiable, runs failing):
 * or an estimate's relative standard error above --max-relative-se, or
 * its numerical error not well below its standard error, or
 * with sd columns residuals inconsistent with them (fit_report.c): the
 * best point is still reported and written; 2 bad input (options, preset,
 * --set, data file, a recording that is no bouncing sequence, a start at
 * which the runs fail, an unwritable output): nothing is written (but
 * --onsets-out).
 */
#ifndef HYBOUNCE_CLI_FIT_H
#define HYBOUNCE_CLI_FIT_H

#include <stdio.h>
#include "hybounce/fit.h"

/* argv[0] is "fit".  Returns the exit status. */
int
fit_main(int argc, char **argv);

struct hb_onset_result;

/* The onsets of a recording, then the clicks dropped with their reason. */
void
fit_print_onsets(const char *path, const struct hb_onset_result *on);

/* hb_atomic_write_with's filler for --onsets-out: the t_e CSV, dropped
 * clicks as comments; ctx is the struct hb_onset_result. */
void
fit_fill_onsets(FILE *f, const void *ctx);

/* The text plot of measured against simulated values (fit_plot.c). */
void
fit_plot(FILE *f, const struct hb_fit_result *r, const struct hb_fit_data *d);

/* The verdict on a fit (fit_report.c): credible (status 0), or the reasons not. */
enum { FIT_VERDICT_MAX = 16 };
struct fit_verdict {
	int status;                 /* 0 credible, 1 not */
	int n;                      /* reasons */
	char reason[FIT_VERDICT_MAX][640];
};

/* 1 when estimate i's numerical error is not well below its standard error
 * (above HB_FIT_NUM_RATIO of it). */
int
fit_num_flagged(const struct hb_fit_result *r, int i);

/*
 * Credible: converged, every relative standard error at most max_rse, every
 * numerical error well below its standard error (fit_num_flagged), and
 * with stated noise the residuals consistent with it (hb_fit_stats).
 * Returns v->status.
 */
int
fit_verdict(const struct hb_fit_result *r, const struct hb_fit_stats *st, double max_rse,
            struct fit_verdict *v);

/* The text report on stdout; quiet: no residual table. */
void
fit_report_print(const struct hb_fit_result *r, const struct hb_fit_data *d,
                 const struct hb_fit_stats *st, int quiet);

/* hb_atomic's filler for --report: the same as JSON; ctx is a struct fit_report_ctx. */
struct fit_report_ctx {
	const char *preset, *data;
	const char *law;            /* --laws: the law's name, else NULL */
	const struct hb_fit_data *d;
	const struct hb_fit_result *r;
	const struct hb_fit_stats *st;
	const struct fit_verdict *v;
	int status;                 /* the exit status */
	int sig;                    /* the signal that stopped the fit, or 0 */
};

void
fit_report_json(FILE *f, const void *ctx);

/* fit_output.c: the fitted preset, the residuals and the report (fill(f, rc)) as one atomic set. */
struct hb_outputs;
struct hb_atomic_target;


int
fit_write_outputs(const char *out, const struct hb_scene *sc, const char *resid_path,
                  const struct hb_fit_result *r, const struct hb_outputs *pol, int k_out,
                  int k_resid, const char *report_path, void (*fill)(FILE *, const void *),
                  const void *rc, int k_report);

/* One report as a JSON object (no newline after it): fit_report_json's body. */
void
fit_report_json_object(FILE *f, const struct fit_report_ctx *c);

/* --laws (fit_laws.c): every law fitted to the same data, ranked by AIC. */
struct plot_out;
struct fit_laws_args {
	const char *laws, *preset, *data;
	const char *const *sets;    /* every --set, LAW:KEY=VALUE ones too */
	int nsets;
	const char *const *keys;    /* every --free key, LAW:KEY ones too */
	int nkeys;
	const struct hb_fit_data *d;
	const struct hb_fit_options *fo; /* jobs, max_iter */
	double max_rse;
	int quiet;
	const char *out, *resid_path, *report_path;
	const struct hb_outputs *pol;
	int k_out, k_resid, k_report;
	struct plot_out *plot;      /* --plot (plot_out.h), or NULL */
};

/* Returns the exit status: the best law's verdict, 2 for bad input. */
int
fit_laws(const struct fit_laws_args *a);

/*
 * 1 when s is "LAW:REST" (a law's name, then a colon before any '.' or
 * '='), with *rest = REST when rest is not NULL; else 0.
 */
int
fit_laws_prefix(const char *s, const char **rest);

#endif
