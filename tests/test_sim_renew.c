/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_sim_renew.c - a simulator made again for a new scene in its own
 * memory (hbs_sim_renew, src/core/sim_life.h: what a sweep's worker does
 * from its second point on) runs exactly as a new one: the same arc and
 * collisions to the byte (as CSV), the same statistics and end, whatever
 * ran on it before (a chain, a thinned arc, another stepper, a failed
 * run); a refused scene frees it and gives hb_sim_new's message.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/csv.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "sim_life.h"
#include "testutil.h"

/* The arc and the collisions of s as their CSV files, in one malloc'd string. */
static char *
tables(const struct hb_sim *s)
{
	char *buf = NULL, msg[256];
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);

	cr_assert_not_null(f);
	cr_assert_eq(hb_csv_stream_arc(f, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_csv_stream_collisions(f, s, msg, sizeof msg), HB_OK, "%s", msg);
	fclose(f);
	return buf;
}

/* a and b ended the same way with the same tables and statistics. */
static void
same_run(const struct hb_sim *a, const struct hb_sim *b, const char *what)
{
	const struct hb_sim_stats *sa = hb_sim_stats(a), *sb = hb_sim_stats(b);
	char *ta = tables(a), *tb = tables(b);

	cr_assert_eq(hb_sim_end(a), hb_sim_end(b), "%s: end %d, renewed %d", what, hb_sim_end(a),
	             hb_sim_end(b));
	cr_assert_str_eq(hb_sim_end_str(a), hb_sim_end_str(b), "%s: the end's words", what);
	cr_assert_str_eq(hb_sim_errmsg(a), hb_sim_errmsg(b), "%s: the error", what);
	cr_assert_eq(hb_sim_collisions_total(a), hb_sim_collisions_total(b), "%s: collisions", what);
	cr_assert(strlen(ta) > 100, "%s: a table of %zu bytes", what, strlen(ta));
	cr_assert(strcmp(ta, tb) == 0, "%s: the arc and collisions differ (%zu and %zu bytes)", what,
	          strlen(ta), strlen(tb));
	cr_assert(sa->steps == sb->steps && sa->rejected == sb->rejected && sa->rhs == sb->rhs &&
	          sa->jac == sb->jac && sa->jumps == sb->jumps && sa->kinks == sb->kinks &&
	          sa->located == sb->located && sa->dips == sb->dips &&
	          sa->flights_closed == sb->flights_closed && sa->stiff_checks == sb->stiff_checks &&
	          sa->stiff == sb->stiff && sa->switched == sb->switched,
	          "%s: statistics (steps %ld and %ld, rhs %ld and %ld)", what, sa->steps, sb->steps,
	          sa->rhs, sb->rhs);
	free(ta);
	free(tb);
}

/* A preset's scene with KEY=VALUE set (key NULL: none). */
static void
scene_with(const char *preset, const char *key, const char *value, struct hb_scene *sc)
{
	char msg[512];

	scene_preset(preset, sc);
	if (key != NULL)
		cr_assert_eq(hb_scene_set(sc, key, value, msg, sizeof msg), HB_OK, "%s=%s: %s", key,
		             value, msg);
}

/* Runs before (on a new simulator), renews it for after and compares with a new one. */
static void
renewed_as_new(const struct hb_scene *before, const struct hb_scene *after, const char *what)
{
	char msg[512];
	struct hb_sim *s = hb_sim_new(before, msg, sizeof msg), *fresh;

	cr_assert_not_null(s, "%s: %s", what, msg);
	(void)hb_sim_run(s);
	s = hbs_sim_renew(s, after, msg, sizeof msg);
	cr_assert_not_null(s, "%s: renewed: %s", what, msg);
	(void)hb_sim_run(s);
	fresh = hb_sim_new(after, msg, sizeof msg);
	cr_assert_not_null(fresh, "%s: %s", what, msg);
	(void)hb_sim_run(fresh);
	same_run(fresh, s, what);
	hb_sim_free(fresh);
	hb_sim_free(s);
}

Test(sim_renew, after_a_chain_a_pair_and_after_a_pair_a_chain)
{
	struct hb_scene a, b;

	scene_preset("granular-chain", &a);
	scene_preset("nonunique-separation", &b);
	renewed_as_new(&a, &b, "granular-chain, then nonunique-separation");
	renewed_as_new(&b, &a, "nonunique-separation, then granular-chain");
	scene_preset("newtons-cradle-5-bwmcl", &b);
	renewed_as_new(&a, &b, "granular-chain, then newtons-cradle-5-bwmcl");
}

Test(sim_renew, after_a_thinned_arc)
{
	struct hb_scene a, b;

	/* 1,024 samples at most: the arc is thinned (its count of thinnings too) */
	scene_with("newtons-cradle-5-bwmcl", "run.max_samples", "1024", &a);
	scene_preset("steel-on-bitumen", &b);
	renewed_as_new(&a, &b, "a thinned arc, then steel-on-bitumen");
	scene_with("steel-on-bitumen", "run.max_samples", "1024", &b);
	renewed_as_new(&a, &b, "a thinned arc, then a thinned arc");
}

Test(sim_renew, after_another_stepper_and_the_same_scene_twice)
{
	struct hb_scene a, b;

	scene_with("permanent-contact-shccl", "run.stepper", "dop853", &a);
	scene_preset("permanent-contact-shccl", &b);
	renewed_as_new(&a, &b, "dop853, then rk8pd");
	renewed_as_new(&b, &a, "rk8pd, then dop853");
	renewed_as_new(&b, &b, "the same scene twice");
}

Test(sim_renew, after_a_failed_run)
{
	struct hb_scene a, b;

	scene_with("steel-on-bitumen", "run.h_max", "1e-300", &a);
	scene_preset("hertz-elastic", &b);
	renewed_as_new(&a, &b, "a failed run, then hertz-elastic");
	renewed_as_new(&b, &a, "hertz-elastic, then a failed run");
}

Test(sim_renew, a_refused_scene_frees_it_with_hb_sim_new_s_message)
{
	struct hb_scene a, bad;
	char m1[512] = "", m2[512] = "";
	struct hb_sim *s;

	scene_preset("hertz-elastic", &a);
	bad = a;
	bad.run.rtol = -1;   /* stored directly: refused by the validation */
	cr_assert_null(hb_sim_new(&bad, m1, sizeof m1), "a negative rtol runs");
	s = hb_sim_new(&a, m2, sizeof m2);
	cr_assert_not_null(s, "%s", m2);
	(void)hb_sim_run(s);
	cr_assert_null(hbs_sim_renew(s, &bad, m2, sizeof m2), "a negative rtol is renewed");
	cr_assert(m1[0] != '\0' && strcmp(m1, m2) == 0, "messages '%s' and '%s'", m1, m2);
}
