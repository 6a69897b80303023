/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_flow.c - the flow map: the right-hand side and its Jacobian in scaled variables, the
 * layouts and GSL workspaces of the phases, the scales of the components, and
 * the packing of the canonical state (see sim.c for the method).
 */
#include "sim_impl.h"
#include "sim_iface.h"
#include "step_vern98.h"

int
hbs_explicit_stepper(int stepper)
{
	return stepper == HB_STEPPER_RK8PD || stepper == HB_STEPPER_RKF45 || stepper == HB_STEPPER_RKCK ||
	       stepper == HB_STEPPER_DOP853 || stepper == HB_STEPPER_VERN98;
}

/* The GSL step type of a stepper (auto's is rk8pd until it goes over to bsimp): both systems'. */
const gsl_odeiv2_step_type *
hbs_stepper_type(int stepper)
{
	switch (stepper) {
	case HB_STEPPER_RKF45: return gsl_odeiv2_step_rkf45;
	case HB_STEPPER_RKCK: return gsl_odeiv2_step_rkck;
	case HB_STEPPER_MSBDF: return gsl_odeiv2_step_msbdf;
	case HB_STEPPER_RK4IMP: return gsl_odeiv2_step_rk4imp;
	case HB_STEPPER_BSIMP: return hb_step_bsimp_shifted;
	case HB_STEPPER_DOP853: return hb_step_dop853;
	case HB_STEPPER_VERN98: return hb_step_vern98;
	default: return hb_step_rk8pd;
	}
}

/*
 * One accepted step of GSL's evolver from (t0, u0) towards t1, for the
 * engine's driver (sim.c): the state into (*t, u), the step's length into *H, the
 * rejections counted; what the step evaluated of f kept in k (known.h).
 * A step whose accepted state is not finite is taken again, a quarter as
 * long, with the stepper's memory cleared (never let a NaN error norm pass
 * as small); a run of steps at the resolution of t fails.  0, or
 * hbs_fail's status with u = u0.
 */
int
hbs_evolve(struct hb_sim *s, struct known_f *k, gsl_odeiv2_evolve *e, gsl_odeiv2_control *c,
           gsl_odeiv2_step *st, const gsl_odeiv2_system *sys, double t0, const double *u0, double t1,
           double *t, double *h, double *u, double *H)
{
	size_t n = sys->dimension, i;
	int rc, tries = 0;
	double fin;

	for (;;) {
		unsigned long failed0 = e->failed_steps;

		rc = gsl_odeiv2_evolve_apply(e, c, st, sys, t, t1, h, u);
		if (rc == GSL_SUCCESS)
			known_keep(k, t0);
		s->st.rejected += (long)(e->failed_steps - failed0);
		if (rc != GSL_SUCCESS) {
			memcpy(u, u0, n * sizeof *u);
			return hbs_fail(s, HB_ENUMERIC, rc == GSL_EBADFUNC ? "the flow function failed"
			                : "no acceptable step could be made (step size underflow)");
		}
		/* 0 x u is 0 where u is finite, NaN where it is not: the sum is 0 where all are */
		for (fin = 0.0, i = 0; i < n; i++)
			fin += 0.0 * u[i];
		if (fin == 0.0)
			break;
		memcpy(u, u0, n * sizeof *u);
		*t = t0;
		*h *= 0.25;
		gsl_odeiv2_evolve_reset(e);
		gsl_odeiv2_step_reset(st);
		if (!(++tries < MAX_RETRY && t0 + *h > t0))
			return hbs_fail(s, HB_ENUMERIC, "the state became non-finite");
	}
	s->st.steps++;
	*H = *t - t0;
	if (*H <= fmax(4.0 * DBL_EPSILON * fabs(*t), 1e-13 * s->Tc)) {
		if (++s->ntiny > MAX_TINY)
			return hbs_fail(s, HB_ENUMERIC, "step size underflow: the error cannot be controlled");
	} else {
		s->ntiny = 0;
	}
	return 0;
}

void
hbs_unscale(const struct phase *p, const double *u, double *y)
{
	int i;

	for (i = 0; i < p->L.dim; i++)
		y[i] = u[i] * p->s->scale[i];
}

