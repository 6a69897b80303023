/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit.h - identify a scene's parameters from measured collisions: nonlinear
 * least squares over runs of the simulator.
 *
 *     struct hb_fit_data d;
 *     struct hb_fit_result r;
 *     hb_fit_data_load(path, &d, msg, sizeof msg);           // or hb_fit_data_from_times()
 *     hb_fit_run(&scene, &d, &opts, &r, msg, sizeof msg);
 *     ... r.value[k] +- r.se[k], r.corr, r.point[i] ...
 *     hb_fit_result_free(&r);
 *     hb_fit_data_free(&d);
 *
 * Data (hb_fit_data_load), recognised by their columns (CSV, one header row;
 * blank lines and lines starting with '#' are skipped):
 *  - a bouncing sequence: a column t_e, the commencement time of every
 *    collision in order.  The first one aligns the clocks: the observables
 *    are t_e^i - t_e^r for i > r, r the first impact with a time, against
 *    the same differences of the run.
 *  - separate drops: columns v_i (the approach velocity, m/s; its sign is
 *    ignored) and e, optionally x_c_r and/or t_d.  Each row is its own run
 *    of the scene started at contact (x0 = 0, v0 = -|v_i|) and stopped after
 *    the first separation; the observables are e, x_c^r and t_d of that
 *    collision.  A drop that does not separate before run.T (or within
 *    5000 steps) has e = 0, and x_c^r and t_d where it stopped.
 *  - drop and rebound heights: columns h_0, h_1, ... h_K, a row per drop:
 *    h_0 the height the ball is dropped from (at rest, x0 = h_0, v0 = 0),
 *    h_i the apex after impact i - 1.  The run's apex after impact i is
 *    (e_i v_i)^2 / (2 g) (free flight under loads.g > 0 alone: the rise
 *    above the point of separation, a residual indentation apart), so that
 *    e_i = sqrt(h_{i+1} / h_i) and the flight after impact i lasts
 *    2 sqrt(2 h_{i+1} / g).  An optional sd_h gives the standard deviation
 *    of every height of its row.
 *    A sequence whose run ends in permanent contact has its missing
 *    impacts at that contact's commencement (continuous in the parameters),
 *    and a rebound height of 0 after it.
 * Units: a bare value is SI; a header may give the column's unit in
 * brackets or parentheses, "t_e [ms]", "t_e (s)", "h_0 [mm]", "v_i [m/s]"
 * (units.h; "e [-]" or "e [1]" for the dimensionless), and every value of
 * the column is converted to SI.  A missed value is "NA", "N/A" or an empty
 * cell (in t_e, h_1 ..., e, x_c_r, t_d): the point is left out and the
 * sequence keeps its indices (the third t_e is impact 2 whatever is
 * missing before it).  Several trials in one file: a column "trial" (any
 * label; the rows of a trial together) makes each trial its own sequence;
 * a file of heights has a trial per row.  Every trial is fitted with the
 * same parameters (jointly); each run starts from the scene's initial
 * state (heights: from its h_0).
 * A column sd_NAME (sd_t_e, sd_e, sd_x_c_r, sd_t_d, sd_h) gives the standard
 * deviation of each value of NAME; residuals are divided by it.  A column
 * without one is weighted by 1 / (largest |value| of the column), and the
 * standard errors are then scaled by the residual variance
 * (cost / (N - P)), as is usual when the measurement error is unknown.
 * Columns of any other name are ignored.
 *
 * Parameters.  Any numeric scene key that is typed (law.*, body1.E ...,
 * body1.mass, loads.g, initial.x0 ...) can be free.  The solver works on
 * unconstrained u, and the value is theta(u), so that every trial stays in
 * the key's admissible range:
 *     (lo, hi)    theta = lo + (hi - lo) / (1 + exp(-k u)), k <= 1 such that
 *                 d theta / d u at the start is at most |theta| (1 for a
 *                 start at 0): a range far wider than the value, such as
 *                 initial.v0 in [-100 km/s, 100 km/s], then moves theta on
 *                 the scale of the value, not of the range
 *     (lo, inf)   theta = lo + exp(u)
 *     (-inf, hi)  theta = hi - exp(-u)
 *     (-inf, inf) theta = u
 * with gamma of the Bouc-Wen laws in [-beta, beta] as theta = beta tanh(u).
 * Standard errors are propagated by the derivative d theta / d u.
 *
 * Solver: GSL gsl_multifit_nlinear, trust region with Levenberg-Marquardt
 * steps and More's scaling; the Jacobian by forward differences over
 * runs, computed on `jobs` threads (each run has its own sim), P mod jobs
 * of its columns beside each trial point (ready when the step is
 * accepted).  The result does not depend on jobs, to the bit.
 *
 * Everything here is engine code: it never prints and never exits; the
 * progress callback is how a front end shows the iterations.
 */
