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
 * whether it goes on or restarts is hbs_chain_continues's rule.
 *
 * A change of scene that did not go through here (hb_sim_set_scene that
 * continues the run, or a seek back past a branch) is remembered by its
 * time: hb_sim_unrecorded() says the run is no longer described by its
 * first scene and branches.
 */
#include "sim_impl.h"
#include "scene_chain.h"

#include "cnum.h"

/*
 * A chain's run goes on with scene nsc from its current state unless that
 * changes what the state was computed from or what is in contact (as the
 * two-body scenes' rule): the number of bodies, the floor, the system, any
 * body's initial velocity, gap or radius (its position at t = 0), the mass
 * or load of a body in contact, or the law or extension of an interface in
 * contact.  Then 0: the run begins again from t = 0.
 */
int
hbs_chain_continues(const struct hb_sim *s, const struct hb_scene *nsc)
{
	const struct hb_scene *o = &s->sc;
	int i;

	if (nsc->chain.n != o->chain.n || nsc->chain.floor != o->chain.floor ||
	    nsc->d.system != o->d.system || memcmp(&nsc->init, &o->init, sizeof nsc->init) != 0)
		return 0;
	for (i = 0; i < s->nbody; i++) {
		struct scene_chain_body a, b;

		if (scene_chain_body(o, i, &a) != HB_OK || scene_chain_body(nsc, i, &b) != HB_OK)
			return 0;
		if (a.v0 != b.v0 || a.gap != b.gap || a.R != b.R)
			return 0;
		if (s->body[i].cl >= 0 && (a.m != b.m || a.F != b.F))
			return 0;
	}
	for (i = 0; i < s->nif; i++) {
		struct scene_chain_iface a, b;

		if (!s->ifc[i].q)
			continue;
		if (scene_chain_iface(o, s->k0 + i, &a) != HB_OK ||
		    scene_chain_iface(nsc, s->k0 + i, &b) != HB_OK || a.law != b.law || a.ext != b.ext)
			return 0;
	}
	return 1;
}

/*
 * Before a chain's bodies take new constants: each flying body's (y, u)
 * moved to the current t on its parabola, so that a new acceleration acts
 * from now on (a body in contact keeps its mass and load).
 */
void
hbs_chain_settle_flying(struct hb_sim *s)
{
	for (int i = 0; i < s->nbody; i++) {
		double y, u;

		if (s->body[i].cl >= 0)
			continue;
		hbs_body_now(&s->body[i], s->t, &y, &u);
		hbs_body_set(&s->body[i], s->t, y, u);
	}
}

/* Forgets every branch: the run is its scene from t = 0 again. */
void
hbs_branches_clear(struct hb_sim *s)
{
	s->sc0 = s->sc;
	s->nbr = 0;
	s->unrec_t = -1;
}

/* Drops the branches taken after sample i (the run was cut there). */
void
hbs_branches_cut(struct hb_sim *s, size_t i)
{
	const struct hb_arc_sample *a = hb_arc_at(s->arc, i);
	size_t k = s->nbr;

	while (k > 0 && (s->br[k - 1].t > a->t || (s->br[k - 1].t == a->t && s->br[k - 1].j > a->j)))
		k--;
	if (s->unrec_t > a->t)
		s->unrec_t = -1;     /* that change was after the cut: gone with it */
	if (k < s->nbr && s->unrec_t < 0)
		s->unrec_t = a->t;   /* the run goes on with the scene of a dropped branch */
	s->nbr = k;
}

static int
push(struct hb_sim *s, const struct hb_branch *b)
{
	if (s->nbr == s->brcap) {
		size_t cap = s->brcap ? 2 * s->brcap : 4;
		struct hb_branch *nb = realloc(s->br, cap * sizeof *nb);

		if (nb == NULL)
			return -1;
		s->br = nb;
		s->brcap = cap;
	}
	s->br[s->nbr++] = *b;
	return 0;
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
		*same_state = a->x == b->x && a->v == b->v && a->xc == b->xc && a->q == b->q;
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
		a = hb_arc_last(s->arc);
		nb.t = a->t;
		nb.j = a->j;
		nb.x = a->x;
		nb.v = a->v;
		nb.xc = a->xc;
		nb.q = a->q;
	}
	if ((rc = hb_sim_set_scene(s, &b->sc, restarted, msg, n)) != HB_OK)
		return rc;
	if (*restarted)
		return HB_OK;   /* hb_sim_set_scene began the run again with b->sc */
	s->unrec_t = unrec; /* set_scene marked the change; here it is recorded */
	return push(s, &nb) == 0 ? HB_OK : hb_status_set(msg, n, HB_ENOMEM, "out of memory");
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
	const struct hb_arc_sample *a;
	size_t nkeep = 0;
	int rc = HB_OK, rs = 0;

	if (restarted != NULL)
		*restarted = 0;
	if (i >= hb_arc_len(s->arc))
		return hb_status_set(msg, n, HB_EINVAL, "no sample %zu: the run has %zu", i,
		                     hb_arc_len(s->arc));
	if ((rc = hb_scene_validate(&chk, msg, n)) != HB_OK)
		return rc;
	a = hb_arc_at(s->arc, i);
	nb.t = a->t;
	nb.j = a->j;
	nb.x = a->x;
	nb.v = a->v;
	nb.xc = a->xc;
	nb.q = a->q;
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

size_t
hb_sim_nbranches(const struct hb_sim *s)
{
	return s->nbr;
}

const struct hb_branch *
hb_sim_branch_get(const struct hb_sim *s, size_t k)
{
	return k < s->nbr ? &s->br[k] : NULL;
}

const struct hb_scene *
hb_sim_scene0(const struct hb_sim *s)
{
	return &s->sc0;
}

double
hb_sim_unrecorded(const struct hb_sim *s)
{
	return s->unrec_t;
}
