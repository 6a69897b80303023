/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_obs.c - the sweep view's observables: their units and the current
 * run's value, which the view (sweep_view.c) and its pane (pane_sweep.c)
 * both use.  Read only: calls no mode and no pane (tests/cli/calls.sh).
 */
#include <math.h>

#include "sweep_view.h"
#include "tui.h"

const char *
sv_obs_unit(int obs)
{
	if (obs >= HB_CURVE_RUN && obs < HB_CURVE_COUNT) /* the run observables' table */
		return hb_observables[obs - HB_CURVE_RUN].unit[0] ? hb_observables[obs - HB_CURVE_RUN].unit
		                                                  : NULL;
	switch (obs) {
	case HB_CURVE_VI: return "m/s";
	case HB_CURVE_XCR: return "m";
	default: return NULL;
	}
}

struct hb_unit_dim
sv_obs_dim(int obs)
{
	if (obs >= HB_CURVE_RUN && obs < HB_CURVE_COUNT)
		return *hb_observables[obs - HB_CURVE_RUN].dim;
	return obs == HB_CURVE_VI ? hb_unit_velocity : obs == HB_CURVE_XCR ? hb_unit_length
	                                                                  : hb_unit_none;
}

double
sv_current_y(const struct app *a, int obs, long coll)
{
	/* a value of collision i is final once it completed; the others once the run ended */
	if (obs != HB_CURVE_E && obs != HB_CURVE_VI && obs != HB_CURVE_XCR
	    && (hb_sim_end(a->sim) == HB_SIM_RUNNING || hb_sim_end(a->sim) == HB_SIM_END_FAIL))
		return NAN;
	return hb_sweep_observe(a->sim, obs, coll);
}
