/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_arc.c - the hybrid arc (src/core/arc.c) on its own, with arcs built
 * by hand: the interval index, hybrid-time look-ups against a linear scan,
 * thinning under the memory bound (never a first or last sample of an
 * interval, never a jump), truncation, and the bound changed later.
 */
#include <string.h>

#include "arc_impl.h"
#include "testutil.h"

/*
 * Appends an arc of njumps + 1 flow intervals: interval j has per samples
 * evenly spaced over [j, j + 1) in t (closed at the end), alternating
 * flight and contact; each jump is recorded.  The pre-jump sample of
 * interval j and the post-jump sample of j + 1 share t = j + 1.
 */
static void
build(struct hb_arc *a, long njumps, int per)
{
	for (long j = 0; j <= njumps; j++) {
		for (int k = 0; k < per; k++) {
			struct hb_arc_sample s = { 0 };

			s.t = (double)j + (double)k / (per - 1);
			s.j = j;
			s.q = (int)(j % 2);
			s.kind = k == 0 ? (j == 0 ? HB_ARC_START : HB_ARC_POST_JUMP)
			                : k == per - 1 ? (j == njumps ? HB_ARC_END : HB_ARC_PRE_JUMP)
			                               : HB_ARC_STEP;
			s.x = (double)(j * per + k); /* the sample's number, to recognise it */
			cr_assert_eq(arc_push(a, &s), HB_OK);
		}
		if (j < njumps) {
			struct hb_arc_jump jr = { 0 };

			jr.t = (double)j + 1;
			jr.j = j;
			jr.from_q = (int)(j % 2);
			cr_assert_eq(arc_push_jump(a, &jr), HB_OK);
		}
	}
}

/* Hybrid-time order, the interval index and the jumps, checked against the samples. */
static void
check_invariants(const struct hb_arc *a)
{
	size_t n = hb_arc_len(a), k = 0;

	for (size_t i = 1; i < n; i++) {
		const struct hb_arc_sample *p = hb_arc_at(a, i - 1), *s = hb_arc_at(a, i);
		cr_assert(s->j == p->j ? s->t >= p->t : s->j == p->j + 1 && s->t == p->t,
		          "samples %zu, %zu out of hybrid-time order: (%g, %ld) then (%g, %ld)", i - 1,
		          i, p->t, p->j, s->t, s->j);
	}
	for (size_t i = 0; i < n; i++) {
		const struct hb_arc_interval *iv;

		if (i > 0 && hb_arc_at(a, i)->j != hb_arc_at(a, i - 1)->j)
			k++;
		iv = hb_arc_interval_at(a, k);
		cr_assert_not_null(iv, "no interval %zu for sample %zu", k, i);
		cr_assert(iv->first <= i && i <= iv->last && iv->j == hb_arc_at(a, i)->j,
		          "sample %zu not in interval %zu [%zu, %zu]", i, k, iv->first, iv->last);
		cr_assert_eq(hb_arc_interval_of(a, i), k, "arc_interval_of(%zu)", i);
	}
	cr_assert_eq(hb_arc_nintervals(a), n ? k + 1 : 0);
	for (k = 0; k < hb_arc_nintervals(a); k++) {
		const struct hb_arc_interval *iv = hb_arc_interval_at(a, k);
		cr_assert_eq(iv->q, hb_arc_at(a, iv->first)->q);
		cr_assert_eq(iv->t0, hb_arc_at(a, iv->first)->t);
		cr_assert_eq(iv->t1, hb_arc_at(a, iv->last)->t);
	}
	cr_assert_null(hb_arc_interval_at(a, hb_arc_nintervals(a)));
	/* each jump leads from an interval present to the next one */
	for (k = 0; k < hb_arc_njumps(a); k++)
		cr_assert(hb_arc_jump_at(a, k)->j + 1 <= hb_arc_last(a)->j, "jump %zu beyond the samples", k);
}

/* hb_arc_find by a linear scan: the last sample at or before (t, j), else 0. */
static size_t
find_scan(const struct hb_arc *a, double t, long j)
{
	size_t best = 0;

	for (size_t i = 0; i < hb_arc_len(a); i++) {
		const struct hb_arc_sample *s = hb_arc_at(a, i);
		if (s->j < j || (s->j == j && s->t <= t))
			best = i;
	}
	return best;
}

/* hb_arc_find_t by a linear scan: the last sample with t <= t, else 0. */
static size_t
find_t_scan(const struct hb_arc *a, double t)
{
	size_t best = 0;

	for (size_t i = 0; i < hb_arc_len(a); i++)
		if (hb_arc_at(a, i)->t <= t)
			best = i;
	return best;
}

