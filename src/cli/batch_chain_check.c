/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_chain_check.c - the physics lines of a chain's batch report
 * (check.h, hb_check_chain): its energy balance and momentum, each
 * contact by its own interface's law, and the model limits passed.
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/check.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"

#include "batch_chain_check.h"

#define PROG "hybounce"

int
batch_chain_check(FILE *out, const struct hb_sim *s, int check)
{
	struct hb_check_chain r;
	char msg[1400];
	int rc = hb_check_chain(s, &r, msg, sizeof msg);

	if (rc == 0 && check) {
		fprintf(out, "  check       physics: ok (%zu contacts, each by its interface's law: W "
		        "within what the law allows; e of the %zu with no neighbour in contact)\n",
		        r.ncontacts, r.nisolated);
		if (isnan(r.eresid))
			fprintf(out, "  check       energy, momentum: not checked (the run failed)\n");
		else {
			fprintf(out, "  check       energy: ok (K %.9g J + absorbed by the interfaces "
			        "%.9g J (stored %.9g J, dissipated %.9g J) = K(0) %.9g J + work of "
			        "the loads %.9g J, to %.2g of the largest, %.2g x the tolerance "
			        "%.2g)\n", r.kinetic, r.absorbed, r.stored, r.dissipated, r.kinetic0,
			        r.loads, r.eresid, r.eresid / r.tol, r.tol);
			if (r.momentum)
				fprintf(out, "  check       momentum: ok (%.12g kg m/s = %.12g at t = 0 "
				        "+ the loads' impulse %.6g, to %.2g of the largest, %.2g x the "
				        "tolerance)\n", r.p, r.p0, r.impulse, r.presid, r.presid / r.tol);
			else
				fprintf(out, "  check       momentum: not an identity (the floor takes "
				        "momentum)\n");
		}
	} else if (rc != 0) {
		fprintf(out, "  %-11s physics: %s: %s\n", check ? "check" : "warning",
		        check ? "FAILED" : "the run breaks what it must obey", msg);
		fprintf(stderr, PROG ": %s: the computed chain fails %d physics check%s; a tighter "
		        "run.rtol and run.atol, or another run.stepper, should fix it (see 'physics' "
		        "in the report)\n", check ? "check failed" : "warning", r.failed,
		        r.failed == 1 ? "" : "s");
	}
	if (check && r.limits > 0)
		fprintf(out, "  check       model limits: passed %ld time%s under run.chain_limits = "
		        "warn (the computation is not at fault; the model's assumptions are "
		        "stretched there): the first: %s\n", r.limits, r.limits == 1 ? "" : "s",
		        r.limnote);
	return rc != 0 && check;
}
