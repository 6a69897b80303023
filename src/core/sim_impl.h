/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_impl.h - what the files of the simulator share (private to the engine):
 * the state of a run (struct hb_sim), the layouts and phases of the flow
 * intervals, and the functions one file calls in another.  sim.c holds the
 * driver (its header comment describes the method), sim_life.c a
 * simulator's making, change of scene, freeing and accessors, sim_seek.c
 * hb_sim_seek, sim_branch.c hb_sim_branch.
 *
 * The files call one another one way (make lint-cycles): a branch seeks,
 * sets the scene and advances; a change of scene seeks and restarts; a
 * seek replays (advances) and restarts; the run advances.  What several
 * of them keep is below them all: the outputs a seek keeps aside
 * (sim_pend.c), the record of the branches (sim_branch_log.c), a run's
 * ends (sim_end.c), a chain's bodies (sim_body.h).  What the files of a
 * chain declare for the rest: sim_chain_impl.h (included at the end).
 */
#ifndef HYBOUNCE_SIM_IMPL_H
#define HYBOUNCE_SIM_IMPL_H

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
#include "known.h"
#include "step_bsimp.h"
#include "step_dop853.h"
#include "step_rk8pd.h"
#include "sim_body.h"

enum {
	MAXDIM = 11,           /* x, v, x_c, z1, z2, W, JFc, JFe, E_e, x_m, v_m */
	MAXFUN = HB_LAW_MAX_KINKS + 3,
	CACHE = 96,
	CCACHE = 16,           /* re-steps of a chain's step kept */
	FLIGHT_SAMPLES = 48,   /* samples drawn along a closed-form flight, for plots */
	MAX_BRENT = 100,
	MAX_RETRY = 60,        /* retries of a step that produced a non-finite state */
	MAX_TINY = 200,        /* consecutive steps at the resolution of t before failing */
};
_Static_assert(MAXDIM <= HB_SIM_MAXCOMP, "hb_sim_stats holds every component's scale");

/* A function the hot paths take inline whatever the compiler's estimate (the rhs, the snaps). */
#define ALWAYS_INLINE inline __attribute__((always_inline))

/* Which components the ODE of a flow interval carries; -1 when absent. */
struct layout {
	int dim;
	int ix, iv, ixc, iz, iW, iJc, iJe, ixm, ivm, iEe;
	int nread;              /* f reads components [0, nread) (and v_m): x, x_c, v, z */
};

struct phase {
	struct hb_sim *s;
	struct layout L;
	int q;
	gsl_odeiv2_system sys;
	gsl_odeiv2_driver *d;    /* stepper, control and evolver */
	gsl_odeiv2_driver *loc;  /* single steps for event location */
	struct known_f known;    /* f where d's steps have evaluated it (known.h) */
	double fer_t, fer;       /* a ramp's F_e,r at fer_t, the last t the rhs asked (sim_rhs.c) */
};

/* Kinds of the functions watched along a step. */
enum fun_kind { FUN_EVENT, FUN_KINK, FUN_XCMAX, FUN_FCMAX };


struct iface {
	const struct hb_law_type *law;
	const double *par;      /* the law's parameters (a chain's: parv) */
	double parv[HB_LAW_MAX_PARAMS]; /* a chain's: its own parameters (derived for its pair) */
	int ext;                /* rule R1 continuation */
	int lo, hi;             /* the bodies below and above (index into body[]; lo = -1: the floor) */
	double m;               /* effective mass m_lo m_hi / (m_lo + m_hi) (m_hi on the floor) */
	double wlo, whi;        /* a chain's: m_lo / (m_lo + m_hi), m_hi / (m_lo + m_hi) */
	double Fer;             /* a chain's: F_e,r = (m_lo F_hi - m_hi F_lo) / (m_lo + m_hi), constant */
	double (*Fer_at)(const struct hb_sim *s, const struct iface *I, double t); /* F_e,r at t */
	double ilo, ihi;        /* a chain's: 1 / m_lo (0 on the floor), 1 / m_hi */
	double arel;            /* a chain's: a_hi - a_lo, the gap's acceleration in flight */
	int off;                /* a chain's: its block in the clusters' ODE (sim_cluster.c), -1: none */
	int watch;              /* a chain's: 1 while in flight next to a cluster (its gap is watched) */
	double tphi;            /* a chain's: Phi at the state rhs evaluates (scratch) */
	double tdphi[HB_LAW_MAX_Z + 2]; /* a chain's: Phi's and Psi's partials there (scratch) */
	double tdpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];
	int msign;              /* a chain's: the sign of its law's mode term, frozen for a step */
	int mforce;             /* a chain's: the sign the mode takes at t = mforce_t (a located crossing) */
	double mforce_t;
	int fo;                 /* a chain's: its first watched function (index; sim_cluster_step.c) */
	double vmax;            /* a chain's: the largest |v| in the contact in progress (sim_snap.c) */
	int over;               /* a chain's: the model limits passed in this contact (1 indentation,
	                           2 non-neighbours above it) */

	/* its state at (t, j) */
	int q;
	double x, v, xc, z[HB_LAW_MAX_Z];
	double W, JFc, JFe, xcmax, Fcmax;
	double Ee, Wc;          /* works of its F_er and F_c since t = 0 */
	double Wc0;             /* Wc at the commencement of the contact in progress */
	double xe;              /* x at the commencement of the contact in progress */
	double te, vi;          /* commencement time and approach velocity */
	int pushed;             /* a chain's: the contact in progress began as a touching pair
	                           pushed together, not an impact (no e; sim_record.c) */
	int ninst;              /* its jumps at the instant tinst (run.chatter bounds them) */
	double tinst;
};

