/* SPDX-License-Identifier: GPL-3.0-or-later */
/* control.c - the standard control, no growth after a rejection (see control.h). */
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "control.h"

struct cautious {
	gsl_odeiv2_control *inner; /* GSL's standard control */
	int rejected;              /* the last adjustment was a decrease */
};

static void *
cautious_alloc(void)
{
	struct cautious *c = calloc(1, sizeof *c);

	if (c == NULL)
		return NULL;
	c->inner = gsl_odeiv2_control_standard_new(1e-6, 1e-6, 1.0, 0.0); /* init sets the real values */
	return c;
}

static int
cautious_init(void *state, double eps_abs, double eps_rel, double a_y, double a_dydt)
{
	struct cautious *c = state;

	c->rejected = 0;
	return gsl_odeiv2_control_init(c->inner, eps_abs, eps_rel, a_y, a_dydt);
}

static int
cautious_hadjust(void *state, size_t dim, unsigned int ord, const double y[],
                 const double yerr[], const double yp[], double *h)
{
	struct cautious *c = state;
	double h0 = *h;
	int r = c->inner->type->hadjust(c->inner->state, dim, ord, y, yerr, yp, h);

	if (r == GSL_ODEIV_HADJ_INC && c->rejected) {
		*h = h0;
		r = GSL_ODEIV_HADJ_NIL;
	}
	c->rejected = r == GSL_ODEIV_HADJ_DEC;
	return r;
}

static int
cautious_errlevel(void *state, double y, double dydt, double h, size_t ind, double *errlev)
{
	struct cautious *c = state;

	return gsl_odeiv2_control_errlevel(c->inner, y, dydt, h, ind, errlev);
}

static int
cautious_set_driver(void *state, const gsl_odeiv2_driver *d)
{
	struct cautious *c = state;

	return gsl_odeiv2_control_set_driver(c->inner, d);
}

static void
cautious_free(void *state)
{
	struct cautious *c = state;

	if (c->inner)
		gsl_odeiv2_control_free(c->inner);
	free(c);
}

static const gsl_odeiv2_control_type cautious_type = {
	"standard, no growth after a rejection", cautious_alloc, cautious_init, cautious_hadjust,
	cautious_errlevel, cautious_set_driver, cautious_free,
};

int
hb_control_cautious(gsl_odeiv2_driver *d, double eps_abs, double eps_rel)
{
	gsl_odeiv2_control *c = gsl_odeiv2_control_alloc(&cautious_type);

	if (c == NULL || ((struct cautious *)c->state)->inner == NULL) {
		if (c)
			gsl_odeiv2_control_free(c);
		return -1;
	}
	if (gsl_odeiv2_control_init(c, eps_abs, eps_rel, 1.0, 0.0) != GSL_SUCCESS ||
	    gsl_odeiv2_control_set_driver(c, d) != GSL_SUCCESS) {
		gsl_odeiv2_control_free(c);
		return -1;
	}
	gsl_odeiv2_control_free(d->c);
	d->c = c;
	return 0;
}
