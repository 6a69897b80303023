/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * error.h - an error bar on every observable of a run: an estimate of its
 * global error (the integrator's, not the model's).
 *
 * How: the scene is run a second time with rk8pd at run.rtol / 100 and
 * run.atol / 100 (rtol never below HB_ERROR_RTOL_MIN), and each
 * observable's estimate is its difference from the first run, at least the
 * value's rounding (for a time, that of t, a sum of steps: sqrt(steps)
 * ulps of it).  The evidence for this choice, against the binary128
 * reference of tests/reference/ (study 1, the largest error over the
 * collisions; atol = rtol / 100):
 *
 *     stepper  rtol   true     same stepper at rtol/100   rk8pd at rtol/100
 *     rk8pd    1e-10  3.46e-9  3.42e-9                    3.42e-9
 *     dop853   1e-10  3.44e-8  3.13e-8                    3.44e-8
 *     (dop853 with the combined error estimate of dop853.f, since replaced)
 *     rkf45    1e-10  3.22e-7  3.17e-7                    3.22e-7
 *     msbdf    1e-12  1.20e-7  1.17e-7                    1.20e-7
 *
 * rk8pd's error is proportional to its tolerance, so the second run's own
 * error is about a hundredth of the first's whatever the first run's
 * stepper; the work-energy residual of hb_check_physics is 3 to 3,800
 * times below the true error and is no estimate.  tests/cli/error.sh holds
 * every error bar of the five paper studies within [0.5, 100] x the true
 * error where that is above 1e-13 (measured at the presets' tolerances:
 * 0.81 to 21).
 *
 *     struct hb_error_estimate e;
 *     if (hb_error_estimate(s, NULL, &e, msg, sizeof msg) == HB_OK) {
 *             const struct hb_collision *de = hb_error_find(&e, c->i);
 *             printf("e = %.9f +- %.1g\n", c->e, de->e);
 *             hb_error_free(&e);
 *     }
 *
 * The run observables (observables.h) get an estimate too, but for the
 * counts of work (steps, rejected, rhs, jac), which are NAN.
 */
#ifndef HB_ERROR_H
#define HB_ERROR_H
#include <stddef.h>

#include "collisions.h"
#include "columns.h"
#include "export.h"
#include "observables.h"
HB_BEGIN_DECLS

struct hb_sim;
struct hb_scene;

/* The second run's tolerances are the first's divided by this. */
#define HB_ERROR_TIGHTEN 100.0
/* ... but never below this (double precision). */
#define HB_ERROR_RTOL_MIN 1e-15
/* hb_error_check: an error bar may be this many times run.rtol (the
 * observables of a collision amplify the state's error: up to about 62x
 * on e of study 1's last collision). */
#define HB_ERROR_CHECK_FACTOR 100.0

struct hb_error_estimate {
	int stepper;          /* the second run's (HB_STEPPER_RK8PD) */
	double rtol, atol;    /* the second run's tolerances */
	int at_floor;         /* 1: rtol / 100 was below HB_ERROR_RTOL_MIN; the second
	                       * run is less than 100 times tighter, the estimate less sure */
	size_t ncoll;         /* the first run's kept completed collisions */
	/* One per kept completed collision of the first run, in its order: i and
	 * j as there, every double the absolute error of that observable (NAN
	 * where the second run has no collision i). */
	struct hb_collision *coll;
	double obs[HB_OBS_COUNT]; /* absolute error of each run observable; NAN: none */
	long other_total;     /* completed collisions of the second run */
	long other_rhs;       /* its right-hand side evaluations */
};

/*
 * Estimates the errors of the finished run s (see above).  stop may be
 * NULL; when *stop becomes non-zero during the second run the estimate is
 * abandoned and HB_EINVAL is returned with "interrupted" in msg.  Returns
 * HB_OK, or the second run's failure (HB_ENUMERIC ...; e is then empty)
 * with a message.  Free e with hb_error_free.
 */
int
hb_error_estimate(const struct hb_sim *s, const volatile int *stop,
                  struct hb_error_estimate *e, char *msg, size_t n);

/*
 * The same estimate in two halves, for a front end that runs the second
 * run itself (in slices, between frames): hb_error_scene gives the second
 * run's scene (sc with rk8pd at the tolerances / HB_ERROR_TIGHTEN, rtol
 * never below HB_ERROR_RTOL_MIN; *at_floor 1 when it was raised), and
 * hb_error_compare, once both the run s and the second run t of that scene
 * have ended, fills e as hb_error_estimate does (HB_ENUMERIC with a message
 * when t failed, HB_EINVAL when it has not ended).
 */
void
hb_error_scene(const struct hb_scene *sc, struct hb_scene *tight, int *at_floor);

int
hb_error_compare(const struct hb_sim *s, const struct hb_sim *t, struct hb_error_estimate *e,
                 char *msg, size_t n);

void
hb_error_free(struct hb_error_estimate *e);

struct hb_scene;

/*
 * Makes sc the scene of the estimate's second run: rk8pd, run.rtol and
 * run.atol divided by HB_ERROR_TIGHTEN, rtol never below
 * HB_ERROR_RTOL_MIN.  Returns 1 when that floor was hit (at_floor), else 0.
 * For a front end that makes its own tighter runs (hybounce fit: the
 * numerical error of its estimates).
 */
int
hb_error_tighten(struct hb_scene *sc);

/* 1 when the estimate gives run observable k (observables.h) an error bar;
 * 0 for the counts of work (steps, rejected, rhs, jac), always NAN. */
int
hb_error_observable(int k);

/* The error of collision i (its index, as hb_collision.i), or NULL. */
const struct hb_collision *
hb_error_find(const struct hb_error_estimate *e, long i);

/*
 * An error in the measure the check and the tests use: t_e and t_s
 * relative to the collision's t_d, x_c^r relative to its x_c^max, W
 * relative to the larger of |W| and |J_Fc v_i| (the collision's energy
 * scale: W is near 0 in an elastic one), every other value relative to
 * its own size.  NAN where there is none.
 */
double
hb_error_relative(const struct hb_collision *value, const struct hb_collision *err,
                  const struct hb_collision_column *col);

/*
 * The check of batch --check --error: every completed collision's
 * observables (the columns of columns.h) must have a relative error
 * (hb_error_relative) of at most HB_ERROR_CHECK_FACTOR x run.rtol, and
 * both runs the same number of collisions.  *worst gets the largest ratio
 * error / run.rtol.  Returns HB_OK, or HB_ENUMERIC with the first
 * offender (collision, observable, error, limit) in msg.
 */
int
hb_error_check(const struct hb_sim *s, const struct hb_error_estimate *e, double *worst,
               char *msg, size_t n);

HB_END_DECLS

#endif
