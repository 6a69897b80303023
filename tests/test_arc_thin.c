/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_arc_thin.c - memory stays bounded whatever J and T: the arc thins
 * jumps as it thins flow samples, the collision list is thinned the same
 * way, and the checker accepts exactly the jumps the arc says it thinned.
 * Short and bounded (the 60 s figure is measured outside make check).
 */
#include <math.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/arc.h"
#include "hybounce/check.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "arc_impl.h"
#include "testutil.h"

/* A sample of interval j: flight (q = 0) on even j, contact on odd. */
static struct hb_arc_sample
sample(double t, long j, int kind)
{
	struct hb_arc_sample s;

	memset(&s, 0, sizeof s);
	s.t = t;
	s.j = j;
	s.q = (int)(j % 2);
	s.kind = kind;
	s.x = 1e-9;
	return s;
}

/* The jump records list only jumps whose two intervals are both kept. */
static void
assert_consistent(const struct hb_arc *a)
{
	long gaps = 0;

	for (size_t k = 1; k < hb_arc_nintervals(a); k++) {
		const struct hb_arc_interval *p = hb_arc_interval_at(a, k - 1), *q = hb_arc_interval_at(a, k);

		cr_assert(q->j > p->j);
		cr_assert_eq(q->first, p->last + 1);
		gaps += q->j - p->j - 1;
	}
	cr_assert_eq(gaps, hb_arc_skipped(a), "%ld intervals missing, %ld recorded", gaps,
	    hb_arc_skipped(a));
	for (size_t r = 0; r < hb_arc_njumps(a); r++) {
		const struct hb_arc_jump *jp = hb_arc_jump_at(a, r);
		size_t i = hb_arc_find(a, jp->t, jp->j);

		cr_assert_eq(hb_arc_at(a, i)->j, jp->j, "jump %zu: its pre-jump sample is gone", r);
		cr_assert(i + 1 < hb_arc_len(a) && hb_arc_at(a, i + 1)->j == jp->j + 1,
		    "jump %zu (j = %ld): its post-jump sample is gone", r, jp->j);
	}
}

Test(arc_thin, an_arc_of_jumps_stays_within_its_bound)
{
	struct hb_arc *a = arc_new(1024);
	const long J = 200000;
	size_t peak = 0;

	cr_assert_not_null(a);
	for (long j = 0; j < J; j++) {
		struct hb_arc_sample s0 = sample((double)j, j, j ? HB_ARC_POST_JUMP : HB_ARC_START);
		struct hb_arc_sample s1 = sample((double)j + 0.5, j, HB_ARC_STEP);
		struct hb_arc_sample s2 = sample((double)j + 1, j, HB_ARC_PRE_JUMP);
		struct hb_arc_jump jr = { .t = (double)j + 1, .j = j };

		cr_assert_eq(arc_push(a, &s0), 0);
		cr_assert_eq(arc_push(a, &s1), 0);
		cr_assert_eq(arc_push(a, &s2), 0);
		if (j + 1 < J)
			cr_assert_eq(arc_push_jump(a, &jr), 0);
		if (hb_arc_bytes(a) > peak)
			peak = hb_arc_bytes(a);
	}
	/* 600,000 samples and 200,000 jumps pushed; at most 1024 samples' worth
	 * kept (capacity may round up to twice that). */
	cr_assert_leq(hb_arc_len(a), 1024);
	cr_assert_leq(peak, 2 * 1024 * sizeof(struct hb_arc_sample) + 4096 * 200,
	    "the arc grew to %zu bytes", peak);
	cr_assert_gt(hb_arc_skipped(a), J / 2, "jumps were not thinned: %ld", hb_arc_skipped(a));
	/* The first interval (t = 0) and the last one are kept. */
	cr_assert_eq(hb_arc_at(a, 0)->j, 0);
	cr_assert_eq(hb_arc_at(a, 0)->t, 0.0);
	cr_assert_eq(hb_arc_last(a)->j, J - 1);
	cr_assert_eq(hb_arc_last(a)->t, (double)J);
	/* The newest quarter keeps every jump. */
	cr_assert_eq(hb_arc_interval_at(a, hb_arc_nintervals(a) - 2)->j, J - 2);
	assert_consistent(a);
	/* Rewind keeps the record straight. */
	arc_truncate(a, hb_arc_len(a) / 2);
	assert_consistent(a);
	arc_free(a);
}

