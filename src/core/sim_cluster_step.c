/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_step.c - a chain's clusters of contacts: a flow interval
 * begun (the blocks of the ODE laid out, scaled and packed, the earliest
 * closing of a gap between flying bodies), and one accepted step with
 * the earliest crossing of a watched function (located by
 * sim_cluster_locate.c; see sim_cluster.c for the method).
 */
#include <float.h>

#include "sim_impl.h"
#include "sim_iface.h"

/* Whether a chain's clusters can run with the scene's stepper (explicit, bsimp, or auto). */
int
hbs_chain_stepper_ok(int stepper)
{
	return stepper == HB_STEPPER_AUTO || stepper == HB_STEPPER_BSIMP || hbs_explicit_stepper(stepper);
}

/* (Re)allocates the ODE's workspace for dimension n. */
static int
alloc_ode(struct hb_sim *s, int n)
{
	struct clusters *c = &s->cx;
	const struct hb_scene *sc = &s->sc;
	const int st = s->stepper[1]; /* the scene's, or rk8pd for auto until it goes over to bsimp */
	const gsl_odeiv2_step_type *T = hbs_stepper_type(st);
	int cap = c->capdim;

	if (n > cap) {
		int m = cap > 0 ? cap : 16;
		double **arr[] = { &c->u, &c->u0, &c->u1, &c->scale, &c->iscale, &c->yerr, &c->d0, &c->d1 };

		while (m < n)
			m *= 2;
		for (size_t i = 0; i < sizeof arr / sizeof arr[0]; i++) {
			double *q = realloc(*arr[i], (size_t)m * sizeof(double));

			if (q == NULL)
				return HB_ENOMEM;
			*arr[i] = q;
		}
		{
			double *q = realloc(c->rsu, (size_t)CCACHE * (size_t)m * sizeof(double));

			if (q == NULL)
				return HB_ENOMEM;
			c->rsu = q;
		}
		c->capdim = m;
	}
	if (c->built_dim == n && c->built_stepper == st && c->step != NULL) {
		gsl_odeiv2_control_init(c->ctl, sc->run.atol, sc->run.rtol, 1.0, 0.0);
		return 0;
	}
	if (c->step)
		gsl_odeiv2_step_free(c->step);
	if (c->loc)
		gsl_odeiv2_step_free(c->loc);
	if (c->ev)
		gsl_odeiv2_evolve_free(c->ev);
	c->step = gsl_odeiv2_step_alloc(T, (size_t)n);
	c->loc = gsl_odeiv2_step_alloc(T, (size_t)n);
	c->ev = gsl_odeiv2_evolve_alloc((size_t)n);
	if (c->ctl == NULL)
		c->ctl = gsl_odeiv2_control_standard_new(sc->run.atol, sc->run.rtol, 1.0, 0.0);
	else
		gsl_odeiv2_control_init(c->ctl, sc->run.atol, sc->run.rtol, 1.0, 0.0);
	if (c->step == NULL || c->loc == NULL || c->ev == NULL || c->ctl == NULL) {
		c->built_dim = 0;
		return HB_ENOMEM;
	}
	c->sys = (gsl_odeiv2_system){ hbs_cluster_rhs, hbs_cluster_jacobian, (size_t)n, s };
	known_init(&c->known, c->ev, c->step);
	c->built_dim = n;
	c->built_stepper = st;
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
		c->scale[o] = X;
		c->scale[o + 1] = Vk;
		for (i = 0; i < nz; i++)
			c->scale[o + 2 + i] = X;
		c->scale[o + 2 + nz] = 0.5 * I->m * Vk * Vk;
		c->scale[o + 3 + nz] = I->m * Vk;
		c->scale[o + 4 + nz] = I->m * Vk;
	}
	for (i = 0; i < c->dim; i++) {
		c->scale[i] = pow2(c->scale[i]);
		c->iscale[i] = 1.0 / c->scale[i];
	}
	known_forget(&c->known); /* f of the scaled variables */
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

