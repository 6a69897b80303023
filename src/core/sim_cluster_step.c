/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_step.c - a chain's clusters of contacts: a flow interval
 * begun (the blocks of the ODE laid out, scaled and packed into the
 * engine's arrays, its phase made for the engine's driver, the earliest
 * closing of a gap between flying bodies), what begins each step (a jump
 * due at once, the step's target, the modes), and an interface's jump
 * (the steps and the location are the engine's, sim.c and sim_locate.c;
 * see sim_cluster.c for the method).
 */
#include <float.h>

#include "sim_impl.h"
#include "sim_iface.h"

/*
 * The driver of the clusters' ODE of dimension n (the engine's, sim.c and
 * sim_locate.c, stepping a phase of this system), made again where the
 * dimension or the stepper changed; room for nf watched functions.
 */
static int
build_phase(struct hb_sim *s, int n, int nf)
{
	struct clusters *c = &s->cx;
	const int st = s->stepper[1]; /* the scene's, or rk8pd for auto until it goes over to bsimp */

	if (hbs_work_reserve(s, n, nf))
		return HB_ENOMEM;
	if (c->built_dim != n || c->built_stepper != st || s->cph.d == NULL) {
		gsl_odeiv2_system sys = { hbs_cluster_rhs, hbs_cluster_jacobian, (size_t)n, s };

		c->built_dim = 0;
		if (hbs_phase_alloc_sys(s, &s->cph, &sys))
			return HB_ENOMEM;
		c->built_dim = n;
		c->built_stepper = st;
	}
	s->cur = &s->cph;
	return 0;
}

static double
pow2(double x)
{
	int e;
	double f = frexp(x, &e);

	if (!(isfinite(x) && x > 0))
		return 1.0;
	return ldexp(1.0, f < M_SQRT1_2 ? e - 1 : e);
}

/*
 * Scales of the blocks: the speed V is the largest approach or relative
 * speed of the interfaces in contact (a wave's energy passes from one to
 * the next), each interface's indentation X and speed from its law
 * (hbs_contact_scale, as the pair's), W ~ m V^2 / 2, impulses ~ m V;
 * powers of 2.
 */
static void
cscales(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	double V = 0.0;
	int p, i;

	for (p = 0; p < c->nact; p++) {
		const struct iface *I = &s->ifc[c->act[p]];

		V = fmax(V, fmax(fabs(I->v), fabs(I->vi)));
	}
	if (!(V > 1e-12))
		V = 1e-12;
	for (p = 0; p < c->nact; p++) {
		const struct iface *I = &s->ifc[c->act[p]];
		int o = I->off, nz = I->law->n_z;
		double X, Vk;

		hbs_contact_scale(I, V, I->Fer, &X, &Vk);
		s->scale[o] = X;
		s->scale[o + 1] = Vk;
		for (i = 0; i < nz; i++)
			s->scale[o + 2 + i] = X;
		s->scale[o + 2 + nz] = 0.5 * I->m * Vk * Vk;
		s->scale[o + 3 + nz] = I->m * Vk;
		s->scale[o + 4 + nz] = I->m * Vk;
	}
	for (i = 0; i < c->dim; i++) {
		s->scale[i] = pow2(s->scale[i]);
		s->iscale[i] = 1.0 / s->scale[i];
	}
	s->w.valid = 0; /* the watched values were of the old scales */
	known_forget(&s->cph.known); /* f of the scaled variables */
}

/*
 * The earliest closing of a gap between two flying bodies (both in no
 * cluster): their parabolas' quadratic, placed in D ulp by ulp.
 */
static void
free_gaps(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int i;

	c->tfree = INFINITY;
	c->ifree = -1;
	for (i = 0; i < s->nif; i++) {
		const struct iface *J = &s->ifc[i];
		double x, v, tau;

		if (J->off >= 0 || J->watch)
			continue;
		hbs_chain_gap(s, i, s->t, &x, &v);
		tau = hbs_flight_event(x, v, J->arel);
		if (s->t + tau < c->tfree) {
			c->tfree = s->t + tau;
			c->ifree = i;
		}
	}
	if (c->ifree >= 0 && c->tfree <= s->sc.run.T) {
		double x, v, te = c->tfree;
		int it = 0;

		hbs_chain_gap(s, c->ifree, te, &x, &v);
		while (!(x <= 0.0 && v <= 0.0) && it++ < 1000) {
			te = nextafter(te, INFINITY);
			hbs_chain_gap(s, c->ifree, te, &x, &v);
		}
		c->tfree = te;
	}
}

/* Room for the bodies' scratch. */
static int
ensure_bodies(struct hb_sim *s)
{
	struct clusters *c = &s->cx;

	if (c->capb < s->nbody) {
		double *by = realloc(c->by, (size_t)s->nbody * sizeof(double));
		double *bu;

		if (by == NULL)
			return HB_ENOMEM;
		c->by = by;
		bu = realloc(c->bu, (size_t)s->nbody * sizeof(double));
		if (bu == NULL)
			return HB_ENOMEM;
		c->bu = bu;
		c->capb = s->nbody;
	}
	if (c->capf < c->nf) {
		int m = c->capf > 0 ? c->capf : 16;
		int *k, *f;

		while (m < c->nf)
			m *= 2;
		if ((k = realloc(c->fkind, (size_t)m * sizeof *k)) == NULL)
			return HB_ENOMEM;
		c->fkind = k;
		if ((f = realloc(c->fif, (size_t)m * sizeof *f)) == NULL)
			return HB_ENOMEM;
		c->fif = f;
		c->capf = m;
	}
	return 0;
}

/* Begins a flow interval of a chain: its clusters' ODE laid out, scaled and packed. */
int
hbs_cluster_setup(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int p, i, n = 0, nf = 0;

	s->setup = 0;
	s->ntiny = 0;
	s->resume = 0;
	s->closed = c->nact == 0;
	for (i = 0; i < s->nif; i++)
		s->ifc[i].off = -1;
	if (c->nact == 0) {
		c->dim = 0;
		return 0;
	}
	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];

		I->off = n;
		n += 5 + I->law->n_z; /* x_c, v, z..., W, J_Fc, J_Fe */
		nf += 3 + (I->law->n_kinks && s->sc.run.kinks ? I->law->n_kinks : 0);
	}
	nf += c->nwatch;
	c->nf = nf;
	if (build_phase(s, n, nf) || ensure_bodies(s))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters' integrator");
	c->dim = n;
	/* the functions' kinds and interfaces, in the order hbs_cluster_watch computes them */
	{
		int q = 0, w = 0, f = 0;

		while (q < c->nact || w < c->nwatch) {
			if (w >= c->nwatch || (q < c->nact && c->act[q] < c->wif[w])) {
				const struct iface *I = &s->ifc[c->act[q]];
				int nk = I->law->n_kinks && s->sc.run.kinks ? I->law->n_kinks : 0;

				s->ifc[c->act[q]].fo = f;
				c->fif[f] = c->act[q];
				c->fkind[f++] = FUN_EVENT;
				for (i = 0; i < nk; i++) {
					c->fif[f] = c->act[q];
					c->fkind[f++] = FUN_KINK;
				}
				c->fif[f] = c->act[q];
				c->fkind[f++] = FUN_XCMAX;
				c->fif[f] = c->act[q];
				c->fkind[f++] = FUN_FCMAX;
				q++;
			} else {
				c->fif[f] = c->wif[w++];
				c->fkind[f++] = FUN_EVENT;
			}
		}
	}
	cscales(s);
	for (p = 0; p < c->nact; p++) {
		const struct iface *I = &s->ifc[c->act[p]];
		int o = I->off, nz = I->law->n_z;

		s->u[o] = I->xc * s->iscale[o];
		s->u[o + 1] = I->v * s->iscale[o + 1];
		for (i = 0; i < nz; i++)
			s->u[o + 2 + i] = I->z[i] * s->iscale[o + 2 + i];
		s->u[o + 2 + nz] = I->W * s->iscale[o + 2 + nz];
		s->u[o + 3 + nz] = I->JFc * s->iscale[o + 3 + nz];
		s->u[o + 4 + nz] = I->JFe * s->iscale[o + 4 + nz];
	}
	for (i = 0; i < nf; i++)
		s->gmax[i] = 0.0;
	s->first = 0;
	s->hug = 0;
	s->use_dense = s->use_herm = 0;
	free_gaps(s);
	gsl_odeiv2_driver_reset(s->cph.d);
	{
		/* the first step: 1e-2 of the fastest contact's time scale X / V */
		double Tc = INFINITY;

		for (p = 0; p < c->nact; p++) {
			const struct iface *I = &s->ifc[c->act[p]];

			Tc = fmin(Tc, s->scale[I->off] / s->scale[I->off + 1]);
		}
		s->h = s->h > 0 && s->h < 1e-2 * Tc ? s->h : 1e-2 * Tc; /* or the last interval's last */
		s->Tc = Tc;
	}
	return 0;
}

