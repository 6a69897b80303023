/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_branch.c - runs with branches (sim.h: hb_sim_branch): a branch is
 * made the same way whatever the run had computed, a preset records it,
 * and replaying the preset gives the run bit for bit; where a run cannot
 * be recorded, the preset's first line says so.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <criterion/criterion.h>

#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "testutil.h"

/* The first sample in contact with jump count j, or of j in flight (contact 0). */
static size_t
sample_at(const struct hb_sim *s, long j, int contact)
{
	const struct hb_arc *arc = hb_sim_arc(s);

	for (size_t i = 0; i < hb_arc_len(arc); i++) {
		const struct hb_arc_sample *a = hb_arc_at(arc, i);

		if (a->j == j && a->q == contact && (i + 1 < hb_arc_len(arc) && hb_arc_at(arc, i + 1)->j == j))
			return i + 1;
	}
	cr_assert_fail("no sample at j = %ld", j);
	return 0;
}

static void
assert_same_collisions(const struct hb_sim *a, const struct hb_sim *b)
{
	cr_assert_eq(hb_sim_ncollisions(a), hb_sim_ncollisions(b), "%zu against %zu collisions",
	             hb_sim_ncollisions(a), hb_sim_ncollisions(b));
	for (size_t i = 0; i < hb_sim_ncollisions(a); i++) {
		const struct hb_collision *x = hb_sim_collision(a, i), *y = hb_sim_collision(b, i);

		cr_assert(x->ts == y->ts && x->e == y->e && x->W == y->W && x->xcmax == y->xcmax &&
		          x->te == y->te, "collision %zu differs", i);
	}
	cr_assert_eq(hb_arc_len(hb_sim_arc(a)), hb_arc_len(hb_sim_arc(b)));
}

/* Writes the run as a preset to a temporary file; returns its path (static). */
static const char *
save_run(const struct hb_sim *s, char **text)
{
	static char path[64];
	size_t len = hb_preset_format_run(s, NULL, 0);
	char *buf = malloc(len + 1);
	FILE *f;
	int fd;

	cr_assert_not_null(buf);
	cr_assert_eq(hb_preset_format_run(s, buf, len + 1), len);
	snprintf(path, sizeof path, "/tmp/hbbranchXXXXXX");
	fd = mkstemp(path);
	cr_assert(fd >= 0);
	f = fdopen(fd, "w");
	cr_assert_not_null(f);
	fputs(buf, f);
	fclose(f);
	*text = buf;
	return path;
}

/* Opens the preset at path with its branches and runs it: what --batch does. */
static struct hb_sim *
replay(const char *path, const char *const *sets, int nsets, int *same)
{
	struct hb_scene sc;
	struct hb_branch *br = NULL;
	size_t nbr = 0;
	char p[512], msg[1024];
	struct hb_sim *s;

	cr_assert_eq(hb_preset_open_branched(path, sets, nsets, &sc, &br, &nbr, p, sizeof p, msg,
	             sizeof msg), HB_OK, "%s", msg);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(s, "%s", msg);
	*same = 1;
	for (size_t k = 0; k < nbr; k++) {
		int one = 0, restarted = 0;

		if (hb_sim_branch_at(s, &br[k], &one, &restarted, msg, sizeof msg) != HB_OK) {
			free(br);
			hb_sim_free(s);
			return NULL;
		}
		cr_assert_eq(restarted, 0);
		*same &= one;
	}
	free(br);
	cr_assert_eq(hb_sim_run(s), 0, "%s", hb_sim_errmsg(s));
	return s;
}

static void
edited(const struct hb_scene *from, const char *key, const char *value, struct hb_scene *out)
{
	char msg[512];

	*out = *from;
	cr_assert_eq(hb_scene_set(out, key, value, msg, sizeof msg), 0, "%s", msg);
}

