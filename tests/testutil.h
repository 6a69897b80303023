/* testutil.h - helpers shared by the engine's Criterion tests. */
#ifndef HYBOUNCE_TESTUTIL_H
#define HYBOUNCE_TESTUTIL_H

#include <math.h>
#include <stdio.h>
#include <criterion/criterion.h>

#include "hybounce/preset.h"
#include "hybounce/sim.h"

/* |a - b| <= tol |b| */
#define assert_rel(a, b, tol)                                                              \
	do {                                                                               \
		double a_ = (a), b_ = (b), t_ = (tol);                                     \
		cr_assert(fabs(a_ - b_) <= t_ * fabs(b_),                                 \
		          "%s = %.17g, expected %.17g (relative error %.3g > %.3g)", #a, a_, \
		          b_, fabs(a_ - b_) / fabs(b_), t_);                               \
	} while (0)

/* |a - b| <= tol */
#define assert_abs(a, b, tol)                                                              \
	do {                                                                               \
		double a_ = (a), b_ = (b), t_ = (tol);                                     \
		cr_assert(fabs(a_ - b_) <= t_, "%s = %.17g, expected %.17g (error %.3g > %.3g)", \
		          #a, a_, b_, fabs(a_ - b_), t_);                                  \
	} while (0)

/* Loads a scene from INI text; fails the test on error. */
static inline void
scene_from(const char *ini, struct scene *sc)
{
	char msg[1024];

	cr_assert_eq(preset_load_string(ini, "test.preset", sc, msg, sizeof msg), 0, "%s", msg);
}

/* Loads a preset file by name from presets/. */
static inline void
scene_preset(const char *name, struct scene *sc)
{
	char path[512], msg[1024];

	snprintf(path, sizeof path, "presets/%s.preset", name);
	cr_assert_eq(preset_load(path, sc, msg, sizeof msg), 0, "%s", msg);
}

/* Runs a scene to its end; fails the test if the run fails. */
static inline struct sim *
run_scene(const struct scene *sc)
{
	char msg[1024];
	struct sim *s = sim_new(sc, msg, sizeof msg);

	cr_assert_not_null(s, "sim_new: %s", msg);
	cr_assert_eq(sim_run(s), 0, "run failed: %s", sim_errmsg(s));
	cr_assert_eq(sim_end(s), SIM_END_T, "run ended: %s", sim_end_str(s));
	return s;
}

static inline struct sim *
run_ini(const char *ini)
{
	struct scene sc;

	scene_from(ini, &sc);
	return run_scene(&sc);
}

#endif
