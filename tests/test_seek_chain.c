/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_seek_chain.c - a chain's run continued from one of its samples
 * (sim.h: hb_sim_seek, src/core/sim_seek.c): after the seek the arc ends
 * at that sample, and the run continued from there is the straight run,
 * its samples, jump records and collision table bit for bit.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/status.h"
#include "testutil.h"

/* Two doubles to the bit (NaN included); two ints or longs. */
#define SAME_D(a, b) (memcmp(&(a), &(b), sizeof(double)) == 0)
#define SAME_I(a, b) ((a) == (b))

/* Two samples field by field, to the bit (a struct's padding is not compared). */
static int
same_sample(const struct hb_arc_sample *a, const struct hb_arc_sample *b)
{
	int ok = SAME_D(a->t, b->t) && SAME_I(a->j, b->j) && SAME_I(a->q, b->q) && SAME_I(a->kind, b->kind)
	         && SAME_D(a->x, b->x) && SAME_D(a->v, b->v) && SAME_D(a->xc, b->xc) && SAME_D(a->Fc, b->Fc)
	         && SAME_D(a->Fer, b->Fer) && SAME_D(a->xm, b->xm) && SAME_D(a->vm, b->vm)
	         && SAME_D(a->W, b->W) && SAME_D(a->JFc, b->JFc) && SAME_D(a->JFe, b->JFe)
	         && SAME_D(a->xcmax, b->xcmax) && SAME_D(a->Fcmax, b->Fcmax) && SAME_D(a->Ee, b->Ee)
	         && SAME_D(a->Wc, b->Wc) && SAME_I(a->k, b->k);

	for (int i = 0; i < HB_LAW_MAX_Z; i++)
		ok = ok && SAME_D(a->z[i], b->z[i]);
	return ok;
}

static int
same_jump(const struct hb_arc_jump *a, const struct hb_arc_jump *b)
{
	return SAME_D(a->t, b->t) && SAME_I(a->j, b->j) && SAME_I(a->from_q, b->from_q) &&
	       a->left == b->left && SAME_I(a->how, b->how) && SAME_I(a->iterations, b->iterations) &&
	       SAME_D(a->width, b->width) && SAME_D(a->ind_lo, b->ind_lo) && SAME_D(a->ind_hi, b->ind_hi);
}

static int
same_collision(const struct hb_collision *a, const struct hb_collision *b)
{
	return SAME_I(a->i, b->i) && SAME_I(a->j, b->j) && SAME_D(a->te, b->te) && SAME_D(a->ts, b->ts) &&
	       SAME_D(a->td, b->td) && SAME_D(a->tf, b->tf) && SAME_D(a->vi, b->vi) && SAME_D(a->e, b->e) &&
	       SAME_D(a->xcmax, b->xcmax) && SAME_D(a->Fcmax, b->Fcmax) && SAME_D(a->xcr, b->xcr) &&
	       SAME_D(a->W, b->W) && SAME_D(a->JFc, b->JFc) && SAME_D(a->JFe, b->JFe) &&
	       SAME_D(a->Lambda, b->Lambda) && SAME_D(a->xcr_sum, b->xcr_sum) &&
	       SAME_I(a->complete, b->complete) && SAME_I(a->k, b->k);
}

