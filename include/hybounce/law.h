/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law.h - incremental contact laws (paper eq. law):
 *
 *     d/dt x_c = v_c,   d/dt z_c = Psi(x_c, z_c, v_c),   F_s = Phi(x_c, z_c, v_c),
 *
 * with F_c = -F_s the force on the bodies, x_c < 0 in compression, and the
 * condition Phi(0, 0, v) = 0 for every v (paper eq. vanishing).
 *
 * Each law is one file under src/core/ ending in one `const struct hb_law_type`;
 * the registry in law.c lists them.  Adding a law means adding one file and
 * one registry line.
 *
 * Rule R1 (paper, section Non-Uniqueness).  Laws are written for x_c <= 0.
 * Each law says in its description how it is continued to x_c > 0.  With
 * `ext` = 1 (the default in a scene) the continuation is adhesive: Phi > 0
 * for small x_c > 0, so a contact whose force is extinguished while the
 * bodies recede leaves the flow set at once.  With `ext` = 0 the law is
 * clamped, Phi(x_c, z, v) = Phi(min(x_c, 0), z, v), which is what the
 * paper's solution chi^d of the clamped example needs to appear.
 *
 * Parameters are passed as an array of doubles in the order of the law's
 * parameter table.  All values are SI.
 */
#ifndef HB_LAW_H
#define HB_LAW_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>

#include "units.h" /* struct hb_unit_dim */

enum {
	HB_LAW_MAX_Z = 2,       /* largest n_z of any law */
	HB_LAW_MAX_PARAMS = 10, /* largest parameter table */
	HB_LAW_MAX_KINKS = 4,   /* largest number of switching functions */
};

/* Flags of a parameter. */
enum {
	HB_LAW_PARAM_STIFFNESS = 1, /* the stiffness k: derived by eq. k_hertz when
	                            both bodies are given by their materials and
	                            the law has k_hertz; typed otherwise */
	HB_LAW_PARAM_EXPONENT_P = 2, /* the exponent p (used in unit dimensions) */
	HB_LAW_PARAM_EXPONENT_N = 4, /* the exponent n (used in unit dimensions) */
	HB_LAW_PARAM_CHECKED = 8,    /* constrained by the law's check beyond its own
	                             range (gamma in [-beta, beta]): the key that
	                             a failed check names */
};

struct hb_law_param {
	const char *name;        /* key in presets and the panel: "alpha", "beta", "c" */
	struct hb_unit_dim dim;     /* expected dimension */
	double lo, hi;           /* admissible range; -HUGE_VAL/HUGE_VAL for none */
	int lo_open, hi_open;    /* 1 if the bound itself is excluded */
	double def;              /* default value */
	int flags;               /* LAW_PARAM_* */
	const char *help;        /* one line: meaning and where in the paper */
};

struct hb_law_type {
	const char *name;        /* short key: "shccl", "bwshccl", "bwmcl", "hertz", "linear" */
	const char *title;       /* "Simon-Hunt-Crossley (SHCCL)" */
	const char *description; /* one line, including how x_c > 0 is continued (rule R1) */
	int n_z;                 /* dimension of the internal state */
	int n_params;
	const struct hb_law_param *params;
	int n_kinks;             /* number of switching functions (see kinks) */

	/* Phi(x_c, z, v).  z has n_z entries (may be NULL when n_z = 0). */
	double (*phi)(const double *par, int ext, double xc, const double *z, double v);

	/* Psi(x_c, z, v) into dz[0 .. n_z-1].  NULL when n_z = 0. */
	void (*psi)(const double *par, int ext, double xc, const double *z, double v,
	            double *dz);

	/*
	 * Partial derivatives.  Columns are ordered (x_c, z_1 .. z_nz, v):
	 * dphi has n_z + 2 entries; dpsi is n_z rows of n_z + 2 entries, row
	 * major (may be NULL when n_z = 0).  Where the law is not differentiable
	 * (at a kink) any one-sided derivative is returned.
	 */
	void (*jac)(const double *par, int ext, double xc, const double *z, double v,
	            double *dphi, double *dpsi);

	/*
	 * Switching functions: values g[0 .. n_kinks-1] whose zero crossings
	 * are the points where Phi or Psi is not smooth (|v|, z|z|^(n-1),
	 * x_c|x_c|^(p-1), |Psi_2| ...) but still continuous: the engine ends a
	 * step on each crossing inside a flow interval (DESIGN.md section 4a),
	 * within 0.1 sqrt(rtol) of the step past it, which continuity makes an
	 * error of second order only.  NULL when n_kinks = 0.
	 */
	void (*kinks)(const double *par, int ext, double xc, const double *z, double v,
	              double *g);

	/*
	 * Constraints between parameters beyond each one's range (e.g. gamma in
	 * [-beta, beta]).  Returns 0, or HB_EINVAL with a message in msg naming
	 * the parameters and the accepted range.  May be NULL.
	 */
	int (*check)(const double *par, char *msg, size_t n);

	/*
	 * k from the Hertz coefficient k_H by eq. k_hertz, e.g.
	 * k_H / (alpha + (1 - alpha) A^p).  NULL when k is not derivable
	 * (the clamped linear law, whose k is N/m).
	 */
	double (*k_hertz)(const double *par, double kH);

	/*
	 * Kinks as modes (may be NULL).  Psi with the |w| term of switching
	 * function g[mode_kink] given its sign: |w| is replaced by sign * w
	 * (sign = +1 or -1; 0 keeps |w|), the smooth continuation of the
	 * branch the state is on.  The engine freezes the sign at a step's
	 * start, so the flow is smooth inside the step, and ends the step
	 * where g changes sign.  mode_kink is read only when psi_mode is set.
	 */
	void (*psi_mode)(const double *par, int ext, double xc, const double *z, double v,
	                 int sign, double *dz);
	int mode_kink;
};

/* The registered laws, NULL-terminated, in a fixed order. */
const struct hb_law_type *const *
hb_law_list(void);

/* The law with this name (case-insensitive), or NULL. */
const struct hb_law_type *
hb_law_find(const char *name);

/* Index of a parameter in the law's table, or -1. */
int
hb_law_param_index(const struct hb_law_type *law, const char *name);

/* Fills par[0 .. n_params-1] with the defaults. */
void
hb_law_defaults(const struct hb_law_type *law, double *par);

/* The parameter's admissible range. */
struct hb_unit_range
hb_law_param_range(const struct hb_law_param *pp);

/*
 * Checks one value against the parameter's range.  Returns 0, or HB_EINVAL
 * with "NAME must be in (lo, hi]" style text in msg.
 */
int
hb_law_param_check(const struct hb_law_param *pp, double value, char *msg, size_t n);

/* The exponent p / n of this parameter set (1 if the law has none). */
double
hb_law_exponent_p(const struct hb_law_type *law, const double *par);
double
hb_law_exponent_n(const struct hb_law_type *law, const double *par);

/* The laws, for direct use by tests. */
extern const struct hb_law_type hb_law_shccl;
extern const struct hb_law_type hb_law_bwshccl;
extern const struct hb_law_type hb_law_bwmcl;
extern const struct hb_law_type hb_law_hertz;
extern const struct hb_law_type hb_law_linear;

HB_END_DECLS

#endif
