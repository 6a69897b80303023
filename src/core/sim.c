/*
 * sim.c - the simulator of the hybrid systems H_r and H_f (paper section
 * Model, eqs. Hr_f .. Hr_init and H_f .. H_init).
 *
 * State and sets, exactly as the paper:
 *     C = {q_c = 0, (x >= 0 or v >= 0)} u {q_c = 1, (Phi <= 0 or v <= 0)}
 *     D = {q_c = 0, x <= 0, v <= 0}     u {q_c = 1, Phi >= 0, v >= 0}
 *     g: x, v, x_m, v_m unchanged; x_c = 0, z_c = 0, q_c = 1 - q_c.
 * Continuous indicators of C: I = max(x, v) in flight and I = -min(Phi, v)
 * in contact; the state is in C while I >= 0, and only a strictly negative
 * I leaves C (rule R2: a state on the boundary keeps flowing).
 *
 * Work is organised by flow interval (DESIGN.md section 3):
 *  - flight, F_er constant on [t, T]: closed form x + v tau + a tau^2 / 2,
 *    the event from the quadratic, then nudged by ulps into D;
 *  - flight otherwise: GSL on (x, v) (+ (x_m, v_m) when REDUCE_COM is off);
 *  - contact: GSL on (x_c, v, z_c, W, J_Fc, J_Fe) with x = x_e + x_c
 *    (or with x as well when REDUCE_CONTACT is off).
 * The ODE is integrated in scaled variables u_i = y_i / s_i, with s_i the
 * component's scale taken from the interval's own sizes (see scales()), so
 * that GSL's standard control with one eps_abs = atol gives each component
 * the absolute tolerance atol * s_i.
 *
 * After every accepted step the indicator, the law's switching functions
 * and the extremum functions (v for x_c^max, dPhi/dt for F_c^max) are
 * compared with their values at the step's start.  A change of sign is
 * located by re-stepping from the step's start (one step of the same
 * method of length h, h in the bracket) with GSL's Brent solver down to a
 * few ulps of t, the earliest of several crossings first.  An event ends
 * the interval at the bracket's end in D; a switching or extremum crossing
 * ends the step at the bracket's far end and restarts the stepper
 * (DESIGN.md section 4a).  Load kinks (T_e, T_s) are step targets.  An
 * event inside a step whose two ends are in C is looked for by a cubic
 * Hermite test of the indicator (dip()).
 *
 * Scales are powers of 2 (exact scaling); GSL's standard control is used
 * without growth right after a rejection (control.c); bsimp runs on
 * shifted variables (step_bsimp.c).  Every 32nd step of an explicit
 * stepper in contact checks the stiffness of the flow (stiffness()):
 * run.stepper = auto then goes over to bsimp for the contacts.
 *
 * Invariants: the arc's samples are all in C except each pre-jump sample,
 * which is in D by check_in_D's test; post-jump samples are g of the
 * pre-jump ones bit for bit; a failed step leaves the arc as it was.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <gsl/gsl_complex_math.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>

#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "arc_impl.h"
#include "control.h"
#include "step_bsimp.h"
#include "step_dop853.h"

enum {
	MAXDIM = 11,           /* x, v, x_c, z1, z2, W, JFc, JFe, E_e, x_m, v_m */
	MAXFUN = LAW_MAX_KINKS + 3,
	CACHE = 96,
	FLIGHT_SAMPLES = 48,   /* samples drawn along a closed-form flight, for plots */
	MAX_BRENT = 100,
	MAX_RETRY = 60,        /* retries of a step that produced a non-finite state */
	MAX_TINY = 200,        /* consecutive steps at the resolution of t before failing */
};

/* Which components the ODE of a flow interval carries; -1 when absent. */
struct layout {
	int dim;
	int ix, iv, ixc, iz, iW, iJc, iJe, ixm, ivm, iEe;
};

struct phase {
	struct sim *s;
	struct layout L;
	int q;
	gsl_odeiv2_system sys;
	gsl_odeiv2_driver *d;    /* stepper, control and evolver */
	gsl_odeiv2_driver *loc;  /* single steps for event location */
};

/* Kinds of the functions watched along a step. */
enum fun_kind { FUN_EVENT, FUN_KINK, FUN_XCMAX, FUN_FCMAX };

struct cached {
	double h;
	double u[MAXDIM];
};

struct sim {
	struct scene sc;
	struct arc *arc;
	struct collision *col;
	size_t ncol, colcap;
	long ncol_total;        /* collisions completed, kept or thinned out (col[].i) */
	enum sim_end end;
	char err[640];
	char endmsg[700];
	struct sim_stats st;

	/* canonical state at (t, j) */
	double t;
	long j;
	int q;
	double x, v, xc, z[LAW_MAX_Z], xm, vm;
	double W, JFc, JFe, xcmax, Fcmax;
	double Ee, Wc;      /* works of F_er and F_c since t = 0 */
	double Wc0;         /* Wc at the commencement of the contact in progress */
	double xe;          /* x at the commencement of the contact in progress */
	double te, vi;      /* commencement time and approach velocity */
	double t_instant;   /* time of the last jump, and jumps at it */
	int n_instant;

	/* the current flow interval */
	int setup;          /* 1: the next work begins a new interval */
	int closed;         /* 1: closed-form flight */
	struct phase ph[2]; /* numeric flight, contact */
	struct phase *cur;
	double scale[MAXDIM];
	double iscale[MAXDIM]; /* 1 / scale, exact: every scale is a power of 2 */
	double u[MAXDIM];   /* scaled ODE state */
	double h;           /* step size suggestion */
	double Tc;          /* time scale of the interval */
	int ntiny;
	double gmax[MAXFUN]; /* largest |value| of each watched function in the interval */
	double vmax;        /* largest |v| in the contact */

	/* location workspace */
	double t0, H, u0[MAXDIM], u1[MAXDIM];
	struct cached cache[CACHE];
	int ncache, cache_next;
	int fun_target, fun_sign0;
	int use_dense;      /* 1: restep() reads the last step's continuous extension */
	int hug;            /* 1: the step began on Phi = 0 to the noise, receding (see snap_separation) */
	int msign;          /* the frozen sign of the law's mode kink in this step (0: none) */
	int resume;         /* 1: the next interval continues one cut by sim_seek (see resume_interval) */
	size_t resume_first, resume_last; /* its samples kept in the arc */
	double resume_h;    /* the step the run had taken from the seek point, or 0 */
	int mforce;         /* the sign the mode takes at t = mforce_t (a located crossing) */
	double mforce_t;
	int loc_iter;
	gsl_root_fsolver *root;
	long work;          /* units of work, for the step budget */

	/* steppers: the one each phase uses now, and the one its workspace was built for */
	int stepper[2], built[2];
	int stiff_row;      /* consecutive stiffness hits in this contact */
	gsl_eigen_nonsymm_workspace *eig;
	gsl_matrix *Jdyn;
	gsl_vector_complex *lambda;
};

static int
explicit_stepper(int stepper)
{
	return stepper == STEPPER_RK8PD || stepper == STEPPER_RKF45 || stepper == STEPPER_RKCK ||
	       stepper == STEPPER_DOP853;
}

static const gsl_odeiv2_step_type *
stepper_type(int stepper)
{
	switch (stepper) {
	case STEPPER_RKF45: return gsl_odeiv2_step_rkf45;
	case STEPPER_RKCK: return gsl_odeiv2_step_rkck;
	case STEPPER_MSBDF: return gsl_odeiv2_step_msbdf;
	case STEPPER_RK4IMP: return gsl_odeiv2_step_rk4imp;
	case STEPPER_BSIMP: return hb_step_bsimp_shifted;
	case STEPPER_DOP853: return hb_step_dop853;
	default: return gsl_odeiv2_step_rk8pd;
	}
}

