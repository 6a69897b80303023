/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_input.c - the input of "hybounce sweep" (sweep_cmd.h): the preset,
 * read once, with the --set values; the axes of --vary and of the preset's
 * '; sweep:' lines, the bound on the points, --error and --refine.  Bad
 * input is refused here, before anything runs.
 */
#include <stdio.h>
#include <stdlib.h>

#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"

#include "sweep_cmd.h"
#include "report.h"

#define PROG "hybounce sweep"

/* A refusal (report.h): "hybounce sweep: ...", then where usage is. */
#define bad(...) cli_refuse_usage(PROG, PROG, __VA_ARGS__)

/*
 * The preset, the --set values and the axes; NULL after printing why (exit
 * 2).  check: every point's scene checked now (--emit, which writes jobs
 * and runs none); a sweep that runs checks each point once, in its run
 * (hb_sim_new), and is refused with the same message.
 */
struct hb_sweep *
sweep_build(const char *preset, const char *const *sets, int nsets,
            const char *const *varies, int nvaries, const char *out, long max_points,
            const char *refine, int error, int check)
{
	char path[4096], spec[4200], msg[4096], more[128];
	struct hb_scene sc;
	struct hb_sweep *sw;
	char *text = NULL;

	msg[0] = '\0';
	/* Read once (a pipe or FIFO works), bounded; the scene and the axes come from it. */
	if (hb_preset_open_text(preset, sets, nsets, &sc, path, sizeof path, &text, msg,
	                        sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg[0] ? msg : preset);
		return NULL;
	}
	sw = hb_sweep_new(&sc, msg, sizeof msg);
	if (sw == NULL) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		return NULL;
	}
	/*
	 * Work bounded: at most max_points unless asked for.  The folder's own
	 * sweep.preset (a shard of --emit, a resume) was allowed when it was made.
	 */
	snprintf(spec, sizeof spec, "%s/sweep.preset", out);
	if (max_points == 0 && hb_outputs_same_file(path, spec))
		max_points = 1000000000L;
	snprintf(more, sizeof more, "--max-points N allows up to N (at most 1000000000)");
	hb_sweep_set_max_points(sw, max_points ? max_points : HB_SWEEP_MAX_POINTS, more);
	msg[0] = '\0';
	if (hb_sweep_vary_from_preset(sw, text, path, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		hb_sweep_free(sw);
		return NULL;
	}
	for (int i = 0; i < nvaries; i++) {
		msg[0] = '\0';
		if (hb_sweep_vary(sw, varies[i], msg, sizeof msg) != HB_OK) {
			fprintf(stderr, PROG ": %s\n", msg);
			free(text);
			hb_sweep_free(sw);
			return NULL;
		}
	}
	/* --error: the command line's, or the preset's line */
	hb_sweep_error_from_preset(sw, text);
	if (error)
		hb_sweep_set_error(sw, 1);
	/* --refine after every axis: the command line's, else the preset's line */
	msg[0] = '\0';
	if (hb_sweep_npoints(sw) > 0 &&
	    (refine != NULL ? hb_sweep_refine(sw, refine, msg, sizeof msg)
	                    : hb_sweep_refine_from_preset(sw, text, path, msg, sizeof msg)) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		free(text);
		hb_sweep_free(sw);
		return NULL;
	}
	free(text);
	if (hb_sweep_npoints(sw) == 0) {
		bad("nothing to vary: expected --vary KEY=SPEC (e.g. --vary "
		    "law.c=1e8:1e10:20:log), or a preset with '; sweep: --vary' lines");
		hb_sweep_free(sw);
		return NULL;
	}
	msg[0] = '\0';
	if (check && hb_sweep_check(sw, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, PROG ": %s\n", msg);
		hb_sweep_free(sw);
		return NULL;
	}
	return sw;
}
