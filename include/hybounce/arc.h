/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * arc.h - the hybrid arc: samples over the hybrid time domain (t, j).
 *
 * Samples are stored in hybrid-time order: by j, then by t.  A jump appears
 * as two samples with the same t and consecutive j: the pre-jump sample,
 * which lies in the jump set D, and the post-jump sample, which is g of it
 * exactly.  Samples are every accepted step, every located event, kink and
 * extremum, the start and the end.
 *
 * Flow intervals: for each j that has samples, the index of its first and
 * last sample, q_c, and its ordinary-time extent [t_j, t_{j+1}].
 *
 * Memory is bounded, whatever the number of samples and jumps: the arc
 * holds at most what the scene's run.max_samples samples would (samples,
 * interval index and jump records together).  Past that it thins the
 * interior samples of old flow intervals by half; when the arc is mostly
 * jumps, whose samples that cannot remove, it removes every other whole
 * old flow interval too, with its two jumps, so that j then steps by more
 * than one between two samples (hb_arc_skipped() counts the intervals
 * removed; the jump records list only the jumps whose two samples remain).
 * The first interval and the one in progress are never removed, so rewind
 * always reaches t = 0.  hb_arc_thinned() counts the passes.
 *
 * The arc is owned by the sim that produced it; pointers returned here stay
 * valid until the next hb_sim_advance / hb_sim_seek / hb_sim_restart / hb_sim_free.
 */
#ifndef HB_ARC_H
#define HB_ARC_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "law.h"

enum hb_arc_kind {
	HB_ARC_START = 0,    /* the initial state (0, 0) */
	HB_ARC_STEP,         /* an accepted integrator step (or a closed-form flight point) */
	HB_ARC_PRE_JUMP,     /* last sample of a flow interval, in D */
	HB_ARC_POST_JUMP,    /* first sample of the next interval, g of the previous sample */
	HB_ARC_KINK,         /* a step ended on a switching function of the law or the load */
	HB_ARC_EXTREMUM,     /* a located extremum of x_c (v = 0) or of F_c inside a contact */
	HB_ARC_END,          /* the last sample of the run */
};

struct hb_arc_sample {
	double t;
	long j;
	int q;                  /* q_c: 1 in contact */
	int kind;               /* enum hb_arc_kind */
	double x, v;            /* relative displacement and velocity */
	double xc;              /* indentation (0 in flight) */
	double z[HB_LAW_MAX_Z];    /* internal state of the law (0 in flight) */
	double Fc;              /* contact force on body 1: -q_c Phi */
	double Fer;             /* reduced applied force */
	double xm, vm;          /* centre of mass (full system; 0 otherwise) */
	/* running values over the contact in progress (0 in flight): */
	double W, JFc, JFe;     /* -int F_c v dt, int F_c dt, int F_er dt since t_e */
	double xcmax, Fcmax;    /* greatest |x_c| and F_c since t_e */
	/* running over the whole run: */
	double Ee;              /* int_0^t F_er v dt, the work of the applied force, J */
	double Wc;              /* int_0^t F_c v dt, the work of the contact force, J */
	int k;                  /* the interface the sample is of: a chain's interface (0 on
	                           the floor), 1 in the full system, 0 in the reduced one */
};

struct hb_arc_interval {
	long j;
	int q;
	size_t first, last;     /* sample indices (inclusive) */
	double t0, t1;          /* ordinary-time extent */
};

/* How a jump was located, kept for every jump. */
enum hb_arc_how {
	HB_LOCATE_START = 0,   /* the state was already in D where the interval began */
	HB_LOCATE_CLOSED_FORM, /* flight: root of the closed-form parabola */
	HB_LOCATE_BRENT,       /* re-stepping from the step's start, bracketing root finder */
};

struct hb_arc_jump {
	double t;
	long j;                 /* j of the pre-jump sample */
	int from_q;             /* q_c before the jump */
	const char *left;       /* which part of C was left: "flight: x < 0 and v < 0",
	                           "contact: Phi > 0 and v > 0" */
	int how;                /* enum hb_arc_how */
	int iterations;         /* root-finder iterations */
	double width;           /* final bracket width in t, s */
	double ind_lo, ind_hi;  /* flow-set indicator at the bracket's C side and D side
	                           (>= 0 in C; < 0 outside) */
};

struct hb_arc;

size_t hb_arc_len(const struct hb_arc *a);
const struct hb_arc_sample *hb_arc_at(const struct hb_arc *a, size_t i);
const struct hb_arc_sample *hb_arc_last(const struct hb_arc *a); /* NULL when empty */

size_t hb_arc_nintervals(const struct hb_arc *a);
const struct hb_arc_interval *hb_arc_interval_at(const struct hb_arc *a, size_t k);
/* Index k of the interval containing sample i. */
size_t hb_arc_interval_of(const struct hb_arc *a, size_t i);

size_t hb_arc_njumps(const struct hb_arc *a);
const struct hb_arc_jump *hb_arc_jump_at(const struct hb_arc *a, size_t k);

/*
 * The last sample at or before hybrid time (t, j) in hybrid-time order
 * (0 if (t, j) precedes everything).
 */
size_t hb_arc_find(const struct hb_arc *a, double t, long j);

/* The last sample with sample.t <= t (of the greatest j at that t). */
size_t hb_arc_find_t(const struct hb_arc *a, double t);

/* Number of thinning passes so far (0: every sample is kept). */
int hb_arc_thinned(const struct hb_arc *a);

/* Number of flow intervals thinned out (0: j steps by one between samples). */
long hb_arc_skipped(const struct hb_arc *a);

/* Bytes held by the arc. */
size_t hb_arc_bytes(const struct hb_arc *a);

HB_END_DECLS

#endif