/* Seconds on a clock: CLOCK_MONOTONIC (wall) or CLOCK_PROCESS_CPUTIME_ID (CPU). */
static double
now_seconds(clockid_t clock)
{
	struct timespec ts;

	if (clock_gettime(clock, &ts) != 0)
		return 0.0;
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static double
phi_at(const struct sim *s, double xc, const double *z, double v)
{
	return s->sc.law->phi(s->sc.par, s->sc.ext, xc, z, v);
}

/* ---------------------------------------------------------------------- */
/* The flow map in scaled variables.                                        */

static void
unscale(const struct phase *p, const double *u, double *y)
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
static int
rhs(double t, const double u[], double du[], void *params)
{
	struct phase *p = params;
	struct sim *s = p->s;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	double y[MAXDIM], dy[MAXDIM];
	double Fer = scene_Fer(sc, t), phi = 0.0, v;
	int i;

	s->st.rhs++;
	unscale(p, u, y);
	v = y[L->iv];
	if (p->q) {
		const double *z = sc->law->n_z ? &y[L->iz] : NULL;

		phi = sc->law->phi(sc->par, sc->ext, y[L->ixc], z, v);
		dy[L->ixc] = v;
		if (s->msign)
			sc->law->psi_mode(sc->par, sc->ext, y[L->ixc], z, v, s->msign, &dy[L->iz]);
		else if (sc->law->n_z)
			sc->law->psi(sc->par, sc->ext, y[L->ixc], z, v, &dy[L->iz]);
		dy[L->iW] = phi * v;
		dy[L->iJc] = -phi;
		dy[L->iJe] = Fer;
	}
	if (L->ix >= 0)
		dy[L->ix] = v;
	dy[L->iv] = (-phi + Fer) / sc->d.m;
	dy[L->iEe] = Fer * v;
	if (L->ixm >= 0) {
		double F1, F2;

		scene_loads_at(sc, t, &F1, &F2);
		dy[L->ixm] = y[L->ivm];
		dy[L->ivm] = sc->d.system == SCENE_FULL ? (F1 + F2) / (sc->d.m1 + sc->d.m2) : 0.0;
	}
	{
		double nan_if_bad = 0.0;

		for (i = 0; i < L->dim; i++) {
			du[i] = dy[i] * s->iscale[i];
			nan_if_bad += 0.0 * du[i]; /* NaN as soon as one du is NaN or infinite */
		}
		if (nan_if_bad != 0.0 || isnan(nan_if_bad))
			return GSL_FAILURE;
	}
	return GSL_SUCCESS;
}

static double
Fer_rate(const struct scene *sc, double t)
{
	double h = 1e-7 * (fabs(t) + 1e-3);

	return (scene_Fer(sc, t + h) - scene_Fer(sc, t - h)) / (2 * h);
}

/* The Jacobian of rhs, for the implicit steppers; the law's partials. */
static int
jacobian(double t, const double u[], double *dfdu, double dfdt[], void *params)
{
	struct phase *p = params;
	struct sim *s = p->s;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	int n = L->dim, nz = sc->law->n_z, i, k;
	double y[MAXDIM], J[MAXDIM * MAXDIM], dt[MAXDIM];
	double m = sc->d.m, Ferdot = Fer_rate(sc, t);

	s->st.jac++;
	unscale(p, u, y);
	memset(J, 0, sizeof J);
	memset(dt, 0, sizeof dt);
	if (L->ix >= 0)
		J[L->ix * n + L->iv] = 1.0;
	dt[L->iv] = Ferdot / m;
	if (p->q) {
		double dphi[LAW_MAX_Z + 2], dpsi[LAW_MAX_Z * (LAW_MAX_Z + 2)];
		const double *z = nz ? &y[L->iz] : NULL;
		double v = y[L->iv];
		double phi = sc->law->phi(sc->par, sc->ext, y[L->ixc], z, v);
		int col[LAW_MAX_Z + 2];

		sc->law->jac(sc->par, sc->ext, y[L->ixc], z, v, dphi, nz ? dpsi : NULL);
		col[0] = L->ixc;
		for (i = 0; i < nz; i++)
			col[1 + i] = L->iz + i;
		col[nz + 1] = L->iv;
		J[L->ixc * n + L->iv] = 1.0;
		for (k = 0; k < nz + 2; k++) {
			J[L->iv * n + col[k]] = -dphi[k] / m;
			J[L->iW * n + col[k]] = dphi[k] * v;
			J[L->iJc * n + col[k]] = -dphi[k];
			for (i = 0; i < nz; i++)
				J[(L->iz + i) * n + col[k]] = dpsi[i * (nz + 2) + k];
		}
		J[L->iW * n + L->iv] += phi;
		dt[L->iJe] = Ferdot;
	}
	J[L->iEe * n + L->iv] = scene_Fer(sc, t);
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

/* ---------------------------------------------------------------------- */
/* Phases: layouts and GSL workspaces.                                      */

static void
make_layout(const struct scene *sc, int q, struct layout *L)
{
	int n = 0;
	int com = sc->d.system == SCENE_FULL ? !(sc->run.reduce & REDUCE_COM)
	                                     : !(sc->run.reduce & REDUCE_COM);

	*L = (struct layout){ 0, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1 };
	if (q) {
		if (!(sc->run.reduce & REDUCE_CONTACT))
			L->ix = n++;
		L->ixc = n++;
		L->iv = n++;
		if (sc->law->n_z) {
			L->iz = n;
			n += sc->law->n_z;
		}
		L->iW = n++;
		L->iJc = n++;
		L->iJe = n++;
	} else {
		L->ix = n++;
		L->iv = n++;
	}
	L->iEe = n++;
	if (com) {
		L->ixm = n++;
		L->ivm = n++;
	}
	L->dim = n;
}

static void
phase_free(struct phase *p)
{
	if (p->d)
		gsl_odeiv2_driver_free(p->d);
	if (p->loc)
		gsl_odeiv2_driver_free(p->loc);
	p->d = p->loc = NULL;
}

static int
phase_alloc(struct sim *s, struct phase *p, int q)
{
	const struct scene *sc = &s->sc;
	const gsl_odeiv2_step_type *T = stepper_type(s->stepper[q]);
	/* msbdf is multistep: locate with the single-step implicit bsimp */
	const gsl_odeiv2_step_type *TL = T == gsl_odeiv2_step_msbdf ? hb_step_bsimp_shifted : T;

	phase_free(p);
	p->s = s;
	p->q = q;
	make_layout(sc, q, &p->L);
	p->sys = (gsl_odeiv2_system){ rhs, jacobian, (size_t)p->L.dim, p };
	p->d = gsl_odeiv2_driver_alloc_standard_new(&p->sys, T, 1e-6, sc->run.atol,
	                                            sc->run.rtol, 1.0, 0.0);
	p->loc = gsl_odeiv2_driver_alloc_standard_new(&p->sys, TL, 1e-6, sc->run.atol,
	                                              sc->run.rtol, 1.0, 0.0);
	s->built[q] = s->stepper[q];
	if (p->d == NULL || p->loc == NULL || hb_control_cautious(p->d, sc->run.atol, sc->run.rtol)) {
		phase_free(p);
		return HB_ENOMEM;
	}
	return 0;
}

/* ---------------------------------------------------------------------- */
/* Samples, collisions, failures.                                           */

static int
fail(struct sim *s, int status, const char *why)
{
	s->end = SIM_END_FAIL;
	snprintf(s->err, sizeof s->err,
	         "%s at (t = %.12g s, j = %ld): x = %.6g m, v = %.6g m/s, x_c = %.6g m, q_c = %d",
	         why, s->t, s->j, s->x, s->v, s->xc, s->q);
	snprintf(s->endmsg, sizeof s->endmsg, "failed: %s", s->err);
	return status;
}

static int
push_sample(struct sim *s, int kind)
{
	struct arc_sample a;
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
	a.Fer = scene_Fer(&s->sc, s->t);
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
		return fail(s, HB_ENOMEM, "out of memory for the arc");
	return 0;
}

static int
push_collision(struct sim *s)
{
	struct collision c;

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
		struct collision *p = realloc(s->col, cap * sizeof *p);

		if (p == NULL)
			return fail(s, HB_ENOMEM, "out of memory for the collisions");
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
static int
jump(struct sim *s, int how, int iterations, double width, double ilo, double ihi)
{
	struct arc_jump jr;
	int rc;

	if ((rc = push_sample(s, ARC_PRE_JUMP)))
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
		return fail(s, HB_ECHATTER, why);
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
		return fail(s, HB_ENOMEM, "out of memory for the jump records");
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
	if ((rc = push_sample(s, ARC_POST_JUMP)))
		return rc;
	s->setup = 1;
	if (s->j >= s->sc.run.J) {
		s->end = SIM_END_J;
		snprintf(s->endmsg, sizeof s->endmsg,
		         "jump cap J = %ld reached at t = %.9g s", s->sc.run.J, s->t);
	}
	return 0;
}

static void
finish_T(struct sim *s)
{
	s->end = SIM_END_T;
	snprintf(s->endmsg, sizeof s->endmsg, "horizon T = %.9g s reached at j = %ld",
	         s->sc.run.T, s->j);
}

/* ---------------------------------------------------------------------- */
/* Flight in closed form.                                                   */

/* State of a flight after tau under the constant acceleration a. */
static void
flight_at(double x, double v, double a, double tau, double *xo, double *vo)
{
	*xo = x + tau * (v + 0.5 * a * tau);
	*vo = v + a * tau;
}

/*
 * The first tau >= 0 after which max(x, v) < 0 (the state leaves C), for
 * x(tau) = x + v tau + a tau^2 / 2; INFINITY if it never does.
 */
static double
flight_event(double x, double v, double a)
{
	double best = INFINITY, r[2];
	int nr = 0, i;

	if (x <= 0 && v <= 0 && (x < 0 || v < 0 || a < 0) && (v < 0 || a < 0))
		return 0.0;
	/* roots of x(tau) = 0, stable form */
	if (a == 0.0) {
		if (v != 0.0)
			r[nr++] = -x / v;
	} else {
		double disc = v * v - 2.0 * a * x;

		if (disc >= 0.0) {
			double sq = sqrt(disc);
			double qq = -0.5 * (v + (v >= 0 ? sq : -sq));

			if (qq != 0.0) {
				r[nr++] = qq / (0.5 * a);
				r[nr++] = x / qq;
			} else {
				r[nr++] = 0.0;
			}
		}
	}
	for (i = 0; i < nr; i++)
		if (r[i] > 0.0 && v + a * r[i] < 0.0 && r[i] < best)
			best = r[i];
	/* v crossing zero downwards while x <= 0 */
	if (a < 0.0 && v > 0.0) {
		double tv = -v / a, xv, vv;

		flight_at(x, v, a, tv, &xv, &vv);
		if (xv <= 0.0 && tv < best)
			best = tv;
	}
	return best;
}

static void
set_com(struct sim *s)
{
	if (s->sc.d.system == SCENE_FULL)
		scene_com(&s->sc, s->t, &s->xm, &s->vm);
	else
		s->xm = s->vm = 0.0;
}

static int
flight_closed(struct sim *s)
{
	const double T = s->sc.run.T;
	const double t0 = s->t, x0 = s->x, v0 = s->v;
	const double a = scene_Fer(&s->sc, t0) / s->sc.d.m;
	const double Ee0 = s->Ee;
	double tau = flight_event(x0, v0, a), tend, tapex = INFINITY;
	int i, rc, it = 0;

	if (!isfinite(v0 * v0) || !isfinite(a * x0) || !isfinite(x0 + v0 * (T - t0))) {
		return fail(s, HB_ENUMERIC, "the flight overflows a double: v^2 and x + v T must be finite");
	}
	s->st.flights_closed++;
	tend = fmin(tau, T - t0);
	if (a != 0.0 && -v0 / a > 0.0 && -v0 / a < tend)
		tapex = -v0 / a;
	for (i = 1; i < FLIGHT_SAMPLES; i++) {
		double tk = tend * i / FLIGHT_SAMPLES;
		int kind = ARC_STEP;

		if (tapex < tk) { /* the apex, an extremum of x */
			tk = tapex;
			tapex = INFINITY;
			i--;
			kind = ARC_EXTREMUM;
		}
		if (tk <= 0.0)
			continue;
		s->t = t0 + tk;
		flight_at(x0, v0, a, s->t - t0, &s->x, &s->v);
		s->Ee = Ee0 + a * s->sc.d.m * (s->x - x0);
		set_com(s);
		if ((rc = push_sample(s, kind)))
			return rc;
	}
	if (tau > T - t0) {
		s->t = T;
		flight_at(x0, v0, a, T - t0, &s->x, &s->v);
		s->Ee = Ee0 + a * s->sc.d.m * (s->x - x0);
		set_com(s);
		if ((rc = push_sample(s, ARC_END)))
			return rc;
		finish_T(s);
		return 0;
	}
	/* the event: place the state in D by the checker's test, ulp by ulp */
	{
		double te = t0 + tau, tprev, xp, vp;

		if (tau == 0.0)
			te = t0;
		flight_at(x0, v0, a, te - t0, &s->x, &s->v);
		while (!(s->x <= 0.0 && s->v <= 0.0) && it < 1000) {
			te = nextafter(te, INFINITY);
			flight_at(x0, v0, a, te - t0, &s->x, &s->v);
			it++;
		}
		if (!(s->x <= 0.0 && s->v <= 0.0))
			return fail(s, HB_ENUMERIC, "flight event could not be placed in D");
		tprev = te > t0 ? nextafter(te, -INFINITY) : te;
		flight_at(x0, v0, a, tprev - t0, &xp, &vp);
		s->t = te;
		s->Ee = Ee0 + a * s->sc.d.m * (s->x - x0);
		set_com(s);
		return jump(s, tau == 0.0 ? LOCATE_START : LOCATE_CLOSED_FORM, it, te - tprev,
		            fmax(xp, vp), fmax(s->x, s->v));
	}
}

/* ---------------------------------------------------------------------- */
/* Numeric flow intervals.                                                  */

/* The stiffness k and exponent p of the law (k of the first stiffness param). */
static void
law_kp(const struct scene *sc, double *k, double *p)
{
	int i;

	*k = NAN;
	for (i = 0; i < sc->law->n_params; i++)
		if (sc->law->params[i].flags & LAW_PARAM_STIFFNESS || !strcmp(sc->law->params[i].name, "k")) {
			*k = sc->par[i];
			break;
		}
	*p = law_exponent_p(sc->law, sc->par);
}

/*
 * Scales of the components for this interval, from the scene's own sizes
 * (DESIGN.md section 4a).  In contact with approach speed v and load F:
 * indentation X = max(((p+1) m v^2 / (2k))^(1/(p+1)), (|F|/k)^(1/p)),
 * speed V = max(|v|, X sqrt(k X^(p-1)/m)), z ~ X, W ~ m V^2 / 2, impulses
 * ~ m V.  In flight: X = max(|x|, v^2/(2|a|)), V = max(|v|, sqrt(2|a|X)).
 */
static void
scales(struct sim *s, const struct layout *L, int q)
{
	const struct scene *sc = &s->sc;
	double m = sc->d.m, F = fabs(scene_Fer(sc, s->t)), X, V, k, p;
	int i;

	if (q) {
		law_kp(sc, &k, &p);
		if (!(k > 0))
			k = 1.0;
		X = pow((p + 1) * m * s->v * s->v / (2 * k), 1 / (p + 1));
		X = fmax(X, pow(F / k, 1 / p));
		if (!(X > 1e-15))
			X = 1e-15;
		V = fmax(fabs(s->v), X * sqrt(k * pow(X, p - 1) / m));
	} else {
		double acc = F / m;

		X = fmax(fabs(s->x), acc > 0 ? s->v * s->v / (2 * acc) : 0.0);
		if (!(X > 1e-12))
			X = 1e-12;
		V = fmax(fabs(s->v), sqrt(2 * acc * X));
		if (!(V > 1e-12))
			V = 1e-12;
	}
	for (i = 0; i < L->dim; i++)
		s->scale[i] = 1.0;
	if (L->ix >= 0)
		s->scale[L->ix] = q ? X + fabs(s->xe) : X;
	s->scale[L->iv] = V;
	if (L->ixc >= 0)
		s->scale[L->ixc] = X;
	for (i = 0; L->iz >= 0 && i < sc->law->n_z; i++)
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
		s->st.ncomp = L->dim < 8 ? L->dim : 8;
		for (i = 0; i < s->st.ncomp; i++)
			s->st.scale[i] = s->scale[i];
	}
}

/* Packs the canonical state into u (scaled). */
static void
pack(struct sim *s, const struct layout *L, double *u)
{
	double y[MAXDIM];
	int i;

	if (L->ix >= 0)
		y[L->ix] = s->x;
	y[L->iv] = s->v;
	if (L->ixc >= 0) {
		y[L->ixc] = s->xc;
		for (i = 0; i < s->sc.law->n_z; i++)
			y[L->iz + i] = s->z[i];
		y[L->iW] = s->W;
		y[L->iJc] = s->JFc;
		y[L->iJe] = s->JFe;
	}
	y[L->iEe] = s->Ee;
	if (L->ixm >= 0) {
		y[L->ixm] = s->xm;
		y[L->ivm] = s->vm;
	}
	for (i = 0; i < L->dim; i++)
		u[i] = y[i] * s->iscale[i];
}

/* Unpacks u at time t into the canonical state. */
static void
unpack(struct sim *s, const struct phase *p, double t, const double *u)
{
	const struct layout *L = &p->L;
	double y[MAXDIM];
	int i;

	unscale(p, u, y);
	s->t = t;
	s->v = y[L->iv];
	if (p->q) {
		s->xc = y[L->ixc];
		s->x = L->ix >= 0 ? y[L->ix] : s->xe + s->xc;
		for (i = 0; i < s->sc.law->n_z; i++)
			s->z[i] = y[L->iz + i];
		s->W = y[L->iW];
		s->JFc = y[L->iJc];
		s->JFe = y[L->iJe];
		s->Wc = s->Wc0 - s->W;
	} else {
		s->x = y[L->ix];
	}
	s->Ee = y[L->iEe];
	if (L->ixm >= 0) {
		s->xm = y[L->ixm];
		s->vm = y[L->ivm];
	} else {
		set_com(s);
	}
}

/* The flow-set indicator of an unscaled state: >= 0 in C. */
static double
indicator(const struct sim *s, int q, double xc, const double *z, double v, double x)
{
	if (q)
		return -fmin(phi_at(s, xc, z, v), v);
	return fmax(x, v);
}

/*
 * Values of the watched functions at a scaled state: [0] the indicator,
 * then the law's switching functions, then v (x_c extremum) and dPhi/dt
 * (F_c extremum).  Returns their number; kinds in kind[].
 */
static int
watch(const struct sim *s, const struct phase *p, double t, const double *u, double *f,
      int *kind)
{
	const struct scene *sc = &s->sc;
	const struct layout *L = &p->L;
	double y[MAXDIM], v, x, xc = 0, z[LAW_MAX_Z] = { 0 };
	int n = 0, i, nz = sc->law->n_z;

	unscale(p, u, y);
	v = y[L->iv];
	if (p->q) {
		xc = y[L->ixc];
		for (i = 0; i < nz; i++)
			z[i] = y[L->iz + i];
		x = L->ix >= 0 ? y[L->ix] : s->xe + xc;
	} else {
		x = y[L->ix];
	}
	kind[n] = FUN_EVENT;
	f[n++] = indicator(s, p->q, xc, z, v, x);
	if (!p->q)
		return n;
	if (sc->law->n_kinks && sc->run.kinks) {
		sc->law->kinks(sc->par, sc->ext, xc, z, v, &f[n]);
		for (i = 0; i < sc->law->n_kinks; i++)
			kind[n++] = FUN_KINK;
	}
	kind[n] = FUN_XCMAX;
	f[n++] = v;
	{
		double dphi[LAW_MAX_Z + 2], dpsi[LAW_MAX_Z * (LAW_MAX_Z + 2)], dz[LAW_MAX_Z];
		double phi = phi_at(s, xc, z, v), vdot, d;

		sc->law->jac(sc->par, sc->ext, xc, z, v, dphi, nz ? dpsi : NULL);
		if (nz)
			sc->law->psi(sc->par, sc->ext, xc, z, v, dz);
		vdot = (-phi + scene_Fer(sc, t)) / sc->d.m;
		d = dphi[0] * v + dphi[nz + 1] * vdot;
		for (i = 0; i < nz; i++)
			d += dphi[1 + i] * dz[i];
		kind[n] = FUN_FCMAX;
		f[n++] = d;
	}
	return n;
}

/* Did function i cross between values a (step start) and b? */
static int
crossed(int kind, double a, double b)
{
	switch (kind) {
	case FUN_EVENT: return a >= 0.0 && b < 0.0;
	case FUN_KINK: return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
	default: return a < 0.0 && b > 0.0; /* minima of x_c and of Phi */
	}
}

static void snap_stick(struct sim *s, double *u);
static int snap_separation(struct sim *s, double *u);

/* The state one step of length h from (t0, u0), cached. */
static int
restep(struct sim *s, double h, double *u)
{
	struct phase *p = s->cur;
	double yerr[MAXDIM];
	int i, rc;

	if (s->t0 + h == s->t0) { /* h below the resolution of t: the start (bsimp refuses such a step) */
		memcpy(u, s->u0, sizeof s->u0);
		return 0;
	}
	if (h == s->H) {
		memcpy(u, s->u1, sizeof s->u1);
		return 0;
	}
	if (s->use_dense) {
		/* on the step's continuous extension: no evaluation of f */
		if ((rc = hb_dop853_dense(p->d->s, s->t0 + h, u)) != GSL_SUCCESS)
			return rc;
		for (i = 0; i < p->L.dim; i++)
			if (!isfinite(u[i]))
				return GSL_FAILURE;
		if (p->q) {
			snap_stick(s, u);
			if (s->hug)
				snap_separation(s, u);
		}
		return 0;
	}
	for (i = 0; i < s->ncache; i++)
		if (s->cache[i].h == h) {
			memcpy(u, s->cache[i].u, sizeof s->u0);
			return 0;
		}
	memcpy(u, s->u0, sizeof s->u0);
	gsl_odeiv2_step_reset(p->loc->s);
	rc = gsl_odeiv2_step_apply(p->loc->s, s->t0, h, u, yerr, NULL, NULL, &p->sys);
	if (rc != GSL_SUCCESS)
		return rc;
	/* a step whose error estimate is not finite was not made (bsimp's divergence) */
	for (i = 0; i < p->L.dim; i++)
		if (!isfinite(u[i]) || !isfinite(yerr[i]))
			return GSL_FAILURE;
	if (p->q) {
		snap_stick(s, u);
		if (s->hug)
			snap_separation(s, u);
	}
	i = s->cache_next;
	s->cache_next = (s->cache_next + 1) % CACHE;
	if (s->ncache < CACHE)
		s->ncache++;
	s->cache[i].h = h;
	memcpy(s->cache[i].u, u, sizeof s->u0);
	return 0;
}

/* The kind of the function being located (fun_target): 0 is the indicator, the event. */
static int
kind_of_target(const struct sim *s)
{
	return s->fun_target == 0 ? FUN_EVENT : FUN_KINK;
}

/*
 * The oriented value of the target function at h for Brent: > 0 where it
 * has not crossed yet (an exact zero counts as not crossed), < 0 where it
 * has.
 */
static double
oriented(double h, void *params)
{
	struct sim *s = params;
	double u[MAXDIM], f[MAXFUN], val;
	int kind[MAXFUN];

	s->loc_iter++;
	if (kind_of_target(s) != FUN_EVENT && s->t0 + h == s->t0)
		return DBL_MIN; /* the step's start has not crossed (a mode's side is its sign there) */
	if (restep(s, h, u))
		return NAN;
	watch(s, s->cur, s->t0 + h, u, f, kind);
	val = f[s->fun_target];
	if (kind[s->fun_target] == FUN_EVENT)
		return val >= 0.0 ? fmax(val, DBL_MIN) : val;
	val *= s->fun_sign0;
	return val > 0.0 ? val : (val == 0.0 ? DBL_MIN : val);
}

/*
 * Brackets the crossing of function k in [lo, hi] (not crossed at lo,
 * crossed at hi) down to a few ulps of t.  Returns 0, with the bracket in
 * *a, *b.
 */
static int
bracket(struct sim *s, int k, int sign0, double lo, double hi, double *a, double *b)
{
	gsl_function F = { oriented, s };
	double tol = 4.0 * DBL_EPSILON * fmax(fabs(s->t0 + hi), 1e-300);
	int it = 0, rc;

	s->fun_target = k;
	s->fun_sign0 = sign0;
	if (!(oriented(lo, s) > 0) || !(oriented(hi, s) < 0))
		return GSL_FAILURE;
	if ((rc = gsl_root_fsolver_set(s->root, &F, lo, hi)) != GSL_SUCCESS)
		return rc;
	*a = lo;
	*b = hi;
	while (it++ < MAX_BRENT) {
		double xl, xu;

		if ((rc = gsl_root_fsolver_iterate(s->root)) != GSL_SUCCESS)
			return rc;
		xl = gsl_root_fsolver_x_lower(s->root);
		xu = gsl_root_fsolver_x_upper(s->root);
		if (xu - xl <= tol)
			break;
	}
	{
		double xl = gsl_root_fsolver_x_lower(s->root);
		double xu = gsl_root_fsolver_x_upper(s->root);
		double fl = oriented(xl, s), fu = oriented(xu, s);

		/* GSL keeps opposite signs at the ends; order them as (not crossed, crossed) */
		if (fl > 0 && fu < 0) {
			*a = xl;
			*b = xu;
		} else if (fu > 0 && fl < 0) {
			*a = xu;
			*b = xl;
		} else {
			return GSL_FAILURE;
		}
		if (*b < *a) /* a crossing cannot come back: take the earlier crossed point */
			return GSL_FAILURE;
	}
	return 0;
}

/* Accepts the state at h (a located point) as the current state and restarts the stepper. */
static void
accept_at(struct sim *s, double h)
{
	double u[MAXDIM];

	restep(s, h, u);
	memcpy(s->u, u, sizeof u);
	unpack(s, s->cur, s->t0 + h, u);
	gsl_odeiv2_driver_reset(s->cur->d);
}

/*
 * Round-off at a sticking contact.  When the force and the velocity both
 * decay towards zero without changing sign (a Maxwell element with c below
 * sqrt(k m)/2), the computed values eventually wander about zero at the
 * level of round-off and may both turn positive, which would be read as a
 * separation.  A state whose v and Phi are both positive but below
 * eta = 100 max(rtol, atol) of the contact's largest |v| and F_c (the noise
 * of the integration, whose components are controlled to atol of their
 * scales) is on
 * the boundary of C to the precision of the computation: its v is set to 0,
 * which keeps it in C (rule R2) and changes it by less than the tolerance.
 */
static void
snap_stick(struct sim *s, double *u)
{
	struct phase *p = s->cur;
	const struct layout *L = &p->L;
	double y[MAXDIM], eta = fmax(64 * DBL_EPSILON, 100 * fmax(s->sc.run.rtol, s->sc.run.atol)), phi, v;
	double z[LAW_MAX_Z] = { 0 };
	int i;

	unscale(p, u, y);
	v = y[L->iv];
	for (i = 0; i < s->sc.law->n_z; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, v);
	if (v > 0 && phi > 0 && v <= eta * s->vmax && phi <= eta * s->Fcmax)
		u[L->iv] = 0.0;
}

/*
 * The noise of v at a scaled state: NOISE times the tolerance the control
 * allows it (atol + rtol |u_v| of its scale).
 */
enum { NOISE = 100 };

static double
v_noise(const struct sim *s, const double *u)
{
	int iv = s->cur->L.iv;

	return NOISE * s->scale[iv] * (s->sc.run.atol + s->sc.run.rtol * fabs(u[iv]));
}

/*
 * A separation that rounding cannot fake.  Under heavy damping (SHCCL
 * with c v0 / k beyond about 35) the receding velocity creeps up to the
 * value at which Phi = 0 (k / c for SHCCL) while x_c returns to 0: Phi is
 * then zero to within the integration's noise for the whole restitution,
 * and its computed sign says nothing.  A receding state (v > 0) whose Phi
 * is positive but vanishes within the noise of v (Newton's step on Phi in
 * v, Phi / (dPhi/dv), below v_noise) is on the boundary of C to the
 * precision of the computation: its v is moved by that step (and ulps)
 * until Phi <= 0, so that it stays in C (rule R2).  The contact then ends where Phi turns positive beyond
 * the noise, which is where the exact law ends it (x_c = 0 for SHCCL).
 * Laws whose Phi does not grow with v are left alone.  Returns 1 if the
 * state was moved.
 */
static int
snap_separation(struct sim *s, double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	double y[MAXDIM], z[LAW_MAX_Z] = { 0 }, dphi[LAW_MAX_Z + 2], phi, v, vn, dv;
	int nz = sc->law->n_z, i;

	if (!p->q)
		return 0;
	unscale(p, u, y);
	v = y[L->iv];
	if (!(v > 0))
		return 0;
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, v);
	if (!(phi > 0))
		return 0;
	sc->law->jac(sc->par, sc->ext, y[L->ixc], z, v, dphi, NULL);
	dv = dphi[nz + 1];
	if (!(dv > 0) || phi > dv * v_noise(s, u))
		return 0;
	vn = v - phi / dv;
	for (i = 0; i < 8 && phi_at(s, y[L->ixc], z, vn) > 0; i++)
		vn -= ldexp(fabs(vn) * DBL_EPSILON, i);
	if (phi_at(s, y[L->ixc], z, vn) > 0)
		return 0;
	u[L->iv] = vn * s->iscale[L->iv];
	return 1;
}

/* Does the step from the scaled state u begin on Phi = 0 to the noise, receding? */
static int
hugging(struct sim *s, const double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	double y[MAXDIM], z[LAW_MAX_Z] = { 0 }, dphi[LAW_MAX_Z + 2], phi;
	int nz = sc->law->n_z, i;

	if (!p->q)
		return 0;
	unscale(p, u, y);
	if (!(y[L->iv] > 0))
		return 0;
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, y[L->iv]);
	sc->law->jac(sc->par, sc->ext, y[L->ixc], z, y[L->iv], dphi, NULL);
	return dphi[nz + 1] > 0 && fabs(phi) <= dphi[nz + 1] * v_noise(s, u);
}