/*
 * A chain's clusters (docs/chains.md section 8): maximal runs of bodies
 * b0..b1 joined by interfaces in contact, with the floor when its
 * interface is in contact; the centre of mass of one without the floor in
 * closed form from (t0, y0, u0) under its loads alone.
 */
struct cluster {
	int b0, b1, floor;
	double M, t0, y0, u0, a;
};

/* The clusters' ODE (sim_cluster.c): one block per interface in contact. */
struct clusters {
	int nact, ncl, nwatch, dim, nf;
	int *act;               /* the interfaces in contact (index into ifc), ascending */
	struct cluster *cl;
	int *wif;               /* the interfaces in flight next to a cluster, ascending */
	int capact, capcl, capwif, capf;
	double *by, *bu;        /* scratch: the bodies' (y, u) of the clusters at a state */
	int capb;
	int *fkind, *fif;       /* each watched function's kind and interface (index) */
	int built_dim, built_stepper; /* what the driver of the phase (hb_sim.cph) was made for */
	double tfree;           /* the earliest closing of a gap between two flying bodies */
	int ifree;              /* ... its interface (index), -1: none */
};

struct hb_sim {
	struct hb_scene sc;
	struct clusters cx;     /* a chain's clusters in contact */
	char limnote[400];      /* a chain's first passing of a model limit (run.chain_limits = warn) */
	long nlim;              /* ... and how many times one was passed */
	int chain;              /* 1: a chain scene (sc.chain.n >= 1) */
	int nbody, k0, nif;     /* N, the first interface's number (0: a floor), N - k0 */
	int ia;                 /* I - ifc */
	struct body *body;      /* body[i] is body i + 1 */
	struct iface *ifc;      /* ifc[i] is interface k0 + i */
	int capbody, capif;     /* their allocated lengths */
	struct iface *I;        /* the interface of the flow interval (the cluster in contact, or in flight) */
	struct hb_arc *arc;
	struct hb_collision *col;
	size_t ncol, colcap;
	long ncol_total;        /* collisions completed, kept or thinned out (col[].i) */
	enum hb_sim_end end;
	char err[640];
	char endmsg[700];
	struct hb_sim_stats st;

	/* canonical state at (t, j): the interfaces' (above) and the centre of mass of the cluster */
	double t;
	long j;
	double xm, vm;

	/* the current flow interval */
	int setup;          /* 1: the next work begins a new interval */
	int closed;         /* 1: closed-form flight */
	struct phase ph[2]; /* numeric flight, contact */
	struct phase cph;   /* a chain's clusters in contact (sim_cluster_step.c) */
	struct phase *cur;
	/*
	 * The arrays of the flow interval's ODE (sim_work.c): of dim.u
	 * components, of dim.f watched functions, sized for the pair or for a
	 * chain's clusters.
	 */
	struct {
		int u, f, ncache;
		double *buf;
		int *ibuf;
	} dim;
	double *scale;
	double *iscale;     /* 1 / scale, exact: every scale is a power of 2 */
	double pscale[MAXDIM], piscale[MAXDIM]; /* the pair's: where scale and iscale point
	                       for it (its rhs reads them here: no pointers to hold) */
	double *u;          /* scaled ODE state */
	double h;           /* step size suggestion */
	double Tc;          /* time scale of the interval */
	int ntiny;
	double *gmax;       /* largest |value| of each watched function in the interval */
	double vmax;        /* largest |v| in the contact */

