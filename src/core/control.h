/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * control.h - GSL's standard step-size control, without growth right after
 * a rejected step.  Internal to the engine.
 */
#ifndef HYBOUNCE_CONTROL_H
#define HYBOUNCE_CONTROL_H

#include <gsl/gsl_odeiv2.h>

/*
 * Replaces the control of driver d (made by gsl_odeiv2_driver_alloc_*) by
 * the standard control with the same eps_abs, eps_rel, a_y = 1, a_dydt = 0,
 * wrapped so that the step that follows a rejection is never lengthened
 * (Hairer, Norsett and Wanner, Solving ODE I, section II.4: after a
 * rejected step the growth factor is capped at 1).  GSL's own control
 * lengthens it as soon as the error allows, which near a point of low
 * smoothness (the start or end of a contact, F_c ~ |x_c|^p) gives a
 * rejection at almost every step.  Returns 0, or -1 on no memory.
 */
int
hb_control_cautious(gsl_odeiv2_driver *d, double eps_abs, double eps_rel);

#endif
