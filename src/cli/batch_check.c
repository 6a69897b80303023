/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_check.c - the check lines that end the batch report
 * (batch_report.h): with --check, the solution pair (check.h) and the
 * error bars of --error (error.h); always the physics, a chain's by
 * batch_chain_check.c, a failure a warning (exit 1 with --check).
 */
#include <stdio.h>

#include "hybounce/arc.h"
#include "hybounce/check.h"
#include "hybounce/error.h"
#include "hybounce/law.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"

#include "batch_chain_check.h"
#include "batch_report.h"

#define PROG "hybounce"

int
batch_print_checks(FILE *out, const struct hb_sim *s, int check,
                   const struct hb_error_estimate *est)
{
	char msg[4096];
	int failed = 0;

	if (check) {
		msg[0] = '\0';
		if (hb_check_solution_pair(hb_sim_scene(s), hb_sim_arc(s), msg, sizeof msg) == HB_OK) {
			fprintf(out, "  check       solution pair: ok (%zu samples, %zu jumps: "
			         "ordered domain, flow samples in C, pre-jump samples in D, "
			         "post-jump = g(pre-jump))\n",
			         hb_arc_len(hb_sim_arc(s)), hb_arc_njumps(hb_sim_arc(s)));
		} else {
			fprintf(out, "  check       solution pair: FAILED: %s\n", msg);
			if (out != stderr)
				fprintf(stderr, PROG ": check failed: %s\n", msg);
			failed = 1;
		}
	}
	if (check && est != NULL) {
		double worst;

		msg[0] = '\0';
		if (hb_error_check(s, est, &worst, msg, sizeof msg) == HB_OK) {
			fprintf(out, "  check       error bars: ok (the largest is %.2g x rtol; each "
			        "must be at most %g x rtol = %.3g, relative to its value; t_e and "
			        "t_s to t_d, x_c^r to x_c^max, W to |J_Fc v_i| where larger)\n",
			        worst, HB_ERROR_CHECK_FACTOR,
			        HB_ERROR_CHECK_FACTOR * hb_sim_scene(s)->run.rtol);
		} else {
			fprintf(out, "  check       error bars: FAILED: %s\n", msg);
			if (out != stderr)
				fprintf(stderr, PROG ": check failed: %s\n", msg);
			failed = 1;
		}
	}
	if (hb_sim_scene(s)->chain.n > 0) {
		/* a chain's physics, over its bodies and per interface */
		if (batch_chain_check(out, s, check))
			failed = 1;
	} else {
		/*
		 * The physics (check.h): a failure is a warning, and exit 1 with
		 * --check; a pass is said only when --check asks.
		 */
		struct hb_check_physics ph;

		msg[0] = '\0';
		if (hb_check_physics(hb_sim_scene(s), hb_sim_arc(s), &ph, msg, sizeof msg) == HB_OK) {
			if (check)
				fprintf(out, "  check       physics: ok (work-energy residual %.2g of the "
				        "energy scale, %.2g x the tolerance %.2g; %zu contacts: W and e "
				        "within what %s allows)\n", ph.resid, ph.resid / ph.tol, ph.tol,
				        ph.ncontacts, hb_sim_scene(s)->law->name);
		} else {
			fprintf(out, "  %-11s physics: %s: %s\n", check ? "check" : "warning",
			        check ? "FAILED" : "the run breaks what it must obey", msg);
			if (out != stderr) {
				char line[256];

				hb_check_physics_summary(&ph, line, sizeof line);
				fprintf(stderr, PROG ": %s: %s (see 'physics' in the report)\n",
				        check ? "check failed" : "warning", line);
			}
			if (check)
				failed = 1;
		}
		if (ph.nzero > 0)
			fprintf(out, "  note        collision %ld%s began at zero approach velocity "
			        "(v_i = %.3g m/s, an impact energy below what the tolerance "
			        "resolves): e = -v(t_s)/v_i means nothing there (\"-\" when v_i = 0); "
			        "what separates the bodies is the applied force\n", ph.zero_at,
			        ph.nzero > 1 ? " and others" : "", ph.vi_zero);
	}
	return failed;
}