	/* location workspace */
	double t0, H, *u0, *u1;
	double *ut;         /* a root finder's iterate (oriented_value; its unread tail stale, not read) */
	double *yerr, *ua, *ub, *uc; /* scratch states of the location */
	double *lf0, *lf1, *lfa, *lfb; /* scratch watched values of the location */
	double *lr0, *lr1;  /* ... the rates of their indicators (NAN: none) */
	int *lkind, *lka, *cand, *cand0; /* ... their kinds, the candidates */
	struct {            /* the watched values at the last state hbs_watch_at was asked */
		int valid, n, *kind;
		const struct phase *p;
		double t, xe, *u, *f, rate, *r; /* rate: the pair's indicator's; r: a chain's events' */
		double pf[2]; /* in contact: Phi and F_e,r there (the arc sample's, hbs_push_sample) */
	} w;
	double *cache_h, *cache_u; /* the re-steps of the step (dim.ncache of them) */
	int ncache, cache_next;
	int fun_target, fun_kind, fun_sign0; /* the function located (sim_locate.c) */
	int use_dense;      /* 1: restep() reads the last step's continuous extension */
	int use_herm;       /* 1: restep() reads the cubic Hermite interpolant of the step */
	double *f0, *f1;    /* its derivatives at the step's ends (scaled) */
	int hug;            /* 1: the step began on Phi = 0 to the noise, receding (see snap_separation) */
	int msign;          /* the frozen sign of the law's mode kink in this step (0: none) */
	int resume;         /* 1: the next interval continues one cut by hb_sim_seek (see resume_interval) */
	size_t resume_first, resume_last; /* its samples kept in the arc */
	double resume_h;    /* the step to continue with from the seek point, or 0 */
	double h1[2];       /* the first step of the last numeric interval of each q, / its Tc */
	int first;          /* 1: the next step is its interval's first */
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

	/* sim_branch_log.c: the run as its first scene and the branches taken since */
	struct hb_scene sc0;        /* the scene the run began with at t = 0 */
	struct hb_branch *br;
	size_t nbr, brcap;
	double unrec_t;             /* -1, or the first t the scene changed unrecorded */

	/*
	 * sim_seek.c, sim_pend.c: a chain's seek.  unit_n counts the samples the last unit
	 * of work pushed (hb_sim_advance's, or hbs_reset_state's start); what that
	 * unit pushed after the sample a seek cut at is kept aside (pend) and
	 * given back, unchanged, before any further work.
	 */
	size_t unit_n;
	struct {
		int active;
		struct hb_arc_sample *s;    /* the samples after the cut, in order */
		size_t n, cap;
		int has_jump, has_col, tf_row;
		struct hb_arc_jump jr;      /* the unit's jump, when its post-jump sample is aside */
		struct hb_collision col;    /* the collision that jump completed */
		double tf;                  /* the flight time that jump gave row tf_row (-1: none) */
		double t;                   /* the simulator's t and j after the unit */
		long j;
		enum hb_sim_end end;
		char err[640];
		char endmsg[700];
	} pend;
};

/*
 * Copies a state of the flow interval's ODE: its dim components, or the
 * whole of the pair's arrays (MAXDIM: a fixed size the compiler copies
 * inline; their capacity is MAXDIM).
 */
static inline void
hbs_ucopy(const struct hb_sim *s, double *dst, const double *src)
{
	if (s->dim.u == MAXDIM)
		memcpy(dst, src, MAXDIM * sizeof *dst);
	else
		memcpy(dst, src, (size_t)s->cur->L.dim * sizeof *dst);
}

static inline double
phi_at(const struct hb_sim *s, double xc, const double *z, double v)
{
	return s->I->law->phi(s->I->par, s->I->ext, xc, z, v);
}

/*
 * The interface's reduced applied force F_e,r at t (the paper's, for its
 * pair; the scene's loads in the reduced and the full system).
 */
static inline double
iface_Fer(const struct hb_sim *s, const struct iface *I, double t)
{
	return I->Fer_at(s, I, t);
}

/*
 * sim_pend.c: the outputs of a chain's unit of work after the sample a
 * seek cut at (sim_seek.c), kept aside; given back (before any work, a
 * seek or a change of scene); forgotten (a restart).
 */
int
hbs_pend_put_aside(struct hb_sim *s, size_t i);
int
hbs_pend_flush(struct hb_sim *s);
void
hbs_pend_drop(struct hb_sim *s);
/* sim.c: the run begun at t = 0 (a new simulator, a restart, a chain's replay in sim_seek.c) */
void
hbs_reset_state(struct hb_sim *s);

/* sim_branch_log.c: the branches taken, forgotten, cut at sample i, one recorded (-1: no memory) */
void
hbs_branches_clear(struct hb_sim *s);
void
hbs_branches_cut(struct hb_sim *s, size_t i);
int
hbs_branches_push(struct hb_sim *s, const struct hb_branch *b);

