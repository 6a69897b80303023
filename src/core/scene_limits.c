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
 * uses the 5th-order error estimate (step_dop853.c).  vern98 is within
 * 0.3 to 7.9 x rk8pd's error at every measured tolerance but one: on the
 * BWSHCCL study rk8pd's own error dips to 0.07-0.1 x rtol between rtol
 * 3e-10 and 3e-11 while vern98's stays at 2 to 4 x rtol, 16 to 67 x
 * rk8pd's at 8e-10, 3e-10, 1e-10 and 3e-11 (4 x at 1e-9, 2.3 x at 1e-11):
 * it is refused in that band only.  run.limits = no lifts the refusal, to measure.
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
	double again;       /* but offered again for rtol <= this; 0: never */
	const char *worst;  /* the measurement, for the message */
};

static const struct limit limits[] = {
	{ HB_STEPPER_RK8PD, 0, 0, "" },
	{ HB_STEPPER_AUTO, 0, 0, "" },
	{ HB_STEPPER_DOP853, 0, 0, "" }, /* with its 5th-order estimate (step_dop853.c) */
	{ HB_STEPPER_VERN98, 8e-10, 1e-11, "28 x at rtol 1e-10 on BWSHCCL, 16 to 67 x between "
	                                    "8e-10 and 3e-11; 4 x at 1e-9, 2.3 x at 1e-11" },
	{ HB_STEPPER_RKF45, 1e-6, 0, "33 x at rtol 1e-6, up to 920 x at 1e-10" },
	{ HB_STEPPER_RKCK, 1e-6, 0, "50 x at rtol 1e-6, up to 280 x at 1e-10" },
	{ HB_STEPPER_MSBDF, 1e-6, 0, "810 x at rtol 1e-6, up to 17,000 x at 1e-10" },
	{ HB_STEPPER_RK4IMP, 1e-7, 0, "16 x at rtol 1e-7, up to 362 x at 1e-10" },
	{ HB_STEPPER_BSIMP, 1e-6, 0, "a different number of collisions at rtol 1e-6, up to "
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
		char acc[192], band[64];

		if (l->stepper != sc->run.stepper || !(rtol <= l->refused_at) || rtol <= l->again)
			continue;
		if (l->again > 0) {
			cnum_snprintf(acc, sizeof acc, "%s with run.rtol > %g or <= %g; rk8pd, auto or "
			              "dop853 at any rtol; or run.limits = no to run it anyway",
			              hb_scene_stepper_name(l->stepper), l->refused_at, l->again);
			cnum_snprintf(band, sizeof band, "%g < rtol <= %g", l->again, l->refused_at);
		} else {
			cnum_snprintf(acc, sizeof acc, "%s with run.rtol > %g; rk8pd, auto or dop853 at any "
			              "rtol; or run.limits = no to run it anyway",
			              hb_scene_stepper_name(l->stepper), l->refused_at);
			cnum_snprintf(band, sizeof band, "rtol <= %g", l->refused_at);
		}
		return scene_error_set(err, "run.stepper", acc, "%s at run.rtol = %g is refused: its "
		                       "global error on the paper's studies is more than 10 x "
		                       "rk8pd's at %s (%s; tests/bench/REPORT.md)",
		                       hb_scene_stepper_name(l->stepper), rtol, band, l->worst);
	}
	return HB_OK;
}
