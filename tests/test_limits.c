/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_limits.c - the tolerances at which each stepper is offered
 * (src/core/scene_limits.c, measured by make bench-steppers): a stepper
 * whose global error on the paper's studies is more than 10 x rk8pd's is
 * refused at and below the tolerance where it was measured so, with a
 * message naming the stepper, the tolerance and what is accepted (vern98
 * only in the band where it was); rk8pd, auto and dop853 are offered at
 * every tolerance; run.limits = no lifts it.
 */
#include "hybounce/scene.h"
#include "testutil.h"

static int
validate(const char *stepper, double rtol, int limits, char *msg, size_t n)
{
	struct hb_scene sc;

	scene_preset("steel-on-bitumen", &sc);
	sc.run.stepper = hb_scene_stepper_find(stepper);
	cr_assert(sc.run.stepper >= 0, "%s", stepper);
	sc.run.rtol = rtol;
	sc.run.limits = limits;
	msg[0] = '\0';
	return hb_scene_validate(&sc, msg, n);
}

Test(limits, refused_with_what_is_accepted)
{
	char msg[1024];

	cr_assert_eq(validate("rkf45", 1e-12, 1, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "run.stepper: rkf45 at run.rtol = 1e-12 is refused") != NULL, "%s", msg);
	cr_assert(strstr(msg, "more than 10 x rk8pd's") != NULL, "%s", msg);
	cr_assert(strstr(msg, "accepted: rkf45 with run.rtol > 1e-06; rk8pd, auto or dop853 at any rtol; "
	                      "or run.limits = no") != NULL, "%s", msg);
}

Test(limits, each_stepper_where_it_is_offered)
{
	static const struct { const char *st; double ok, refused; } rows[] = {
		{ "rkf45", 1e-5, 1e-6 }, { "rkck", 1e-5, 1e-9 },
		{ "msbdf", 1e-3, 1e-12 }, { "bsimp", 1e-3, 1e-8 }, { "rk4imp", 3e-7, 1e-7 },
	};
	char msg[1024];

	for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
		cr_assert_eq(validate(rows[i].st, rows[i].ok, 1, msg, sizeof msg), HB_OK,
		             "%s at %g: %s", rows[i].st, rows[i].ok, msg);
		cr_assert_eq(validate(rows[i].st, rows[i].refused, 1, msg, sizeof msg), HB_EINVAL,
		             "%s at %g is refused", rows[i].st, rows[i].refused);
		cr_assert_eq(validate(rows[i].st, rows[i].refused, 0, msg, sizeof msg), HB_OK,
		             "%s at %g with run.limits = no: %s", rows[i].st, rows[i].refused, msg);
	}
	cr_assert_eq(validate("rk8pd", 1e-14, 1, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(validate("auto", 1e-14, 1, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(validate("dop853", 1e-14, 1, msg, sizeof msg), HB_OK, "%s", msg);
}

Test(limits, vern98_refused_in_a_band)
{
	static const double ok[] = { 1e-6, 1e-9, 1e-11, 1e-12, 1e-14 };
	static const double refused[] = { 8e-10, 1e-10, 3e-11 };
	char msg[1024];

	for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++)
		cr_assert_eq(validate("vern98", ok[i], 1, msg, sizeof msg), HB_OK, "at %g: %s", ok[i], msg);
	for (size_t i = 0; i < sizeof refused / sizeof refused[0]; i++) {
		cr_assert_eq(validate("vern98", refused[i], 1, msg, sizeof msg), HB_EINVAL, "at %g",
		             refused[i]);
		cr_assert_eq(validate("vern98", refused[i], 0, msg, sizeof msg), HB_OK, "%s", msg);
	}
	validate("vern98", 1e-10, 1, msg, sizeof msg);
	cr_assert(strstr(msg, "more than 10 x rk8pd's at 1e-11 < rtol <= 8e-10") != NULL, "%s", msg);
	cr_assert(strstr(msg, "accepted: vern98 with run.rtol > 8e-10 or <= 1e-11; rk8pd, auto or "
	                      "dop853 at any rtol") != NULL, "%s", msg);
}

Test(limits, the_key_reads_and_defaults_to_yes)
{
	struct hb_scene sc;
	char msg[512];

	scene_preset("steel-on-bitumen", &sc);
	cr_assert_eq(sc.run.limits, 1);
	cr_assert_eq(hb_scene_set(&sc, "run.limits", "no", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(sc.run.limits, 0);
}
