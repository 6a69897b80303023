/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_branch_log.c - the record of a run's changes of scene (sim.h): the
 * scene it began with at t = 0, the branches taken since (hb_sim_branch
 * records them, sim_branch.c), and the time of a change that went
 * unrecorded.  Below the run, its seek and its branches, which all keep
 * it: the run forgets the branches when it begins again, a seek drops
 * those after the sample it cuts at.
 */
#include "sim_impl.h"

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

/* Records branch b, taken at the run's end; -1 when out of memory. */
int
hbs_branches_push(struct hb_sim *s, const struct hb_branch *b)
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