/* sim_work.c: room for an ODE of nu components and nf watched functions; freed */
int
hbs_work_reserve(struct hb_sim *s, int nu, int nf);
void
hbs_work_free(struct hb_sim *s);

/*
 * sim_restep.c: the state one step of length h from the step's start
 * (t0, u0) (sim_locate.c), its first n components where it is read from
 * the Hermite guide, cached for the step; a function of the state's
 * crossing in (0, hend] of the step located on such re-steps with the
 * engine's root finder (sim_root.c): a chain's limits (sim_limits.c)
 */
int
hbs_restep_n(struct hb_sim *s, double h, double *u, int n);
typedef double hbs_val_fn(struct hb_sim *s, double t, const double *u, const void *arg);
int
hbs_locate_fn(struct hb_sim *s, hbs_val_fn *val, const void *arg, double hend, double fa, double *hb,
              int *iters);

/* sim_flow.c */
int
hbs_explicit_stepper(int stepper);
const gsl_odeiv2_step_type *
hbs_stepper_type(int stepper);
int
hbs_evolve(struct hb_sim *s, struct known_f *k, gsl_odeiv2_evolve *e, gsl_odeiv2_control *c,
           gsl_odeiv2_step *st, const gsl_odeiv2_system *sys, double t0, const double *u0, double t1,
           double *t, double *h, double *u, double *H);

void
hbs_unscale(const struct phase *p, const double *u, double *y);

int
hbs_jacobian(double t, const double u[], double *dfdu, double dfdt[], void *params);

void
hbs_phase_free(struct phase *p);

int
hbs_phase_alloc(struct hb_sim *s, struct phase *p, int q);
/* ... a phase of the system sys (a chain's clusters) stepped by the scene's stepper[1] */
int
hbs_phase_alloc_sys(struct hb_sim *s, struct phase *p, const gsl_odeiv2_system *sys);

void
hbs_set_com(struct hb_sim *s);

void
hbs_scales(struct hb_sim *s, const struct layout *L, int q);

/* ... and interface I's contact sizes at approach speed V under load F (both systems) */
void
hbs_contact_scale(const struct iface *I, double V, double F, double *X, double *Vk);

void
hbs_pack(struct hb_sim *s, const struct layout *L, double *u);

void
hbs_unpack(struct hb_sim *s, const struct phase *p, double t, const double *u);

void
hbs_pack_sample(const struct hb_sim *s, const struct layout *L, const struct hb_arc_sample *a, double *u);

/* sim_end.c: the run failed (status returned), at interface I (a chain's limit), ended at T or J */
int
hbs_fail(struct hb_sim *s, int status, const char *why);
int
hbs_fail_iface(struct hb_sim *s, const struct iface *I, int status, const char *why);
void
hbs_finish_T(struct hb_sim *s);
void
hbs_finish_J(struct hb_sim *s);

/* sim_record.c */
int
hbs_push_sample(struct hb_sim *s, int kind);
int
hbs_jump(struct hb_sim *s, int how, int iterations, double width, double ilo, double ihi);

/* sim_flight.c */
int
hbs_flight_closed(struct hb_sim *s);

/* sim_iface.h: one interface's watched terms (Phi, kinks, dPhi/dt, its mode), for both systems */

/* sim_watch.c: the values of the pair's watched functions at a scaled state, their kinds */
int
hbs_watch(struct hb_sim *s, const struct phase *p, double t, const double *u, double *f,
          int *kind);
/* ... the value of function k alone (the same double), its kind in *kind */
double
hbs_watch_one(struct hb_sim *s, const struct phase *p, double t, const double *u, int k,
              int *kind);

/*
 * The same, remembered for the last state asked (where one step ends, the
 * next begins); hbs_scales forgets it.  With rate not NULL, the rate of
 * each event's indicator into rate[] at its index (a chain's: NAN where
 * none, and at the functions that are no events; the pair's: rate[0],
 * its one event, alone).
 */
int
hbs_watch_at(struct hb_sim *s, const struct phase *p, double t, const double *u, double *f,
             int *kind, double *rate);

/* Only f[0] (the indicator of C) of hbs_watch_at, from the same cache. */
double
hbs_watch_indicator(struct hb_sim *s, const struct phase *p, double t, const double *u);

/* sim_snap.c: a state on the boundary of C to the precision of the computation */
int
hbs_hugging(struct hb_sim *s, const double *u);
void
hbs_snap_stick(struct hb_sim *s, double *u);
int
hbs_snap_separation(struct hb_sim *s, double *u);