/*
 * f of eqs. Hr_f / H_f restricted to the components of the layout:
 *     x' = v, v' = (-q Phi + F_er)/m, x_c' = v, z' = Psi,
 *     W' = Phi v (= -F_c v), J_Fc' = -Phi (= F_c), J_Fe' = F_er,
 *     x_m' = v_m, v_m' = (F_e1 + F_e2)/(m1 + m2).
 * Returns GSL_FAILURE (a plain error: the evolver halves the step) when a
 * trial stage is not finite.
 */
int
hbs_rhs(double t, const double u[], double du[], void *params)
{
	struct phase *p = params;
	struct hb_sim *s = p->s;
	const struct layout *L = &p->L;
	const struct hb_scene *sc = &s->sc;
	const struct iface *I = s->I;
	const double *is = s->iscale;
	double y[MAXDIM];
	double Fer = iface_Fer(s, I, t), phi = 0.0, v, bad = 0.0;
	int i;

	s->st.rhs++;
	for (i = 0; i < L->nread; i++) /* the components f depends on; the rest are integrals */
		y[i] = u[i] * s->scale[i];
	v = y[L->iv];
	/* each du is scaled as it is written; bad turns NaN as soon as one du is NaN or infinite */
#define PUT(k, val) (du[k] = (val) * is[k], bad += 0.0 * du[k])
	if (p->q) {
		const int nz = I->law->n_z;
		const double *z = nz ? &y[L->iz] : NULL;
		double dz[HB_LAW_MAX_Z];

		phi = I->law->phi(I->par, I->ext, y[L->ixc], z, v);
		if (s->msign)
			I->law->psi_mode(I->par, I->ext, y[L->ixc], z, v, s->msign, dz);
		else if (nz)
			I->law->psi(I->par, I->ext, y[L->ixc], z, v, dz);
		PUT(L->ixc, v);
		for (i = 0; i < nz; i++)
			PUT(L->iz + i, dz[i]);
		PUT(L->iW, phi * v);
		PUT(L->iJc, -phi);
		PUT(L->iJe, Fer);
	}
	if (L->ix >= 0)
		PUT(L->ix, v);
	PUT(L->iv, (-phi + Fer) / I->m);
	PUT(L->iEe, Fer * v);
	if (L->ixm >= 0) {
		double F1, F2;

		hb_scene_loads_at(sc, t, &F1, &F2);
		PUT(L->ixm, u[L->ivm] * s->scale[L->ivm]);
		PUT(L->ivm, sc->d.system == HB_SCENE_FULL ? (F1 + F2) / (sc->d.m1 + sc->d.m2) : 0.0);
	}
#undef PUT
	if (bad != 0.0 || isnan(bad))
		return GSL_FAILURE;
	return GSL_SUCCESS;
}

static double
Fer_rate(const struct hb_sim *s, const struct iface *I, double t)
{
	double h = 1e-7 * (fabs(t) + 1e-3);

	return (iface_Fer(s, I, t + h) - iface_Fer(s, I, t - h)) / (2 * h);
}

/* The pair's Jacobian, unscaled: an entry set (hbs_iface_jac_block's put). */
struct jset {
	double *J;
	int n;
};

static void
jset(void *ctx, int row, int col, double val)
{
	struct jset *j = ctx;

	j->J[row * j->n + col] = val;
}

