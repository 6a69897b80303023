/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * check.h - the paper's checks of a computed solution (section Simulation).
 *
 *  - hb_check_solution_pair: the hybrid time domain is ordered; every sample
 *    lies in the flow set C except the last before a jump, which lies in the
 *    jump set D (in a chain, whose samples show one interface each, a
 *    sample at the instant its flow interval ends may lie in D: interfaces
 *    that reach their jump sets at one instant jump there one at a time);
 *    each post-jump state is g of the pre-jump state, exactly.
 *  - hb_check_euler: forward Euler, started from a flow interval's initial
 *    state, converges to its final state; returns the estimated order.
 */
#ifndef HB_CHECK_H
#define HB_CHECK_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "scene.h"
#include "arc.h"

/* 1 if the state of sample a lies in C (resp. D), by the paper's sets. */
int hb_check_in_C(const struct hb_scene *sc, const struct hb_arc_sample *a);
int hb_check_in_D(const struct hb_scene *sc, const struct hb_arc_sample *a);

/* Returns 0, or HB_EINVAL with the first violation (sample, t, j) in msg. */
int
hb_check_solution_pair(const struct hb_scene *sc, const struct hb_arc *a, char *msg, size_t n);

/*
 * Forward Euler on interval k of the arc with N, 2N, 4N, ... steps; fills
 * *order with the estimated order of convergence to the interval's final
 * state (in the scaled norm).  Returns 0 or HB_EINVAL (msg) if the interval
 * is too short to say.
 */
int
hb_check_euler(const struct hb_scene *sc, const struct hb_arc *a, size_t k, double *order,
            char *msg, size_t n);

/*
 * The physics a computed arc must obey, to the accuracy asked for
 * (tol = max(run.rtol, run.atol)):
 *  - the work-energy identity of the relative motion, at every sample:
 *        m v^2/2 - m v0^2/2 = E_e + W_c
 *    (E_e and W_c are the works of F_er and F_c since t = 0, integrated
 *    with the flow); its residual, relative to the run's energy scale, is
 *    the run's error estimate, and must stay within HB_CHECK_PHYS_FACTOR tol;
 *  - passivity: for a law that cannot give energy back (every law so far:
 *    springs, dampers, Bouc-Wen with |gamma| <= beta), each completed
 *    contact absorbs W >= 0, up to HB_CHECK_PHYS_FACTOR tol of its impact
 *    energy m v_i^2/2;
 *  - restitution: for such a law e <= sqrt(1 + 2 max(E_e,c, 0) / (m v_i^2)),
 *    E_e,c the work of the applied force over the contact (1 without
 *    loads), up to the same margin;
 *  - for an elastic law (hertz, linear) W = 0 and e = that bound, to the
 *    same margin: their deviations are the contact's error.
 * Collision i is read from the arc: the contact's first sample (t_e) and
 * its pre-jump sample (t_s).
 */
#define HB_CHECK_PHYS_FACTOR 100.0

struct hb_check_physics {
	double tol;          /* max(rtol, atol): what was asked */
	double escale;       /* energy scale of the run, J */
	double resid;        /* largest |work-energy residual| / escale */
	size_t resid_at;     /* sample where it is largest */
	int passive;         /* 1: the law cannot give energy back */
	int elastic;         /* 1: the law stores and returns, no dissipation */
	size_t ncontacts;    /* completed contacts checked */
	double wmin;         /* smallest W / (m v_i^2 / 2) over them (elastic: largest |W| / ...) */
	long wmin_at;        /* its collision index, -1 if none */
	double W_at;         /* that contact's W, J */
	double emax;         /* largest e - e_bound over them (elastic: |e - e_bound|) */
	long emax_at;        /* its collision index, -1 if none */
	double e_at;         /* that contact's e */
	double e_bound;      /* and its bound */
	size_t nzero;        /* contacts begun at zero approach velocity: m v_i^2/2 at most
	                        tol times the energy scale (e meaningless, not checked) */
	long zero_at;        /* the first of them, -1 if none */
	double vi_zero;      /* its v_i, m/s */
	int failed;          /* number of checks that failed (0..3) */
};

/*
 * Fills *r; returns 0 when every check passes, or HB_EINVAL with one line
 * per failure ("; "-separated; no line holds "; " itself) in msg.
 */
int
hb_check_physics(const struct hb_scene *sc, const struct hb_arc *a, struct hb_check_physics *r,
              char *msg, size_t n);