/* Interface J in flight at (t, its bodies set there): x, v into the struct, then the jump into contact. */
int
hbs_cluster_jump(struct hb_sim *s, int i, int how, int iters, double width, double ilo, double ihi)
{
	hbs_chain_activate(s, i);
	/*
	 * A gap is a difference of displacements and carries their rounding
	 * (1e-21 m for displacements of 10 um): a slow approach located to
	 * the resolution of t may end where the gap reads a rounding above 0.
	 * The pre-jump state is put on the boundary of D, x = 0, as the pair's
	 * location puts it (the bodies then differ by that rounding).
	 */
	if (!s->I->q && s->I->x > 0.0 && s->I->v < 0.0 &&
	    s->I->x <= 64.0 * DBL_EPSILON * (fabs(s->body[s->I->hi].y) +
	                                     (s->I->lo >= 0 ? fabs(s->body[s->I->lo].y) : 0.0)))
		s->I->x = 0.0;
	return hbs_jump(s, how, iters, width, ilo, ihi);
}

/*
 * Kinks as modes, per interface (hbs_iface_mode, as the pair's): the sign
 * of each law's |w| term is frozen for the step that begins at the current
 * state, so that the flow is smooth inside the step, the side a crossing
 * located at this instant went over to (I->mforce); a change restarts the
 * stepper.
 */