/* The Jacobian of rhs, for the implicit steppers; the law's partials (the contact's block per interface). */
int
hbs_jacobian(double t, const double u[], double *dfdu, double dfdt[], void *params)
{
	struct phase *p = params;
	struct hb_sim *s = p->s;
	const struct layout *L = &p->L;
	const struct iface *I = s->I;
	int n = L->dim, nz = I->law->n_z, i, k;
	double y[MAXDIM], J[MAXDIM * MAXDIM], dt[MAXDIM];
	double m = I->m, Ferdot = Fer_rate(s, I, t);

	s->st.jac++;
	hbs_unscale(p, u, y);
	memset(J, 0, sizeof J);
	memset(dt, 0, sizeof dt);
	if (L->ix >= 0)
		J[L->ix * n + L->iv] = 1.0;
	dt[L->iv] = Ferdot / m;
	if (p->q) {
		double dphi[HB_LAW_MAX_Z + 2], dpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];
		const double *z = nz ? &y[L->iz] : NULL;
		double v = y[L->iv];
		double phi = I->law->phi(I->par, I->ext, y[L->ixc], z, v);
		struct jrows r = { L->ixc, L->iv, L->iz, L->iW, L->iJc };
		struct jset js = { J, n };

		I->law->jac(I->par, I->ext, y[L->ixc], z, v, dphi, nz ? dpsi : NULL);
		hbs_iface_jac_block(I, &r, v, phi, dphi, dpsi, 1.0, m, jset, &js);
		dt[L->iJe] = Ferdot;
	}
	J[L->iEe * n + L->iv] = iface_Fer(s, I, t);
	dt[L->iEe] = Ferdot * y[L->iv];
	if (L->ixm >= 0)
		J[L->ixm * n + L->ivm] = 1.0;
	for (i = 0; i < n; i++) {
		for (k = 0; k < n; k++)
			dfdu[i * n + k] = J[i * n + k] * s->scale[k] * s->iscale[i];
		dfdt[i] = dt[i] * s->iscale[i];
	}
	return GSL_SUCCESS;
}

static void
make_layout(const struct hb_scene *sc, const struct iface *I, int q, struct layout *L)
{
	int n = 0;
	int com = !(sc->run.reduce & HB_REDUCE_COM);

	*L = (struct layout){ 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0 };
	if (q) {
		if (!(sc->run.reduce & HB_REDUCE_CONTACT))
			L->ix = n++;
		L->ixc = n++;
		L->iv = n++;
		if (I->law->n_z) {
			L->iz = n;
			n += I->law->n_z;
		}
		L->nread = n;
		L->iW = n++;
		L->iJc = n++;
		L->iJe = n++;
	} else {
		L->ix = n++;
		L->iv = n++;
		L->nread = n;
	}
	L->iEe = n++;
	if (com) {
		L->ixm = n++;
		L->ivm = n++;
	}
	L->dim = n;
}

void
hbs_phase_free(struct phase *p)
{
	if (p->d)
		gsl_odeiv2_driver_free(p->d);
	if (p->loc)
		gsl_odeiv2_driver_free(p->loc);
	p->d = p->loc = NULL;
}

/* The drivers of phase p, of its system p->sys, for stepper st: 0, or HB_ENOMEM (none). */
static int
phase_drivers(struct hb_sim *s, struct phase *p, int st)
{
	const struct hb_scene *sc = &s->sc;
	const gsl_odeiv2_step_type *T = hbs_stepper_type(st);
	/* msbdf is multistep: locate with the single-step implicit bsimp */
	const gsl_odeiv2_step_type *TL = T == gsl_odeiv2_step_msbdf ? hb_step_bsimp_shifted : T;

	p->d = gsl_odeiv2_driver_alloc_standard_new(&p->sys, T, 1e-6, sc->run.atol,
	                                            sc->run.rtol, 1.0, 0.0);
	p->loc = gsl_odeiv2_driver_alloc_standard_new(&p->sys, TL, 1e-6, sc->run.atol,
	                                              sc->run.rtol, 1.0, 0.0);
	if (p->d == NULL || p->loc == NULL || hb_control_cautious(p->d, sc->run.atol, sc->run.rtol)) {
		hbs_phase_free(p);
		return HB_ENOMEM;
	}
	known_init(&p->known, p->d->e, p->d->s);
	p->fer_t = NAN;
	return 0;
}

int
hbs_phase_alloc(struct hb_sim *s, struct phase *p, int q)
{
	hbs_phase_free(p);
	p->s = s;
	p->q = q;
	make_layout(&s->sc, s->I, q, &p->L);
	p->sys = (gsl_odeiv2_system){ hbs_rhs_special(s, p), hbs_jacobian, (size_t)p->L.dim, p };
	if (p->sys.function == NULL)
		p->sys.function = hbs_rhs;
	s->built[q] = s->stepper[q];
	return phase_drivers(s, p, s->stepper[q]);
}

