/*
 * sim_watch.c - the functions watched along a step: the indicator of the
 * flow set C, the law's switching functions, the extremum functions of x_c
 * and F_c, and the rate of the indicator; when one has crossed (see
 * sim_locate.c for how crossings are located).
 */
#include "sim_impl.h"

/*
 * Values of the watched functions at a scaled state: [0] the indicator of
 * the flow set C (>= 0 in C), then the law's switching functions, then v
 * (x_c extremum) and dPhi/dt (F_c extremum).  Returns their number; kinds
 * in kind[].  With rate not NULL, *rate = dI/dt, the rate of the indicator
 * (one-sided where I has a corner).
 */
static int
watch(const struct sim *s, const struct phase *p, double t, const double *u, double *f,
      int *kind, double *rate)
{
	const struct scene *sc = &s->sc;
	const struct layout *L = &p->L;
	double y[MAXDIM], v, xc, z[LAW_MAX_Z] = { 0 };
	double dphi[LAW_MAX_Z + 2], dpsi[LAW_MAX_Z * (LAW_MAX_Z + 2)], dz[LAW_MAX_Z];
	double phi, vdot, d;
	int n = 0, i, nz = sc->law->n_z;

	hbs_unscale(p, u, y);
	v = y[L->iv];
	kind[n] = FUN_EVENT;
	if (!p->q) {
		f[n++] = fmax(y[L->ix], v);
		if (rate != NULL)
			*rate = y[L->ix] > v ? v : scene_Fer(sc, t) / sc->d.m;
		return n;
	}
	xc = y[L->ixc];
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, xc, z, v);
	f[n++] = -fmin(phi, v);
	if (sc->law->n_kinks && sc->run.kinks) {
		sc->law->kinks(sc->par, sc->ext, xc, z, v, &f[n]);
		for (i = 0; i < sc->law->n_kinks; i++)
			kind[n++] = FUN_KINK;
	}
	kind[n] = FUN_XCMAX;
	f[n++] = v;
	sc->law->jac(sc->par, sc->ext, xc, z, v, dphi, nz ? dpsi : NULL);
	if (nz)
		sc->law->psi(sc->par, sc->ext, xc, z, v, dz);
	vdot = (-phi + scene_Fer(sc, t)) / sc->d.m;
	d = dphi[0] * v + dphi[nz + 1] * vdot;
	for (i = 0; i < nz; i++)
		d += dphi[1 + i] * dz[i];
	kind[n] = FUN_FCMAX;
	f[n++] = d;
	if (rate != NULL)
		*rate = phi < v ? -d : -vdot;
	return n;
}

int
hbs_watch(const struct sim *s, const struct phase *p, double t, const double *u, double *f,
          int *kind)
{
	return watch(s, p, t, u, f, kind, NULL);
}

int
hbs_watch_at(struct sim *s, const struct phase *p, double t, const double *u, double *f,
             int *kind, double *rate)
{
	size_t nu = (size_t)p->L.dim * sizeof *u;

	if (!(s->w.valid && s->w.p == p && s->w.t == t && s->w.xe == s->xe
	      && memcmp(s->w.u, u, nu) == 0)) {
		s->w.n = watch(s, p, t, u, s->w.f, s->w.kind, &s->w.rate);
		s->w.p = p;
		s->w.t = t;
		s->w.xe = s->xe;
		memcpy(s->w.u, u, nu);
		s->w.valid = 1;
	}
	memcpy(f, s->w.f, (size_t)s->w.n * sizeof *f);
	memcpy(kind, s->w.kind, (size_t)s->w.n * sizeof *kind);
	if (rate != NULL)
		*rate = s->w.rate;
	return s->w.n;
}
