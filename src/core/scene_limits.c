/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_limits.c - the tolerances at which each stepper is offered.
 *
 * Measured by `make bench-steppers` (tests/bench/steppers.sh, the table in
 * tests/bench/REPORT.md): each stepper's true global error against the
 * binary128 reference of tests/reference/ on the paper's studies, at rtol
 * 1e-6 ... 1e-12 (atol = rtol / 100).  rk8pd keeps its error proportional
 * to its tolerance; a stepper whose error is more than 10 times rk8pd's at
 * some measured tolerance is refused at that tolerance and every tighter
 * one, since its error does not fall with the tolerance as the tolerance
 * promises (at looser tolerances than measured it is accepted).  auto is
 * rk8pd on those studies; dop853 is within 10 x since its step control
 * uses the 5th-order error estimate (step_dop853.c).  run.limits = no lifts the refusal, to measure.
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"

#include "cnum.h"
#include "scene_keys.h"

struct limit {
	int stepper;
	double refused_at;  /* refused for rtol <= this; 0: never */
	const char *worst;  /* the measurement, for the message */
};

static const struct limit limits[] = {
	{ HB_STEPPER_RK8PD, 0, "" },
	{ HB_STEPPER_AUTO, 0, "" },
	{ HB_STEPPER_DOP853, 0, "" }, /* with its 5th-order estimate (step_dop853.c) */
	{ HB_STEPPER_RKF45, 1e-6, "33 x at rtol 1e-6, up to 920 x at 1e-10" },
	{ HB_STEPPER_RKCK, 1e-6, "50 x at rtol 1e-6, up to 280 x at 1e-10" },
	{ HB_STEPPER_MSBDF, 1e-6, "810 x at rtol 1e-6, up to 17,000 x at 1e-10" },
	{ HB_STEPPER_RK4IMP, 1e-7, "16 x at rtol 1e-7, up to 362 x at 1e-10" },
	{ HB_STEPPER_BSIMP, 1e-6, "a different number of collisions at rtol 1e-6, up to "
	                          "1,580 x at 1e-11" },
};

int
scene_check_stepper(const struct hb_scene *sc, struct hb_scene_error *err)
{
	const double rtol = sc->run.rtol;

	if (!sc->run.limits)
		return HB_OK;
	for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++) {
		const struct limit *l = &limits[i];
		char acc[192];

		if (l->stepper != sc->run.stepper || !(rtol <= l->refused_at))
			continue;
		cnum_snprintf(acc, sizeof acc, "%s with run.rtol > %g; rk8pd, auto or dop853 at any rtol; "
		         "or run.limits = no to run it anyway", hb_scene_stepper_name(l->stepper),
		         l->refused_at);
		return scene_error_set(err, "run.stepper", acc, "%s at run.rtol = %g is refused: its "
		                       "global error on the paper's studies is more than 10 x "
		                       "rk8pd's at rtol <= %g (%s; tests/bench/REPORT.md)",
		                       hb_scene_stepper_name(l->stepper), rtol, l->refused_at,
		                       l->worst);
	}
	return HB_OK;
}