/* Room for nf watched functions and the bodies' scratch. */
static int
ensure_f(struct hb_sim *s, int nf)
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
	if (nf > c->capf) {
		int m = c->capf > 0 ? c->capf : 16;
		double **d[] = { &c->f0, &c->fe, &c->gmax };
		int **k[] = { &c->fkind, &c->fif };

		while (m < nf)
			m *= 2;
		for (size_t i = 0; i < sizeof d / sizeof d[0]; i++) {
			double *q = realloc(*d[i], (size_t)m * sizeof(double));

			if (q == NULL)
				return HB_ENOMEM;
			*d[i] = q;
		}
		for (size_t i = 0; i < sizeof k / sizeof k[0]; i++) {
			int *q = realloc(*k[i], (size_t)m * sizeof(int));

			if (q == NULL)
				return HB_ENOMEM;
			*k[i] = q;
		}
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
	if (alloc_ode(s, n) || ensure_f(s, nf))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the clusters' integrator");
	c->dim = n;
	c->nf = nf;
	/* the functions' kinds and interfaces, in the order hbs_cluster_watch computes them */
	{
		int q = 0, w = 0, f = 0;

		while (q < c->nact || w < c->nwatch) {
			if (w >= c->nwatch || (q < c->nact && c->act[q] < c->wif[w])) {
				const struct iface *I = &s->ifc[c->act[q]];
				int nk = I->law->n_kinks && s->sc.run.kinks ? I->law->n_kinks : 0;

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

		c->u[o] = I->xc * c->iscale[o];
		c->u[o + 1] = I->v * c->iscale[o + 1];
		for (i = 0; i < nz; i++)
			c->u[o + 2 + i] = I->z[i] * c->iscale[o + 2 + i];
		c->u[o + 2 + nz] = I->W * c->iscale[o + 2 + nz];
		c->u[o + 3 + nz] = I->JFc * c->iscale[o + 3 + nz];
		c->u[o + 4 + nz] = I->JFe * c->iscale[o + 4 + nz];
	}
	for (i = 0; i < nf; i++)
		c->gmax[i] = 0.0;
	hbs_cluster_watch(s, s->t, c->u, c->f0);
	free_gaps(s);
	gsl_odeiv2_evolve_reset(c->ev);
	gsl_odeiv2_step_reset(c->step);
	{
		/* the first step: 1e-2 of the fastest contact's time scale X / V */
		double Tc = INFINITY;

		for (p = 0; p < c->nact; p++) {
			const struct iface *I = &s->ifc[c->act[p]];

			Tc = fmin(Tc, c->scale[I->off] / c->scale[I->off + 1]);
		}
		c->h = c->h > 0 && c->h < 1e-2 * Tc ? c->h : 1e-2 * Tc;
		s->Tc = Tc;
	}
	return 0;
}

/* A watched function's value at (t, u): the root finder's function for events, kinks and extrema. */
static double
watched(struct hb_sim *s, double t, const double *u, const void *arg)
{
	return hbs_cluster_watch_one(s, t, u, *(const int *)arg);
}

/* Interface J in flight at (t, its bodies set there): x, v into the struct, then the jump into contact. */
static int
jump_iface(struct hb_sim *s, int i, int how, int iters, double width, double ilo, double ihi)
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
 * state, so that the flow is smooth inside the step; a change restarts
 * the stepper.
 */
static void
set_modes(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	int p, changed = 0;

	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];
		int m = hbs_iface_mode(s, I, I->xc, I->z, I->v);

		if (m != I->msign) {
			I->msign = m;
			changed = 1;
		}
	}
	if (changed) {
		gsl_odeiv2_evolve_reset(c->ev);
		gsl_odeiv2_step_reset(c->step);
	}
}

