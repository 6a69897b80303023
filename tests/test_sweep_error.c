/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_sweep_error.c - a sweep with error bars (sweep.h: hb_sweep_set_error):
 * the spec line read back, the headers, and a point's block equal to the
 * plain run's collisions with hb_error_estimate's bars, to the byte.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "sweeptest.h"

Test(sweep_error, spec_line_and_headers)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl"), *back;
	struct hb_scene sc;
	char a[32768], b[32768], h[4096], msg[512];

	cr_assert_eq(hb_sweep_vary(sw, "law.c=1e9:2e9:3", msg, sizeof msg), HB_OK, "%s", msg);
	hb_sweep_spec_format(sw, a, sizeof a);
	cr_assert_null(strstr(a, "; sweep: --error"));
	hb_sweep_runs_header(sw, h, sizeof h);
	cr_assert_null(strstr(h, "_err"));
	hb_sweep_set_error(sw, 1);
	cr_assert(hb_sweep_error(sw));
	cr_assert_lt(hb_sweep_spec_format(sw, a, sizeof a), sizeof a);
	cr_assert(strstr(a, "\n; sweep: --vary law.c=1e9:2e9:3\n; sweep: --error\n"), "%s", a);
	hb_sweep_runs_header(sw, h, sizeof h);
	/* an error bar for each observable but the counts of work */
	cr_assert(strstr(h, ",jac,collisions_err,t_pc_err,e_first_err,") != NULL, "%s", h);
	cr_assert(strstr(h, ",x_c_end_err,leaving_err,cpu_s") != NULL, "%s", h);
	cr_assert_null(strstr(h, "steps_err"));
	cr_assert(!hb_error_observable(HB_OBS_RHS) && hb_error_observable(HB_OBS_E_FIRST));
	/* read back from the spec */
	cr_assert_eq(hb_preset_load_string(a, "spec", &sc, msg, sizeof msg), HB_OK, "%s", msg);
	back = hb_sweep_new(&sc, msg, sizeof msg);
	cr_assert_eq(hb_sweep_vary_from_preset(back, a, "spec", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert(!hb_sweep_error(back));
	hb_sweep_error_from_preset(back, a);
	cr_assert(hb_sweep_error(back));
	hb_sweep_spec_format(back, b, sizeof b);
	cr_assert_str_eq(a, b);
	/* a line that only starts so is not it */
	hb_sweep_set_error(back, 0);
	hb_sweep_error_from_preset(back, "; sweep: --errors\n; sweep: --error x\n");
	cr_assert(!hb_sweep_error(back));
	hb_sweep_free(back);
	hb_sweep_free(sw);
}

/* The block of a point: the plain run's collisions with hb_error_estimate's bars. */
Test(sweep_error, point_equals_the_estimate)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");
	struct hb_error_estimate est;
	struct hb_sim *s;
	char *blk, *coll = NULL, msg[512];
	size_t len = 0;
	int failed;
	FILE *f;

	cr_assert_eq(hb_sweep_vary(sw, "initial.x0=10um,30um", msg, sizeof msg), HB_OK);
	hb_sweep_set_error(sw, 1);
	cr_assert_eq(hb_sweep_point_block(sw, 1, &blk, &failed, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(failed, 0);
	s = plain_run_with("permanent-contact-shccl", "initial.x0", "30um");
	cr_assert_eq(hb_error_estimate(s, NULL, &est, msg, sizeof msg), HB_OK, "%s", msg);
	f = open_memstream(&coll, &len);
	cr_assert_eq(hb_csv_stream_collisions_err(f, s, &est, msg, sizeof msg), HB_OK);
	fclose(f);
	{
		const char *q;
		char want[64];

		cr_assert(hb_sim_ncollisions(s) > 0);
		q = block_has_collisions(blk, coll);
		cr_assert(strncmp(q, "r,1,", 4) == 0, "%s", q);
		/* the runs row holds the estimate's e_first error, as %.17g */
		snprintf(want, sizeof want, ",%.17g,", est.obs[HB_OBS_E_FIRST]);
		cr_assert(strstr(q, want) != NULL, "%s lacks %s", q, want);
	}
	free(coll);
	free(blk);
	hb_error_free(&est);
	hb_sim_free(s);
	hb_sweep_free(sw);
}
