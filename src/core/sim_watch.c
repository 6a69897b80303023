/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_watch.c - the functions watched along a step: the indicator of the
 * flow set C, the law's switching functions, the extremum functions of x_c
 * and F_c, and the rate of the indicator; when one has crossed (see
 * sim_locate.c for how crossings are located), for the pair's interface,
 * from the per-interface terms (sim_iface.h) that a chain's clusters
 * watch with too (hbs_cluster_watch).
 */
#include "sim_impl.h"
#include "sim_iface.h"

/*
 * Values of the watched functions at a scaled state: [0] the indicator of
 * the flow set C (>= 0 in C), then the law's switching functions, then v
 * (x_c extremum) and dPhi/dt (F_c extremum).  Returns their number; kinds
 * in kind[].  With rate not NULL, *rate = dI/dt, the rate of the indicator
 * (one-sided where I has a corner).  With only >= 0, only f[only] is
 * computed (the same double), and the law's partials only where it needs
 * them: a bracketing evaluates one function many times.  With pf not NULL
 * (and all of them computed in contact), pf[0] = Phi and pf[1] = F_e,r.
 */
static int
watch(const struct hb_sim *s, const struct phase *p, double t, const double *u, double *f,
      int *kind, double *rate, int only, double *pf)
{
	const struct hb_scene *sc = &s->sc;
	const struct iface *I = s->I;
	const struct layout *L = &p->L;
	double y[MAXDIM], v, xc, z[HB_LAW_MAX_Z] = { 0 };
	double phi = 0.0, vdot, d, Fer;
	int i, nz = I->law->n_z;
	int nk = I->law->n_kinks && sc->run.kinks ? I->law->n_kinks : 0;
	int all = only < 0;

	for (i = 0; i < L->nread; i++) /* the components the functions read (as rhs) */
		y[i] = u[i] * s->scale[i];
	v = y[L->iv];
	kind[0] = FUN_EVENT;
	if (!p->q) {
		f[0] = fmax(y[L->ix], v);
		if (rate != NULL)
			*rate = y[L->ix] > v ? v : iface_Fer(s, I, t) / I->m;
		return 1;
	}
	xc = y[L->ixc];
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	for (i = 1; i <= nk; i++)
		kind[i] = FUN_KINK;
	kind[nk + 1] = FUN_XCMAX;
	kind[nk + 2] = FUN_FCMAX;
	if (all || only == 0 || only == nk + 2)
		phi = hbs_iface_phi(I, xc, z, v);
	if (all || only == 0)
		f[0] = -fmin(phi, v);
	if (nk && (all || (only >= 1 && only <= nk)))
		hbs_iface_kinks(I, xc, z, v, &f[1]);
	f[nk + 1] = v;
	if (all || only == nk + 2) {
		Fer = iface_Fer(s, I, t);
		vdot = (-phi + Fer) / I->m;
		if (pf != NULL) {
			pf[0] = phi;
			pf[1] = Fer;
		}
		d = hbs_iface_dphidt(I, xc, z, v, vdot, 0);
		f[nk + 2] = d;
		if (rate != NULL)
			*rate = phi < v ? -d : -vdot;
	}
	return nk + 3;
}

/*
 * The watched functions of the flow interval: the pair's (above), or a
 * chain's clusters' (sim_cluster.c: interface by interface, their kinds
 * laid out by the interval's setup; no rate of an indicator).
 */
int
hbs_watch(struct hb_sim *s, const struct phase *p, double t, const double *u, double *f,
          int *kind)
{
	if (s->chain) {
		hbs_cluster_watch(s, t, u, f, NULL);
		memcpy(kind, s->cx.fkind, (size_t)s->cx.nf * sizeof *kind);
		return s->cx.nf;
	}
	return watch(s, p, t, u, f, kind, NULL, -1, NULL);
}

double
hbs_watch_one(struct hb_sim *s, const struct phase *p, double t, const double *u, int k,
              int *kind)
{
	double f[MAXFUN];
	int kinds[MAXFUN];

	if (s->chain) {
		*kind = s->cx.fkind[k];
		return hbs_cluster_watch_one(s, t, u, k);
	}
	watch(s, p, t, u, f, kinds, NULL, k, NULL);
	*kind = kinds[k];
	return f[k];
}

/* The watched values at (t, u) into s->w, computed unless they are there. */
static void
watch_cached(struct hb_sim *s, const struct phase *p, double t, const double *u)
{
	size_t nu = (size_t)p->L.dim * sizeof *u;

	if (!(s->w.valid && s->w.p == p && s->w.t == t && s->w.xe == s->I->xe
	      && memcmp(s->w.u, u, nu) == 0)) {
		if (s->chain) {
			hbs_cluster_watch(s, t, u, s->w.f, s->w.r);
			s->w.n = s->cx.nf;
			memcpy(s->w.kind, s->cx.fkind, (size_t)s->w.n * sizeof *s->w.kind);
		} else {
			s->w.n = watch(s, p, t, u, s->w.f, s->w.kind, &s->w.rate, -1, s->w.pf);
		}
		s->w.p = p;
		s->w.t = t;
		s->w.xe = s->I->xe;
		memcpy(s->w.u, u, nu);
		s->w.valid = 1;
	}
}

double
hbs_watch_indicator(struct hb_sim *s, const struct phase *p, double t, const double *u)
{
	watch_cached(s, p, t, u);
	return s->w.f[0];
}

int
hbs_watch_at(struct hb_sim *s, const struct phase *p, double t, const double *u, double *f,
             int *kind, double *rate)
{
	watch_cached(s, p, t, u);
	memcpy(f, s->w.f, (size_t)s->w.n * sizeof *f);
	memcpy(kind, s->w.kind, (size_t)s->w.n * sizeof *kind);
	if (rate != NULL && s->chain) {
		memcpy(rate, s->w.r, (size_t)s->w.n * sizeof *rate);
	} else if (rate != NULL) {
		rate[0] = s->w.rate; /* its one event's (the others are no events: not read) */
	}
	return s->w.n;
}
