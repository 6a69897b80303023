/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_rhs.c - the right-hand side specialised for the scene when a phase
 * is set up (hbs_phase_alloc): one function per law, with its Phi and Psi
 * inline (law_terms.h) and the layout's indices constant, F_e,r of the
 * scene evaluated once and directly (its constant part inline, the
 * ramp's cos only when there is a ramp).  The same operations in the same
 * order as the general rhs of sim_flow.c, so the same doubles: the
 * components are scaled by the exact powers of 2 of hbs_scales as they are
 * read and written.  A scene it does not cover (a chain, the centre of
 * mass integrated, a law of the host's own) keeps the general rhs.
 */
#include "sim_impl.h"
#include "law_terms.h"

enum rhs_law { RL_SHCCL, RL_BWSHCCL, RL_BWMCL, RL_HERTZ, RL_LINEAR };


/*
 * F_e,r of a two-body scene at t, as hb_scene_Fer (scene.c) computes it.
 * A ramp's is kept for the last t asked: a step's last stages, and the
 * next step's first, are at the same t (rk8pd: 3 of its 13 evaluations).
 */
static ALWAYS_INLINE double
scene_Fer_at(struct phase *p, const struct hb_scene *sc, double t)
{
	if (sc->loads.ramp) {
		if (t != p->fer_t) {
			p->fer = hb_scene_Fer(sc, t);
			p->fer_t = t;
		}
		return p->fer;
	}
	if (sc->d.system == HB_SCENE_FULL)
		return sc->d.etac * sc->loads.F1 - sc->d.eta * sc->loads.F2;
	return sc->loads.F1 - sc->d.m1 * sc->loads.g;
}

/*
 * Phi of the law at (x_c, z, v), and Psi (on the mode sign, 0: none) into
 * dz, with the exponents p and n given (constants where the caller has
 * checked the law's: its powers are then written out).
 */
static ALWAYS_INLINE double
law_terms(enum rhs_law law, const double *par, int ext, double xc, const double *z, double v,
          int sign, double *dz, double p, double n)
{
	double phi;

	switch (law) {
	case RL_SHCCL:
		return law_shccl_phi_p(par, ext, xc, v, p);
	case RL_BWSHCCL:
		law_bwshccl_psi_mode_n(par, z, v, sign, dz, n);
		return law_bwshccl_phi_p(par, ext, xc, z, v, p);
	case RL_BWMCL:
		phi = law_bwmcl_phi_p(par, z, p);
		law_bwmcl_psi_mode_n(par, phi, v, z, sign, dz, n);
		return phi;
	case RL_HERTZ:
		return law_hertz_phi_p(par, ext, xc, p);
	case RL_LINEAR:
		return law_linear_phi(par, ext, xc, z, v);
	}
	return 0.0;
}

/*
 * Whether the law's exponents are Hertz's p = 3/2 and n = 2 (every paper
 * study's), for which the powers are written out (apow's own branches for
 * them, so the same doubles); a law without p or n has them as well.
 */
static int
law_hertzian(enum rhs_law law, const double *par)
{
	switch (law) {
	case RL_SHCCL:
		return par[LAW_SHCCL_P] == 1.5;
	case RL_BWSHCCL:
	case RL_BWMCL:
		return par[LAW_BW_P] == 1.5 && par[LAW_BW_N] == 2.0;
	case RL_HERTZ:
		return par[LAW_HERTZ_P] == 1.5;
	case RL_LINEAR:
		return 1;
	}
	return 0;
}

/* The law's exponents p and n (NAN where it has none). */
static ALWAYS_INLINE void
law_pn(enum rhs_law law, const double *par, double *p, double *n)
{
	*p = *n = NAN;
	switch (law) {
	case RL_SHCCL:
		*p = par[LAW_SHCCL_P];
		break;
	case RL_BWSHCCL:
	case RL_BWMCL:
		*p = par[LAW_BW_P];
		*n = par[LAW_BW_N];
		break;
	case RL_HERTZ:
		*p = par[LAW_HERTZ_P];
		break;
	case RL_LINEAR:
		break;
	}
}

/* each du is scaled as it is written; bad turns NaN as soon as one du is NaN or infinite */
#define PUT(k, val) (du[k] = (val) * is[k], bad += 0.0 * du[k])

/*
 * In contact, layout [x], x_c, v, z (nz), W, J_Fc, J_Fe, E_e (make_layout
 * of sim_flow.c): o = 1 with x, else 0.  hertzian: the law's exponents are
 * 3/2 and 2 (law_hertzian, checked when the phase was set up: the scene,
 * and so its parameters, change only by a new set-up).
 */
static ALWAYS_INLINE int
rhs_contact(double t, const double u[], double du[], void *params, enum rhs_law law, int nz,
            int o, int hertzian)
{
	struct phase *p = params;
	struct hb_sim *s = p->s;
	const struct iface *I = s->I;
	const double *sc = s->pscale, *is = s->piscale; /* = scale, iscale (sim_work.c) */
	double Fer = scene_Fer_at(p, &s->sc, t), phi, xc, v, z[2], dz[2], pp, nn, bad = 0.0;
	int i;

	s->st.rhs++;
	xc = u[o] * sc[o];
	v = u[o + 1] * sc[o + 1];
	for (i = 0; i < nz; i++)
		z[i] = u[o + 2 + i] * sc[o + 2 + i];
	if (hertzian) {
		pp = 1.5;
		nn = 2.0;
	} else {
		law_pn(law, I->par, &pp, &nn);
	}
	phi = law_terms(law, I->par, I->ext, xc, z, v, s->msign, dz, pp, nn);
	PUT(o, v);
	for (i = 0; i < nz; i++)
		PUT(o + 2 + i, dz[i]);
	PUT(o + 2 + nz, phi * v);
	PUT(o + 3 + nz, -phi);
	PUT(o + 4 + nz, Fer);
	if (o)
		PUT(0, v);
	PUT(o + 1, (-phi + Fer) / I->m);
	PUT(o + 5 + nz, Fer * v);
	if (bad != 0.0 || isnan(bad))
		return GSL_FAILURE;
	return GSL_SUCCESS;
}

/* In flight, layout x, v, E_e. */
static int
rhs_flight(double t, const double u[], double du[], void *params)
{
	struct phase *p = params;
	struct hb_sim *s = p->s;
	const double *is = s->piscale; /* = iscale (sim_work.c) */
	double Fer = scene_Fer_at(p, &s->sc, t), phi = 0.0, v, bad = 0.0;

	s->st.rhs++;
	v = u[1] * s->pscale[1];
	PUT(0, v);
	PUT(1, (-phi + Fer) / s->I->m);
	PUT(2, Fer * v);
	if (bad != 0.0 || isnan(bad))
		return GSL_FAILURE;
	return GSL_SUCCESS;
}

#undef PUT

/* rhs of law with nz components of z: without x (o = 0), with x (1); general exponents, or Hertz's */
#define RHS_LAW(name, law, nz)                                                    \
	static int name##_0(double t, const double u[], double du[], void *params) \
	{                                                                         \
		return rhs_contact(t, u, du, params, law, nz, 0, 0);              \
	}                                                                         \
	static int name##_1(double t, const double u[], double du[], void *params) \
	{                                                                         \
		return rhs_contact(t, u, du, params, law, nz, 1, 0);              \
	}                                                                         \
	static int name##_h0(double t, const double u[], double du[], void *params) \
	{                                                                         \
		return rhs_contact(t, u, du, params, law, nz, 0, 1);              \
	}                                                                         \
	static int name##_h1(double t, const double u[], double du[], void *params) \
	{                                                                         \
		return rhs_contact(t, u, du, params, law, nz, 1, 1);              \
	}                                                                         \
	static hbs_rhs_fn *const name[2][2] = { { name##_0, name##_1 }, { name##_h0, name##_h1 } };
RHS_LAW(rhs_shccl, RL_SHCCL, 0)
RHS_LAW(rhs_bwshccl, RL_BWSHCCL, 1)
RHS_LAW(rhs_bwmcl, RL_BWMCL, 2)
RHS_LAW(rhs_hertz, RL_HERTZ, 0)
RHS_LAW(rhs_linear, RL_LINEAR, 0)
#undef RHS_LAW

hbs_rhs_fn *
hbs_rhs_special(const struct hb_sim *s, const struct phase *p)
{
	const struct layout *L = &p->L;
	const struct hb_law_type *law = s->I->law;
	int o = L->ix >= 0, nz = law->n_z;

	if (s->chain || L->ixm >= 0)
		return NULL;
	if (!p->q)
		return L->ix == 0 && L->iv == 1 && L->iEe == 2 && L->dim == 3 ? rhs_flight : NULL;
	if (!(L->ixc == o && L->iv == o + 1 && (nz == 0 || L->iz == o + 2) && L->iW == o + 2 + nz &&
	      L->iJc == o + 3 + nz && L->iJe == o + 4 + nz && L->iEe == o + 5 + nz && L->dim == o + 6 + nz))
		return NULL;
	if (law == &hb_law_shccl)
		return rhs_shccl[law_hertzian(RL_SHCCL, s->I->par)][o];
	if (law == &hb_law_bwshccl)
		return rhs_bwshccl[law_hertzian(RL_BWSHCCL, s->I->par)][o];
	if (law == &hb_law_bwmcl)
		return rhs_bwmcl[law_hertzian(RL_BWMCL, s->I->par)][o];
	if (law == &hb_law_hertz)
		return rhs_hertz[law_hertzian(RL_HERTZ, s->I->par)][o];
	if (law == &hb_law_linear)
		return rhs_linear[law_hertzian(RL_LINEAR, s->I->par)][o];
	return NULL;
}
