/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim.h - the simulator: flow, event location, jump map, rules R1 and R2.
 *
 *     struct hb_sim *s = hb_sim_new(&scene, msg, sizeof msg);
 *     while (hb_sim_end(s) == HB_SIM_RUNNING)
 *             if (hb_sim_advance(s, 0, 0.010) != HB_OK)   // 10 ms of work
 *                     break;                          // hb_sim_errmsg(s) says why
 *     ... hb_sim_arc(s), hb_sim_collision(s, i) ...
 *     hb_sim_free(s);
 *
 * The caller drives: hb_sim_advance does a bounded amount of work and returns.
 * A failed advance changes nothing already computed: the run ends at the
 * last good sample, with the reason in hb_sim_errmsg().
 *
 * The sim copies the scene; it owns its GSL workspaces and its arc.  All
 * pointers it returns stay valid until the next call that changes it
 * (hb_sim_advance, hb_sim_seek, hb_sim_set_scene, hb_sim_restart, hb_sim_free).
 *
 * Process state.  The library changes nothing that belongs to the process:
 * not GSL's error handler, the locale, signal dispositions, the buffering
 * of stdio streams, the environment, the umask or the working directory
 * (tests/cli/host.sh checks each).  The engine checks what GSL returns and
 * tests the cases it expects before calling GSL (a root bracket that does
 * not straddle, a non-finite value), so GSL's handler sees only what GSL
 * itself calls an error (out of memory, a bug).  GSL's default handler
 * aborts: a host that would rather have the status returned calls
 * gsl_set_error_handler_off() itself, as GSL's manual advises; the
 * hybounce program does.
 *
 * Numerical method (see README "How the engine integrates"):
 *  - flight: closed form when F_er is constant on the interval (a parabola;
 *    the event by a quadratic), otherwise GSL on (x, v);
 *  - contact: GSL odeiv2 on (x_c, v, z_c, W, J_Fc, J_Fe), x = x_e + x_c;
 *  - the absolute tolerance of each component is atol times its scale,
 *    taken from the scene's own sizes (hb_sim_stats.scale);
 *  - a step that leaves C is bracketed with a root finder on the
 *    flow-set indicator (max(x, v) in flight, -min(Phi, v) in contact;
 *    only a strictly negative value leaves C): on the step's continuous
 *    extension under dop853 (then once more on re-steps in a narrow
 *    window), on re-steps from the step's start under the GSL steppers;
 *    the bracket's end in D becomes the pre-jump sample; g is applied
 *    exactly;
 *  - steps end on the zero crossings of the law's switching functions and
 *    at the load's kinks, and on v = 0 and dPhi/dt = 0 in contact (the
 *    extrema of x_c and F_c), without a jump;
 *  - kinks as modes: the sign of a law's |w| term (law_type.psi_mode) is
 *    frozen for each step, so the flow is smooth inside it; the step is
 *    cut where w changes sign and the next one starts on the other mode;
 *  - a receding contact whose Phi vanishes within the noise of v stays on
 *    the boundary of C (rule R2): the contact ends where the exact law
 *    ends it, not where a force within rounding of zero changes sign.
 */
#ifndef HB_SIM_H
#define HB_SIM_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "scene.h"
#include "arc.h"
#include "collisions.h"

enum hb_sim_end {
	HB_SIM_RUNNING = 0,
	HB_SIM_END_T,      /* reached the horizon T */
	HB_SIM_END_J,      /* reached the jump cap J */
	HB_SIM_END_FAIL,   /* failed: hb_sim_errmsg() says why, at which (t, j) */
};

/* Room for the components of any contact ODE in hb_sim_stats (11 today). */
#define HB_SIM_MAXCOMP 16

struct hb_sim_stats {
	long steps;        /* accepted integrator steps */
	long rejected;     /* rejected trial steps */
	long rhs;          /* right-hand-side evaluations (all, including location) */
	long jac;          /* Jacobian evaluations */
	long jumps;
	long kinks;        /* steps ended on a switching function or load kink */
	long located;      /* root-finder runs */
	long dips;         /* events found inside a step whose ends are both in C */
	long flights_closed; /* flight intervals solved in closed form */
	/*
	 * Stiffness of the contact flow, checked every 32nd step of an explicit
	 * stepper in contact: h |lambda| over the decaying eigenvalues (Re
	 * lambda <= 0) of the flow's Jacobian, real or oscillatory.  Beyond half
	 * the stepper's stability radius (6.1 for dop853, 5.3 for rk8pd, 4.4
	 * for vern98, 3 for rkf45 and rkck) the step is limited by stability, not accuracy; eight
	 * such checks in a row make the contact stiff.
	 */
	long stiff_checks;
	long stiff_hits;   /* checks with h |lambda| beyond half the stability radius */
	double stiff_hrho; /* largest h |lambda| seen */
	int stiff;         /* 1: a contact was found stiff: an implicit stepper is faster */
	double stiff_t;    /* the time it was found, s */
	int switched;      /* 1: run.stepper = auto went over to bsimp for the contacts */
	double seconds;    /* CPU time spent in hb_sim_advance (CLOCK_PROCESS_CPUTIME_ID), s */
	double wall;       /* wall time spent in hb_sim_advance (CLOCK_MONOTONIC), s */
	int ncomp;         /* components of the contact ODE (at most HB_SIM_MAXCOMP) */
	double scale[HB_SIM_MAXCOMP]; /* per-component scale of the absolute tolerance */
	const char *comp[HB_SIM_MAXCOMP]; /* their names */
};