/* Is function i a candidate crossing from f0 to fx (with the noise filter of after_step)? */
static int
candidate(const struct sim *s, int kind, int i, double f0, double fx)
{
	/*
	 * A switching or extremum function that only wanders about zero at the
	 * level of the tolerance (|Psi_2| while a Maxwell element creeps,
	 * dPhi/dt at rest) marks no real kink or extremum.
	 */
	if (kind != FUN_EVENT && fmax(fabs(f0), fabs(fx)) <= s->sc.run.rtol * s->gmax[i])
		return 0;
	return crossed(kind, f0, fx);
}

/* dI/dt of the indicator of C at a scaled state (one-sided where I has a corner). */
static double
indicator_rate(const struct sim *s, const struct phase *p, double t, const double *u,
               const double *f, int n)
{
	const struct layout *L = &p->L;
	double y[MAXDIM], v, vdot;

	unscale(p, u, y);
	v = y[L->iv];
	if (p->q) {
		double z[LAW_MAX_Z] = { 0 }, phi;
		int i;

		for (i = 0; i < s->sc.law->n_z; i++)
			z[i] = y[L->iz + i];
		phi = phi_at(s, y[L->ixc], z, v);
		vdot = (-phi + scene_Fer(&s->sc, t)) / s->sc.d.m;
		return phi < v ? -f[n - 1] : -vdot; /* f[n - 1] = dPhi/dt */
	}
	vdot = scene_Fer(&s->sc, t) / s->sc.d.m;
	return y[L->ix] > v ? v : vdot;
}