/* One accepted step of a chain's clusters, with what follows from it. */
int
hbs_cluster_step(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	const struct hb_scene *sc = &s->sc;
	double t = s->t, t1 = sc->run.T, hbest = INFINITY;
	int i, rc, best = -1, iters = 0;

	/* an interface already outside its flow set where the interval begins jumps at once, lowest k first */
	for (i = 0; i < c->nf; i++)
		if (c->fkind[i] == FUN_EVENT && c->f0[i] < 0.0) {
			hbs_cluster_unpack(s, s->t, c->u);
			return jump_iface(s, c->fif[i], HB_LOCATE_START, 0, 0.0, c->f0[i], c->f0[i]);
		}
	if (c->ifree >= 0 && c->tfree < t1)
		t1 = c->tfree;
	if (t >= t1 && c->ifree >= 0 && c->tfree <= t) { /* a free gap closes now */
		double x, v;

		hbs_cluster_unpack(s, s->t, c->u);
		hbs_cluster_sync(s);
		hbs_chain_settle(s, c->ifree, s->t);
		hbs_chain_gap(s, c->ifree, s->t, &x, &v);
		s->ifc[c->ifree].x = x;
		s->ifc[c->ifree].v = v;
		return jump_iface(s, c->ifree, HB_LOCATE_CLOSED_FORM, 0, 0.0, fmax(x, v), fmax(x, v));
	}
	set_modes(s);
	memcpy(c->u0, c->u, (size_t)c->dim * sizeof(double));
	c->t0 = t;
	c->hd0 = 0;
	c->hh = NAN;
	c->nrs = c->rsnext = 0;
	if ((rc = hbs_evolve(s, &c->known, c->ev, c->ctl, c->step, &c->sys, c->t0, c->u0, t1, &t, &c->h,
	                     c->u, &c->H)))
		return rc;
	/* the watched functions at the step's end against its start: the earliest crossing */
	{
		double *fend = c->fe;

		hbs_cluster_watch(s, t, c->u, fend);
		for (i = 0; i < c->nf; i++) {
			double a = c->f0[i], b = fend[i], hb = 0.0;
			int it = 0;

			if (!hbs_candidate(s, c->fkind[i], c->gmax[i], a, b))
				continue;
			if ((rc = hbs_cluster_locate(s, c->fkind[i], watched, &i, c->H, a,
			                             fmax(c->gmax[i], fmax(fabs(a), fabs(b))), &hb, &it)))
				return rc;
			iters += it;
			/* a kink or extremum at the step's start to the resolution of t: no progress to make */
			if (c->fkind[i] != FUN_EVENT && hb <= fmax(8.0 * DBL_EPSILON * fabs(c->t0 + c->H), 1e-13 * c->H))
				continue;
			if (hb < hbest) {
				hbest = hb;
				best = i;
			}
		}
		if (best >= 0) {
			if (hbs_cluster_restep(s, hbest) != GSL_SUCCESS)
				return hbs_fail(s, HB_ENUMERIC, "a re-step to locate an event failed");
			memcpy(c->u, c->u1, (size_t)c->dim * sizeof(double));
			t = c->t0 + hbest;
			hbs_cluster_watch(s, t, c->u, fend);
			/*
			 * A kink or an extremum located within the resolution of t
			 * just past an event (Hertz separates where its kink at
			 * x_c = 0 is): the state is out of C there, so the event is
			 * taken (the lowest k first).
			 */
			if (c->fkind[best] != FUN_EVENT)
				for (i = 0; i < c->nf; i++)
					if (c->fkind[i] == FUN_EVENT && c->f0[i] >= 0.0 && fend[i] < 0.0) {
						best = i;
						break;
					}
		}
		for (i = 0; i < c->nf; i++) {
			c->gmax[i] = fmax(c->gmax[i], fabs(fend[i]));
			c->f0[i] = fend[i];
		}
	}
	hbs_cluster_unpack(s, t, c->u);
	if ((rc = hbs_cluster_limits(s)))
		return rc;
	if (best >= 0)
		s->st.located++;
	if (best >= 0 && c->fkind[best] == FUN_EVENT) {
		double fb = c->f0[best];

		return jump_iface(s, c->fif[best], HB_LOCATE_BRENT, iters, 0.0, fb, fb);
	}
	if (best >= 0 && c->fkind[best] == FUN_KINK)
		s->st.kinks++;
	if (best >= 0) { /* a kink or an extremum: the step ends there, the stepper restarts */
		gsl_odeiv2_evolve_reset(c->ev);
		gsl_odeiv2_step_reset(c->step);
		if (c->fkind[best] == FUN_XCMAX || c->fkind[best] == FUN_FCMAX)
			return hbs_push_sample(s, HB_ARC_EXTREMUM);
	}
	if ((rc = hbs_push_sample(s, HB_ARC_STEP)))
		return rc;
	if ((rc = hbs_cluster_stiffness(s)))
		return rc;
	if (s->t >= sc->run.T) {
		if ((rc = hbs_push_sample(s, HB_ARC_END)))
			return rc;
		hbs_finish_T(s);
	}
	return 0;
}
