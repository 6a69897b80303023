/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_branch.c - runs that change their scene part-way, reproducibly (sim.h:
 * hb_sim_branch).
 *
 * A branch is "from the run's sample at (t, j) on, go on with scene S".
 * Where a run continues after a seek depends on more than the sample: the
 * first-step guesses of the intervals computed since (h1), a stepper that
 * auto went over to, the samples a full arc thinned out.  So a branch is
 * always made the same way, whatever the run had computed before: the run
 * is started again from t = 0 with the scene it began with, its earlier
 * branches are taken again, it is advanced one step at a time until it
 * holds the sample at (t, j), cut there and continued with S
 * (branch_at).  A host that opens a fresh simulator with the first scene
 * and takes the same branches with hb_sim_branch_at gets the same run, bit
 * for bit: what `hybounce --batch` does with a preset that records
 * branches (preset.h: hb_preset_open_branched).
 *
 * A chain (sim_seek.c) is cut at the end of the unit of work that holds
 * the sample, where its state is known, and the branch is recorded there;
 * whether it goes on or restarts is hbs_chain_continues's rule (sim_chain.c).
 *
 * A change of scene that did not go through here (hb_sim_set_scene that
 * continues the run, or a seek back past a branch) is remembered by its
 * time: hb_sim_unrecorded() says the run is no longer described by its
 * first scene and branches.  The record itself (the first scene, the
 * branches, that time) is sim_branch_log.c's; this file is above the
 * run, its seek and its change of scene, and none of them calls it.
 */
#include "sim_impl.h"

#include "cnum.h"

/* The state a branch records of its sample, field by field (same names in struct hb_arc_sample). */
#define BRANCH_STATE(X) X(x) X(v) X(xc) X(q)

/* Branch b begins at sample a: its (t, j) and state (b's scene is left as it is). */
static void
branch_from(struct hb_branch *b, const struct hb_arc_sample *a)
{
#define COPY(f) b->f = a->f;
	b->t = a->t;
	b->j = a->j;
	BRANCH_STATE(COPY)
#undef COPY
}

/* 1 when sample a's state is the one branch b recorded, to the bit. */
static int
branch_state_is(const struct hb_branch *b, const struct hb_arc_sample *a)
{
#define SAME(f) && a->f == b->f
	return 1 BRANCH_STATE(SAME);
#undef SAME
}

/* The first sample of the arc at exactly (t, j), or -1. */
static long
find_sample(const struct hb_arc *arc, double t, long j)
{
	long found = -1;

	for (size_t i = hb_arc_len(arc); i-- > 0;) {
		const struct hb_arc_sample *a = hb_arc_at(arc, i);

		if (a->t < t)
			break;
		if (a->t == t && a->j == j)
			found = (long)i;
	}
	return found;
}

/*
 * Advances the run step by step until it holds the sample at (b->t, b->j),
 * cuts it there and continues with b->sc.  *same_state: 1 when the state
 * there is b's (x, v, x_c, in contact or not) to the bit.  *restarted: 1
 * when b->sc cannot continue there and the run began again with it
 * (hb_sim_set_scene).
 */
