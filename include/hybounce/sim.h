/*
 * sim.h - the simulator: flow, event location, jump map, rules R1 and R2.
 *
 *     struct sim *s = sim_new(&scene, msg, sizeof msg);
 *     while (sim_end(s) == SIM_RUNNING)
 *             if (sim_advance(s, 0, 0.010) != HB_OK)   // 10 ms of work
 *                     break;                          // sim_errmsg(s) says why
 *     ... sim_arc(s), sim_collision(s, i) ...
 *     sim_free(s);
 *
 * The caller drives: sim_advance does a bounded amount of work and returns.
 * A failed advance changes nothing already computed: the run ends at the
 * last good sample, with the reason in sim_errmsg().
 *
 * The sim copies the scene; it owns its GSL workspaces and its arc.  All
 * pointers it returns stay valid until the next call that changes it
 * (sim_advance, sim_seek, sim_set_scene, sim_restart, sim_free).
 *
 * Numerical method (see README "How the engine integrates"):
 *  - flight: closed form when F_er is constant on the interval (a parabola;
 *    the event by a quadratic), otherwise GSL on (x, v);
 *  - contact: GSL odeiv2 on (x_c, v, z_c, W, J_Fc, J_Fe), x = x_e + x_c;
 *  - the absolute tolerance of each component is atol times its scale,
 *    taken from the scene's own sizes (sim_stats.scale);
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
#ifndef HYBOUNCE_SIM_H
#define HYBOUNCE_SIM_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "scene.h"
#include "arc.h"
#include "collisions.h"

enum sim_end {
	SIM_RUNNING = 0,
	SIM_END_T,      /* reached the horizon T */
	SIM_END_J,      /* reached the jump cap J */
	SIM_END_FAIL,   /* failed: sim_errmsg() says why, at which (t, j) */
};

struct sim_stats {
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
	 * the stepper's stability radius (6.1 for dop853, 5.3 for rk8pd, 3 for
	 * rkf45 and rkck) the step is limited by stability, not accuracy; eight
	 * such checks in a row make the contact stiff.
	 */
	long stiff_checks;
	long stiff_hits;   /* checks with h |lambda| beyond half the stability radius */
	double stiff_hrho; /* largest h |lambda| seen */
	int stiff;         /* 1: a contact was found stiff: an implicit stepper is faster */
	double stiff_t;    /* the time it was found, s */
	int switched;      /* 1: run.stepper = auto went over to bsimp for the contacts */
	double seconds;    /* CPU time spent in sim_advance (CLOCK_PROCESS_CPUTIME_ID), s */
	double wall;       /* wall time spent in sim_advance (CLOCK_MONOTONIC), s */
	int ncomp;         /* components of the contact ODE */
	double scale[8];   /* per-component scale of the absolute tolerance */
	const char *comp[8]; /* their names */
};

struct sim;

/*
 * Validates and copies the scene and builds the workspaces.  Returns NULL
 * with a message in msg on bad input (HB_EINVAL) or no memory.  Turns
 * GSL's aborting error handler off.
 */
struct sim *
sim_new(const struct scene *sc, char *msg, size_t n);

/* Frees everything.  sim_free(NULL) does nothing. */
void
sim_free(struct sim *s);

/*
 * Advances the run by at most max_steps accepted steps (0: no limit) and at
 * most max_seconds of wall time (0: no limit; a frame's budget), or to its end.  Returns HB_OK
 * (check sim_end), HB_EDONE if the run had already ended, or the failure
 * (HB_ENUMERIC, HB_ECHATTER, HB_ENOMEM) with sim_errmsg() set; after a
 * failure sim_end() is SIM_END_FAIL and the arc ends at the last good sample.
 */
int
sim_advance(struct sim *s, long max_steps, double max_seconds);

/* Runs to the end (horizon, jump cap or failure). Returns as sim_advance. */
int
sim_run(struct sim *s);

enum sim_end
sim_end(const struct sim *s);

/* Why the run ended, in words ("horizon T = 0.5 s reached", "...failed at (t, j)..."). */
const char *
sim_end_str(const struct sim *s);

/* The last error message ("" if none).  Owned by s. */
const char *
sim_errmsg(const struct sim *s);

const struct scene *
sim_scene(const struct sim *s);

const struct arc *
sim_arc(const struct sim *s);

const struct sim_stats *
sim_stats(const struct sim *s);

/*
 * Completed collisions (those ended by a separation) that are kept.  The
 * list is bounded: past run.max_samples / 8 of them every other one of the
 * older three quarters is thinned out, and each kept one has its index i
 * among all (so i then has gaps); sim_collisions_total() counts them all.
 */
size_t
sim_ncollisions(const struct sim *s);
long
sim_collisions_total(const struct sim *s);
const struct collision *
sim_collision(const struct sim *s, size_t i);

/*
 * The contact in progress, if any: fills *out with the values so far
 * (complete = 0) and returns 1; returns 0 in flight.
 */
int
sim_contact_live(const struct sim *s, struct collision *out);

/*
 * Truncates the run after sample i (which becomes the last sample; a
 * pre-jump sample is kept with its jump undone) and continues from its
 * state on the next sim_advance.  Collisions that end after it are dropped.
 * Returns HB_OK or HB_EINVAL for a bad index.
 */
int
sim_seek(struct sim *s, size_t i);

/*
 * Adopts new scene values for what is computed from now on (after the
 * current last sample).  The new scene is validated first; on error
 * nothing changes.  Changing the law or the bodies while the last sample is
 * in contact (or changing the initial conditions or the system) restarts
 * the run from t = 0, and *restarted says so (may be NULL).
 */
int
sim_set_scene(struct sim *s, const struct scene *sc, int *restarted, char *msg, size_t n);

/* Discards the run and starts again from t = 0 with the current scene. */
int
sim_restart(struct sim *s);

HB_END_DECLS

#endif