/*
 * The collisions that break what the law allows, by the same measure and
 * margin as hb_check_physics (r is its result for this scene and arc):
 * flags[i] gets HB_CHECK_BAD_W when completed collision i returns energy
 * (or, for an elastic law, absorbs some), HB_CHECK_BAD_E when its e is
 * above the bound (elastic: off the exact value), 0 otherwise, for
 * i < nflags.  Returns how many collisions in the arc fail (those thinned
 * out of a long run are not there and not counted).
 */
#define HB_CHECK_BAD_W 1u
#define HB_CHECK_BAD_E 2u
size_t
hb_check_physics_flags(const struct hb_scene *sc, const struct hb_arc *arc,
                       const struct hb_check_physics *r, unsigned char *flags, size_t nflags);

/*
 * One line for a person: "the computed run fails N physics checks; a
 * tighter run.rtol and run.atol, or another run.stepper, should fix it"
 * (or that it passes).  The batch report and the explorer both say it.
 */
void
hb_check_physics_summary(const struct hb_check_physics *r, char *buf, size_t n);

/*
 * A chain's run (docs/chains.md section 5), at its last sample, to the
 * same margin (HB_CHECK_PHYS_FACTOR tol, tol = max(run.rtol, run.atol)):
 *  - energy: the kinetic energy K of the bodies, plus what the interfaces
 *    absorbed since t = 0 (-sum_k W_c,k: stored in the contacts in
 *    progress and dissipated), equals K(0) plus the work of the applied
 *    forces, sum_i F_i (y_i - y_i(0)); the residual relative to the
 *    largest of these terms;
 *  - momentum, on a chain without a floor: sum_i m_i u_i = its value at
 *    t = 0 plus t sum_i F_i (equal with no load); relative to the largest
 *    term;
 *  - each completed contact by its own interface's law (overrides
 *    applied): W >= 0 for a passive law, W = 0 for an elastic one,
 *    relative to the larger of its impact energy m_k v_i^2/2 and
 *    F_c^max x_c^max; and, for a contact during which neither neighbouring
 *    interface was in contact (its relative motion then feels its own
 *    force and its F_e,r alone), e <= sqrt(1 + |F_e,r| x_c^r / (m_k v_i^2/2))
 *    (e equal to it for an elastic law); a contact begun at no approach
 *    velocity (touching bodies) has no e to check;
 *  - the model limits passed under run.chain_limits = warn are reported
 *    (limits, limnote), not counted as failures.
 * The identities are not checked on a run that failed (its bodies are
 * not placed at the failing state): energy and momentum are then NAN.
 */
struct hb_check_chain {
	double tol;          /* max(rtol, atol) */
	double t;            /* the time checked (the last sample), s */
	double kinetic0;     /* K(0), J */
	double kinetic;      /* K(t), J */
	double absorbed;     /* -sum_k W_c,k: stored + dissipated by the interfaces, J */
	double stored;       /* held by the interfaces in contact at t: int F_c dx_c of each
	                        contact in progress, J (0 with none; NAN: not checked) */
	double dissipated;   /* absorbed - stored: what the contacts took and did not give
	                        back (the W of the completed ones), J (NAN: not checked) */
	double loads;        /* the work of the applied forces, J */
	double eresid;       /* |K + absorbed - K(0) - loads| / the largest of them; NAN: not checked */
	int momentum;        /* 1: checked (no floor) */
	double p0, p;        /* momentum at 0 and t, kg m/s */
	double impulse;      /* t sum_i F_i, kg m/s */
	double presid;       /* |p - p0 - impulse| / the largest of them; NAN: not checked */
	size_t ncontacts;    /* completed contacts checked (W) */
	size_t nisolated;    /* ... of which isolated, with an approach velocity (e checked) */
	double wworst;       /* largest W violation / its energy scale (>= 0 is a violation measure) */
	long wworst_at;      /* its collision index (struct hb_collision.i), -1 if none */
	int wworst_k;        /* its interface */
	double W_at;         /* its W, J */
	double eworst;       /* largest e - bound (elastic: |e - bound|) */
	long eworst_at;      /* its collision index, -1 if none */
	int eworst_k;        /* its interface */
	double e_at, e_bound;
	long limits;         /* model limits passed (run.chain_limits = warn) */
	const char *limnote; /* the first, in words ("" when none) */
	int failed;          /* checks that failed (0..4) */
};

struct hb_sim;

/*
 * Fills *r for the chain run s (a scene with chain.n > 0); returns 0 when
 * every check passes, or HB_EINVAL with one line per failure
 * ("; "-separated) in msg.  HB_EINVAL with a message for a run that is not
 * a chain's.
 */
int
hb_check_chain(const struct hb_sim *s, struct hb_check_chain *r, char *msg, size_t n);

HB_END_DECLS

#endif
