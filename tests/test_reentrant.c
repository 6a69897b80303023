/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_reentrant.c - the library's re-entrancy promise (README, "The
 * library"): sims run at the same time in several threads give, to the
 * bit, the collisions they give one after another, and preset look-ups in
 * those threads do not disturb each other.  (tests/cli/install.sh checks
 * the other half: no writable static storage in the core's objects.)
 */
#include <pthread.h>
#include <stddef.h>
#include <string.h>

#include "testutil.h"

#define NTHREADS 8
#define MAXCOLL 256

struct job {
	const char *name;
	struct hb_collision c[MAXCOLL];
	size_t n;
	int status;             /* 0, or the first failure's status */
	char msg[512];
};

/* Resolves, loads and runs a preset; no Criterion assertion (not the test's thread). */
static void *
work(void *arg)
{
	struct job *jb = arg;
	char path[512];
	struct hb_scene sc;
	struct hb_sim *s;

	jb->status = hb_preset_resolve(jb->name, path, sizeof path, jb->msg, sizeof jb->msg);
	if (jb->status == HB_OK)
		jb->status = hb_preset_load(path, &sc, jb->msg, sizeof jb->msg);
	if (jb->status != HB_OK)
		return NULL;
	s = hb_sim_new(&sc, jb->msg, sizeof jb->msg);
	if (s == NULL) {
		jb->status = HB_EINVAL;
		return NULL;
	}
	jb->status = hb_sim_run(s);
	if (jb->status != HB_OK)
		snprintf(jb->msg, sizeof jb->msg, "%s", hb_sim_errmsg(s));
	jb->n = hb_sim_ncollisions(s);
	for (size_t i = 0; i < jb->n && i < MAXCOLL; i++)
		jb->c[i] = *hb_sim_collision(s, i);
	hb_sim_free(s);
	return NULL;
}

Test(reentrant, concurrent_runs_match_sequential_ones, .timeout = 120)
{
	static struct job seq[NTHREADS], par[NTHREADS];
	pthread_t th[NTHREADS];

	for (int k = 0; k < NTHREADS; k++) {
		/* two of each of the first four paper presets */
		seq[k].name = par[k].name = paper_presets[k % 4];
		work(&seq[k]);
		cr_assert_eq(seq[k].status, HB_OK, "%s: %s", seq[k].name, seq[k].msg);
		cr_assert(seq[k].n > 0 && seq[k].n <= MAXCOLL, "%s: %zu collisions", seq[k].name,
		          seq[k].n);
	}
	for (int k = 0; k < NTHREADS; k++)
		cr_assert_eq(pthread_create(&th[k], NULL, work, &par[k]), 0);
	for (int k = 0; k < NTHREADS; k++)
		cr_assert_eq(pthread_join(th[k], NULL), 0);
	for (int k = 0; k < NTHREADS; k++) {
		cr_assert_eq(par[k].status, HB_OK, "%s in a thread: %s", par[k].name, par[k].msg);
		cr_assert_eq(par[k].n, seq[k].n, "%s: %zu collisions in a thread, %zu alone",
		             par[k].name, par[k].n, seq[k].n);
		for (size_t i = 0; i < seq[k].n; i++)
			/* every field up to `complete` is a long or a double: no padding */
			cr_assert(memcmp(&par[k].c[i], &seq[k].c[i], offsetof(struct hb_collision, complete)) == 0
			              && par[k].c[i].complete == seq[k].c[i].complete,
			          "%s: collision %zu differs between a thread and a run alone",
			          par[k].name, i);
	}
}

/* hb_preset_dirs() gives each thread its own list. */
static void *
dirs_of(void *arg)
{
	*(const char *const **)arg = hb_preset_dirs();
	return NULL;
}

Test(reentrant, preset_dirs_is_per_thread)
{
	const char *const *mine = hb_preset_dirs(), *const *theirs = NULL;
	pthread_t t;

	cr_assert_eq(pthread_create(&t, NULL, dirs_of, &theirs), 0);
	cr_assert_eq(pthread_join(t, NULL), 0);
	cr_assert_not_null(theirs);
	cr_assert(mine != theirs, "two threads share preset_dirs()'s storage");
	cr_assert_not_null(mine[0]);
}