/*
 * An event inside a step whose ends are both in C (the indicator dips
 * below zero and comes back: a separation or an impact stepped over).  The
 * cubic Hermite interpolant of the indicator from its values and rates at
 * the ends predicts where it is least; if it predicts a negative value,
 * the state there is computed.  Returns the fraction theta of the step
 * where the indicator was found negative (with the watched values there in
 * fx), or 0.
 */
static double
dip(struct sim *s, const double *f0, const double *f1, int n, double *fx)
{
	struct phase *p = s->cur;
	double H = s->H, d0, d1, c2, c3, th[2], u[MAXDIM];
	int kind[MAXFUN], nt, i;

	if (!(f0[0] >= 0.0 && f1[0] >= 0.0))
		return 0.0;
	d0 = H * indicator_rate(s, p, s->t0, s->u0, f0, n);
	d1 = H * indicator_rate(s, p, s->t0 + H, s->u1, f1, n);
	if (d0 >= 0.0 && d1 <= 0.0)
		return 0.0; /* rising then falling: no interior minimum */
	/* P(th) = f0 + d0 th + c2 th^2 + c3 th^3; its critical points solve P'(th) = 0 */
	c2 = 3.0 * (f1[0] - f0[0]) - 2.0 * d0 - d1;
	c3 = 2.0 * (f0[0] - f1[0]) + d0 + d1;
	nt = gsl_poly_solve_quadratic(3.0 * c3, 2.0 * c2, d0, &th[0], &th[1]);
	for (i = 0; i < nt; i++) {
		double t = th[i], P;

		if (!(t > 0.0 && t < 1.0))
			continue;
		P = f0[0] + t * (d0 + t * (c2 + t * c3));
		if (P >= 0.0)
			continue;
		if (restep(s, t * H, u))
			continue;
		watch(s, p, s->t0 + t * H, u, fx, kind);
		if (fx[0] < 0.0)
			return t;
	}
	return 0.0;
}

