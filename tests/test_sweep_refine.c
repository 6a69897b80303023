/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_sweep_refine.c - refinement (hb_sweep_refine): the lattice is the
 * uniform sweep FROM:TO:M to the bit and holds the grid every 2^L values,
 * the spec round-trips with its --refine line, bad specs are refused, and
 * the explorer's curve locates a boundary where the lattice puts it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "testutil.h"

static struct hb_sweep *
sweep_with(const struct hb_scene *sc, const char *a1, const char *a2)
{
	char msg[512];
	struct hb_sweep *sw = hb_sweep_new(sc, msg, sizeof msg);

	cr_assert_not_null(sw, "%s", msg);
	hb_sweep_set_max_points(sw, 10000000L, NULL);   /* the dense comparison sweep */
	cr_assert_eq(hb_sweep_vary(sw, a1, msg, sizeof msg), HB_OK, "%s", msg);
	if (a2 != NULL)
		cr_assert_eq(hb_sweep_vary(sw, a2, msg, sizeof msg), HB_OK, "%s", msg);
	return sw;
}

static void
restitution(struct hb_scene *sc)
{
	char msg[512], path[4096];

	/* the example beside the presets (a fresh clone: presets/../examples) */
	snprintf(path, sizeof path, "%s/../examples/sweeps/restitution-shccl.preset", preset_dir());
	cr_assert_eq(hb_preset_load(path, sc, msg, sizeof msg), HB_OK, "%s", msg);
}

