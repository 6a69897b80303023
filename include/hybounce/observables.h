/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * observables.h - the observables of a finished run: one table (name,
 * unit, meaning, the function that computes it from an hb_sim) behind the
 * batch summary, the columns of a sweep's runs.csv and the explorer's sweep
 * view, so that they count alike.
 *
 *     for (int k = 0; k < HB_OBS_COUNT; k++)
 *             printf("%s = %g %s\n", hb_observables[k].name,
 *                    hb_observable_value(sim, k), hb_observables[k].unit);
 *
 * Every collision counts, the ones that the bounded list of kept
 * collisions has thinned out included (hb_sim_collisions_total).
 */
#ifndef HB_OBSERVABLES_H
#define HB_OBSERVABLES_H
#include "export.h"
HB_BEGIN_DECLS

#include "units.h"

struct hb_sim;

/* In the order of the columns of runs.csv. */
enum hb_observable {
	HB_OBS_COLLISIONS = 0, /* completed collisions, all of them */
	HB_OBS_T_PC,           /* time of permanent contact, s */
	HB_OBS_E_FIRST,        /* e of the first collision */
	HB_OBS_V_I_FIRST,      /* v_i of the first collision, m/s */
	HB_OBS_E_LAST,         /* e of the last completed collision */
	HB_OBS_V_I_LAST,       /* v_i of the last completed collision, m/s */
	HB_OBS_X_C_R_TOTAL,    /* sum of x_c^r over every collision, m */
	HB_OBS_T_END,          /* the end state: t, s */
	HB_OBS_J_END,          /* j */
	HB_OBS_Q_C_END,        /* q_c */
	HB_OBS_X_END,          /* x, m */
	HB_OBS_V_END,          /* v, m/s */
	HB_OBS_X_C_END,        /* x_c, m */
	HB_OBS_LEAVING,        /* a chain's bodies leaving it at the end (none for two bodies) */
	HB_OBS_STEPS,          /* accepted steps */
	HB_OBS_REJECTED,       /* rejected steps */
	HB_OBS_RHS,            /* right-hand side evaluations */
	HB_OBS_JAC,            /* Jacobian evaluations */
	HB_OBS_COUNT
};

struct hb_observable_def {
	const char *name;    /* the runs.csv column, e.g. "t_pc" */
	const char *unit;    /* SI unit as text ("" for a pure number) */
	const struct hb_unit_dim *dim; /* the same as a dimension */
	const char *meaning; /* one line, for documentation */
	int whole;           /* 1: a count or an index, written as a whole number */
	/* The value of a finished run; NAN when it does not exist (no collision ...). */
	double (*value)(const struct hb_sim *s);
};

extern const struct hb_observable_def hb_observables[HB_OBS_COUNT];

/* hb_observables[k].value(s); NAN for k out of range. */
double
hb_observable_value(const struct hb_sim *s, int k);

/* The index of the observable called name, or -1. */
int
hb_observable_find(const char *name);

HB_END_DECLS

#endif