/* Every sample, jump record and collision of b is a's, to the bit. */
static void
assert_same_run(const struct hb_sim *a, const struct hb_sim *b, const char *what)
{
	const struct hb_arc *x = hb_sim_arc(a), *y = hb_sim_arc(b);
	size_t i;

	cr_assert_eq(hb_sim_end(b), hb_sim_end(a), "%s: end", what);
	cr_assert_eq(hb_arc_len(y), hb_arc_len(x), "%s: %zu samples against %zu", what, hb_arc_len(y),
	             hb_arc_len(x));
	for (i = 0; i < hb_arc_len(x); i++)
		cr_assert(same_sample(hb_arc_at(x, i), hb_arc_at(y, i)),
		          "%s: sample %zu differs (t = %.17g against %.17g)", what, i, hb_arc_at(y, i)->t,
		          hb_arc_at(x, i)->t);
	cr_assert_eq(hb_arc_njumps(y), hb_arc_njumps(x), "%s: jump records", what);
	for (i = 0; i < hb_arc_njumps(x); i++)
		cr_assert(same_jump(hb_arc_jump_at(x, i), hb_arc_jump_at(y, i)), "%s: jump record %zu differs",
		          what, i);
	cr_assert_eq(hb_sim_ncollisions(b), hb_sim_ncollisions(a), "%s: collisions", what);
	cr_assert_eq(hb_sim_collisions_total(b), hb_sim_collisions_total(a), "%s: collisions total", what);
	for (i = 0; i < hb_sim_ncollisions(a); i++)
		cr_assert(same_collision(hb_sim_collision(a, i), hb_sim_collision(b, i)),
		          "%s: collision %zu differs", what, i);
}

/* The first sample of this kind after sample from (0 when none). */
static size_t
next_kind(const struct hb_arc *arc, size_t from, int kind)
{
	for (size_t i = from + 1; i < hb_arc_len(arc); i++)
		if (hb_arc_at(arc, i)->kind == kind)
			return i;
	return 0;
}

/*
 * Seeks a full run of the preset to sample i, checks the cut, continues
 * and compares with the straight run a.
 */
static void
seek_continue(const struct hb_scene *sc, const struct hb_sim *a, struct hb_sim *b, size_t i,
              const char *name)
{
	const struct hb_arc_sample *want = hb_arc_at(hb_sim_arc(a), i);
	char what[96];
	size_t c = 0;

	(void)sc;
	snprintf(what, sizeof what, "%s, sample %zu (kind %d)", name, i, want->kind);
	cr_assert_eq(hb_sim_seek(b, i), HB_OK, "%s: %s", what, hb_sim_errmsg(b));
	cr_assert_eq(hb_arc_len(hb_sim_arc(b)), i + 1, "%s: the arc ends at the sample", what);
	cr_assert(same_sample(hb_arc_last(hb_sim_arc(b)), want), "%s: the last sample", what);
	/* the end sample ends the run again (as the two-body scenes' seek) */
	cr_assert_eq(hb_sim_end(b), want->kind == HB_ARC_END ? HB_SIM_END_T : HB_SIM_RUNNING, "%s", what);
	/* the collisions that end after the sample are not there yet */
	while (c < hb_sim_ncollisions(a) && hb_sim_collision(a, c)->ts <= want->t &&
	       hb_sim_collision(a, c)->j < want->j)
		c++;
	cr_assert_eq(hb_sim_ncollisions(b), c, "%s: %zu collisions before it, not %zu", what, c,
	             hb_sim_ncollisions(b));
	for (size_t r = 0; r < c; r++)
		cr_assert_eq(hb_sim_collision(b, r)->ts, hb_sim_collision(a, r)->ts, "%s", what);
	cr_assert_eq(hb_sim_run(b), want->kind == HB_ARC_END ? HB_EDONE : HB_OK, "%s: %s", what,
	             hb_sim_errmsg(b));
	assert_same_run(a, b, what);
}