static int
branch_at(struct hb_sim *s, const struct hb_branch *b, int *same_state, int *restarted,
          char *msg, size_t n)
{
	const struct hb_arc_sample *a;
	struct hb_branch nb;
	double unrec = s->unrec_t;
	long i;
	int rc;

	for (;;) {
		a = hb_arc_at(s->arc, hb_arc_len(s->arc) - 1);
		if (a->t > b->t || (a->t == b->t && a->j >= b->j) || s->end != HB_SIM_RUNNING)
			break;
		rc = hb_sim_advance(s, 1, 0.0);
		if (rc != HB_OK && rc != HB_EDONE)
			return hb_status_set(msg, n, rc, "the run failed before the branch at t = %.17g s: %s",
			                     b->t, s->err);
	}
	i = find_sample(s->arc, b->t, b->j);
	if (i < 0) {
		char tb[40];

		cnum_snprintf(tb, sizeof tb, "%.17g", b->t);
		return hb_status_set(msg, n, HB_EINVAL, "the run has no sample at t = %s s, j = %ld, "
		                     "where the branch begins (the run before it differs: another scene, "
		                     "--set or build)", tb, b->j);
	}
	a = hb_arc_at(s->arc, (size_t)i);
	if (same_state != NULL)
		*same_state = branch_state_is(b, a);
	if ((rc = hb_sim_seek(s, (size_t)i)) != HB_OK)
		return hb_status_set(msg, n, rc, "cannot cut the run at its sample %ld%s%s", i,
		                     s->err[0] ? ": " : "", s->err);
	nb = *b;
	if (s->pend.active) {
		/*
		 * A chain's state is known where a unit of work ends (sim_seek.c):
		 * the branch begins at the end of the one that holds the sample
		 * (the rest of its flight, its jump), and is recorded there.
		 */
		if ((rc = hbs_pend_flush(s)) != HB_OK)
			return hb_status_set(msg, n, rc, "%s", s->err);
		branch_from(&nb, hb_arc_last(s->arc));
	}
	if ((rc = hb_sim_set_scene(s, &b->sc, restarted, msg, n)) != HB_OK)
		return rc;
	if (*restarted)
		return HB_OK;   /* hb_sim_set_scene began the run again with b->sc */
	s->unrec_t = unrec; /* set_scene marked the change; here it is recorded */
	return hbs_branches_push(s, &nb) == 0 ? HB_OK : hb_status_set(msg, n, HB_ENOMEM, "out of memory");
}

int
hb_sim_branch_at(struct hb_sim *s, const struct hb_branch *b, int *same_state, int *restarted,
                 char *msg, size_t n)
{
	int rs = 0;
	int rc = branch_at(s, b, same_state, &rs, msg, n);

	if (restarted != NULL)
		*restarted = rs;
	return rc;
}

int
hb_sim_branch(struct hb_sim *s, size_t i, const struct hb_scene *sc, int *restarted, char *msg,
              size_t n)
{
	struct hb_branch nb, *keep = NULL;
	struct hb_scene chk = *sc;
	size_t nkeep = 0;
	int rc = HB_OK, rs = 0;

	if (restarted != NULL)
		*restarted = 0;
	if (i >= hb_arc_len(s->arc))
		return hb_status_set(msg, n, HB_EINVAL, "no sample %zu: the run has %zu", i,
		                     hb_arc_len(s->arc));
	if ((rc = hb_scene_validate(&chk, msg, n)) != HB_OK)
		return rc;
	branch_from(&nb, hb_arc_at(s->arc, i));
	nb.sc = chk;
	/* the branches before the sample stay; those at or after it are replaced */
	while (nkeep < s->nbr && (s->br[nkeep].t < nb.t || (s->br[nkeep].t == nb.t && s->br[nkeep].j < nb.j)))
		nkeep++;
	if (nkeep > 0) {
		keep = malloc(nkeep * sizeof *keep);
		if (keep == NULL)
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		memcpy(keep, s->br, nkeep * sizeof *keep);
	}
	{
		struct hb_scene sc0 = s->sc0;

		if ((rc = hb_sim_set_scene(s, &sc0, &rs, msg, n)) != HB_OK)
			goto out;
		if (!rs)
			hb_sim_restart(s);   /* sets sc0 = sc and forgets the branches */
	}
	for (size_t k = 0; k < nkeep && rc == HB_OK; k++) {
		rc = branch_at(s, &keep[k], NULL, &rs, msg, n);
		if (rc == HB_OK && rs)
			rc = hb_status_set(msg, n, HB_EINVAL, "the branch at t = %.17g s no longer "
			                   "continues the run", keep[k].t);
	}
	if (rc == HB_OK && (rc = branch_at(s, &nb, NULL, &rs, msg, n)) == HB_OK && restarted != NULL)
		*restarted = rs;
out:
	free(keep);
	return rc;
}