/*
 * A phase whose ODE is sys (of sys->dimension components, every one read
 * by its watched functions), in contact: a chain's clusters.
 */
int
hbs_phase_alloc_sys(struct hb_sim *s, struct phase *p, const gsl_odeiv2_system *sys)
{
	int n = (int)sys->dimension;

	hbs_phase_free(p);
	p->s = s;
	p->q = 1;
	p->L = (struct layout){ n, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, n };
	p->sys = *sys;
	return phase_drivers(s, p, s->stepper[1]);
}

void
hbs_set_com(struct hb_sim *s)
{
	if (s->chain)
		return; /* a chain's centres of mass are its clusters' (sim_cluster.c) */
	if (s->sc.d.system == HB_SCENE_FULL)
		hb_scene_com(&s->sc, s->t, &s->xm, &s->vm);
	else
		s->xm = s->vm = 0.0;
}

/*
 * The sizes of interface I's contact (per interface: both systems
 * scale with them), from its law's stiffness k (of the first stiffness
 * parameter; 1 where it has none) and exponent p, at approach speed V
 * under the load F: indentation X = max(((p+1) m V^2 / (2k))^(1/(p+1)),
 * (|F|/k)^(1/p)) (at least 1e-15 m), speed max(V, X sqrt(k X^(p-1)/m)).
 */
void
hbs_contact_scale(const struct iface *I, double V, double F, double *X, double *Vk)
{
	double k = NAN, p = hb_law_exponent_p(I->law, I->par), m = I->m, x;
	int i;

	for (i = 0; i < I->law->n_params; i++)
		if (I->law->params[i].flags & HB_LAW_PARAM_STIFFNESS || !strcmp(I->law->params[i].name, "k")) {
			k = I->par[i];
			break;
		}
	if (!(k > 0))
		k = 1.0;
	if (!(p > 0))
		p = 1.0;
	x = pow((p + 1) * m * V * V / (2 * k), 1 / (p + 1));
	x = fmax(x, pow(fabs(F) / k, 1 / p));
	if (!(x > 1e-15))
		x = 1e-15;
	*X = x;
	*Vk = fmax(V, x * sqrt(k * pow(x, p - 1) / m));
}

/*
 * Scales of the components for this interval, from the scene's own sizes
 * (DESIGN.md section 4a).  In contact with approach speed v and load F:
 * the indentation X and speed V of hbs_contact_scale, z ~ X, W ~ m V^2 / 2,
 * impulses ~ m V.  In flight: X = max(|x|, v^2/(2|a|)), V = max(|v|, sqrt(2|a|X)).
 */
void
hbs_scales(struct hb_sim *s, const struct layout *L, int q)
{
	struct iface *I = s->I;
	const struct hb_scene *sc = &s->sc;
	double m = I->m, F = fabs(iface_Fer(s, I, s->t)), X, V;
	int i;

	s->w.valid = 0; /* the watched values were of the old scales */
	known_forget(&s->ph[0].known); /* and f, of the scaled variables */
	known_forget(&s->ph[1].known);

	if (q) {
		hbs_contact_scale(I, fabs(I->v), F, &X, &V);
	} else {
		double acc = F / m;

		X = fmax(fabs(I->x), acc > 0 ? I->v * I->v / (2 * acc) : 0.0);
		if (!(X > 1e-12))
			X = 1e-12;
		V = fmax(fabs(I->v), sqrt(2 * acc * X));
		if (!(V > 1e-12))
			V = 1e-12;
	}
	for (i = 0; i < L->dim; i++)
		s->scale[i] = 1.0;
	if (L->ix >= 0)
		s->scale[L->ix] = q ? X + fabs(I->xe) : X;
	s->scale[L->iv] = V;
	if (L->ixc >= 0)
		s->scale[L->ixc] = X;
	for (i = 0; L->iz >= 0 && i < I->law->n_z; i++)
		s->scale[L->iz + i] = X;
	s->scale[L->iEe] = 0.5 * m * V * V;
	if (L->iW >= 0) {
		s->scale[L->iW] = 0.5 * m * V * V;
		s->scale[L->iJc] = m * V;
		s->scale[L->iJe] = m * V;
	}
	if (L->ixm >= 0) {
		s->scale[L->ixm] = fmax(fabs(s->xm) + fabs(s->vm) * sc->run.T, 1e-3);
		s->scale[L->ivm] = fmax(fabs(s->vm), 1e-3);
	}
	/*
	 * Each scale rounded to the nearest power of 2 (a factor of at most
	 * sqrt 2 in the tolerance): scaling and unscaling are then exact, and
	 * rhs multiplies by the exact inverse instead of dividing.
	 */
	for (i = 0; i < L->dim; i++) {
		int e;
		double f = frexp(s->scale[i], &e); /* scale = f 2^e, f in [0.5, 1) */

		if (isfinite(s->scale[i]) && s->scale[i] > 0)
			s->scale[i] = ldexp(1.0, f < M_SQRT1_2 ? e - 1 : e);
		s->iscale[i] = 1.0 / s->scale[i];
	}
	if (q) {
		s->st.ncomp = L->dim < HB_SIM_MAXCOMP ? L->dim : HB_SIM_MAXCOMP;
		for (i = 0; i < s->st.ncomp; i++)
			s->st.scale[i] = s->scale[i];
	}
}