static void
seek_preset(const char *name)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;
	const struct hb_arc *arc;
	size_t n, at[12], nat = 0, pre, post;
	char msg[256];

	scene_preset(name, &sc);
	a = run_scene(&sc);
	arc = hb_sim_arc(a);
	n = hb_arc_len(arc);
	cr_assert(hb_arc_thinned(arc) == 0, "%s: the test wants an arc that was not thinned", name);
	cr_assert(hb_arc_njumps(arc) >= 4, "%s", name);
	pre = next_kind(arc, n / 3, HB_ARC_PRE_JUMP);
	post = next_kind(arc, 2 * n / 3, HB_ARC_POST_JUMP);
	cr_assert(pre > 0 && post > 0, "%s", name);
	at[nat++] = 0;                    /* the start */
	at[nat++] = 1;
	at[nat++] = pre;                  /* a pre-jump sample: the jump comes again */
	at[nat++] = pre - 1;
	at[nat++] = pre + 1;              /* its post-jump sample */
	at[nat++] = post;
	at[nat++] = n / 2;
	at[nat++] = next_kind(arc, 0, HB_ARC_PRE_JUMP) - 5; /* inside the first flight */
	at[nat++] = n - 2;                /* the step before the end: the end comes again */
	at[nat++] = n - 1;
	b = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(b, "%s", msg);
	cr_assert_eq(hb_sim_run(b), HB_OK);
	for (size_t k = 0; k < nat; k++)
		seek_continue(&sc, a, b, at[k], name);
	/* every pre-jump sample (the jump is kept aside, and a row's flight time, or its collision) */
	for (size_t k = next_kind(arc, 0, HB_ARC_PRE_JUMP); k > 0; k = next_kind(arc, k, HB_ARC_PRE_JUMP))
		seek_continue(&sc, a, b, k, name);
	/* a seek back, then one further back before continuing; then a seek in the last unit of work */
	cr_assert_eq(hb_sim_seek(b, 2 * n / 3), HB_OK, "%s", hb_sim_errmsg(b));
	seek_continue(&sc, a, b, pre, name);
	cr_assert_eq(hb_sim_seek(b, n / 2), HB_OK);
	seek_continue(&sc, a, b, hb_arc_len(hb_sim_arc(b)) - 1, name);
	/* a run advanced part-way, cut back and continued */
	hb_sim_restart(b);
	cr_assert_eq(hb_sim_advance(b, 40, 0.0), HB_OK);
	cr_assert(hb_arc_len(hb_sim_arc(b)) > 20);
	cr_assert_eq(hb_sim_seek(b, hb_arc_len(hb_sim_arc(b)) / 2), HB_OK);
	cr_assert_eq(hb_sim_run(b), HB_OK);
	assert_same_run(a, b, "advanced part-way, cut, continued");
	cr_assert_eq(hb_sim_seek(b, n), HB_EINVAL);
	hb_sim_free(a);
	hb_sim_free(b);
}

Test(seek_chain, newtons_cradle_5)
{
	seek_preset("newtons-cradle-5");
}

Test(seek_chain, granular_chain)
{
	seek_preset("granular-chain");
}

/* A floor, gravity and bounces (the stacked drop): the same. */
Test(seek_chain, stacked_drop)
{
	seek_preset("stacked-drop");
}

/* ---- branches (sim.h: hb_sim_branch) on a chain ---- */

/* The sample of the k-th post-jump (k = 1, 2, ...). */
static size_t
post_jump(const struct hb_arc *arc, int k)
{
	size_t i = 0;

	while (k-- > 0 && (i = next_kind(arc, i, HB_ARC_POST_JUMP)) > 0)
		;
	cr_assert(i > 0);
	return i;
}

/*
 * Branches a straight run of the preset at sample i with the key set to
 * the value: the run up to the branch is the straight run's, the edit
 * changes the table after it, and a fresh simulator taking the recorded
 * branch gives the same run bit for bit.
 */
