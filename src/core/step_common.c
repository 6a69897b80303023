/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_common.c - what the engine's GSL step types share (see step_common.h). */
#include <stdlib.h>

#include <gsl/gsl_errno.h>

#include "step_common.h"

void *
step_state_alloc(size_t size, size_t nvec, size_t dim)
{
	void *st = calloc(1, size);
	double *mem;

	if (st == NULL)
		return NULL;
	mem = calloc(nvec * dim, sizeof *mem);
	if (mem == NULL) {
		free(st);
		return NULL;
	}
	*(double **)st = mem;
	return st;
}

void
step_state_free(void *state)
{
	free(*(double **)state);
	free(state);
}

int
step_reset_none(void *state, size_t dim)
{
	(void)state;
	(void)dim;
	return GSL_SUCCESS;
}

int
step_set_driver_none(void *state, const gsl_odeiv2_driver *d)
{
	(void)state;
	(void)d;
	return GSL_SUCCESS;
}

unsigned int
step_order8(void *state)
{
	(void)state;
	return 8;
}

unsigned int
step_order9(void *state)
{
	(void)state;
	return 9;
}
