/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_record.c - samples, collision records, the jump map g and the ends of a run (see sim.c for the method).
 */
#include "sim_impl.h"
#include "cnum.h"

int
hbs_fail(struct hb_sim *s, int status, const char *why)
{
	s->end = HB_SIM_END_FAIL;
	cnum_snprintf(s->err, sizeof s->err,
	         "%s at (t = %.12g s, j = %ld): x = %.6g m, v = %.6g m/s, x_c = %.6g m, q_c = %d",
	         why, s->t, s->j, s->x, s->v, s->xc, s->q);
	snprintf(s->endmsg, sizeof s->endmsg, "failed: %s", s->err);
	return status;
}

int
hbs_push_sample(struct hb_sim *s, int kind)
{
	struct hb_arc_sample a;
	double phi = 0.0;

	memset(&a, 0, sizeof a);
	a.t = s->t;
	a.j = s->j;
	a.q = s->q;
	a.kind = kind;
	a.x = s->x;
	a.v = s->v;
	if (s->q) {
		phi = phi_at(s, s->xc, s->z, s->v);
		a.xc = s->xc;
		memcpy(a.z, s->z, sizeof a.z);
		if (fabs(s->xc) > s->xcmax)
			s->xcmax = fabs(s->xc);
		if (-phi > s->Fcmax)
			s->Fcmax = -phi;
	}
	a.Fc = -phi;
	a.Fer = hb_scene_Fer(&s->sc, s->t);
	a.xm = s->xm;
	a.vm = s->vm;
	a.W = s->W;
	a.JFc = s->JFc;
	a.JFe = s->JFe;
	a.xcmax = s->xcmax;
	a.Fcmax = s->Fcmax;
	a.Ee = s->Ee;
	a.Wc = s->Wc;
	if (arc_push(s->arc, &a))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the arc");
	return 0;
}

static int
push_collision(struct hb_sim *s)
{
	struct hb_collision c;

	/*
	 * Bounded like the arc: at run.max_samples / 8 collisions every other
	 * one of the older three quarters goes; each kept row has its index i.
	 */
	size_t bound = s->sc.run.max_samples / 8 < 128 ? 128 : (size_t)s->sc.run.max_samples / 8;

	if (s->ncol >= bound) {
		size_t w = 0, upto = s->ncol - s->ncol / 4;

		for (size_t r = 0; r < s->ncol; r++)
			if (r >= upto || r % 2 == 0)
				s->col[w++] = s->col[r];
		s->ncol = w;
	}
	if (s->ncol == s->colcap) {
		size_t cap = s->colcap ? 2 * s->colcap : 64;
		struct hb_collision *p = realloc(s->col, cap * sizeof *p);

		if (p == NULL)
			return hbs_fail(s, HB_ENOMEM, "out of memory for the collisions");
		s->col = p;
		s->colcap = cap;
	}
	memset(&c, 0, sizeof c);
	c.i = s->ncol_total++;
	c.j = s->j;
	c.te = s->te;
	c.ts = s->t;
	c.td = s->t - s->te;
	c.tf = NAN;
	c.vi = s->vi;
	c.e = s->vi != 0.0 ? -s->v / s->vi : NAN;
	c.xcmax = s->xcmax;
	c.Fcmax = s->Fcmax;
	c.xcr = fabs(s->xc);
	c.xcr_sum = (s->ncol > 0 ? s->col[s->ncol - 1].xcr_sum : 0.0) + c.xcr;
	c.W = s->W;
	c.JFc = s->JFc;
	c.JFe = s->JFe;
	c.Lambda = s->JFc != 0.0 ? s->JFe / s->JFc : NAN;
	c.complete = 1;
	s->col[s->ncol++] = c;
	return 0;
}

/*
 * The jump: the pre-jump sample (in D), the record of how it was located,
 * the collision when a contact ends, g applied exactly, the post-jump
 * sample.
 */
int
hbs_jump(struct hb_sim *s, int how, int iterations, double width, double ilo, double ihi)
{
	struct hb_arc_jump jr;
	int rc;

	if ((rc = hbs_push_sample(s, HB_ARC_PRE_JUMP)))
		return rc;
	if (s->n_instant > 0 && s->t == s->t_instant)
		s->n_instant++;
	else {
		s->n_instant = 1;
		s->t_instant = s->t;
	}
	if (s->n_instant > s->sc.run.chatter) {
		char why[160];

		snprintf(why, sizeof why,
		         "%d jumps at one instant (run.chatter = %d): the run would jump without end",
		         s->n_instant, s->sc.run.chatter);
		return hbs_fail(s, HB_ECHATTER, why);
	}
	jr.t = s->t;
	jr.j = s->j;
	jr.from_q = s->q;
	jr.left = s->q ? "contact: Phi > 0 and v > 0" : "flight: x < 0 and v < 0";
	jr.how = how;
	jr.iterations = iterations;
	jr.width = width;
	jr.ind_lo = ilo;
	jr.ind_hi = ihi;
	if (arc_push_jump(s->arc, &jr))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the jump records");
	if (s->q && (rc = push_collision(s)))
		return rc;

	/* g: x, v, x_m, v_m unchanged; x_c = 0, z_c = 0, q_c = 1 - q_c */
	s->q = 1 - s->q;
	s->j++;
	s->xc = 0.0;
	memset(s->z, 0, sizeof s->z);
	s->W = s->JFc = s->JFe = 0.0;
	s->xcmax = s->Fcmax = 0.0;
	if (s->q) {
		s->te = s->t;
		s->vi = s->v;
		s->xe = s->x;
		s->Wc0 = s->Wc;
		if (s->ncol > 0 && isnan(s->col[s->ncol - 1].tf))
			s->col[s->ncol - 1].tf = s->t - s->col[s->ncol - 1].ts;
	}
	s->st.jumps++;
	if ((rc = hbs_push_sample(s, HB_ARC_POST_JUMP)))
		return rc;
	s->setup = 1;
	if (s->j >= s->sc.run.J) {
		s->end = HB_SIM_END_J;
		cnum_snprintf(s->endmsg, sizeof s->endmsg,
		         "jump cap J = %ld reached at t = %.9g s", s->sc.run.J, s->t);
	}
	return 0;
}

void
hbs_finish_T(struct hb_sim *s)
{
	s->end = HB_SIM_END_T;
	cnum_snprintf(s->endmsg, sizeof s->endmsg, "horizon T = %.9g s reached at j = %ld",
	         s->sc.run.T, s->j);
}