static void
branch_preset(const char *name, size_t (*where)(const struct hb_arc *), const char *key,
              const char *value)
{
	struct hb_scene sc, sc2;
	struct hb_sim *a, *b, *c;
	const struct hb_branch *br;
	size_t i, k, nc = 0;
	int restarted = -1, same = -1, differ = 0;
	char msg[512];

	scene_preset(name, &sc);
	a = run_scene(&sc);
	b = run_scene(&sc);
	i = where(hb_sim_arc(a));
	sc2 = sc;
	cr_assert_eq(hb_scene_set(&sc2, key, value, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_branch(b, i, &sc2, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(restarted, 0, "%s: %s = %s at sample %zu continues the run", name, key, value, i);
	cr_assert_eq(hb_sim_nbranches(b), 1);
	br = hb_sim_branch_get(b, 0);
	/* the branch is at the sample, or where the unit of work holding it ends */
	cr_assert(br->j > hb_arc_at(hb_sim_arc(a), i)->j ||
	          (br->j == hb_arc_at(hb_sim_arc(a), i)->j && br->t >= hb_arc_at(hb_sim_arc(a), i)->t));
	cr_assert_eq(hb_sim_run(b), HB_OK, "%s", hb_sim_errmsg(b));
	/* before the branch: the straight run's samples */
	for (k = 0; k < hb_arc_len(hb_sim_arc(a)); k++) {
		const struct hb_arc_sample *x = hb_arc_at(hb_sim_arc(a), k);

		if (x->j > br->j || (x->j == br->j && x->t > br->t))
			break;
		cr_assert(same_sample(x, hb_arc_at(hb_sim_arc(b), k)), "%s: sample %zu before the branch", name, k);
	}
	cr_assert(k > 1);
	/* the collisions completed before it are the straight run's; one after it differs */
	for (k = 0; k < hb_sim_ncollisions(a) && k < hb_sim_ncollisions(b); k++) {
		if (hb_sim_collision(a, k)->j < br->j) {
			struct hb_collision x = *hb_sim_collision(b, k);

			x.tf = hb_sim_collision(a, k)->tf; /* the flight after it ends after the branch */
			cr_assert(same_collision(hb_sim_collision(a, k), &x),
			          "%s: collision %zu, before the branch", name, k);
			nc++;
		} else if (!same_collision(hb_sim_collision(a, k), hb_sim_collision(b, k))) {
			differ = 1;
		}
	}
	cr_assert(nc > 0 || hb_arc_at(hb_sim_arc(a), i)->j < 8);
	cr_assert(differ || hb_sim_ncollisions(a) != hb_sim_ncollisions(b),
	          "%s: %s = %s changes the table after the branch", name, key, value);
	/* taken again by a fresh simulator (what --batch does with the export): the same run */
	c = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	cr_assert_eq(hb_sim_branch_at(c, br, &same, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(same, 1);
	cr_assert_eq(restarted, 0);
	cr_assert_eq(hb_sim_run(c), HB_OK, "%s", hb_sim_errmsg(c));
	assert_same_run(b, c, "the branch taken again");
	/* a change of the initial state cannot continue: the run begins again with it */
	sc2 = sc;
	cr_assert_eq(hb_scene_set(&sc2, "striker.v", "-0.5 m/s", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_branch(c, i, &sc2, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(restarted, 1);
	cr_assert_eq(hb_sim_nbranches(c), 0);
	cr_assert_eq(hb_arc_len(hb_sim_arc(c)), 1);
	hb_sim_free(a);
	hb_sim_free(b);
	hb_sim_free(c);
}

static size_t
second_collision(const struct hb_arc *arc)
{
	return post_jump(arc, 2);   /* the second contact begins */
}

static size_t
fortieth_jump(const struct hb_arc *arc)
{
	return post_jump(arc, 40);
}

static size_t
first_flight(const struct hb_arc *arc)
{
	return next_kind(arc, 0, HB_ARC_PRE_JUMP) / 2;  /* inside the striker's flight */
}

Test(seek_chain, branch_cradle_at_second_collision)
{
	branch_preset("newtons-cradle-5", second_collision, "body.1.mass", "10 g");
}

Test(seek_chain, branch_granular_chain)
{
	branch_preset("granular-chain", fortieth_jump, "body.1.mass", "1 g");
}

/* Inside a flight: the branch begins where the flight ends (a chain's state is known there). */
Test(seek_chain, branch_in_a_flight)
{
	branch_preset("granular-chain", first_flight, "body.1.mass", "1 g");
}