/*
 * From a point located on the continuous extension to the step's own
 * state there.  A kink or an extremum: the state at b is recomputed by one
 * step of the method from the step's start (it is then as accurate as any
 * step end), unless that state has left C, when the interpolated one
 * (which has not) is kept.  An event: the indicator of the recomputed
 * states is bracketed again in a window about b, widened until it holds
 * the crossing, so that the pre-jump state is a step's state in D; if no
 * window does, the interpolated bracket stands (its end is in D too).
 * Leaves use_dense set when the interpolated points stand.
 */
static void
real_point(struct sim *s, int event, double hi, double *a, double *b)
{
	double w = fmax(16.0 * (*b - *a), 1e-10 * s->H), ra, rb;
	int tries;

	s->use_dense = 0;
	if (!event) {
		double u[MAXDIM], f[MAXFUN];
		int kind[MAXFUN];

		if (restep(s, *b, u) != 0)
			goto keep;
		watch(s, s->cur, s->t0 + *b, u, f, kind);
		if (!(f[0] >= 0.0))
			goto keep;
		return;
	}
	for (tries = 0; tries < 5; tries++, w *= 64.0) {
		double lo = fmax(0.0, *b - w), up = fmin(hi, *b + w);

		if (up <= *b || tries == 4) /* the last window: the whole step */
			up = hi;
		if (tries == 4)
			lo = 0.0;
		if (bracket(s, 0, 1, lo, up, &ra, &rb) == 0) {
			*a = ra;
			*b = rb;
			return;
		}
	}
keep:
	s->use_dense = 1;
}

/*
 * Handles an accepted step (t0, u0) -> (t0 + H, u1): finds the earliest
 * crossing of the watched functions, if any, and acts on it.
 */