Test(arc_thin, a_lower_bound_later_thins_at_once)
{
	struct hb_arc *a = arc_new(1 << 16);

	for (long j = 0; j < 20000; j++) {
		struct hb_arc_sample s0 = sample((double)j, j, HB_ARC_POST_JUMP);
		struct hb_arc_sample s1 = sample((double)j + 1, j, HB_ARC_PRE_JUMP);

		arc_push(a, &s0);
		arc_push(a, &s1);
	}
	cr_assert_eq(hb_arc_skipped(a), 0, "thinned below its bound");
	arc_set_max(a, 1024);
	cr_assert_leq(hb_arc_len(a), 1024);
	assert_consistent(a);
	arc_free(a);
}

/* The elastic ball from 1 nm: a jump every few microseconds, J unbounded. */
static struct hb_sim *
bouncing(long steps)
{
	struct hb_scene sc;
	char msg[512];
	struct hb_sim *s;

	scene_preset("hertz-elastic", &sc);
	cr_assert_eq(hb_scene_set(&sc, "initial.x0", "1 nm", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "run.J", "1e18", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "run.T", "1e9", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "run.max_samples", "1024", msg, sizeof msg), HB_OK, "%s", msg);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(s, "%s", msg);
	cr_assert_eq(hb_sim_advance(s, steps, 0), HB_OK, "%s", hb_sim_errmsg(s));
	return s;
}

Test(arc_thin, bouncing_without_end_is_bounded_and_still_a_solution_pair)
{
	struct hb_sim *s = bouncing(60000);
	const struct hb_arc *a = hb_sim_arc(s);
	char msg[512] = "";
	long prev = -1;

	cr_assert_eq(hb_sim_end(s), HB_SIM_RUNNING);
	cr_assert_gt(hb_sim_stats(s)->jumps, 1000, "only %ld jumps", hb_sim_stats(s)->jumps);
	cr_assert_leq(hb_arc_len(a), 1024);
	cr_assert_gt(hb_arc_skipped(a), 0);
	/* The collision list: at most max_samples / 8 = 128 kept, each with its index. */
	cr_assert_leq(hb_sim_ncollisions(s), 128);
	cr_assert_gt(hb_sim_collisions_total(s), 500);
	for (size_t i = 0; i < hb_sim_ncollisions(s); i++) {
		cr_assert_gt(hb_sim_collision(s, i)->i, prev);
		prev = hb_sim_collision(s, i)->i;
	}
	cr_assert_eq(prev, hb_sim_collisions_total(s) - 1, "the newest collision is kept");
	cr_assert_eq(hb_check_solution_pair(hb_sim_scene(s), a, msg, sizeof msg), HB_OK, "%s", msg);
	hb_sim_free(s);
}

Test(arc_thin, the_checker_rejects_a_skip_the_arc_did_not_make)
{
	struct hb_scene sc;
	struct hb_arc *a = arc_new(1024);
	struct hb_arc_sample s0 = sample(0, 0, HB_ARC_START), s1, s2;
	char msg[256] = "";

	scene_preset("hertz-elastic", &sc);
	s0.x = 1e-3;
	s0.v = -1;
	s1 = s0;
	s1.t = 1e-3;
	s1.kind = HB_ARC_PRE_JUMP;
	s1.x = 0;
	s2 = s1;   /* j 0 -> 2: two jumps, nothing thinned */
	s2.j = 2;
	s2.kind = HB_ARC_POST_JUMP;
	arc_push(a, &s0);
	arc_push(a, &s1);
	arc_push(a, &s2);
	cr_assert_eq(hb_arc_skipped(a), 0);
	cr_assert_eq(hb_check_solution_pair(&sc, a, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "j goes from 0 to 2") != NULL, "%s", msg);
	arc_free(a);
}
