/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_common.h - what the engine's own GSL odeiv2 step types share: their
 * state's allocation and release, the hooks with nothing to do, the orders
 * and the table.  Internal to the engine.
 *
 * A state made by step_state_alloc has as its first member the one block
 * that holds all its vectors (double *mem); step_state_free releases both.
 */
#ifndef HYBOUNCE_STEP_COMMON_H
#define HYBOUNCE_STEP_COMMON_H

#include <stddef.h>

#include <gsl/gsl_odeiv2.h>

/*
 * A zeroed state of size bytes whose first member, a double *, is set to a
 * zeroed block of nvec * dim doubles.  NULL when either allocation fails
 * (nothing is left allocated).
 */
void *
step_state_alloc(size_t size, size_t nvec, size_t dim);

/* Frees a state whose first member is its block (as step_state_alloc makes it). */
void
step_state_free(void *state);

/* The hooks of a step that keeps nothing from one step to the next and has no driver to know. */
int
step_reset_none(void *state, size_t dim);
int
step_set_driver_none(void *state, const gsl_odeiv2_driver *d);

/* The orders of the steps' solutions. */
unsigned int
step_order8(void *state);
unsigned int
step_order9(void *state);

/*
 * The table of a step type whose state is freed by step_state_free and
 * that needs no driver: its name, whether it can use dydt_in, whether it
 * gives an exact dydt_out (as GSL's gsl_odeiv2_step_type), and its hooks.
 */
#define STEP_TYPE(var, name, can_use_dydt_in, gives_exact_dydt_out, alloc, apply, reset, order) \
	static const gsl_odeiv2_step_type var = {                                                \
		name, can_use_dydt_in, gives_exact_dydt_out, alloc, apply,                     \
		step_set_driver_none, reset, order, step_state_free,                           \
	}

#endif