Test(arc, empty)
{
	struct hb_arc *a = arc_new(0);

	cr_assert_not_null(a);
	cr_assert_eq(hb_arc_len(a), 0);
	cr_assert_null(hb_arc_at(a, 0));
	cr_assert_null(hb_arc_last(a));
	cr_assert_eq(hb_arc_nintervals(a), 0);
	cr_assert_null(hb_arc_interval_at(a, 0));
	cr_assert_eq(hb_arc_njumps(a), 0);
	cr_assert_null(hb_arc_jump_at(a, 0));
	cr_assert_eq(hb_arc_find(a, 1.0, 3), 0);
	cr_assert_eq(hb_arc_find_t(a, 1.0), 0);
	cr_assert_eq(hb_arc_thinned(a), 0);
	cr_assert(hb_arc_bytes(a) > 0);
	arc_truncate(a, 5); /* nothing to do */
	cr_assert_eq(hb_arc_len(a), 0);
	arc_free(a);
	arc_free(NULL);
}

Test(arc, intervals_index_the_samples)
{
	struct hb_arc *a = arc_new(100000);
	size_t bytes0 = hb_arc_bytes(a);

	build(a, 6, 5);
	cr_assert_eq(hb_arc_len(a), 35);
	cr_assert_eq(hb_arc_nintervals(a), 7);
	cr_assert_eq(hb_arc_njumps(a), 6);
	check_invariants(a);
	for (size_t k = 0; k < 7; k++) {
		const struct hb_arc_interval *iv = hb_arc_interval_at(a, k);
		cr_assert_eq(iv->j, (long)k);
		cr_assert_eq(iv->first, 5 * k);
		cr_assert_eq(iv->last, 5 * k + 4);
		cr_assert_eq(iv->q, (int)(k % 2));
		assert_abs(iv->t0, (double)k, 0);
		assert_abs(iv->t1, (double)k + 1, 0);
	}
	cr_assert_eq(hb_arc_last(a)->kind, HB_ARC_END);
	cr_assert_eq(hb_arc_jump_at(a, 5)->j, 5);
	cr_assert(hb_arc_bytes(a) > bytes0);
	cr_assert_eq(hb_arc_thinned(a), 0);
	arc_free(a);
}

/* Look-ups at every sample's time, between samples, at the jumps and outside. */
Test(arc, find_agrees_with_a_linear_scan)
{
	struct hb_arc *a = arc_new(100000);

	build(a, 5, 7);
	for (long j = -1; j <= 6; j++) {
		for (double t = -0.5; t <= 7.0; t += 1.0 / 12) {
			cr_assert_eq(hb_arc_find(a, t, j), find_scan(a, t, j), "arc_find(%g, %ld)", t, j);
			cr_assert_eq(hb_arc_find_t(a, t), find_t_scan(a, t), "arc_find_t(%g)", t);
		}
	}
	/* at a jump instant: (t, j) is the pre-jump sample, (t, j + 1) the post-jump one */
	cr_assert_eq(hb_arc_at(a, hb_arc_find(a, 2.0, 1))->kind, HB_ARC_PRE_JUMP);
	cr_assert_eq(hb_arc_at(a, hb_arc_find(a, 2.0, 2))->kind, HB_ARC_POST_JUMP);
	/* by t alone, the greatest j at that t */
	cr_assert_eq(hb_arc_at(a, hb_arc_find_t(a, 2.0))->j, 2);
	cr_assert_eq(hb_arc_find(a, 1e9, 1000), hb_arc_len(a) - 1);
	arc_free(a);
}

/* Many samples in few intervals: thinned under the bound, ends of intervals kept. */
Test(arc, thinning_keeps_the_ends_of_every_interval)
{
	struct hb_arc *a = arc_new(1024);
	const long njumps = 9;
	const int per = 2000;

	build(a, njumps, per);
	cr_assert(hb_arc_thinned(a) > 0);
	cr_assert(hb_arc_len(a) <= 1024, "%zu samples over the bound 1024", hb_arc_len(a));
	cr_assert(hb_arc_len(a) >= 512, "thinned too much: %zu samples", hb_arc_len(a));
	cr_assert_eq(hb_arc_nintervals(a), (size_t)njumps + 1);
	cr_assert_eq(hb_arc_njumps(a), (size_t)njumps);
	check_invariants(a);
	for (long j = 0; j <= njumps; j++) {
		const struct hb_arc_interval *iv = hb_arc_interval_at(a, (size_t)j);
		/* the first and last samples pushed for interval j are still its ends */
		assert_abs(hb_arc_at(a, iv->first)->x, (double)(j * per), 0);
		assert_abs(hb_arc_at(a, iv->last)->x, (double)(j * per + per - 1), 0);
		cr_assert(iv->last > iv->first);
	}
	arc_free(a);
}

/* Intervals of two samples (jumps only) cannot be thinned: the bound grows. */
/*
 * An arc of jumps alone (two samples per interval) cannot be thinned
 * sample by sample: past its bound it loses whole old intervals, each with
 * both of its samples, so memory stays bounded; the first interval and the
 * newest ones stay whole and the samples stay in hybrid-time order.
 */
