/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_record.c - samples, collision records and the jump map g (see sim.c for the method); how
 * a run ends: sim_end.c.
 */
#include "sim_impl.h"
#include "sim_sample.h"

int
hbs_push_sample(struct hb_sim *s, int kind)
{
	struct iface *I = s->I;
	struct hb_arc_sample a;
	double phi = 0.0, Fer;
	/*
	 * Phi and F_e,r at a step's end were computed by the watch of that
	 * state (hbs_watch_at), the same doubles: taken from there when it was
	 * this state, in contact (not for a chain, whose forces the bodies'
	 * sync may move).
	 */
	int watched = !s->chain && I->q && s->w.valid && s->w.p == s->cur && s->w.p->q && s->w.t == s->t
	              && s->w.xe == I->xe
	              && memcmp(s->w.u, s->u, (size_t)s->cur->L.dim * sizeof *s->u) == 0;
	int rc;

	if (s->chain && (rc = hbs_bodies_sync(s)))
		return rc;
	memset(&a, 0, sizeof a);
	a.t = s->t;
	a.j = s->j;
	a.kind = kind;
	if (I->q) {
		phi = watched ? s->w.pf[0] : phi_at(s, I->xc, I->z, I->v);
		if (fabs(I->xc) > I->xcmax)
			I->xcmax = fabs(I->xc);
		if (-phi > I->Fcmax)
			I->Fcmax = -phi;
	}
	hbs_sample_put(&a, I, s); /* the state (sim_sample.h), extrema updated */
	a.Fc = -phi;
	Fer = watched ? s->w.pf[1] : iface_Fer(s, I, s->t);
	a.Fer = Fer;
	a.k = s->k0 + s->ia;
	if (arc_push(s->arc, &a))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the arc");
	s->unit_n++;
	return 0;
}

static int
push_collision(struct hb_sim *s)
{
	struct iface *I = s->I;
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
	c.te = I->te;
	c.ts = s->t;
	c.td = s->t - I->te;
	c.tf = NAN;
	c.vi = I->vi;
	c.e = I->vi != 0.0 && !I->pushed ? -I->v / I->vi : NAN;
	c.xcmax = I->xcmax;
	c.Fcmax = I->Fcmax;
	c.xcr = fabs(I->xc);
	c.xcr_sum = (s->ncol > 0 ? s->col[s->ncol - 1].xcr_sum : 0.0) + c.xcr;
	c.W = I->W;
	c.JFc = I->JFc;
	c.JFe = I->JFe;
	c.Lambda = I->JFc != 0.0 ? I->JFe / I->JFc : NAN;
	c.complete = 1;
	c.k = s->k0 + s->ia;
	s->col[s->ncol++] = c;
	return 0;
}

/*
 * A chain's contact that begins at a relative velocity below 1e-6 of the
 * fastest relative velocity of an interface in contact at that instant is
 * a touching pair pushed together by its neighbour, not an impact: it has
 * no coefficient of restitution (e would be v_s over a rounding error).
 */
static int
pushed_into(const struct hb_sim *s, const struct iface *I)
{
	double vmax = 0.0;
	int i;

	for (i = 0; i < s->nif; i++)
		if (&s->ifc[i] != I && s->ifc[i].q && fabs(s->ifc[i].v) > vmax)
			vmax = fabs(s->ifc[i].v);
	return fabs(I->vi) < 1e-6 * vmax;
}

/*
 * The jump: the pre-jump sample (in D), the record of how it was located,
 * the collision when a contact ends, g applied exactly, the post-jump
 * sample.
 */
int
hbs_jump(struct hb_sim *s, int how, int iterations, double width, double ilo, double ihi)
{
	struct iface *I = s->I;
	struct hb_arc_jump jr;
	int rc;

	if ((rc = hbs_push_sample(s, HB_ARC_PRE_JUMP)))
		return rc;
	/*
	 * Chatter: one interface jumping again and again at one instant.  In
	 * a chain, several interfaces may each jump once at an instant (a
	 * touching chain set moving), so the jumps are counted per interface.
	 */
	if (I->ninst > 0 && s->t == I->tinst)
		I->ninst++;
	else {
		I->ninst = 1;
		I->tinst = s->t;
	}
	if (I->ninst > s->sc.run.chatter) {
		char why[160];

		if (s->chain)
			snprintf(why, sizeof why,
			         "%d jumps of interface %d at one instant (run.chatter = %d): the run "
			         "would jump without end", I->ninst, s->k0 + s->ia, s->sc.run.chatter);
		else
			snprintf(why, sizeof why,
			         "%d jumps at one instant (run.chatter = %d): the run would jump without end",
			         I->ninst, s->sc.run.chatter);
		return hbs_fail(s, HB_ECHATTER, why);
	}
	jr.t = s->t;
	jr.j = s->j;
	jr.from_q = I->q;
	jr.left = I->q ? "contact: Phi > 0 and v > 0" : "flight: x < 0 and v < 0";
	jr.how = how;
	jr.iterations = iterations;
	jr.width = width;
	jr.ind_lo = ilo;
	jr.ind_hi = ihi;
	if (arc_push_jump(s->arc, &jr))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the jump records");
	if (I->q && (rc = push_collision(s)))
		return rc;

	/* g: x, v, x_m, v_m unchanged; x_c = 0, z_c = 0, q_c = 1 - q_c */
	I->q = 1 - I->q;
	s->j++;
	I->xc = 0.0;
	memset(I->z, 0, sizeof I->z);
	I->W = I->JFc = I->JFe = 0.0;
	I->xcmax = I->Fcmax = 0.0;
	I->over = 0;
	I->msign = 0;
	if (I->q) {
		I->te = s->t;
		I->vi = I->v;
		I->vmax = fabs(I->v);
		I->pushed = s->chain && pushed_into(s, I);
		I->xe = I->x;
		I->Wc0 = I->Wc;
		if (!s->chain) {
			if (s->ncol > 0 && isnan(s->col[s->ncol - 1].tf))
				s->col[s->ncol - 1].tf = s->t - s->col[s->ncol - 1].ts;
		} else {
			/* a chain: the flight of this interface since its last collision */
			size_t r = s->ncol;

			while (r > 0 && s->col[r - 1].k != s->k0 + s->ia)
				r--;
			if (r > 0 && isnan(s->col[r - 1].tf))
				s->col[r - 1].tf = s->t - s->col[r - 1].ts;
		}
	}
	if (s->chain && (rc = hbs_cluster_jumped(s)))
		return rc;
	s->st.jumps++;
	if ((rc = hbs_push_sample(s, HB_ARC_POST_JUMP)))
		return rc;
	s->setup = 1;
	if (s->j >= s->sc.run.J)
		hbs_finish_J(s);
	return 0;
}