#ifndef HB_FIT_H
#define HB_FIT_H

#include <stddef.h>
#include <stdio.h>
#include "scene.h"
#include "export.h"

HB_BEGIN_DECLS

enum hb_fit_kind { HB_FIT_SEQUENCE = 0, HB_FIT_DROPS = 1, HB_FIT_HEIGHTS = 2 };

/* Observables of a data point (h: a rebound's apex height). */
enum hb_fit_obs {
	HB_FIT_OBS_TE = 0, HB_FIT_OBS_E, HB_FIT_OBS_XCR, HB_FIT_OBS_TD, HB_FIT_OBS_H,
	HB_FIT_OBS_COUNT
};

enum { HB_FIT_MAX_FREE = 12 };

/*
 * Measured data, SI; every array has n entries (NULL when the column is
 * absent); NAN marks a missed value (and its sd).
 */
struct hb_fit_data {
	int kind;                 /* enum hb_fit_kind */
	size_t n;                 /* rows: collisions of the sequences, drops, or heights */
	double *vi;               /* drops: approach velocity (negative), m/s */
	double *col[HB_FIT_OBS_COUNT]; /* t_e (sequence); e, x_c_r, t_d (drops); h (heights) */
	double *sd[HB_FIT_OBS_COUNT];  /* their standard deviations, or NULL */
	char source[256];         /* file name, for messages */
	/*
	 * Sequences and heights: trial k holds rows trial_row[k] ..
	 * trial_row[k + 1] - 1 (ntrials + 1 entries); a trial of heights is
	 * h_0, h_1 ... of one drop.  Drops: ntrials = 0, trial_row NULL.
	 */
	size_t ntrials;
	size_t *trial_row;
	size_t *file_row;         /* the data row of the file (0-based) of each row */
};

/* Column name of an observable ("t_e", "e", "x_c_r", "t_d", "h"). */
const char *
hb_fit_obs_name(int obs);

/*
 * Reads a data file (see the top of this header): a CSV file, or a
 * recording of a bouncing sequence (a .wav name or a RIFF header; a
 * regular file) whose onsets (onset.h, default options) are the impact
 * times.  Returns 0, or HB_EINVAL / HB_EIO / HB_ENOMEM with "FILE:LINE:
 * ..." in msg naming the column or value and what is accepted.  On error
 * *d holds nothing to free.  A CSV file is read once, whole (a pipe or a
 * FIFO works), up to HB_INPUT_DATA_MAX bytes (input.h); a UTF-8
 * byte-order mark at its start is skipped; a NUL byte in a row is an
 * error naming row and column.  Concurrent calls are safe for CSV files,
 * not for recordings (see hb_fit_data_open).
 */
int
hb_fit_data_load(const char *path, struct hb_fit_data *d, char *msg, size_t n);

struct hb_onset_options;
struct hb_onset_result;

/*
 * hb_fit_data_load with the onset options of a recording (NULL: the
 * defaults) and, when on is not NULL, the onsets found (on->n = 0 for a
 * CSV file; filled as far as detection went even when the onsets make no
 * sequence; hb_onset_result_free(on) in every case).  The one loader of
 * every front end.  A recording is read through aubio, whose log hook is
 * global: not for concurrent calls with a recording (onset.h).
 */