struct hb_sim;

/*
 * Validates and copies the scene and builds the workspaces.  Returns NULL
 * with a message in msg on bad input (HB_EINVAL) or no memory.
 */
struct hb_sim *
hb_sim_new(const struct hb_scene *sc, char *msg, size_t n);

/* Frees everything.  hb_sim_free(NULL) does nothing. */
void
hb_sim_free(struct hb_sim *s);

/*
 * Advances the run by at most max_steps accepted steps (0: no limit) and at
 * most max_seconds of wall time (0: no limit; a frame's budget), or to its end.  Returns HB_OK
 * (check hb_sim_end), HB_EDONE if the run had already ended, or the failure
 * (HB_ENUMERIC, HB_ECHATTER, HB_ENOMEM) with hb_sim_errmsg() set; after a
 * failure hb_sim_end() is HB_SIM_END_FAIL and the arc ends at the last good sample.
 */
int
hb_sim_advance(struct hb_sim *s, long max_steps, double max_seconds);

/* Runs to the end (horizon, jump cap or failure). Returns as hb_sim_advance. */
int
hb_sim_run(struct hb_sim *s);

enum hb_sim_end
hb_sim_end(const struct hb_sim *s);

/* Why the run ended, in words ("horizon T = 0.5 s reached", "...failed at (t, j)..."). */
const char *
hb_sim_end_str(const struct hb_sim *s);

/* The last error message ("" if none).  Owned by s. */
const char *
hb_sim_errmsg(const struct hb_sim *s);

const struct hb_scene *
hb_sim_scene(const struct hb_sim *s);

const struct hb_arc *
hb_sim_arc(const struct hb_sim *s);

const struct hb_sim_stats *
hb_sim_stats(const struct hb_sim *s);

/*
 * Completed collisions (those ended by a separation) that are kept.  The
 * list is bounded: past run.max_samples / 8 of them every other one of the
 * older three quarters is thinned out, and each kept one has its index i
 * among all (so i then has gaps); hb_sim_collisions_total() counts them all.
 */
size_t
hb_sim_ncollisions(const struct hb_sim *s);
long
hb_sim_collisions_total(const struct hb_sim *s);
const struct hb_collision *
hb_sim_collision(const struct hb_sim *s, size_t i);

/*
 * The contact in progress, if any: fills *out with the values so far
 * (complete = 0) and returns 1; returns 0 in flight.
 */
int
hb_sim_contact_live(const struct hb_sim *s, struct hb_collision *out);

/*
 * Every contact in progress: a chain's interfaces may be in contact side
 * by side.  hb_sim_contacts_live counts them (0 or 1 in a two-body scene);
 * hb_sim_contact_live_nth fills *out with the n-th, in increasing
 * interface number k (complete = 0, i = hb_sim_collisions_total + n: a
 * provisional number, as collisions are numbered in the order they end),
 * and returns 1, or 0 when there are not that many.  On a chain
 * hb_sim_contact_live gives one of them: the interface the run last
 * jumped at.
 */
size_t
hb_sim_contacts_live(const struct hb_sim *s);
int
hb_sim_contact_live_nth(const struct hb_sim *s, size_t n, struct hb_collision *out);

/*
 * The bodies of the run's chain, numbered from the bottom up: 2 in the
 * full system (body 1 of the chain is the scene's body 2), 1 in the
 * reduced one, chain.n in a chain.  hb_sim_body fills *out with body i's
 * (0-based) mass, position and velocity at the last sample (positions of
 * the two-body scenes are measured so that the gap is their difference)
 * and its half-length, and returns HB_OK, or HB_EINVAL for a bad index.
 * A chain's gap between bodies i and i + 1 is (y[i+1] - R[i+1]) - (y[i] + R[i]).
 */
struct hb_sim_body {
	double m;  /* kg */
	double y;  /* m, position of its centre */
	double u;  /* m/s */
	double R;  /* m, half-length along the axis (a chain's radius); 0 in the two-body scenes */
};

int
hb_sim_nbodies(const struct hb_sim *s);
int
hb_sim_body(const struct hb_sim *s, int i, struct hb_sim_body *out);

/*
 * A chain's model limits (docs/chains.md section 6) under
 * run.chain_limits = warn: how many times an interface passed
 * run.max_indent or bodies that are not neighbours overlapped, and the
 * first of them in words ("" when none).  Under stop the first one ends
 * the run (hb_sim_errmsg names it).
 */
const char *
hb_sim_limits(const struct hb_sim *s, long *count);