/* Packs the canonical state into u (scaled). */
void
hbs_pack(struct hb_sim *s, const struct layout *L, double *u)
{
	struct iface *I = s->I;
	double y[MAXDIM];
	int i;

	if (L->ix >= 0)
		y[L->ix] = I->x;
	y[L->iv] = I->v;
	if (L->ixc >= 0) {
		y[L->ixc] = I->xc;
		for (i = 0; i < s->I->law->n_z; i++)
			y[L->iz + i] = I->z[i];
		y[L->iW] = I->W;
		y[L->iJc] = I->JFc;
		y[L->iJe] = I->JFe;
	}
	y[L->iEe] = I->Ee;
	if (L->ixm >= 0) {
		y[L->ixm] = s->xm;
		y[L->ivm] = s->vm;
	}
	for (i = 0; i < L->dim; i++)
		u[i] = y[i] * s->iscale[i];
}

/* Unpacks u at time t into the canonical state. */
void
hbs_unpack(struct hb_sim *s, const struct phase *p, double t, const double *u)
{
	struct iface *I = s->I;
	const struct layout *L = &p->L;
	double y[MAXDIM];
	int i;

	hbs_unscale(p, u, y);
	s->t = t;
	I->v = y[L->iv];
	if (p->q) {
		I->xc = y[L->ixc];
		I->x = L->ix >= 0 ? y[L->ix] : I->xe + I->xc;
		for (i = 0; i < s->I->law->n_z; i++)
			I->z[i] = y[L->iz + i];
		I->W = y[L->iW];
		I->JFc = y[L->iJc];
		I->JFe = y[L->iJe];
		I->Wc = I->Wc0 - I->W;
	} else {
		I->x = y[L->ix];
	}
	I->Ee = y[L->iEe];
	if (L->ixm >= 0) {
		s->xm = y[L->ixm];
		s->vm = y[L->ivm];
	} else {
		hbs_set_com(s);
	}
}

/* The scaled state of an arc sample, in the layout L (as pack() for the canonical state). */
void
hbs_pack_sample(const struct hb_sim *s, const struct layout *L, const struct hb_arc_sample *a, double *u)
{
	double y[MAXDIM];
	int i;

	if (L->ix >= 0)
		y[L->ix] = a->x;
	y[L->iv] = a->v;
	if (L->ixc >= 0) {
		y[L->ixc] = a->xc;
		for (i = 0; i < s->I->law->n_z; i++)
			y[L->iz + i] = a->z[i];
		y[L->iW] = a->W;
		y[L->iJc] = a->JFc;
		y[L->iJe] = a->JFe;
	}
	y[L->iEe] = a->Ee;
	if (L->ixm >= 0) {
		y[L->ixm] = a->xm;
		y[L->ivm] = a->vm;
	}
	for (i = 0; i < L->dim; i++)
		u[i] = y[i] * s->iscale[i];
}
