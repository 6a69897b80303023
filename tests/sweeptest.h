/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweeptest.h - helpers of the sweep tests (test_sweep.c,
 * test_sweep_error.c): a sweep over a preset, the plain run that one of
 * its points must equal, and a point's block checked against that run's
 * collision table.  Each fails the test with a message that names what
 * went wrong.
 */
#ifndef HYBOUNCE_SWEEPTEST_H
#define HYBOUNCE_SWEEPTEST_H

#include <stdio.h>
#include <string.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "testutil.h"

/* A sweep over the shipped preset NAME (no axes yet). */
static inline struct hb_sweep *
sweep_of(const char *preset)
{
	struct hb_scene sc;
	char msg[512];
	struct hb_sweep *sw;

	scene_preset(preset, &sc);
	sw = hb_sweep_new(&sc, msg, sizeof msg);
	cr_assert_not_null(sw, "%s", msg);
	return sw;
}

/* The plain run of preset NAME with KEY = VALUE, run to its end (hb_sim_free it). */
static inline struct hb_sim *
plain_run_with(const char *preset, const char *key, const char *value)
{
	struct hb_scene sc;
	struct hb_sim *s;
	char msg[512];

	scene_preset(preset, &sc);
	cr_assert_eq(hb_scene_set(&sc, key, value, msg, sizeof msg), HB_OK);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(s);
	hb_sim_run(s);
	return s;
}

/*
 * Asserts that block blk begins with the rows of collision table csv (a
 * header line, then rows) as point 1's "c,1,ROW" lines, to the byte;
 * returns where the block goes on after them.
 */
static inline const char *
block_has_collisions(const char *blk, const char *csv)
{
	const char *p = strchr(csv, '\n') + 1, *q = blk;
	char line[8192];

	while (*p) {
		const char *e = strchr(p, '\n');

		snprintf(line, sizeof line, "c,1,%.*s\n", (int)(e - p), p);
		cr_assert_eq(strncmp(q, line, strlen(line)), 0, "block '%.60s' vs '%s'", q, line);
		q += strlen(line);
		p = e + 1;
	}
	return q;
}

#endif
