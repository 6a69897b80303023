/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_root.c - the bracketing root finder the engine locates with: where
 * a function of the time into a step crosses, given as its oriented value
 * (struct hbs_root).  The location (sim_locate.c) asks it for the watched
 * functions of the flow interval's system (a two-body contact's, a
 * chain's clusters'), on re-steps, on the step's continuous extension or
 * on its Hermite interpolant; a chain's limits (sim_limits.c, through
 * sim_restep.c) on re-steps.
 */
#include "sim_impl.h"

/* One evaluation of the location, counted. */
static double
counted(struct hbs_root *r, double h)
{
	(*r->iter)++;
	return r->value(h, r->ctx);
}

/* The function at x moves the bracket's end on its side there: xl (not crossed) or xu. */
static int
move_end(struct hbs_root *r, double x, double *xl, double *xu)
{
	double g = counted(r, x);

	if (!isfinite(g))
		return GSL_FAILURE;
	if (g > 0)
		*xl = x;
	else
		*xu = x;
	return GSL_SUCCESS;
}

/*
 * GSL's root solvers call their error handler (process-wide, the host's:
 * GSL's default aborts) for a function value that is not finite and for a
 * bracket whose ends do not straddle the root.  Both are expected here (a
 * re-step that fails; a bracket that Brent left with its ends' signs the
 * other way round), so the solver never sees them: it is given
 * brent_value(), which turns a value that is not finite into DBL_MIN and
 * counts it in bad (brent_iterate returns what GSL would have: GSL_EBADFUNC),
 * and is (re)set through brent_set(), which checks the ends first.
 */
struct brent_fn {
	struct hbs_root *r;
	int bad;
	int nmemo;          /* the bracket's ends, just evaluated, while the solver is set */
	double mh[2], mg[2];
};

static double
brent_value(double h, void *params)
{
	struct brent_fn *b = params;
	double g;
	int i;

	for (i = 0; i < b->nmemo; i++)
		if (h == b->mh[i]) { /* the same double counted() gave: counted as it */
			(*b->r->iter)++;
			return b->mg[i];
		}
	g = counted(b->r, h);

	if (isfinite(g))
		return g;
	b->bad++;
	return DBL_MIN;
}

/*
 * gsl_root_fsolver_set with the ends' values gl, gu (finite) known: the
 * solver's first look at them is answered from them (no second location
 * step), counted as that look was.
 */
static int
solver_set(struct brent_fn *b, gsl_function *F, double lo, double gl, double hi, double gu)
{
	int rc;

	b->mh[0] = lo;
	b->mg[0] = gl;
	b->mh[1] = hi;
	b->mg[1] = gu;
	b->nmemo = 2;
	rc = gsl_root_fsolver_set(b->r->solver, F, lo, hi);
	b->nmemo = 0;
	return rc;
}

static int
brent_set(struct brent_fn *b, gsl_function *F, double lo, double hi)
{
	double gl = b->r->value(lo, b->r->ctx), gu = b->r->value(hi, b->r->ctx);

	if (!isfinite(gl) || !isfinite(gu))
		return GSL_EBADFUNC;
	if (!(lo < hi) || (gl < 0) == (gu < 0))
		return GSL_EINVAL;
	return solver_set(b, F, lo, gl, hi, gu);
}

static int
brent_iterate(struct brent_fn *b)
{
	int rc;

	b->bad = 0;
	rc = gsl_root_fsolver_iterate(b->r->solver);
	return rc == GSL_SUCCESS && b->bad ? GSL_EBADFUNC : rc;
}

/*
 * Brackets the crossing of r's function in [lo, hi] (not crossed at lo,
 * crossed at hi) down to a few ulps of t, or to htol if that is wider.
 * Brent's method proposes the points.  For a switching or extremum
 * function (r->stall: the caller says), where it stalls (its estimate of the root is good,
 * but its steps from it are of one ulp, so that the far end only moves by
 * bisection, every other iteration: Psi_2 = v - Phi/c while a Maxwell
 * element creeps, two equal terms, is zero to rounding over a band far
 * wider than ulps), the bracket is closed by evaluating at tol/2 on either
 * side of the estimate, or just beyond the root the secant of those two
 * gives, or else at least halved.  The pair's indicator keeps Brent's own
 * steps, whose crossing the separation that rounding cannot fake relies
 * on (see snap_separation); a chain's clusters close the stalls of every
 * function (a gap computed from positions moves in steps of their ulps).
 * Returns 0, with the bracket in *a, *b.
 */