Test(sweep_refine, lattice_is_the_uniform_sweep_to_the_bit)
{
	struct hb_scene sc;
	struct hb_sweep *r, *u;
	char msg[512], a[64], b[64];

	restitution(&sc);
	r = sweep_with(&sc, "initial.v0=-1mm/s:-1m/s:21:log", "law.c=1e9:1e10:5");
	cr_assert_eq(hb_sweep_refine(r, "e_first:1e-3", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert(hb_sweep_refined(r));
	/* 20 * 2^6 >= 1000 and 4 * 2^6 >= 1000 is not: 4 * 2^8 = 1024, so L = 8 for both */
	u = sweep_with(&sc, "initial.v0=-1mm/s:-1m/s:5121:log", "law.c=1e9:1e10:1025");
	cr_assert_eq(hb_sweep_npoints(r), 5121L * 1025);
	cr_assert_eq(hb_sweep_npoints(r), hb_sweep_npoints(u));
	for (long id = 0; id < hb_sweep_npoints(r); id += 7919)
		for (int k = 0; k < 2; k++) {
			hb_sweep_point_value(r, id, k, a, sizeof a);
			hb_sweep_point_value(u, id, k, b, sizeof b);
			cr_assert_str_eq(a, b, "point %ld axis %d", id, k);
		}
	/* the grid of the spec: every 256th value, the same doubles as the 21 and 5 values */
	hb_sweep_free(u);
	u = sweep_with(&sc, "initial.v0=-1mm/s:-1m/s:21:log", "law.c=1e9:1e10:5");
	for (long i = 0; i < 21; i++)
		for (long j = 0; j < 5; j++) {
			hb_sweep_point_value(r, (i * 256) * 1025 + j * 256, 0, a, sizeof a);
			hb_sweep_point_value(u, i * 5 + j, 0, b, sizeof b);
			cr_assert_str_eq(a, b);
			hb_sweep_point_value(r, (i * 256) * 1025 + j * 256, 1, a, sizeof a);
			hb_sweep_point_value(u, i * 5 + j, 1, b, sizeof b);
			cr_assert_str_eq(a, b);
		}
	cr_assert_eq(hb_sweep_check(r, msg, sizeof msg), HB_OK, "%s", msg);
	hb_sweep_free(r);
	hb_sweep_free(u);
}

Test(sweep_refine, spec_round_trips_and_refusals)
{
	struct hb_scene sc, back_sc;
	struct hb_sweep *r, *back;
	char msg[512], *a, *b;
	size_t l;

	restitution(&sc);
	r = sweep_with(&sc, "initial.v0=-1mm/s:-1m/s:21:log", NULL);
	cr_assert_eq(hb_sweep_refine(r, "e_first<0.5:0.01", msg, sizeof msg), HB_OK, "%s", msg);
	l = hb_sweep_spec_format(r, NULL, 0);
	a = malloc(l + 1);
	hb_sweep_spec_format(r, a, l + 1);
	cr_assert(strstr(a, "\n; sweep: --refine e_first<0.5:0.01\n") != NULL, "%s", a);
	cr_assert_eq(hb_preset_load_string(a, "spec", &back_sc, msg, sizeof msg), HB_OK, "%s", msg);
	back = hb_sweep_new(&back_sc, msg, sizeof msg);
	cr_assert_eq(hb_sweep_vary_from_preset(back, a, "spec", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sweep_refine_from_preset(back, a, "spec", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sweep_npoints(back), hb_sweep_npoints(r));
	b = malloc(l + 1);
	hb_sweep_spec_format(back, b, l + 1);
	cr_assert_str_eq(a, b);
	/* a --vary after --refine, a second --refine */
	cr_assert_eq(hb_sweep_vary(back, "law.c=1e9:1e10:3", msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "before --refine") != NULL, "%s", msg);
	cr_assert_eq(hb_sweep_refine(back, "collisions", msg, sizeof msg), HB_EINVAL);
	free(a);
	free(b);
	hb_sweep_free(back);
	hb_sweep_free(r);

	/* refusals: each names what is accepted */
	{
		static const char *const bad[][3] = {
			{ "initial.v0=-1mm/s:-1m/s:21:log", "nosuch", "accepted: collisions, t_pc" },
			{ "initial.v0=-1mm/s:-1m/s:21:log", "e_first:0", "between 0 and 1" },
			{ "initial.v0=-1mm/s:-1m/s:21:log", "e_first<:0.1", "threshold" },
			{ "initial.v0=-1mm/s:-1m/s:21:log", "e_first:1e-9", "accepted: a TOL" },
			{ "initial.v0=-1mm/s,-2mm/s", "e_first", "FROM:TO:N" },
			{ "initial.v0=-1mm/s:-2mm/s:1", "e_first", "N >= 2" },
		};

		for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
			r = sweep_with(&sc, bad[i][0], NULL);
			cr_assert_eq(hb_sweep_refine(r, bad[i][1], msg, sizeof msg), HB_EINVAL, "%s",
			             bad[i][1]);
			cr_assert(strstr(msg, bad[i][2]) != NULL, "%s: %s", bad[i][1], msg);
			cr_assert(!hb_sweep_refined(r));
			hb_sweep_free(r);
		}
	}
}

/* The curve's boundary: between the lattice's points 243 and 244 (tests/cli/sweep_refine.sh). */
Test(sweep_refine, curve_locates_the_boundary, .timeout = 60)
{
	struct hb_scene sc;
	struct hb_sweep_curve *c;
	struct hb_sweep *u;
	double lo[4], hi[4];
	int located[4] = { 0 };
	char msg[512], a[64];
	long nb;

	restitution(&sc);
	c = hb_sweep_curve_start_refined(&sc, "initial.v0", "-1mm/s:-1m/s:21:log", HB_CURVE_E, 0,
	                                 1e-3, 2, msg, sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	while ((nb = hb_sweep_curve_boundaries(c, lo, hi, located, 4)) < 1 || !located[0] ||
	       hb_sweep_curve_poll(c, NULL, NULL, NULL, 0) < 21)
		nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
	cr_assert_eq(nb, 1);
	u = sweep_with(&sc, "initial.v0=-1mm/s:-1m/s:1281:log", NULL);
	hb_sweep_point_value(u, 243, 0, a, sizeof a);
	cr_assert_eq(lo[0], strtod(a, NULL), "%.17g %s", lo[0], a);
	hb_sweep_point_value(u, 244, 0, a, sizeof a);
	cr_assert_eq(hi[0], strtod(a, NULL), "%.17g %s", hi[0], a);
	hb_sweep_curve_free(c);
	hb_sweep_free(u);
	/* a list has no lattice; freeing a refining curve cancels it */
	cr_assert_null(hb_sweep_curve_start_refined(&sc, "initial.v0", "-1mm/s,-2mm/s", HB_CURVE_E,
	                                            0, 1e-3, 1, msg, sizeof msg));
	c = hb_sweep_curve_start_refined(&sc, "initial.v0", "-1mm/s:-1m/s:21:log", HB_CURVE_E, 0,
	                                 1e-3, 2, msg, sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	hb_sweep_curve_free(c);
}