int
hb_fit_data_open(const char *path, const struct hb_onset_options *oo, struct hb_fit_data *d,
                 struct hb_onset_result *on, char *msg, size_t n);

/*
 * The same from text already in memory (len bytes; a front end that read
 * the file once, e.g. to tell a recording): `name` stands for the file.
 */
int
hb_fit_data_parse(const char *text, size_t len, const char *name, struct hb_fit_data *d,
                  char *msg, size_t n);

/* The same from an open stream (borrowed); `name` stands for the file in messages. */
int
hb_fit_data_read(FILE *f, const char *name, struct hb_fit_data *d, char *msg, size_t n);

/*
 * A bouncing sequence from impact times t[0 .. n-1] (ascending, s), e.g.
 * from a recording; sd may be NULL.  `source` names it in messages.
 */
int
hb_fit_data_from_times(const double *t, const double *sd, size_t n, const char *source,
                    struct hb_fit_data *d, char *msg, size_t mn);

/* Frees the columns; hb_fit_data_free on a zeroed struct does nothing. */
void
hb_fit_data_free(struct hb_fit_data *d);

/* Why the fit stopped. */
enum hb_fit_reason {
	HB_FIT_CONVERGED_STEP = 0, /* the step became small (xtol) */
	HB_FIT_CONVERGED_GRAD,     /* the gradient became small (gtol) */
	HB_FIT_CONVERGED_COST,     /* the cost stopped decreasing (ftol) */
	HB_FIT_MAXITER,            /* iteration cap reached */
	HB_FIT_NOPROGRESS,         /* no step lowered the cost */
	HB_FIT_SINGULAR,           /* the Jacobian is singular: see fit_result.unident */
	HB_FIT_FAILED,             /* runs failed (message in fit_result.why) */
	HB_FIT_RUNNING,            /* not stopped yet (hb_fit_result_get during a fit) */
};

struct hb_fit_options {
	const char *const *keys; /* the free keys */
	int nkeys;
	int max_iter;            /* 0: 100 */
	int jobs;                /* threads for the runs; 0: every online core */
	double xtol, gtol, ftol; /* 0: 1e-8, 1e-10, 1e-12 */
	/* Called after every iteration (may be NULL): iteration, cost, runs so far. */
	void (*progress)(void *ctx, int iter, double cost, long runs);
	void *ctx;
	/*
	 * 1: once the fit has stopped, estimate each estimate's numerical
	 * error (hb_fit_result.num_err): the data's runs made once more at the
	 * estimates, at the tighter tolerance of an error estimate (error.h:
	 * rk8pd at a hundredth of run.rtol), and the change of the residuals
	 * carried through the Jacobian at the estimates into the parameters
	 * (the Gauss-Newton step of the tighter model from there).  Costs one
	 * evaluation of the data at that tolerance.
	 */
	int numerical;
};

/* A numerical error above this share of the standard error is not well below it. */
#define HB_FIT_NUM_RATIO 0.1

/* One data point and its fit. */
struct hb_fit_point {
	size_t row;              /* data row of the file (0-based) */
	int obs;                 /* enum hb_fit_obs */
	size_t trial;            /* trial (0-based; drops: the row) */
	size_t index;            /* impact i of t_e, i of h_i (0 for drops) */
	double measured, simulated; /* SI; for t_e: the time since the first collision */
	double sd;               /* the weight's standard deviation */
	double resid;            /* (simulated - measured) / sd */
	double start;            /* simulated at the start */
};

