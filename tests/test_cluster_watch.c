/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_cluster_watch.c - a chain's root finder evaluates the one watched
 * function it locates (hbs_cluster_watch_one), not all of them
 * (hbs_cluster_watch): the two must give the same double, bit for bit,
 * for every function of every kind (an interface's event, kinks and
 * extrema, a gap in flight next to a cluster), or a location would
 * change.  Checked along the chain presets' runs, step by step, at each
 * step's start and end and at a state between them.  The run's internal
 * state is reached through sim_impl.h, as the engine's own code reaches it.
 */
#include <stdlib.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/status.h"
#include "sim_impl.h"
#include "testutil.h"

/* Functions compared, by kind: an interface's event, kink, x_c and F_c extrema, a gap's event. */
struct seen {
	long event, kink, xcmax, fcmax, gap;
};

/* Every watched function alone at (t, u) against all of them at once, bit for bit. */
static void
compare_at(struct hb_sim *s, double t, const double *u, double *all, struct seen *n)
{
	struct clusters *c = &s->cx;

	hbs_cluster_watch(s, t, u, all, NULL);
	for (int fi = 0; fi < c->nf; fi++) {
		double one = hbs_cluster_watch_one(s, t, u, fi);

		cr_assert(memcmp(&one, &all[fi], sizeof one) == 0,
		          "function %d (kind %d, interface %d) at t = %.17g: %.17g alone, %.17g with all", fi,
		          c->fkind[fi], c->fif[fi], t, one, all[fi]);
		if (s->ifc[c->fif[fi]].off < 0)
			n->gap++;
		else if (c->fkind[fi] == FUN_EVENT)
			n->event++;
		else if (c->fkind[fi] == FUN_KINK)
			n->kink++;
		else if (c->fkind[fi] == FUN_XCMAX)
			n->xcmax++;
		else
			n->fcmax++;
	}
}

/* Runs preset NAME step by step, comparing after each step of its clusters; the counts into *n. */
static void
check_preset(const char *name, struct seen *n)
{
	struct hb_scene sc;
	char msg[1024];
	struct hb_sim *s;
	double *all = NULL, *mid = NULL;
	long steps = 0;

	scene_preset(name, &sc);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert_not_null(s, "sim_new: %s", msg);
	cr_assert(s->chain, "%s is not a chain", name);
	memset(n, 0, sizeof *n);
	while (hb_sim_end(s) == HB_SIM_RUNNING && steps++ < 200000) {
		struct clusters *c = &s->cx;

		cr_assert_eq(hb_sim_advance(s, 1, 0.0), HB_OK, "%s: %s", name, hb_sim_errmsg(s));
		if (s->setup || c->nact == 0 || c->dim == 0 || !(s->t > s->t0))
			continue; /* no clusters' step just taken, or their layout is to be made again */
		all = realloc(all, (size_t)c->nf * sizeof *all);
		mid = realloc(mid, (size_t)c->dim * sizeof *mid);
		cr_assert(all != NULL && mid != NULL);
		for (int i = 0; i < c->dim; i++)
			mid[i] = 0.5 * (s->u0[i] + s->u[i]);
		compare_at(s, s->t, s->u, all, n);
		compare_at(s, s->t0, s->u0, all, n);
		compare_at(s, 0.5 * (s->t0 + s->t), mid, all, n);
	}
	cr_assert_neq(hb_sim_end(s), HB_SIM_RUNNING, "%s did not end in %ld steps", name, steps);
	free(all);
	free(mid);
	hb_sim_free(s);
}

/* Hertz: events and extrema, and gaps next to the clusters. */
Test(cluster_watch, newtons_cradle_one_function_is_the_same_double)
{
	struct seen n;

	check_preset("newtons-cradle-5", &n);
	cr_assert_gt(n.event, 0);
	cr_assert_gt(n.xcmax, 0);
	cr_assert_gt(n.fcmax, 0);
	cr_assert_gt(n.gap, 0);
}

/* BWMCL: a hysteretic state z and the law's switching functions (kinks) too. */
Test(cluster_watch, bwmcl_cradle_kinks_are_the_same_double)
{
	struct seen n;

	check_preset("newtons-cradle-5-bwmcl", &n);
	cr_assert_gt(n.event, 0);
	cr_assert_gt(n.kink, 0);
	cr_assert_gt(n.fcmax, 0);
	cr_assert_gt(n.gap, 0);
}

/* A granular chain: many interfaces in contact at once, each F_c extremum reading its neighbours'. */
Test(cluster_watch, granular_chain_neighbours_are_the_same_double)
{
	struct seen n;

	check_preset("granular-chain", &n);
	cr_assert_gt(n.event, 0);
	cr_assert_gt(n.fcmax, 0);
}
