/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_stats.c - what a reviewer asks of a fit (fit.h, hb_fit_stats):
 * degrees of freedom, reduced chi-square and the chi-square test of the
 * stated noise, AIC and BIC, 95% intervals from Student's t, parameters at
 * a bound of their range.
 */
#include <math.h>
#include <string.h>

#include <gsl/gsl_cdf.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"

/* How close to a bound (relative to the start's distance from it) is "at" it. */
#define FIT_AT_BOUND 1e-6

/* -1 at the lower bound of key's range, +1 at the upper one, else 0. */
static int
at_bound(const struct hb_scene *sc, const char *key, double start, double v)
{
	struct hb_scene_keyinfo ki;
	double lo, hi;

	if (hb_scene_get(sc, key, &ki, NULL) != HB_OK)
		return 0;
	lo = ki.limits.lo;
	hi = ki.limits.hi;
	if (isfinite(lo) && start > lo && v - lo <= FIT_AT_BOUND * (start - lo))
		return -1;
	if (isfinite(hi) && start < hi && hi - v <= FIT_AT_BOUND * (hi - start))
		return 1;
	return 0;
}

int
hb_fit_stats(const struct hb_fit_result *r, double level, struct hb_fit_stats *s)
{
	double n, p, q;

	memset(s, 0, sizeof *s);
	if (!(level > 0 && level < 1) || r->np < 1 || r->np > HB_FIT_MAX_FREE)
		return HB_EINVAL;
	s->n = r->npoints;
	s->p = r->np;
	s->dof = (long)r->npoints - r->np;
	s->cost = r->cost;
	s->level = level;
	s->noise_stated = !r->sd_scaled;
	n = (double)s->n;
	p = (double)s->p;
	s->chi2_red = s->dof > 0 ? r->cost / (double)s->dof : NAN;
	s->p_below = s->p_above = NAN;
	s->noise = HB_FIT_NOISE_UNSTATED;
	if (s->noise_stated && s->dof > 0 && isfinite(r->cost)) {
		s->p_below = gsl_cdf_chisq_P(r->cost, (double)s->dof);
		s->p_above = gsl_cdf_chisq_Q(r->cost, (double)s->dof);
		s->noise = s->p_above < level / 2 ? HB_FIT_NOISE_ABOVE
		         : s->p_below < level / 2 ? HB_FIT_NOISE_BELOW : HB_FIT_NOISE_CONSISTENT;
	}
	if (s->noise_stated) {
		/* -2 ln L = cost + sum ln(2 pi sd^2): the sum is the data's, omitted */
		s->aic = r->cost + 2 * p;
		s->bic = r->cost + p * log(n);
	} else {
		/* the variance unknown, estimated as cost / N (its own +2 omitted) */
		s->aic = n * log(r->cost / n) + 2 * p;
		s->bic = n * log(r->cost / n) + p * log(n);
	}
	q = s->dof > 0 ? gsl_cdf_tdist_Pinv(0.975, (double)s->dof) : NAN;
	s->t95 = q;
	for (int i = 0; i < r->np; i++) {
		s->lo95[i] = r->value[i] - q * r->se[i];
		s->hi95[i] = r->value[i] + q * r->se[i];
		s->rel_se[i] = r->se[i] / fabs(r->value[i]);
		s->at_bound[i] = at_bound(&r->fitted, r->key[i], r->start[i], r->value[i]);
	}
	return HB_OK;
}

const char *
hb_fit_noise_str(int noise)
{
	switch (noise) {
	case HB_FIT_NOISE_CONSISTENT: return "consistent";
	case HB_FIT_NOISE_ABOVE:      return "residuals larger than the stated noise";
	case HB_FIT_NOISE_BELOW:      return "residuals smaller than the stated noise";
	default:                      return "no noise stated";
	}
}