struct hb_fit_result {
	int np;
	char key[HB_FIT_MAX_FREE][48];
	double start[HB_FIT_MAX_FREE]; /* starting values, SI */
	double value[HB_FIT_MAX_FREE]; /* estimates, SI */
	double se[HB_FIT_MAX_FREE];    /* standard errors, SI (NAN when not identifiable) */
	double corr[HB_FIT_MAX_FREE * HB_FIT_MAX_FREE]; /* correlation matrix, row major */
	size_t npoints;
	struct hb_fit_point *point;    /* npoints entries (malloc'd) */
	double cost0, cost;         /* sum resid^2 at the start and at the end */
	int sd_scaled;              /* 1: standard errors scaled by cost / (N - P) */
	int iter;
	long runs;                  /* simulator runs used */
	/*
	 * Where the time went (measurements: they vary from run to run, the
	 * rest of the result does not): run_cpu, the CPU seconds of every run
	 * made, those run beside f that a rejected step wasted too; run_span,
	 * the wall time the same runs would take were each of the `threads`
	 * threads on a core of its own (run_cpu / run_span: the speed-up the
	 * threads allow, whatever else the machine is doing).
	 */
	double run_cpu, run_span;
	int threads;
	int reason;                 /* enum hb_fit_reason */
	double cond;                /* condition number of the scaled Jacobian */
	char unident[256];          /* "law.c, law.alpha" when not identifiable, else "" */
	char why[512];              /* the reason in words */
	struct hb_scene fitted;        /* the scene at the estimates */
	/*
	 * With hb_fit_options.numerical, once the fit has stopped (num_on 1):
	 * each estimate's numerical error, SI (how far it moves when the runs
	 * are made at num_rtol); NAN, with num_why saying why, when the
	 * tighter runs failed.  It should be well below the standard error
	 * (at most HB_FIT_NUM_RATIO of it), or the tolerance, not the data,
	 * limits the estimate.
	 */
	int num_on;
	double num_err[HB_FIT_MAX_FREE];
	double num_rtol;
	char num_why[256];
};

/* A short phrase for a reason ("converged (small step)" ...). */
const char *
hb_fit_reason_str(int reason);

/*
 * Fits: hb_fit_new, hb_fit_iterate until it returns 1, hb_fit_result_get, hb_fit_free.
 * Returns 0 when the fit ran (whatever the reason it stopped: see
 * r->reason; r->fitted holds the best point found); HB_EINVAL with a
 * message for bad input (unknown or derived key, a key given twice, more
 * keys than data points, a start out of range, a start at which a run
 * fails or gives no collision); HB_ENOMEM.  Call hb_fit_result_free(r) in
 * every case.
 */
int
hb_fit_run(const struct hb_scene *sc, const struct hb_fit_data *d, const struct hb_fit_options *o,
        struct hb_fit_result *r, char *msg, size_t n);

/*
 * The same in steps, for a front end that keeps drawing while it fits
 * (initialize / iterate / test, as GSL's solvers):
 *
 *     struct hb_fit *f = hb_fit_new(&scene, &data, &opts, msg, sizeof msg);
 *     while (f != NULL && !hb_fit_iterate(f))
 *             ... show progress, hb_fit_result_get(f, &r, ...) for the best so far ...
 *     hb_fit_result_get(f, &r, msg, sizeof msg);
 *     hb_fit_free(f);
 *
 * hb_fit_new checks the input and runs the start (NULL with a message as
 * hb_fit_run's errors); it copies the scene and borrows the data, which must
 * outlive it.  hb_fit_iterate does one trust-region iteration (1 + P or more
 * runs) and returns 1 once the fit has stopped (then it does nothing), 0
 * otherwise.  hb_fit_result_get fills *r at the best point so far (reason
 * HB_FIT_RUNNING before the fit has stopped); hb_fit_result_free(r) after.
 * hb_fit_free(NULL) does nothing.
 */
struct hb_fit;

struct hb_fit *
hb_fit_new(const struct hb_scene *sc, const struct hb_fit_data *d, const struct hb_fit_options *o,
        char *msg, size_t n);

int
hb_fit_iterate(struct hb_fit *f);

int
hb_fit_result_get(struct hb_fit *f, struct hb_fit_result *r, char *msg, size_t n);

void
hb_fit_free(struct hb_fit *f);

