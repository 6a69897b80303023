/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_bsimp.h - GSL's bsimp (Bader-Deuflhard semi-implicit extrapolation)
 * applied to shifted variables.  Internal to the engine.
 */
#ifndef HYBOUNCE_STEP_BSIMP_H
#define HYBOUNCE_STEP_BSIMP_H

#include <gsl/gsl_odeiv2.h>

/*
 * bsimp on w = y + BSIMP_SHIFT.  GSL's bsimp rejects a sub-step whose
 * change, summed over the components, exceeds 100 dim times |y_i| (1 where
 * y_i = 0): a component that is round-off about zero (v at x_c^max, a
 * Bouc-Wen state starting to grow) makes every step fail, down to step
 * size underflow, or silently returns an infinite error estimate.  The
 * engine's variables are scaled to be of order 1, so the shift keeps every
 * weight of order 1; the state, the error estimate and the derivatives are
 * those of y.  The cost is the resolution of a component near zero: ulp of
 * the shift, about 1e-15 of the component's scale.
 */
#define BSIMP_SHIFT 4.0

extern const gsl_odeiv2_step_type *hb_step_bsimp_shifted;

#endif