int
hbs_root_bracket(struct hbs_root *r, double lo, double hi, double htol, double *a, double *b)
{
	struct brent_fn bf = { r, 0, 0, { 0 }, { 0 } };
	gsl_function F = { brent_value, &bf };
	double tol = fmax(4.0 * DBL_EPSILON * fmax(fabs(r->t0 + hi), 1e-300), htol);
	double xl = lo, xu = hi, prev = hi - lo, w, gl, gu;
	int it = 0, rc;

	if (!((gl = counted(r, lo)) > 0) || !((gu = counted(r, hi)) < 0))
		return GSL_FAILURE;
	/* the ends are known to straddle: set without brent_set's second look */
	if ((rc = solver_set(&bf, &F, lo, gl, hi, gu)) != GSL_SUCCESS)
		return rc;
	while (xu - xl > tol && it++ < MAX_BRENT) {
		if ((rc = brent_iterate(&bf)) != GSL_SUCCESS)
			return rc;
		xl = gsl_root_fsolver_x_lower(r->solver);
		xu = gsl_root_fsolver_x_upper(r->solver);
		if (r->stall && xu - xl > tol && xu - xl > 0.5 * prev) {
			double rt = gsl_root_fsolver_root(r->solver);
			double p1 = fmax(xl, rt - 0.5 * tol), p2 = fmin(xu, rt + 0.5 * tol);
			double g1 = counted(r, p1), g2 = counted(r, p2);

			if (!isfinite(g1) || !isfinite(g2))
				return GSL_FAILURE;
			if (g1 > 0 && g2 < 0) {
				xl = p1;
				xu = p2;
				break;
			}
			if (g1 < 0)
				xu = p1;
			else
				xl = p2;
			w = xu - xl;
			if (w > tol && g1 != g2) {
				/* the root the two probes' secant gives, and a point just beyond it */
				double r2 = p1 - g1 * (p2 - p1) / (g2 - g1);
				double q = g1 > 0 ? r2 + 0.5 * tol : r2 - 0.5 * tol;

				if (q > xl && q < xu && move_end(r, q, &xl, &xu) != GSL_SUCCESS)
					return GSL_FAILURE;
			}
			/* else a bisection: the bracket at least halves */
			if (xu - xl > tol && xu - xl > 0.5 * w && move_end(r, 0.5 * (xl + xu), &xl, &xu) != GSL_SUCCESS)
				return GSL_FAILURE;
			if (xu - xl <= tol)
				break;
			if ((rc = brent_set(&bf, &F, xl, xu)) != GSL_SUCCESS)
				return rc;
		}
		prev = xu - xl;
		if (r->stall && xu - xl <= 1e-6 * r->H) {
			/* both ends zero to rounding: located as closely as the function can be computed */
			if (fabs(counted(r, xl)) <= r->noise && fabs(counted(r, xu)) <= r->noise)
				break;
		}
	}
	/* the ends as (not crossed, crossed) */
	if (!(counted(r, xl) > 0 && counted(r, xu) < 0))
		return GSL_FAILURE;
	*a = xl;
	*b = xu;
	return 0;
}

/*
 * Brackets a crossing of r's function in [lo, hi] (not crossed at lo,
 * crossed at hi) by bisection down to a few ulps of t, or to htol: slow,
 * but its ends keep their sides whatever the function does between them
 * (the fallback where hbs_root_bracket's ends came out the other way
 * round).  Returns 0, with the bracket in *a, *b.
 */
int
hbs_root_bisect(struct hbs_root *r, double lo, double hi, double htol, double *a, double *b)
{
	double tol = fmax(4.0 * DBL_EPSILON * fmax(fabs(r->t0 + hi), 1e-300), htol);
	int it = 0;

	if (!(counted(r, lo) > 0) || !(counted(r, hi) < 0))
		return GSL_FAILURE;
	while (hi - lo > tol && it++ < 2 * MAX_BRENT) {
		double m = 0.5 * (lo + hi);

		if (!(m > lo && m < hi))
			break;
		if (move_end(r, m, &lo, &hi) != GSL_SUCCESS)
			return GSL_FAILURE;
	}
	*a = lo;
	*b = hi;
	return 0;
}