/*
 * The simulated observables of scene sc for the data's points, into
 * out[0 .. hb_fit_npoints(d)-1], in the order of fit_result.point.  Returns 0
 * or the failure of a run with a message.  jobs as in fit_options.
 */
int
hb_fit_simulate(const struct hb_scene *sc, const struct hb_fit_data *d, int jobs, double *out,
             char *msg, size_t n);

/* Number of data points (residuals) of the data. */
size_t
hb_fit_npoints(const struct hb_fit_data *d);

/*
 * The data points in the order of fit_result.point and hb_fit_simulate's
 * out: row, obs, trial, index, measured (for t_e the time since the
 * trial's first given impact) and sd (the weight's) of each, the rest 0,
 * into pt[0 .. hb_fit_npoints(d) - 1] (a front end that shows data beside
 * a run: missed values and trials are left out or told apart as the fit
 * does).  Returns the number of points.
 */
size_t
hb_fit_data_points(const struct hb_fit_data *d, struct hb_fit_point *pt);

void
hb_fit_result_free(struct hb_fit_result *r);

/*
 * What a reviewer asks of a fit, from its result (hb_fit_stats):
 *  - dof = N - P; chi2_red = cost / dof (NAN when dof < 1).
 *  - With stated noise (the data carry sd for every point: !sd_scaled),
 *    cost is a chi-square with dof degrees of freedom if the model is right
 *    and the sd are the noise: p_below = P(chi2 <= cost), p_above =
 *    P(chi2 >= cost); the noise is HB_FIT_NOISE_CONSISTENT unless a tail is
 *    below level / 2 (a two-sided test at `level`, e.g. 0.05).
 *  - AIC and BIC of least squares: with stated noise (known variance)
 *    aic = cost + 2P, bic = cost + P ln N (-2 ln L up to a constant of the
 *    data); without (unknown variance, estimated as cost / N)
 *    aic = N ln(cost / N) + 2P, bic = N ln(cost / N) + P ln N.  Either way
 *    the values compare models fitted to the same data, not across data.
 *  - t95: Student's t quantile 0.975 with dof degrees; the 95% interval of
 *    parameter i is value +- t95 se (NAN when dof < 1 or se is NAN).
 *  - at_bound[i]: -1 (+1) when the estimate reached the lower (upper)
 *    bound of its key's range: within 1e-6 of the start's distance to it.
 */
enum hb_fit_noise {
	HB_FIT_NOISE_UNSTATED = 0,  /* the data carry no sd (or dof < 1) */
	HB_FIT_NOISE_CONSISTENT,    /* the residuals are consistent with the sd */
	HB_FIT_NOISE_ABOVE,         /* larger: the model or the sd is wrong */
	HB_FIT_NOISE_BELOW,         /* smaller: the sd overstate the noise */
};

struct hb_fit_stats {
	size_t n;                 /* points */
	int p;                    /* free parameters */
	long dof;                 /* n - p */
	double cost, chi2_red;
	int noise_stated;         /* 1: weighted by the data's sd */
	double level;             /* of the chi-square test */
	double p_below, p_above;  /* the chi-square's tails at cost (NAN unstated) */
	int noise;                /* enum hb_fit_noise */
	double aic, bic;
	double t95;
	double lo95[HB_FIT_MAX_FREE], hi95[HB_FIT_MAX_FREE];
	double rel_se[HB_FIT_MAX_FREE]; /* se / |value| */
	int at_bound[HB_FIT_MAX_FREE];
};

/* Fills *s from r; returns 0, or HB_EINVAL for a level outside (0, 1) or np < 1. */
int
hb_fit_stats(const struct hb_fit_result *r, double level, struct hb_fit_stats *s);

/* "consistent", "residuals larger than the stated noise", ... */
const char *
hb_fit_noise_str(int noise);

/*
 * Value of a numeric scene key (the free keys of a fit).  Returns 0, or
 * HB_EINVAL naming the key and the keys accepted.
 */
int
hb_fit_key_get(const struct hb_scene *sc, const char *key, double *v, char *msg, size_t n);

HB_END_DECLS

#endif
