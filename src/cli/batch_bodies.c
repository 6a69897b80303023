/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_bodies.c - --bodies FILE (batch_bodies.h): one row per body at the
 * end of the run, numbered from the bottom as in a chain (docs/chains.md:
 * in a two-body scene body 1 is the scene's body 2, the lower one; on a
 * floor the one body is the scene's body 1):
 *
 *     # hybounce VERSION (commit C): COMMAND
 *     body,m,y,u,K
 *     1,0.032672563597333848,...
 *
 * SI units (kg, m, m/s, J), every value with 17 digits in the C locale; the
 * positions of a two-body scene are measured so that the gap is their
 * difference.  The summary's "body I" lines are the same numbers.
 */
#include <stdio.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/outputs.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"

#include "batch_bodies.h"
#include "report.h"
#include "cnum.h"
#include "csv_impl.h" /* csv_scene_path: the scene beside an export (src/core) */

int
batch_bodies_check(struct hb_outputs *pol, const char *path, const char *trace, const char *coll,
                   char *msg, size_t n)
{
	static char scene[4200]; /* borrowed by pol for the command's life */

	if (strcmp(path, "-") == 0) {
		hb_status_set(msg, n, HB_EINVAL, "--bodies -: the bodies' CSV goes to a file; "
		    "accepted: " HB_OUTPUTS_ACCEPTED);
		return -1;
	}
	if ((trace != NULL && hb_outputs_add(pol, trace, "--trace", msg, n) != HB_OK) ||
	    (coll != NULL && hb_outputs_add(pol, coll, "--collisions", msg, n) != HB_OK))
		return -1;
	if ((trace != NULL || coll != NULL) &&
	    csv_scene_path(trace != NULL ? trace : coll, scene, sizeof scene) == 0 &&
	    hb_outputs_add(pol, scene, "the scene saved beside the CSV", msg, n) != HB_OK)
		return -1;
	return hb_outputs_add(pol, path, "--bodies", msg, n) == HB_OK ? 0 : -1;
}

static void
fill(FILE *f, const void *ctx)
{
	const struct hb_sim *s = ctx;
	const char *prov = cli_provenance();
	int nb = hb_sim_nbodies(s);

	if (prov[0] == ';')     /* the preset comment, as a CSV comment */
		fprintf(f, "#%s\n", prov + 1);
	fprintf(f, "body,m,y,u,K\n");
	for (int i = 0; i < nb; i++) {
		struct hb_sim_body b;

		if (hb_sim_body(s, i, &b) != HB_OK)
			continue;
		cnum_fprintf(f, "%d,%.17g,%.17g,%.17g,%.17g\n", i + 1, b.m, b.y, b.u, 0.5 * b.m * b.u * b.u);
	}
}

int
batch_bodies_write(const struct hb_outputs *pol, const char *path, const struct hb_sim *s,
                   char *msg, size_t n)
{
	const struct hb_atomic_target *t = NULL;

	for (int i = 0; i < pol->nout; i++)
		if (pol->out[i].path == path)
			t = &pol->out[i].target;
	if (hb_atomic_write_with(path, fill, s, msg, n) != HB_OK)
		return -1;
	if (t != NULL)
		cli_print_wrote(path, t);
	else
		fprintf(stderr, "wrote %s\n", path);
	return 0;
}
