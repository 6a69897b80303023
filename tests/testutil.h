/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * testutil.h - helpers shared by every Criterion test file (tests/test_*.c):
 * the paper's presets, where presets are, loading and running a scene,
 * reading a file, and comparisons of numbers with their tolerance stated.
 * Each helper fails the test with a message that names what went wrong.
 */
#ifndef HYBOUNCE_TESTUTIL_H
#define HYBOUNCE_TESTUTIL_H

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <criterion/criterion.h>

#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"

/* The presets of the paper's studies (presets/NAME.preset), NULL-terminated. */
static const char *const paper_presets[] = {
	"steel-on-bitumen", "ptfe-pom", "permanent-contact-shccl", "permanent-contact-bwshccl",
	"permanent-contact-bwmcl", "nonunique-rest", "nonunique-separation", "hertz-elastic", NULL,
};
#define NPAPER_PRESETS (sizeof paper_presets / sizeof paper_presets[0] - 1)

/* The preset folder: $HYBOUNCE_PRESETS when it names one folder, else presets/. */
static inline const char *
preset_dir(void)
{
	const char *e = getenv("HYBOUNCE_PRESETS");

	if (e != NULL && e[0] != '\0' && strchr(e, ':') == NULL)
		return e;
	return "presets";
}

/* The whole file, NUL-terminated, malloc'd (free it); fails the test if unreadable. */
static inline char *
slurp(const char *path)
{
	FILE *f = fopen(path, "rb");
	char *buf;
	long len;

	cr_assert(f != NULL, "%s: %s (run the tests from the repository root)", path, strerror(errno));
	fseek(f, 0, SEEK_END);
	len = ftell(f);
	fseek(f, 0, SEEK_SET);
	cr_assert(len >= 0, "%s: not a regular file", path);
	buf = malloc((size_t)len + 1);
	cr_assert_not_null(buf);
	cr_assert(fread(buf, 1, (size_t)len, f) == (size_t)len, "%s: short read", path);
	buf[len] = '\0';
	fclose(f);
	return buf;
}

/*
 * x agrees with the printed value to the digits printed: |x - printed| is
 * at most half a unit in the last printed place.
 */
static inline void
printed(double x, double value, int sig, const char *what)
{
	double ulp = pow(10, floor(log10(fabs(value))) - (sig - 1));

	cr_assert(fabs(x - value) <= 0.5 * ulp, "%s = %.6e, the paper prints %.*e", what, x,
	    sig - 1, value);
}

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

/* The value of the scene's law parameter NAME; fails the test if the law has none. */
static inline double
scene_par(const struct hb_scene *sc, const char *name)
{
	int i = hb_law_param_index(sc->law, name);

	cr_assert(i >= 0, "%s has no parameter %s", sc->law->name, name);
	return sc->par[i];
}

/*
 * The derived values the paper prints for its second study (PTFE on POM,
 * Table tab:two), checked to the digits printed.
 */
static inline void
study2_printed(const struct hb_scene *sc)
{
	cr_assert_eq(sc->d.system, HB_SCENE_FULL);
	printed(sc->d.Estar, 5.321e8, 4, "E*");
	printed(sc->d.Re, 10e-3, 2, "R_e");
	printed(sc->d.m1, 7.372e-2, 4, "m1");
	printed(sc->d.m2, 4.725e-2, 4, "m2");
	printed(sc->d.m, 2.879e-2, 4, "m");
	printed(sc->d.eta, 0.6094, 4, "eta");
	printed(scene_par(sc, "k"), 7.095e7, 4, "k");
}

/* Loads a scene from INI text; fails the test on error. */
static inline void
scene_from(const char *ini, struct hb_scene *sc)
{
	char msg[1024];

	cr_assert_eq(hb_preset_load_string(ini, "test.preset", sc, msg, sizeof msg), 0, "%s", msg);
}

/* Loads a preset file by name from preset_dir(). */
static inline void
scene_preset(const char *name, struct hb_scene *sc)
{
	char path[512], msg[1024];

	snprintf(path, sizeof path, "%s/%s.preset", preset_dir(), name);
	cr_assert_eq(hb_preset_load(path, sc, msg, sizeof msg), 0, "%s", msg);
}

/* Runs a scene to its end; fails the test if the run fails. */
static inline struct hb_sim *
run_scene(const struct hb_scene *sc)
{
	char msg[1024];
	struct hb_sim *s = hb_sim_new(sc, msg, sizeof msg);

	cr_assert_not_null(s, "sim_new: %s", msg);
	cr_assert_eq(hb_sim_run(s), 0, "run failed: %s", hb_sim_errmsg(s));
	cr_assert_eq(hb_sim_end(s), HB_SIM_END_T, "run ended: %s", hb_sim_end_str(s));
	return s;
}

static inline struct hb_sim *
run_ini(const char *ini)
{
	struct hb_scene sc;

	scene_from(ini, &sc);
	return run_scene(&sc);
}

/*
 * Steel balls (R 10 mm) in a chain: LAW between them with LAWKEYS (a [law]
 * section's lines, "" for none), the [chain] lines CHAIN, the top ball
 * struck at v (m/s), gravity g (m/s^2), run for T (s) at rtol 1e-12, atol
 * 1e-14.  Fails the test on error.
 */
static inline void
steel_chain(struct hb_scene *sc, const char *law, const char *lawkeys, const char *chain, double v,
            double g, double T)
{
	char ini[2048];

	snprintf(ini, sizeof ini,
	         "[scene]\nname = chain\nlaw = %s\n"
	         "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n%s%s"
	         "[chain]\n%s\n[striker]\nv = %.17g\n[loads]\ng = %.17g\n"
	         "[run]\nT = %.17g\nrtol = 1e-12\natol = 1e-14\n",
	         law, *lawkeys ? "[law]\n" : "", lawkeys, chain, v, g, T);
	scene_from(ini, sc);
}

/*
 * Relative tolerances of a comparison of two runs' collisions, a field
 * each (0: that field is not compared).
 */
struct coll_tol {
	double te, td, vi, e, xcmax, Fcmax;
};

/* Run got has as many collisions as run want, each the same within tol. */
static inline void
assert_collisions_match(const struct hb_sim *got, const struct hb_sim *want, struct coll_tol tol)
{
	cr_assert_eq(hb_sim_ncollisions(got), hb_sim_ncollisions(want));
	for (size_t i = 0; i < hb_sim_ncollisions(got); i++) {
		const struct hb_collision *a = hb_sim_collision(got, i), *b = hb_sim_collision(want, i);

		if (tol.te > 0)
			assert_rel(a->te, b->te, tol.te);
		if (tol.td > 0)
			assert_rel(a->td, b->td, tol.td);
		if (tol.vi > 0)
			assert_rel(a->vi, b->vi, tol.vi);
		if (tol.e > 0)
			assert_rel(a->e, b->e, tol.e);
		if (tol.xcmax > 0)
			assert_rel(a->xcmax, b->xcmax, tol.xcmax);
		if (tol.Fcmax > 0)
			assert_rel(a->Fcmax, b->Fcmax, tol.Fcmax);
	}
}

#endif
