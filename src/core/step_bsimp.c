/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_bsimp.c - GSL's bsimp on shifted variables (see step_bsimp.h). */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "step_bsimp.h"
#include "step_common.h"

struct shifted {
	double *y;                    /* first (step_common.h): y for evaluations */
	gsl_odeiv2_step *inner;
	const gsl_odeiv2_system *sys; /* the system in y, during apply */
	gsl_odeiv2_system wsys;       /* the same system in w = y + shift */
	size_t dim;
};

static void
unshift(struct shifted *st, const double w[])
{
	size_t i;

	for (i = 0; i < st->dim; i++)
		st->y[i] = w[i] - BSIMP_SHIFT;
}

static int
wfunction(double t, const double w[], double dwdt[], void *params)
{
	struct shifted *st = params;

	unshift(st, w);
	return st->sys->function(t, st->y, dwdt, st->sys->params);
}

static int
wjacobian(double t, const double w[], double *dfdw, double dfdt[], void *params)
{
	struct shifted *st = params;

	unshift(st, w);
	return st->sys->jacobian(t, st->y, dfdw, dfdt, st->sys->params);
}

static void *
shifted_alloc(size_t dim)
{
	struct shifted *st = step_state_alloc(sizeof *st, 1, dim);

	if (st == NULL)
		return NULL;
	st->dim = dim;
	st->inner = gsl_odeiv2_step_alloc(gsl_odeiv2_step_bsimp, dim);
	if (st->inner == NULL) {
		step_state_free(st);
		return NULL;
	}
	st->wsys = (gsl_odeiv2_system){ wfunction, wjacobian, dim, st };
	return st;
}

static int
shifted_apply(void *state, size_t dim, double t, double h, double y[], double yerr[],
              const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
	struct shifted *st = state;
	size_t i;
	int rc;

	st->sys = sys;
	st->wsys.dimension = dim;
	for (i = 0; i < dim; i++)
		y[i] += BSIMP_SHIFT;
	rc = gsl_odeiv2_step_apply(st->inner, t, h, y, yerr, dydt_in, dydt_out, &st->wsys);
	for (i = 0; i < dim; i++)
		y[i] -= BSIMP_SHIFT;
	return rc;
}

static int
shifted_set_driver(void *state, const gsl_odeiv2_driver *d)
{
	struct shifted *st = state;

	return gsl_odeiv2_step_set_driver(st->inner, d);
}

static int
shifted_reset(void *state, size_t dim)
{
	struct shifted *st = state;

	(void)dim;
	return gsl_odeiv2_step_reset(st->inner);
}

static unsigned int
shifted_order(void *state)
{
	struct shifted *st = state;

	return gsl_odeiv2_step_order(st->inner);
}

static void
shifted_free(void *state)
{
	struct shifted *st = state;

	gsl_odeiv2_step_free(st->inner);
	step_state_free(st);
}

static const gsl_odeiv2_step_type shifted_type = {
	"bsimp", 1, 1, shifted_alloc, shifted_apply, shifted_set_driver,
	shifted_reset, shifted_order, shifted_free,
};

const gsl_odeiv2_step_type *hb_step_bsimp_shifted = &shifted_type;
