/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_pend.c - the outputs of a chain's unit of work kept aside by a seek
 * (sim_seek.c): put aside when the seek cuts the run at a sample inside
 * the unit, given back unchanged before any further work (hb_sim_advance,
 * a seek, a change of scene, a branch), or forgotten (the run begun
 * again).  Below the run and the seek, which both use it, and calling
 * neither.
 */
#include "sim_impl.h"

/* Forgets what was kept aside (the run begun again at t = 0). */
void
hbs_pend_drop(struct hb_sim *s)
{
	s->pend.active = 0;
	s->pend.n = 0;
}

/*
 * Gives back what was kept aside, as the unit of work had pushed it: the
 * samples, the jump record and collision, the flight time, the t, j and
 * end after the unit.  0, or HB_ENOMEM with the run failed.
 */
int
hbs_pend_flush(struct hb_sim *s)
{
	size_t k;

	if (!s->pend.active)
		return 0;
	s->pend.active = 0;
	s->t = s->pend.t;
	s->j = s->pend.j;
	for (k = 0; k < s->pend.n; k++) {
		if (s->pend.has_jump && s->pend.s[k].kind == HB_ARC_POST_JUMP &&
		    arc_push_jump(s->arc, &s->pend.jr))
			return hbs_fail(s, HB_ENOMEM, "out of memory for the jump records");
		if (arc_push(s->arc, &s->pend.s[k]))
			return hbs_fail(s, HB_ENOMEM, "out of memory for the arc");
	}
	if (s->pend.has_col) { /* its row was there: the array has room */
		s->col[s->ncol++] = s->pend.col;
		s->ncol_total++;
	}
	if (s->pend.tf_row >= 0 && (size_t)s->pend.tf_row < s->ncol)
		s->col[s->pend.tf_row].tf = s->pend.tf;
	s->end = s->pend.end;
	memcpy(s->err, s->pend.err, sizeof s->err);
	memcpy(s->endmsg, s->pend.endmsg, sizeof s->endmsg);
	s->pend.n = 0;
	return 0;
}

/*
 * Puts the samples after i (all of the last unit of work's) aside, with
 * what they bring, and leaves the run at sample i.  0; HB_ENOMEM or
 * HB_EINVAL (no jump record or collision where one must be) with the run
 * unchanged.
 */
int
hbs_pend_put_aside(struct hb_sim *s, size_t i)
{
	size_t n = hb_arc_len(s->arc), m = n - 1 - i, k;
	const struct hb_arc_sample *pre = NULL;

	if (m == 0)
		return 0;
	if (m > s->pend.cap) {
		struct hb_arc_sample *p = realloc(s->pend.s, m * sizeof *p);

		if (p == NULL)
			return HB_ENOMEM;
		s->pend.s = p;
		s->pend.cap = m;
	}
	s->pend.n = m;
	s->pend.has_jump = s->pend.has_col = 0;
	s->pend.tf_row = -1;
	for (k = 0; k < m; k++) {
		s->pend.s[k] = *hb_arc_at(s->arc, i + 1 + k);
		if (s->pend.s[k].kind == HB_ARC_POST_JUMP) {
			s->pend.has_jump = 1;
			pre = hb_arc_at(s->arc, i + k);   /* the pre-jump sample before it */
		}
	}
	if (s->pend.has_jump) {
		size_t nj = hb_arc_njumps(s->arc);

		if (nj == 0 || hb_arc_jump_at(s->arc, nj - 1)->j != pre->j)
			return HB_EINVAL;
		s->pend.jr = *hb_arc_jump_at(s->arc, nj - 1);
		if (s->pend.jr.from_q) {
			/* the contact that jump ended: its collision was the unit's */
			if (s->ncol == 0 || s->col[s->ncol - 1].j != pre->j)
				return HB_EINVAL;
			s->pend.col = s->col[s->ncol - 1];
			s->pend.has_col = 1;
		} else {
			/* a contact begun: the flight of its interface since its last collision */
			size_t r = s->ncol;

			while (r > 0 && s->col[r - 1].k != pre->k)
				r--;
			if (r > 0 && !isnan(s->col[r - 1].tf)) {
				s->pend.tf_row = (int)(r - 1);
				s->pend.tf = s->col[r - 1].tf;
			}
		}
	}
	/* nothing can fail from here */
	if (s->pend.has_col) {
		s->ncol--;
		s->ncol_total--;
	}
	if (s->pend.tf_row >= 0)
		s->col[s->pend.tf_row].tf = NAN;
	s->pend.t = s->t;
	s->pend.j = s->j;
	s->pend.end = s->end;
	memcpy(s->pend.err, s->err, sizeof s->err);
	memcpy(s->pend.endmsg, s->endmsg, sizeof s->endmsg);
	arc_truncate(s->arc, i + 1);
	s->t = hb_arc_at(s->arc, i)->t;
	s->j = hb_arc_at(s->arc, i)->j;
	s->end = HB_SIM_RUNNING;
	s->err[0] = s->endmsg[0] = '\0';
	s->pend.active = 1;
	return 0;
}