/* A branch continues as a fresh replay would, whatever the run had computed before. */
Test(branch, a_branch_does_not_depend_on_how_far_the_run_had_gone)
{
	struct hb_scene sc, c44;
	struct hb_sim *a, *b;
	size_t i;
	int restarted = -1;
	char msg[512];

	scene_preset("steel-on-bitumen", &sc);
	edited(&sc, "law.c", "44000 N s/m", &c44);
	a = run_scene(&sc);                      /* computed to the end */
	b = hb_sim_new(&sc, msg, sizeof msg);    /* computed just past the sample */
	cr_assert_not_null(b);
	i = sample_at(a, 6, 0);
	while (hb_arc_len(hb_sim_arc(b)) <= i + 1)
		cr_assert_eq(hb_sim_advance(b, 1, 0), 0);
	cr_assert_eq(hb_sim_branch(a, i, &c44, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(restarted, 0);
	cr_assert_eq(hb_sim_branch(b, i, &c44, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_run(a), 0);
	cr_assert_eq(hb_sim_run(b), 0);
	assert_same_collisions(a, b);
	cr_assert_eq(hb_sim_nbranches(a), 1);
	cr_assert_eq(hb_sim_unrecorded(a), -1);
	cr_assert_eq(hb_sim_scene(a)->par[0], c44.par[0]);
	cr_assert_eq(hb_sim_scene0(a)->par[0], sc.par[0]);
	hb_sim_free(a);
	hb_sim_free(b);
}

/* Two branches (a value, then the law) are written, read back and replayed bit for bit. */
Test(branch, a_preset_with_branches_reproduces_the_run)
{
	struct hb_scene sc, s1, s2;
	struct hb_sim *a, *r;
	char *text, msg[512];
	const char *path;
	int same = 0;

	scene_preset("steel-on-bitumen", &sc);
	a = run_scene(&sc);
	edited(&sc, "law.c", "44000 N s/m", &s1);
	cr_assert_eq(hb_sim_branch(a, sample_at(a, 4, 0), &s1, NULL, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_run(a), 0);
	edited(&s1, "scene.law", "bwshccl", &s2);
	cr_assert_eq(hb_sim_branch(a, sample_at(a, 10, 0), &s2, NULL, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_run(a), 0);
	cr_assert_eq(hb_sim_nbranches(a), 2);
	path = save_run(a, &text);
	cr_assert(strstr(text, "a run with 2 branches") != NULL, "%s", text);
	cr_assert(strstr(text, "[branch 1]\nt = ") != NULL);
	cr_assert(strstr(text, "law.c = 44000 N s/m\n") != NULL, "%s", text);
	cr_assert(strstr(text, "[branch 2]") != NULL);
	cr_assert(strstr(text, "scene.law = bwshccl\n") != NULL, "%s", text);
	r = replay(path, NULL, 0, &same);
	cr_assert_not_null(r);
	cr_assert_eq(same, 1);
	assert_same_collisions(a, r);
	/* a plain opener refuses it rather than run another run */
	{
		struct hb_scene x;

		cr_assert_eq(hb_preset_load(path, &x, msg, sizeof msg), HB_EINVAL);
		cr_assert(strstr(msg, "[branch 1]: this preset records a run with branches") != NULL, "%s", msg);
	}
	/* a --set that changes the run before the branch: the branch's sample is not on it */
	{
		const char *set[] = { "initial.x0=0.25 m" };
		struct hb_scene sx;
		struct hb_branch *br = NULL;
		size_t nbr = 0;
		char p[512];
		struct hb_sim *x;
		int one = 1, restarted = 0;

		cr_assert_eq(hb_preset_open_branched(path, set, 1, &sx, &br, &nbr, p, sizeof p, msg,
		             sizeof msg), HB_OK, "%s", msg);
		cr_assert_eq(nbr, 2);
		x = hb_sim_new(&sx, msg, sizeof msg);
		cr_assert_eq(hb_sim_branch_at(x, &br[0], &one, &restarted, msg, sizeof msg), HB_EINVAL);
		cr_assert(strstr(msg, "no sample at t = ") != NULL, "%s", msg);
		free(br);
		hb_sim_free(x);
	}
	unlink(path);
	free(text);
	hb_sim_free(a);
	hb_sim_free(r);
}

/* A branch before an earlier one replaces it; an edit from t = 0 forgets them all. */
Test(branch, an_earlier_branch_replaces_later_ones)
{
	struct hb_scene sc, s1, s2;
	struct hb_sim *a;
	char msg[512];

	scene_preset("steel-on-bitumen", &sc);
	a = run_scene(&sc);
	edited(&sc, "law.c", "44000 N s/m", &s1);
	edited(&sc, "law.c", "2200 N s/m", &s2);
	cr_assert_eq(hb_sim_branch(a, sample_at(a, 10, 0), &s1, NULL, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_run(a), 0);
	cr_assert_eq(hb_sim_branch(a, sample_at(a, 4, 0), &s2, NULL, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_nbranches(a), 1);
	cr_assert_eq(hb_sim_branch_get(a, 0)->sc.par[0], s2.par[0]);
	cr_assert_eq(hb_sim_restart(a), 0);
	cr_assert_eq(hb_sim_nbranches(a), 0);
	cr_assert_eq(hb_sim_scene0(a)->par[0], s2.par[0]);
	hb_sim_free(a);
}

/* hb_sim_set_scene in mid-run is not a recorded branch: the preset says it does not reproduce. */
Test(branch, an_unrecorded_change_is_said_in_the_first_line)
{
	struct hb_scene sc, s1;
	struct hb_sim *a;
	char *text, msg[512];
	const char *path;
	int restarted = 0;

	scene_preset("steel-on-bitumen", &sc);
	a = run_scene(&sc);
	cr_assert_eq(hb_sim_seek(a, sample_at(a, 4, 0)), 0);
	edited(&sc, "law.c", "44000 N s/m", &s1);
	cr_assert_eq(hb_sim_set_scene(a, &s1, &restarted, msg, sizeof msg), 0, "%s", msg);
	cr_assert(hb_sim_unrecorded(a) > 0);
	path = save_run(a, &text);
	cr_assert(strncmp(strchr(text, ':'), ": hybounce", 10) != 0);
	cr_assert(strstr(text, "preset: does NOT reproduce the run") != NULL, "%s", text);
	unlink(path);
	free(text);
	hb_sim_free(a);
}