Test(arc, jumps_alone_are_thinned_whole_intervals_at_a_time)
{
	struct hb_arc *a = arc_new(1024);

	build(a, 1499, 2);
	cr_assert_lt(hb_arc_len(a), 1024, "%zu samples kept of 3000", hb_arc_len(a));
	cr_assert_gt(hb_arc_skipped(a), 0);
	cr_assert_eq(hb_arc_len(a), 2 * hb_arc_nintervals(a), "every kept interval keeps both samples");
	cr_assert_eq(hb_arc_nintervals(a) + (size_t)hb_arc_skipped(a), 1500);
	assert_abs(hb_arc_at(a, 0)->x, 0, 0);
	assert_abs(hb_arc_at(a, hb_arc_len(a) - 1)->x, 2999, 0);
	for (size_t i = 0; i < hb_arc_len(a); i++) {
		const struct hb_arc_sample *s = hb_arc_at(a, i);

		/* sample k of interval j is number 2j + k */
		assert_abs(s->x, (double)(2 * s->j + (long)(i % 2)), 0);
		if (i > 0)
			cr_assert(s->j > hb_arc_at(a, i - 1)->j || (i % 2 == 1 && s->j == hb_arc_at(a, i - 1)->j),
			          "sample %zu: j = %ld after %ld", i, s->j, hb_arc_at(a, i - 1)->j);
	}
	/* the newest quarter is whole: the last 100 intervals are all there */
	for (long j = 1400; j < 1500; j++)
		cr_assert_eq(hb_arc_at(a, hb_arc_len(a) - 2 * (size_t)(1500 - j))->j, j);
	arc_free(a);
}

Test(arc, truncate_keeps_a_prefix_and_its_jumps)
{
	struct hb_arc *a = arc_new(100000);

	build(a, 6, 5);
	arc_truncate(a, 100); /* beyond the end: nothing changes */
	cr_assert_eq(hb_arc_len(a), 35);
	cr_assert_eq(hb_arc_njumps(a), 6);

	arc_truncate(a, 17); /* into interval 3 (samples 15..19) */
	cr_assert_eq(hb_arc_len(a), 17);
	cr_assert_eq(hb_arc_nintervals(a), 4);
	cr_assert_eq(hb_arc_interval_at(a, 3)->last, 16);
	cr_assert_eq(hb_arc_njumps(a), 3, "the jumps into intervals 1, 2, 3 remain");
	check_invariants(a);

	arc_truncate(a, 15); /* just the post-jump sample of interval 3 is gone */
	cr_assert_eq(hb_arc_nintervals(a), 3);
	cr_assert_eq(hb_arc_njumps(a), 2);
	check_invariants(a);

	/* the run goes on from the truncated arc */
	{
		struct hb_arc_sample s = *hb_arc_last(a);
		struct hb_arc_jump jr = { .t = s.t, .j = s.j };
		s.j++;
		s.x = -1;
		cr_assert_eq(arc_push_jump(a, &jr), HB_OK);
		cr_assert_eq(arc_push(a, &s), HB_OK);
	}
	cr_assert_eq(hb_arc_nintervals(a), 4);
	cr_assert_eq(hb_arc_njumps(a), 3);
	check_invariants(a);

	arc_truncate(a, 0);
	cr_assert_eq(hb_arc_len(a), 0);
	cr_assert_eq(hb_arc_nintervals(a), 0);
	cr_assert_eq(hb_arc_njumps(a), 0);
	arc_free(a);
}

Test(arc, lowering_the_bound_thins_at_once)
{
	struct hb_arc *a = arc_new(1 << 20);
	size_t n0;

	build(a, 3, 3000);
	n0 = hb_arc_len(a);
	cr_assert_eq(n0, 12000);
	cr_assert_eq(hb_arc_thinned(a), 0);
	arc_set_max(a, 2000);
	cr_assert(hb_arc_len(a) <= 2000, "%zu samples over the new bound", hb_arc_len(a));
	cr_assert(hb_arc_thinned(a) > 0);
	check_invariants(a);
	for (long j = 0; j <= 3; j++) {
		const struct hb_arc_interval *iv = hb_arc_interval_at(a, (size_t)j);
		assert_abs(hb_arc_at(a, iv->first)->x, (double)(j * 3000), 0);
		assert_abs(hb_arc_at(a, iv->last)->x, (double)(j * 3000 + 2999), 0);
	}
	/* a bound below the floor of 1024 samples means 1024 */
	arc_set_max(a, 10);
	cr_assert(hb_arc_len(a) <= 1024 && hb_arc_len(a) >= 512, "%zu samples", hb_arc_len(a));
	check_invariants(a);
	/* raising the bound keeps everything */
	n0 = hb_arc_len(a);
	arc_set_max(a, 1 << 20);
	cr_assert_eq(hb_arc_len(a), n0);
	arc_free(a);
}