static int
after_step(struct sim *s, int load_kink)
{
	struct phase *p = s->cur;
	double f0[MAXFUN], f1[MAXFUN];
	int kind[MAXFUN], n, i, rc, any = 0;
	int cand[MAXFUN], ncand = 0;
	double lo = 0.0, hi = s->H, a = 0, b = 0;
	int first = -1;

	s->ncache = 0;
	s->cache_next = 0;
	if (p->q) {
		snap_stick(s, s->u1);
		snap_separation(s, s->u1);
		s->vmax = fmax(s->vmax, fabs(s->u1[p->L.iv] * s->scale[p->L.iv]));
	}
	n = watch(s, p, s->t0, s->u0, f0, kind);
	watch(s, p, s->t0 + s->H, s->u1, f1, kind);
	if (s->msign) {
		/*
		 * The mode's side is its frozen sign, even where the switching
		 * function is still zero to rounding on the other side (a step
		 * that begins on a located crossing): it crosses when its sign
		 * differs from the mode's.
		 */
		int k = 1 + s->sc.law->mode_kink;

		if (!(f0[k] * s->msign > 0))
			f0[k] = s->msign * DBL_MIN;
	}
	for (i = 0; i < n; i++)
		if (candidate(s, kind[i], i, f0[i], f1[i]))
			cand[ncand++] = i;
	if (ncand == 0 || cand[0] != 0) {
		/* the event stepped over: locate everything that crossed before the dip */
		double fx[MAXFUN], th = dip(s, f0, f1, n, fx);

		if (th > 0.0) {
			s->st.dips++;
			hi = th * s->H;
			for (ncand = 0, i = 0; i < n; i++)
				if (candidate(s, kind[i], i, f0[i], fx[i]))
					cand[ncand++] = i;
		}
	}
	for (i = 0; i < n; i++)
		s->gmax[i] = fmax(s->gmax[i], fmax(fabs(f0[i]), fabs(f1[i])));
	if (ncand == 0) {
		memcpy(s->u, s->u1, sizeof s->u1);
		unpack(s, p, s->t0 + s->H, s->u1);
		if (load_kink) {
			gsl_odeiv2_driver_reset(p->d);
			s->st.kinks++;
		}
		return push_sample(s, load_kink ? ARC_KINK : ARC_STEP);
	}
	/* the earliest crossing: bracket one, then look for earlier ones before it */
	s->loc_iter = 0;
	s->st.located++;
	while (ncand > 0) {
		int k = cand[0], nb = 0;
		double fa[MAXFUN];
		int kk[MAXFUN], sign0 = f0[k] > 0 ? 1 : -1;
		double ua[MAXDIM];

		if ((rc = bracket(s, k, sign0, lo, hi, &a, &b)) != 0) {
			if (rc == GSL_FAILURE && first >= 0)
				break;
			return fail(s, HB_ENUMERIC, "event location failed (no bracket)");
		}
		first = k;
		hi = b;
		/*
		 * Which functions have already crossed at a?  Any of them, not only
		 * the candidates: one that crossed and came back within the step
		 * (the indicator, most of all) is found here.
		 */
		restep(s, a, ua);
		watch(s, p, s->t0 + a, ua, fa, kk);
		for (i = 0; i < n; i++)
			if (i != k && candidate(s, kind[i], i, f0[i], fa[i]))
				cand[nb++] = i;
		if (nb == 0)
			break;
		ncand = nb;
		hi = a;
	}
	/* everything that has crossed at b happens here; the event wins */
	{
		double ub[MAXDIM], fb[MAXFUN], ua[MAXDIM], fa[MAXFUN];
		int kb[MAXFUN], event = 0, kink = 0;

		restep(s, b, ub);
		watch(s, p, s->t0 + b, ub, fb, kb);
		for (i = 0; i < n; i++)
			if (crossed(kind[i], f0[i], fb[i])) {
				any = 1;
				if (kind[i] == FUN_EVENT)
					event = 1;
				else if (kind[i] == FUN_KINK)
					kink = 1;
			}
		if (!any)
			return fail(s, HB_ENUMERIC, "event location lost its bracket");
		if (s->use_dense)
			real_point(s, event, hi, &a, &b);
		restep(s, a, ua);
		watch(s, p, s->t0 + a, ua, fa, kb);
		accept_at(s, b);
		if (event)
			return jump(s, LOCATE_BRENT, s->loc_iter, b - a, fa[0], fb[0]);
		if (s->msign && crossed(FUN_KINK, f0[1 + s->sc.law->mode_kink],
		                        fb[1 + s->sc.law->mode_kink])) {
			/* the mode's switching function crossed: the next step is on the other side */
			s->mforce = -s->msign;
			s->mforce_t = s->t;
		}
		s->st.kinks += kink;
		return push_sample(s, kink ? ARC_KINK : ARC_EXTREMUM);
	}
}