/* Did function i (of this kind) cross between values a (step start) and b? */
static inline int
hbs_crossed(int kind, double a, double b)
{
	switch (kind) {
	case FUN_EVENT: return a >= 0.0 && b < 0.0;
	case FUN_KINK: return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
	default: return a < 0.0 && b > 0.0; /* minima of x_c and of Phi */
	}
}

/*
 * ... and is it a candidate?  A switching or extremum function that only
 * wanders about zero at the level of the tolerance (|Psi_2| while a
 * Maxwell element creeps, dPhi/dt at rest) marks no real kink or extremum:
 * gmax is the largest |value| the function has had in the interval.  The
 * driver asks it.  (Called for every function at every step: inline,
 * and without fmax.)
 */
static inline int
hbs_candidate(const struct hb_sim *s, int kind, double gmax, double f0, double fx)
{
	double a0 = fabs(f0), ax = fabs(fx);

	if (kind != FUN_EVENT && (a0 > ax ? a0 : ax) <= s->sc.run.rtol * gmax)
		return 0;
	return hbs_crossed(kind, f0, fx);
}

/*
 * The cubic Hermite interpolant of a step of length H from (u0, its
 * derivative d0) to (u1, d1), at h into it: its first n components into u.
 * Fourth-order: the location is guided by it (a stepper
 * without a continuous extension), and take no located point from it.
 */
static inline void
hbs_hermite(double h, double H, int n, const double *u0, const double *d0, const double *u1,
            const double *d1, double *u)
{
	double th = h / H, th2 = th * th, th3 = th2 * th;
	double a0 = 2 * th3 - 3 * th2 + 1, b0 = (th3 - 2 * th2 + th) * H;
	double a1 = 3 * th2 - 2 * th3, b1 = (th3 - th2) * H;

	for (int i = 0; i < n; i++)
		u[i] = a0 * u0[i] + b0 * d0[i] + a1 * u1[i] + b1 * d1[i];
}

/*
 * sim_root.c: the root finder the engine locates with.  A function of
 * the time h into a step, oriented: value > 0 where it has not crossed (an
 * exact zero counts as not crossed), < 0 where it has, NAN where the state
 * at h cannot be computed; every evaluation counted in *iter.
 */
struct hbs_root {
	double (*value)(double h, void *ctx);
	void *ctx;
	int *iter;
	gsl_root_fsolver *solver; /* Brent's */
	double t0, H;       /* the step's start and length */
	int stall;          /* 1: its stalls are closed (see sim_root.c) */
	double noise;       /* ... where its value is zero to rounding */
};
int
hbs_root_bracket(struct hbs_root *r, double lo, double hi, double htol, double *a, double *b);
int
hbs_root_bisect(struct hbs_root *r, double lo, double hi, double htol, double *a, double *b);

/*
 * sim_dip.c: the earliest fraction theta of the step just accepted where an
 * event that is no candidate (cand, ncand) was found out of C, with the
 * watched values there in fx; 0: none (f0, f1: the watched values at the
 * step's ends, r0, r1 their indicators' rates, hbs_watch_at)
 */
double
hbs_dip(struct hb_sim *s, const double *f0, const double *f1, const double *r0, const double *r1,
        const int *kind, int n, const int *cand, int ncand, double *fx);

/* sim_locate.c: acts on the accepted step (t0, u0) -> (t0 + H, u1) */
int
hbs_after_step(struct hb_sim *s, int load_kink);

/*
 * sim_stiff.c: stiffness detection per interface, for both systems:
 * is a check due after this step (counted as a Jacobian evaluation); the
 * largest decaying |lambda| of interface I's contact flow (sc: the scales
 * of its x_c, v, z...) into *rho (-1: none computable); the verdict on
 * h |lambda| (1: the run goes over to bsimp now); the pair's check.
 */
int
hbs_stiff_begin(struct hb_sim *s);
int
hbs_iface_rho(struct hb_sim *s, const struct iface *I, double minv, const double *sc, double *rho);
int
hbs_stiff_verdict(struct hb_sim *s, double hr);
int
hbs_stiffness(struct hb_sim *s);

/*
 * sim_rhs.c: the right-hand side specialised for the scene's law and the
 * phase's layout, or NULL where the general one of sim_flow.c stays.
 */
typedef int hbs_rhs_fn(double t, const double u[], double du[], void *params);
hbs_rhs_fn *
hbs_rhs_special(const struct hb_sim *s, const struct phase *p);
/* ... the general one (sim_flow.c), for any scene: the same doubles */
hbs_rhs_fn hbs_rhs;

#include "sim_chain_impl.h"

#endif