static void
set_modes(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int p, changed = 0;

	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];
		int m = I->mforce && I->mforce_t == s->t ? I->mforce : hbs_iface_mode(s, I, I->xc, I->z, I->v);

		if (m != I->msign) {
			I->msign = m;
			changed = 1;
		}
	}
	if (changed)
		gsl_odeiv2_driver_reset(s->cph.d);
}

/* See sim_impl.h. */
int
hbs_cluster_step_begin(struct hb_sim *s, double *t1, int *jumped)
{
	struct clusters *c = &s->cx;
	double *f0 = s->lf0;
	int i, n;

	/* an interface already outside its flow set where the interval begins jumps at once, lowest k first */
	*jumped = 1;
	n = hbs_watch_at(s, s->cur, s->t, s->u, f0, s->lkind, NULL);
	for (i = 0; i < n; i++)
		if (s->lkind[i] == FUN_EVENT && f0[i] < 0.0) {
			hbs_cluster_unpack(s, s->t, s->u);
			return hbs_cluster_jump(s, c->fif[i], HB_LOCATE_START, 0, 0.0, f0[i], f0[i]);
		}
	if (c->ifree >= 0 && c->tfree < *t1)
		*t1 = c->tfree;
	if (s->t >= *t1 && c->ifree >= 0 && c->tfree <= s->t) { /* a free gap closes now */
		double x, v;

		hbs_cluster_unpack(s, s->t, s->u);
		hbs_cluster_sync(s);
		hbs_chain_settle(s, c->ifree, s->t);
		hbs_chain_gap(s, c->ifree, s->t, &x, &v);
		s->ifc[c->ifree].x = x;
		s->ifc[c->ifree].v = v;
		return hbs_cluster_jump(s, c->ifree, HB_LOCATE_CLOSED_FORM, 0, 0.0, fmax(x, v), fmax(x, v));
	}
	*jumped = 0;
	set_modes(s);
	return 0;
}