/*
 * Truncates the run after sample i (which becomes the last sample; a
 * pre-jump sample is kept with its jump undone) and continues from its
 * state on the next hb_sim_advance.  Collisions that end after it are dropped.
 * Returns HB_OK or HB_EINVAL for a bad index.
 */
int
hb_sim_seek(struct hb_sim *s, size_t i);
/*
 * A chain's run is recomputed from t = 0 to the sample (the engine is
 * deterministic), so that it goes on after it bit for bit as the run
 * that was not cut: a seek back costs the run up to the sample; one into
 * the last unit of work (a flight, or one step of the contacts) costs
 * nothing.  What that unit computed after the sample is given back by the
 * next hb_sim_advance; until then hb_sim_body gives the bodies at the
 * sample's t on their parabolas and hb_sim_contact_live reports none.  An
 * arc that was thinned (run.max_samples) holds again, before the sample,
 * what the replay kept.  HB_EINVAL too when the chain's scene changed
 * part-way (hb_sim_errmsg says so).
 */

/*
 * Adopts new scene values for what is computed from now on (after the
 * current last sample); where the run continues depends on what it had
 * computed, so the change is not recorded as a branch (hb_sim_unrecorded;
 * hb_sim_branch is the reproducible way).  The new scene is validated first; on error
 * nothing changes.  Changing the law or the bodies while the last sample is
 * in contact (or changing the initial conditions or the system) restarts
 * the run from t = 0, and *restarted says so (may be NULL).  A chain
 * restarts when the change is of the number of bodies, the floor, any
 * body's initial velocity, gap or radius, the mass or load of a body in
 * contact, or the law or extension of an interface in contact; otherwise
 * it goes on, its flying bodies taking their new accelerations from the
 * last sample's t.  After a chain's hb_sim_seek the run goes on from the
 * end of the unit of work that holds the sample (see hb_sim_seek).
 */
int
hb_sim_set_scene(struct hb_sim *s, const struct hb_scene *sc, int *restarted, char *msg, size_t n);

/* Discards the run and starts again from t = 0 with the current scene. */
int
hb_sim_restart(struct hb_sim *s);

/*
 * Branches: a run that changes its scene part-way, reproducibly.  A branch
 * says "from the run's sample at (t, j) on, continue with scene sc"; the
 * state there is kept as a check.
 */
struct hb_branch {
	double t;            /* the sample the run continues from, s */
	long j;              /* its jump count */
	double x, v, xc;     /* the state there (m, m/s, m) */
	int q;               /* 1: in contact there */
	struct hb_scene sc;  /* the scene from there on */
};

/*
 * Continues the run from its sample i with scene sc, the same way whatever
 * the run had computed: the run is begun again from t = 0 with its first
 * scene (hb_sim_scene0), its branches before sample i are taken again, it
 * is advanced one step at a time to the sample at (t, j) of i, cut there,
 * and continued with sc (hb_sim_set_scene).  Branches at or after sample i
 * are replaced.  So hb_sim_new with the first scene, then hb_sim_branch_at
 * for each branch of hb_sim_branch_get, gives this run bit for bit.  When
 * sc cannot continue there (a change of the law or the bodies in contact,
 * of the initial state or the system) the run restarts from t = 0 with sc
 * and *restarted (may be NULL) says so.  Returns HB_OK, HB_EINVAL (a bad
 * index or scene, or the replayed run does not reach the sample) or
 * HB_ENOMEM; on an error other than a bad scene the run is as far as the
 * replay got.  Costs a run from t = 0 to the sample.  A chain's branch
 * begins at the end of the unit of work (a flight, or a step of the
 * contacts, with its jump) that holds sample i, and is recorded there
 * (hb_sim_branch_get): the chain's state is known there.
 */
int
hb_sim_branch(struct hb_sim *s, size_t i, const struct hb_scene *sc, int *restarted, char *msg,
              size_t n);

/*
 * Takes branch b: advances the run one step at a time until it holds the
 * sample at (b->t, b->j), cuts it there and continues with b->sc.
 * *same_state (may be NULL): 1 when the state there is b's to the bit (x,
 * v, x_c, contact), so the run is the one b was taken from.  Returns
 * HB_OK, or HB_EINVAL with a message when the run has no sample at (t, j)
 * (it differs before the branch) or b->sc is refused.
 */
int
hb_sim_branch_at(struct hb_sim *s, const struct hb_branch *b, int *same_state, int *restarted,
                 char *msg, size_t n);

/* The branches the run holds, in order of t; NULL past the last. */
size_t
hb_sim_nbranches(const struct hb_sim *s);
const struct hb_branch *
hb_sim_branch_get(const struct hb_sim *s, size_t k);

/* The scene the run began with at t = 0 (hb_sim_scene is the one in effect now). */
const struct hb_scene *
hb_sim_scene0(const struct hb_sim *s);

/*
 * -1, or the first time at which the run changed its scene in a way its
 * first scene and branches do not record (hb_sim_set_scene continuing the
 * run, a seek back past a branch): from there on the run is not reproduced
 * by them.
 */
double
hb_sim_unrecorded(const struct hb_sim *s);

HB_END_DECLS

#endif