/* The scaled state of an arc sample, in the layout L (as pack() for the canonical state). */
static void
pack_sample(const struct sim *s, const struct layout *L, const struct arc_sample *a, double *u)
{
	double y[MAXDIM];
	int i;

	if (L->ix >= 0)
		y[L->ix] = a->x;
	y[L->iv] = a->v;
	if (L->ixc >= 0) {
		y[L->ixc] = a->xc;
		for (i = 0; i < s->sc.law->n_z; i++)
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

/*
 * A flow interval continued after sim_seek (or sim_set_scene) from inside
 * it: what a run that had not stopped would carry on with.  The scales are
 * those of the interval's first sample (a fresh run took them there), and
 * the noise filter's largest values (gmax, vmax) are those of the samples
 * kept, so that round-off-level kink crossings are ignored as they were
 * before the seek (without them every step "locates" one).
 */
static void
resume_interval(struct sim *s)
{
	const struct layout *L = &s->cur->L;
	const struct arc_sample *f = arc_at(s->arc, s->resume_first);
	double t = s->t, x = s->x, v = s->v, xm = s->xm, vm = s->vm;
	double fv[MAXFUN], u[MAXDIM];
	int kind[MAXFUN], n, i;
	size_t k;

	s->t = f->t;
	s->x = f->x;
	s->v = f->v;
	s->xm = f->xm;
	s->vm = f->vm;
	scales(s, L, s->q);
	s->t = t;
	s->x = x;
	s->v = v;
	s->xm = xm;
	s->vm = vm;
	for (k = s->resume_first; k <= s->resume_last; k++) {
		const struct arc_sample *a = arc_at(s->arc, k);

		pack_sample(s, L, a, u);
		n = watch(s, s->cur, a->t, u, fv, kind);
		for (i = 0; i < n; i++)
			s->gmax[i] = fmax(s->gmax[i], fabs(fv[i]));
		s->vmax = fmax(s->vmax, fabs(a->v));
	}
}

/* Begins a flow interval at the current state. */
static int
setup_interval(struct sim *s)
{
	const struct scene *sc = &s->sc;

	s->setup = 0;
	s->ntiny = 0;
	s->msign = s->mforce = 0;
	memset(s->gmax, 0, sizeof s->gmax);
	s->vmax = fabs(s->v);
	s->closed = !s->q && (sc->run.reduce & REDUCE_FLIGHT) &&
	            scene_Fer_constant(sc, s->t, sc->run.T) &&
	            (sc->d.system == SCENE_REDUCED || (sc->run.reduce & REDUCE_COM));
	if (s->closed) {
		s->resume = 0;
		return 0;
	}
	s->stiff_row = 0;
	if (s->built[s->q] != s->stepper[s->q] && phase_alloc(s, &s->ph[s->q], s->q))
		return fail(s, HB_ENOMEM, "out of memory for the integrator");
	s->cur = &s->ph[s->q];
	if (s->resume)
		resume_interval(s);
	else
		scales(s, &s->cur->L, s->q);
	pack(s, &s->cur->L, s->u);
	gsl_odeiv2_driver_reset(s->cur->d);
	{
		double Tc = s->q ? s->scale[s->cur->L.ixc] / s->scale[s->cur->L.iv]
		                 : s->scale[s->cur->L.ix] / s->scale[s->cur->L.iv];
		s->Tc = Tc;
		s->h = fmin(1e-2 * Tc, sc->run.T - s->t);
		if (s->resume && s->resume_h > 0)
			s->h = fmin(s->resume_h, sc->run.T - s->t);
		if (!(s->h > 0))
			s->h = 1e-9;
	}
	s->resume = 0;
	return 0;
}

/*
 * The radius of an explicit stepper's region of absolute stability along
 * the negative real axis (h |lambda| at its boundary), roughly the same
 * along the rays a damped oscillation lies on: DOP853's 6.1 is Hairer's
 * (the threshold of dop853.f's own stiffness test); rk8pd's 13-stage
 * Prince-Dormand 8(7) about 5.3; rkf45 and rkck about 3.
 */
static double
stability_radius(int stepper)
{
	switch (stepper) {
	case STEPPER_DOP853: return 6.1;
	case STEPPER_RK8PD: return 5.3;
	default: return 3.0;
	}
}

/* A check is a hit when h |lambda| is beyond this share of the stability radius. */
#define STIFF_FRACTION 0.5

/*
 * Stiffness of the contact flow after an accepted step of an explicit
 * stepper: h |lambda| over the decaying eigenvalues (Re lambda <= 0) of the
 * Jacobian of the dynamic components (the quadratures W, J_Fc, J_Fe, E_e
 * add only zero eigenvalues).  An explicit method's step is accurate long
 * before it is unstable, so h |lambda| beyond half the stepper's stability
 * radius means the stepper is held back by stability: a stiff flow, real
 * or oscillatory, where an implicit stepper takes far fewer steps.
 * Checked every 32nd step; eight hits in a row make the contact stiff, and
 * with run.stepper = auto the contacts go over to bsimp from then on.
 */
static int
stiffness(struct sim *s)
{
	struct phase *p = s->cur;
	const struct layout *L = &p->L;
	double J[MAXDIM * MAXDIM], dfdt[MAXDIM], rho = 0.0, hr;
	int idx[MAXDIM], nd = 0, i, k;

	if (!p->q || !explicit_stepper(s->stepper[1]) || (s->st.steps & 31) != 0)
		return 0;
	if (L->ix >= 0) idx[nd++] = L->ix;
	idx[nd++] = L->iv;
	idx[nd++] = L->ixc;
	for (i = 0; i < s->sc.law->n_z; i++)
		idx[nd++] = L->iz + i;
	if (L->ixm >= 0) {
		idx[nd++] = L->ixm;
		idx[nd++] = L->ivm;
	}
	if (s->Jdyn == NULL || s->Jdyn->size1 != (size_t)nd) {
		if (s->eig) gsl_eigen_nonsymm_free(s->eig);
		if (s->Jdyn) gsl_matrix_free(s->Jdyn);
		if (s->lambda) gsl_vector_complex_free(s->lambda);
		s->eig = gsl_eigen_nonsymm_alloc((size_t)nd);
		s->Jdyn = gsl_matrix_alloc((size_t)nd, (size_t)nd);
		s->lambda = gsl_vector_complex_alloc((size_t)nd);
		if (s->eig == NULL || s->Jdyn == NULL || s->lambda == NULL)
			return fail(s, HB_ENOMEM, "out of memory");
	}
	jacobian(s->t, s->u, J, dfdt, p);
	for (i = 0; i < nd; i++)
		for (k = 0; k < nd; k++)
			gsl_matrix_set(s->Jdyn, (size_t)i, (size_t)k, J[idx[i] * L->dim + idx[k]]);
	if (gsl_eigen_nonsymm(s->Jdyn, s->lambda, s->eig) != GSL_SUCCESS)
		return 0;
	/*
	 * The modes that decay (Re lambda <= 0) limit an explicit step by
	 * their modulus, not by their real part alone: an oscillatory mode
	 * -83 +- 1674i (study 1's sinking) holds the step at h |lambda| near the
	 * stability boundary although h max(-Re lambda) is 0.24.
	 */
	for (i = 0; i < nd; i++) {
		gsl_complex l = gsl_vector_complex_get(s->lambda, (size_t)i);

		if (GSL_REAL(l) <= 0.0)
			rho = fmax(rho, gsl_complex_abs(l));
	}
	hr = s->H * rho;
	s->st.stiff_checks++;
	s->st.stiff_hrho = fmax(s->st.stiff_hrho, hr);
	if (!(hr > STIFF_FRACTION * stability_radius(s->stepper[1]))) {
		s->stiff_row = 0;
		return 0;
	}
	s->st.stiff_hits++;
	if (++s->stiff_row < 8 || s->st.stiff)
		return 0;
	s->st.stiff = 1;
	s->st.stiff_t = s->t;
	if (s->sc.run.stepper == STEPPER_AUTO) {
		s->stepper[1] = STEPPER_BSIMP;
		s->st.switched = 1;
		if (phase_alloc(s, &s->ph[1], 1))
			return fail(s, HB_ENOMEM, "out of memory for the integrator");
		s->cur = &s->ph[1];
		gsl_odeiv2_driver_reset(s->cur->d);
	}
	return 0;
}

/*
 * Kinks as modes: the sign of the law's |w| term (law_type.psi_mode) is
 * frozen for the step that begins at the current state, so that the flow
 * is smooth inside it; its value is the sign of the switching function
 * there, or the side a crossing located at this instant went over to.
 * When it changes, the stepper forgets its stored derivative (first same
 * as last), which was of the other mode.
 */
static void
set_mode(struct sim *s)
{
	const struct scene *sc = &s->sc;
	const struct phase *p = s->cur;
	int m = 0;

	if (p->q && sc->law->psi_mode && sc->run.kinks) {
		double y[MAXDIM], g[LAW_MAX_KINKS], z[LAW_MAX_Z] = { 0 };
		const struct layout *L = &p->L;
		int i;

		if (s->mforce && s->mforce_t == s->t) {
			m = s->mforce;
		} else {
			unscale(p, s->u0, y);
			for (i = 0; i < sc->law->n_z; i++)
				z[i] = y[L->iz + i];
			sc->law->kinks(sc->par, sc->ext, y[L->ixc], z, y[L->iv], g);
			m = g[sc->law->mode_kink] > 0 ? 1 : (g[sc->law->mode_kink] < 0 ? -1 : 0);
		}
	}
	if (m != s->msign) {
		s->msign = m;
		gsl_odeiv2_driver_reset(s->cur->d);
	}
}

/* One accepted step of the numeric phase, with what follows from it. */
static int
numeric_step(struct sim *s)
{
	struct phase *p = s->cur;
	const struct scene *sc = &s->sc;
	double t = s->t, t1 = sc->run.T, kinks[4];
	int nk, load_kink = 0, rc, tries = 0;
	unsigned long failed0;

	/* a state already outside C where the interval begins jumps at once (rule R2) */
	{
		double f[MAXFUN];
		int kind[MAXFUN];

		watch(s, p, s->t, s->u, f, kind);
		if (f[0] < 0.0)
			return jump(s, LOCATE_START, 0, 0.0, f[0], f[0]);
	}
	nk = sc->run.kinks ? scene_load_kinks(sc, t, t1, kinks, 4) : 0;
	if (nk > 0) {
		t1 = kinks[0];
		load_kink = 1;
	}
	if (p->q && sc->run.h_max > 0 && t + sc->run.h_max < t1) {
		t1 = t + sc->run.h_max;
		load_kink = 0;
	}
	memcpy(s->u0, s->u, sizeof s->u);
	s->t0 = t;
	s->hug = hugging(s, s->u0);
	set_mode(s);
retry:
	failed0 = p->d->e->failed_steps;
	rc = gsl_odeiv2_evolve_apply(p->d->e, p->d->c, p->d->s, &p->sys, &t, t1, &s->h, s->u);
	s->st.rejected += (long)(p->d->e->failed_steps - failed0);
	if (rc != GSL_SUCCESS) {
		memcpy(s->u, s->u0, sizeof s->u);
		return fail(s, HB_ENUMERIC, rc == GSL_EBADFUNC ? "the flow function failed"
		                                              : "no acceptable step could be made (step size underflow)");
	}
	{
		int i, ok = 1;

		for (i = 0; i < p->L.dim; i++)
			ok &= isfinite(s->u[i]);
		if (!ok) {
			/* a non-finite accepted state: never let a NaN error norm pass as small */
			memcpy(s->u, s->u0, sizeof s->u);
			t = s->t0;
			s->h *= 0.25;
			gsl_odeiv2_driver_reset(p->d);
			if (++tries < MAX_RETRY && s->t0 + s->h > s->t0)
				goto retry;
			return fail(s, HB_ENUMERIC, "the state became non-finite");
		}
	}
	s->st.steps++;
	s->H = t - s->t0;
	{
		double dt0, dh;

		/* on Phi = 0 to the noise, the interpolant's error would exceed the noise: re-step */
		s->use_dense = !s->hug && hb_dop853_last(p->d->s, &dt0, &dh) == 0 && dt0 == s->t0;
	}
	if (s->H <= fmax(4.0 * DBL_EPSILON * fabs(t), 1e-13 * s->Tc)) {
		if (++s->ntiny > MAX_TINY)
			return fail(s, HB_ENUMERIC, "step size underflow: the error cannot be controlled");
	} else {
		s->ntiny = 0;
	}
	memcpy(s->u1, s->u, sizeof s->u);
	if ((rc = after_step(s, load_kink && t == t1)))
		return rc;
	if (s->end == SIM_RUNNING && !s->setup && (rc = stiffness(s)))
		return rc;
	if (s->end == SIM_RUNNING && !s->setup && s->t >= sc->run.T) {
		/* the horizon: the last sample is the end */
		if ((rc = push_sample(s, ARC_END)))
			return rc;
		finish_T(s);
	}
	return 0;
}

/* ---------------------------------------------------------------------- */
/* Public API.                                                              */

static void
reset_state(struct sim *s)
{
	const struct scene *sc = &s->sc;

	s->end = SIM_RUNNING;
	s->err[0] = s->endmsg[0] = '\0';
	s->t = 0.0;
	s->j = 0;
	s->q = 0;
	s->x = sc->init.x0;
	s->v = sc->init.v0;
	s->xc = 0.0;
	memset(s->z, 0, sizeof s->z);
	s->xm = sc->d.system == SCENE_FULL ? sc->init.xm0 : 0.0;
	s->vm = sc->d.system == SCENE_FULL ? sc->init.vm0 : 0.0;
	s->W = s->JFc = s->JFe = s->xcmax = s->Fcmax = 0.0;
	s->Ee = s->Wc = s->Wc0 = 0.0;
	s->xe = s->te = s->vi = 0.0;
	s->n_instant = 0;
	s->setup = 1;
	s->resume = 0;
	s->ncol = 0;
	s->ncol_total = 0;
	s->stepper[1] = sc->run.stepper == STEPPER_AUTO ? STEPPER_DOP853 : sc->run.stepper;
	arc_truncate(s->arc, 0);
	{
		struct sim_stats keep = s->st;

		memset(&s->st, 0, sizeof s->st);
		s->st.ncomp = keep.ncomp;
		memcpy(s->st.comp, keep.comp, sizeof s->st.comp);
	}
	push_sample(s, ARC_START);
}

static int
build(struct sim *s, char *msg, size_t n)
{
	int q;

	for (q = 0; q < 2; q++)
		s->stepper[q] = s->sc.run.stepper == STEPPER_AUTO ? STEPPER_DOP853 : s->sc.run.stepper;
	for (q = 0; q < 2; q++)
		if (phase_alloc(s, &s->ph[q], q))
			return status_set(msg, n, HB_ENOMEM, "out of memory for the integrator");
	{
		const char *names[MAXDIM];
		const struct layout *L = &s->ph[1].L;
		int i;

		for (i = 0; i < MAXDIM; i++)
			names[i] = "";
		if (L->ix >= 0) names[L->ix] = "x";
		names[L->ixc] = "x_c";
		names[L->iv] = "v";
		for (i = 0; i < s->sc.law->n_z; i++)
			names[L->iz + i] = i ? "z_c2" : (s->sc.law->n_z > 1 ? "z_c1" : "z_c");
		names[L->iW] = "W";
		names[L->iJc] = "J_Fc";
		names[L->iJe] = "J_Fe";
		names[L->iEe] = "E_e";
		if (L->ixm >= 0) {
			names[L->ixm] = "x_m";
			names[L->ivm] = "v_m";
		}
		/* the names depend on the law only through n_z: keep per-sim copies */
		for (i = 0; i < 8; i++)
			s->st.comp[i] = i < L->dim ? names[i] : NULL;
	}
	return 0;
}

struct sim *
sim_new(const struct scene *sc, char *msg, size_t n)
{
	struct sim *s;

	gsl_set_error_handler_off();
	s = calloc(1, sizeof *s);
	if (s == NULL) {
		status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	s->sc = *sc;
	if (scene_validate(&s->sc, msg, n) != 0) {
		free(s);
		return NULL;
	}
	s->arc = arc_new((size_t)s->sc.run.max_samples);
	s->root = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
	if (s->arc == NULL || s->root == NULL || build(s, msg, n) != 0) {
		if (s->arc == NULL || s->root == NULL)
			status_set(msg, n, HB_ENOMEM, "out of memory");
		sim_free(s);
		return NULL;
	}
	reset_state(s);
	return s;
}

void
sim_free(struct sim *s)
{
	if (s == NULL)
		return;
	phase_free(&s->ph[0]);
	phase_free(&s->ph[1]);
	if (s->root)
		gsl_root_fsolver_free(s->root);
	if (s->eig)
		gsl_eigen_nonsymm_free(s->eig);
	if (s->Jdyn)
		gsl_matrix_free(s->Jdyn);
	if (s->lambda)
		gsl_vector_complex_free(s->lambda);
	arc_free(s->arc);
	free(s->col);
	free(s);
}

int
sim_advance(struct sim *s, long max_steps, double max_seconds)
{
	double start = now_seconds(CLOCK_MONOTONIC), cpu0 = now_seconds(CLOCK_PROCESS_CPUTIME_ID);
	long work0 = s->work;
	int rc = 0;

	if (s->end != SIM_RUNNING)
		return HB_EDONE;
	while (s->end == SIM_RUNNING) {
		if (max_steps > 0 && s->work - work0 >= max_steps)
			break;
		if (max_seconds > 0 && ((s->work - work0) & 7) == 0 &&
		    now_seconds(CLOCK_MONOTONIC) - start >= max_seconds)
			break;
		if (s->setup) {
			if ((rc = setup_interval(s)))
				break;
		}
		s->work++;
		if (s->closed)
			rc = flight_closed(s);
		else
			rc = numeric_step(s);
		if (rc)
			break;
	}
	s->st.seconds += now_seconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
	s->st.wall += now_seconds(CLOCK_MONOTONIC) - start;
	return rc;
}

int
sim_run(struct sim *s)
{
	return sim_advance(s, 0, 0.0);
}

enum sim_end
sim_end(const struct sim *s)
{
	return s->end;
}

const char *
sim_end_str(const struct sim *s)
{
	return s->end == SIM_RUNNING ? "running" : s->endmsg;
}

const char *
sim_errmsg(const struct sim *s)
{
	return s->err;
}

const struct scene *
sim_scene(const struct sim *s)
{
	return &s->sc;
}

const struct arc *
sim_arc(const struct sim *s)
{
	return s->arc;
}

const struct sim_stats *
sim_stats(const struct sim *s)
{
	return &s->st;
}

size_t
sim_ncollisions(const struct sim *s)
{
	return s->ncol;
}

long
sim_collisions_total(const struct sim *s)
{
	return s->ncol_total;
}

const struct collision *
sim_collision(const struct sim *s, size_t i)
{
	return i < s->ncol ? &s->col[i] : NULL;
}

int
sim_contact_live(const struct sim *s, struct collision *out)
{
	if (!s->q)
		return 0;
	memset(out, 0, sizeof *out);
	out->i = s->ncol_total;
	out->j = s->j;
	out->te = s->te;
	out->ts = s->t;
	out->td = s->t - s->te;
	out->tf = NAN;
	out->vi = s->vi;
	out->e = s->vi != 0.0 ? -s->v / s->vi : NAN;
	out->xcmax = s->xcmax;
	out->Fcmax = s->Fcmax;
	out->xcr = fabs(s->xc);
	out->W = s->W;
	out->JFc = s->JFc;
	out->JFe = s->JFe;
	out->Lambda = s->JFc != 0.0 ? s->JFe / s->JFc : NAN;
	out->complete = 0;
	return 1;
}

int
sim_seek(struct sim *s, size_t i)
{
	const struct arc_sample *a;
	const struct arc_interval *iv;

	if (i >= arc_len(s->arc))
		return HB_EINVAL;
	s->resume_h = 0.0;
	if (i + 1 < arc_len(s->arc) && arc_at(s->arc, i + 1)->j == arc_at(s->arc, i)->j)
		s->resume_h = arc_at(s->arc, i + 1)->t - arc_at(s->arc, i)->t;
	arc_truncate(s->arc, i + 1);
	a = arc_at(s->arc, i);
	iv = arc_interval_at(s->arc, arc_interval_of(s->arc, i));
	/* continuing inside the interval (not at its pre-jump end) */
	s->resume = a->kind != ARC_PRE_JUMP;
	s->resume_first = iv->first;
	s->resume_last = i;
	s->t = a->t;
	s->j = a->j;
	s->q = a->q;
	s->x = a->x;
	s->v = a->v;
	s->xc = a->xc;
	memcpy(s->z, a->z, sizeof s->z);
	s->xm = a->xm;
	s->vm = a->vm;
	s->W = a->W;
	s->JFc = a->JFc;
	s->JFe = a->JFe;
	s->xcmax = a->xcmax;
	s->Fcmax = a->Fcmax;
	s->Ee = a->Ee;
	s->Wc = a->Wc;
	s->Wc0 = a->Wc + a->W;
	s->xe = a->x - a->xc;
	if (s->q) {
		const struct arc_sample *f = arc_at(s->arc, iv->first);

		s->te = f->t;
		s->vi = f->v;
	}
	while (s->ncol > 0 && s->col[s->ncol - 1].j >= s->j)
		s->ncol--;
	s->ncol_total = s->ncol > 0 ? s->col[s->ncol - 1].i + 1 : 0;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 >= s->j && !s->q)
		s->col[s->ncol - 1].tf = NAN;
	if (s->ncol > 0 && s->col[s->ncol - 1].j + 1 == s->j)
		s->col[s->ncol - 1].tf = NAN;
	s->n_instant = 0;
	s->err[0] = s->endmsg[0] = '\0';
	s->end = SIM_RUNNING;
	s->setup = 1;
	if (s->t >= s->sc.run.T)
		finish_T(s);
	else if (s->j >= s->sc.run.J) {
		s->end = SIM_END_J;
		snprintf(s->endmsg, sizeof s->endmsg, "jump cap J = %ld reached at t = %.9g s",
		         s->sc.run.J, s->t);
	}
	return 0;
}

static int
same_bodies(const struct scene *a, const struct scene *b)
{
	return a->d.m1 == b->d.m1 && a->d.m2 == b->d.m2 && a->d.system == b->d.system;
}

int
sim_set_scene(struct sim *s, const struct scene *sc, int *restarted, char *msg, size_t n)
{
	struct scene nsc = *sc;
	int restart, rc;

	if (restarted)
		*restarted = 0;
	if ((rc = scene_validate(&nsc, msg, n)) != 0)
		return rc;
	restart = nsc.d.system != s->sc.d.system ||
	          memcmp(&nsc.init, &s->sc.init, sizeof nsc.init) != 0 ||
	          (s->q && (nsc.law != s->sc.law || nsc.ext != s->sc.ext || !same_bodies(&nsc, &s->sc)));
	{
		/* build for the new scene aside: on failure the simulator is exactly as it was */
		struct scene old = s->sc;
		struct phase oldph[2] = { s->ph[0], s->ph[1] };
		int oldstepper[2] = { s->stepper[0], s->stepper[1] };
		int oldbuilt[2] = { s->built[0], s->built[1] };
		struct sim_stats oldst = s->st;

		s->sc = nsc;
		memset(s->ph, 0, sizeof s->ph);
		if (build(s, msg, n) != 0) {
			phase_free(&s->ph[0]);
			phase_free(&s->ph[1]);
			s->sc = old;
			memcpy(s->ph, oldph, sizeof s->ph);
			memcpy(s->stepper, oldstepper, sizeof s->stepper);
			memcpy(s->built, oldbuilt, sizeof s->built);
			s->st = oldst;
			return HB_ENOMEM;
		}
		phase_free(&oldph[0]);
		phase_free(&oldph[1]);
	}
	arc_set_max(s->arc, (size_t)nsc.run.max_samples);
	if (restart) {
		reset_state(s);
		if (restarted)
			*restarted = 1;
		return 0;
	}
	/* continue from the last sample with the new values */
	return sim_seek(s, arc_len(s->arc) - 1);
}

int
sim_restart(struct sim *s)
{
	reset_state(s);
	return 0;
}
