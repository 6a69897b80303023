/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * physics.c - the physics checks of the current run (check.h), the same
 * that the batch report runs: once the run has ended, the work-energy
 * identity, passivity and restitution are checked; a failure goes to the
 * message line and the log (which check, which collision), and the
 * collisions that break what the law allows are marked in the table.
 * Forgotten whenever the run computes again.
 */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "status.h"
#include "term.h"
#include "tui.h"

void
physics_forget(struct app *a)
{
	free(a->phys.flags);
	memset(&a->phys, 0, sizeof a->phys);
}

void
physics_run(struct app *a)
{
	const struct hb_scene *sc = hb_sim_scene(a->sim);
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	struct hb_check_physics r;
	char msg[2048], line[256];
	size_t n = hb_sim_ncollisions(a->sim);

	physics_forget(a);
	a->phys.valid = 1;
	if (hb_check_physics(sc, arc, &r, msg, sizeof msg) == HB_OK)
		return;
	a->phys.failed = r.failed;
	if (n > 0) {
		a->phys.flags = calloc(n, 1);
		if (a->phys.flags == NULL)
			term_oom();
		a->phys.nflags = n;
	}
	a->phys.nbad = hb_check_physics_flags(sc, arc, &r, a->phys.flags, a->phys.nflags);
	hb_check_physics_summary(&r, line, sizeof line);
	/* one log line per failed check: "; "-separated (check.h) */
	for (char *p = msg, *q; p != NULL && *p; p = q) {
		q = strstr(p, "; ");
		if (q != NULL) {
			*q = 0;
			q += 2;
		}
		app_msg(a, 1, "physics check failed: %s", p);
	}
	app_msg(a, 1, "physics: %s (m: which check, which collision)", line);
}

unsigned
physics_flag(const struct app *a, long i)
{
	if (!a->phys.valid || a->phys.flags == NULL || i < 0 || (size_t)i >= a->phys.nflags)
		return 0;
	return a->phys.flags[i];
}
