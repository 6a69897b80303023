/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_error.c - error bars (error.h): the estimate of a finished run
 * covers every kept completed collision and every run observable but the
 * counts of work, is never below a value's rounding, measures t_e against
 * t_d, and its check passes the presets' tolerance and fails a stepper
 * whose global error is far beyond it (msbdf on study 1).  Its agreement
 * with the true error is tests/cli/error.sh, against tests/reference.
 */
#include <float.h>
#include <math.h>

#include "hybounce/error.h"
#include "testutil.h"

Test(error, covers_every_collision_and_observable)
{
	struct hb_scene sc;
	struct hb_error_estimate e;
	struct hb_sim *s;
	char msg[512];
	double worst;

	scene_preset("permanent-contact-shccl", &sc);
	s = run_scene(&sc);
	cr_assert_eq(hb_error_estimate(s, NULL, &e, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(e.stepper, HB_STEPPER_RK8PD);
	cr_assert_float_eq(e.rtol, sc.run.rtol / 100, 1e-30);
	cr_assert_eq(e.at_floor, 0);
	cr_assert_eq(e.ncoll, hb_sim_ncollisions(s));
	cr_assert_eq(e.other_total, hb_sim_collisions_total(s));
	for (size_t k = 0; k < hb_sim_ncollisions(s); k++) {
		const struct hb_collision *c = hb_sim_collision(s, k), *d = hb_error_find(&e, c->i);

		cr_assert_not_null(d, "collision %ld has error bars", c->i);
		for (int j = 0; j < hb_collision_ncolumns; j++) {
			const struct hb_collision_column *col = &hb_collision_columns[j];
			double v, b;

			if (col->index)
				continue;
			v = hb_collision_value(c, col);
			b = hb_collision_value(d, col);
			if (isnan(v))
				continue;
			cr_assert(b >= 2 * DBL_EPSILON * fabs(v), "collision %ld %s: bar %g below the "
			          "rounding of %g", c->i, col->name, b, v);
		}
		/* t_e relative to t_d */
		cr_assert_float_eq(hb_error_relative(c, d, hb_collision_column_find("t_e")),
		                   d->te / c->td, 1e-30);
	}
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		int work = k == HB_OBS_STEPS || k == HB_OBS_REJECTED || k == HB_OBS_RHS ||
		           k == HB_OBS_JAC;

		cr_assert_eq(isnan(e.obs[k]), work || isnan(hb_observable_value(s, k)),
		             "observable %s", hb_observables[k].name);
	}
	cr_assert_eq(hb_error_check(s, &e, &worst, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert(worst > 0 && worst <= HB_ERROR_CHECK_FACTOR, "worst %g x rtol", worst);
	cr_assert_null(hb_error_find(&e, 1000));
	hb_error_free(&e);
	cr_assert_null(e.coll);
	hb_error_free(&e); /* twice is harmless */
	hb_sim_free(s);
}

Test(error, check_fails_a_stepper_beyond_its_tolerance)
{
	struct hb_scene sc;
	struct hb_error_estimate e;
	struct hb_sim *s;
	char msg[512];
	double worst;

	scene_preset("steel-on-bitumen", &sc);
	sc.run.stepper = HB_STEPPER_MSBDF;
	sc.run.limits = 0; /* msbdf at 1e-12: refused otherwise */
	s = run_scene(&sc);
	cr_assert_eq(hb_error_estimate(s, NULL, &e, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_error_check(s, &e, &worst, msg, sizeof msg), HB_ENUMERIC);
	cr_assert(worst > HB_ERROR_CHECK_FACTOR, "worst %g x rtol", worst);
	cr_assert(strstr(msg, "above 100 x rtol") != NULL, "%s", msg);
	hb_error_free(&e);
	hb_sim_free(s);
}

Test(error, stops_when_asked)
{
	struct hb_scene sc;
	struct hb_error_estimate e;
	struct hb_sim *s;
	char msg[512];
	const volatile int stop = 1;

	scene_preset("permanent-contact-bwmcl", &sc);
	s = run_scene(&sc);
	cr_assert_eq(hb_error_estimate(s, &stop, &e, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "interrupted") != NULL, "%s", msg);
	cr_assert_null(e.coll);
	hb_sim_free(s);
}

Test(error, tolerance_floor)
{
	struct hb_scene sc;
	struct hb_error_estimate e;
	struct hb_sim *s;
	char msg[512];

	scene_preset("permanent-contact-bwmcl", &sc);
	sc.run.rtol = 1e-14;
	s = run_scene(&sc);
	cr_assert_eq(hb_error_estimate(s, NULL, &e, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(e.at_floor, 1);
	cr_assert_float_eq(e.rtol, HB_ERROR_RTOL_MIN, 1e-30);
	hb_error_free(&e);
	hb_sim_free(s);
}

Test(error, halves_give_the_whole_estimate)
{
	struct hb_scene sc, tight;
	struct hb_error_estimate e, h;
	struct hb_sim *s, *t;
	char msg[512];
	int at_floor = -1;

	scene_preset("steel-on-bitumen", &sc);
	s = run_scene(&sc);
	cr_assert_eq(hb_error_estimate(s, NULL, &e, msg, sizeof msg), HB_OK, "%s", msg);
	hb_error_scene(&sc, &tight, &at_floor);
	cr_assert_eq(at_floor, 0);
	cr_assert_eq(tight.run.stepper, HB_STEPPER_RK8PD);
	cr_assert_float_eq(tight.run.rtol, sc.run.rtol / HB_ERROR_TIGHTEN, 1e-30);
	t = hb_sim_new(&tight, msg, sizeof msg);
	cr_assert_not_null(t, "%s", msg);
	/* not ended: refused */
	cr_assert_eq(hb_error_compare(s, t, &h, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "has not ended") != NULL, "%s", msg);
	/* the second run in small slices, as the explorer runs it between frames */
	while (hb_sim_end(t) == HB_SIM_RUNNING)
		cr_assert(hb_sim_advance(t, 0, 0.003) == HB_OK || hb_sim_end(t) != HB_SIM_RUNNING);
	cr_assert_eq(hb_error_compare(s, t, &h, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(h.ncoll, e.ncoll);
	cr_assert_eq(h.at_floor, e.at_floor);
	cr_assert_eq(h.other_total, e.other_total);
	for (size_t k = 0; k < e.ncoll; k++)
		cr_assert(memcmp(&h.coll[k], &e.coll[k], sizeof h.coll[k]) == 0, "collision %zu", k);
	for (int k = 0; k < HB_OBS_COUNT; k++)
		cr_assert(memcmp(&h.obs[k], &e.obs[k], sizeof h.obs[k]) == 0, "observable %d", k);
	hb_error_free(&h);
	hb_error_free(&e);
	/* the floor */
	sc.run.rtol = 1e-14;
	hb_error_scene(&sc, &tight, &at_floor);
	cr_assert_eq(at_floor, 1);
	cr_assert_float_eq(tight.run.rtol, HB_ERROR_RTOL_MIN, 1e-30);
	hb_sim_free(t);
	hb_sim_free(s);
}
