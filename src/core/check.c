/*
 * check.c - the paper's checks of a computed solution pair (section
 * Simulation): the definition of a solution pair, and forward Euler as an
 * independent integrator.  Written from the paper's equations directly
 * (eqs. H_f, H_g, H_C, H_D and their reduced forms), not from the engine's
 * reduced phases, so that it checks them.
 */
#include <math.h>
#include <string.h>

#include "hybounce/check.h"
#include "hybounce/status.h"

static double
phi_of(const struct scene *sc, const struct arc_sample *a)
{
	return sc->law->phi(sc->par, sc->ext, a->xc, a->z, a->v);
}

int
check_in_C(const struct scene *sc, const struct arc_sample *a)
{
	if (a->q == 0)
		return a->x >= 0.0 || a->v >= 0.0;
	return phi_of(sc, a) <= 0.0 || a->v <= 0.0;
}

int
check_in_D(const struct scene *sc, const struct arc_sample *a)
{
	if (a->q == 0)
		return a->x <= 0.0 && a->v <= 0.0;
	return phi_of(sc, a) >= 0.0 && a->v >= 0.0;
}

int
check_solution_pair(const struct scene *sc, const struct arc *arc, char *msg, size_t n)
{
	size_t i, len = arc_len(arc);
	int nz = sc->law->n_z, k;
	long skipped = 0;   /* flow intervals thinned out so far */

	if (len == 0)
		return status_set(msg, n, HB_EINVAL, "empty arc");
	if (arc_at(arc, 0)->j != 0 || arc_at(arc, 0)->t != 0.0 || arc_at(arc, 0)->q != 0)
		return status_set(msg, n, HB_EINVAL, "the arc does not start at (0, 0) with q_c = 0");
	for (i = 0; i < len; i++) {
		const struct arc_sample *a = arc_at(arc, i), *b = i + 1 < len ? arc_at(arc, i + 1) : NULL;

		if (b != NULL) {
			if (b->j == a->j) {
				if (!(b->t >= a->t))
					return status_set(msg, n, HB_EINVAL,
					                  "sample %zu: t decreases within j = %ld (%.17g -> %.17g)",
					                  i, a->j, a->t, b->t);
				if (b->q != a->q)
					return status_set(msg, n, HB_EINVAL, "sample %zu: q_c changes without a jump", i);
			} else if (b->j == a->j + 1) {
				if (b->t != a->t)
					return status_set(msg, n, HB_EINVAL,
					                  "sample %zu: a jump changes t (%.17g -> %.17g)", i, a->t, b->t);
				if (!check_in_D(sc, a))
					return status_set(msg, n, HB_EINVAL,
					                  "sample %zu (t = %.17g, j = %ld): the pre-jump state is not in D",
					                  i, a->t, a->j);
				/* g: x, v, x_m, v_m unchanged, x_c = 0, z_c = 0, q_c = 1 - q_c, exactly */
				if (b->x != a->x || b->v != a->v || b->xm != a->xm || b->vm != a->vm ||
				    b->xc != 0.0 || b->q != 1 - a->q)
					return status_set(msg, n, HB_EINVAL,
					                  "sample %zu (t = %.17g, j = %ld): the post-jump state is not g of the pre-jump state",
					                  i + 1, b->t, b->j);
				for (k = 0; k < nz; k++)
					if (b->z[k] != 0.0)
						return status_set(msg, n, HB_EINVAL,
						                  "sample %zu: z_c is not reset by the jump", i + 1);
				continue;
			} else if (b->j > a->j + 1 && skipped + (b->j - a->j - 1) <= arc_skipped(arc)) {
				/*
				 * Flow intervals thinned out (arc.h): a is still a
				 * pre-jump state in D, b a post-jump one (x_c = 0,
				 * z_c = 0, q_c alternating), later or at once.
				 */
				skipped += b->j - a->j - 1;
				if (!(b->t >= a->t) || !check_in_D(sc, a) || b->xc != 0.0 ||
				    b->q != (int)((a->q + b->j - a->j) % 2))
					return status_set(msg, n, HB_EINVAL,
					                  "sample %zu: the jumps thinned out between j = %ld "
					                  "and j = %ld do not join", i, a->j, b->j);
				for (k = 0; k < nz; k++)
					if (b->z[k] != 0.0)
						return status_set(msg, n, HB_EINVAL,
						                  "sample %zu: z_c is not reset by the jump", i + 1);
				continue;
			} else {
				return status_set(msg, n, HB_EINVAL, "sample %zu: j goes from %ld to %ld",
				                  i, a->j, b->j);
			}
		}
		if (!check_in_C(sc, a))
			return status_set(msg, n, HB_EINVAL,
			                  "sample %zu (t = %.17g, j = %ld, q_c = %d) is not in C",
			                  i, a->t, a->j, a->q);
	}
	if (skipped != arc_skipped(arc))
		return status_set(msg, n, HB_EINVAL, "%ld flow intervals are missing, but the arc "
		                  "thinned out %ld", skipped, arc_skipped(arc));
	return 0;
}

/* The state vector of the paper's H_r / H_f: x, v, x_c, z..., x_m, v_m. */
enum { EX, EV, EXC, EZ };

static int
euler_dim(const struct scene *sc)
{
	return EZ + sc->law->n_z + (sc->d.system == SCENE_FULL ? 2 : 0);
}

static void
euler_f(const struct scene *sc, int q, double t, const double *y, double *dy)
{
	int nz = sc->law->n_z, k;
	double phi = 0.0, Fer = scene_Fer(sc, t);

	for (k = 0; k < euler_dim(sc); k++)
		dy[k] = 0.0;
	if (q) {
		phi = sc->law->phi(sc->par, sc->ext, y[EXC], nz ? &y[EZ] : NULL, y[EV]);
		dy[EXC] = y[EV];
		if (nz)
			sc->law->psi(sc->par, sc->ext, y[EXC], &y[EZ], y[EV], &dy[EZ]);
	}
	dy[EX] = y[EV];
	dy[EV] = (-phi + Fer) / sc->d.m;
	if (sc->d.system == SCENE_FULL) {
		double F1, F2;

		scene_loads_at(sc, t, &F1, &F2);
		dy[EZ + nz] = y[EZ + nz + 1];
		dy[EZ + nz + 1] = (F1 + F2) / (sc->d.m1 + sc->d.m2);
	}
}

static void
euler_pack(const struct scene *sc, const struct arc_sample *a, double *y)
{
	int nz = sc->law->n_z, k;

	y[EX] = a->x;
	y[EV] = a->v;
	y[EXC] = a->xc;
	for (k = 0; k < nz; k++)
		y[EZ + k] = a->z[k];
	if (sc->d.system == SCENE_FULL) {
		y[EZ + nz] = a->xm;
		y[EZ + nz + 1] = a->vm;
	}
}

int
check_euler(const struct scene *sc, const struct arc *arc, size_t k, double *order,
            char *msg, size_t n)
{
	const struct arc_interval *iv = arc_interval_at(arc, k);
	double y0[16], y1[16], scale[16], y[16], dy[16], e_prev = NAN, e = NAN;
	int dim = euler_dim(sc), i, levels = 0;
	long N;
	size_t s;

	if (iv == NULL)
		return status_set(msg, n, HB_EINVAL, "no interval %zu", k);
	if (!(iv->t1 > iv->t0))
		return status_set(msg, n, HB_EINVAL, "interval %zu has no length", k);
	euler_pack(sc, arc_at(arc, iv->first), y0);
	euler_pack(sc, arc_at(arc, iv->last), y1);
	/* each component's size over the interval, for a scaled norm */
	for (i = 0; i < dim; i++)
		scale[i] = 0.0;
	for (s = iv->first; s <= iv->last; s++) {
		euler_pack(sc, arc_at(arc, s), y);
		for (i = 0; i < dim; i++)
			scale[i] = fmax(scale[i], fabs(y[i]));
	}
	for (N = 64; N <= (1L << 22); N *= 2) {
		double h = (iv->t1 - iv->t0) / (double)N, err = 0.0;
		long m;

		memcpy(y, y0, sizeof y0);
		for (m = 0; m < N; m++) {
			euler_f(sc, iv->q, iv->t0 + (double)m * h, y, dy);
			for (i = 0; i < dim; i++)
				y[i] += h * dy[i];
		}
		for (i = 0; i < dim; i++)
			if (scale[i] > 0.0) {
				double d = fabs(y[i] - y1[i]) / scale[i];

				/* fmax would drop a NaN: a blown-up component is an infinite error */
				err = isfinite(d) ? fmax(err, d) : HUGE_VAL;
			}
		e_prev = e;
		e = err;
		levels++;
		if (levels >= 3 && isfinite(e_prev) && e < 1e-4 && e_prev < 1e-3)
			break;
	}
	if (!(e > 0.0) || !isfinite(e_prev)) {
		*order = e == 0.0 ? INFINITY : NAN;
		return e == 0.0 ? 0 : status_set(msg, n, HB_EINVAL,
		                                 "interval %zu: forward Euler did not converge", k);
	}
	/* Euler is exact here (a flight at constant velocity): nothing but rounding to measure */
	if (e_prev < 1e-12 && e < 1e-12) {
		*order = INFINITY;
		return 0;
	}
	*order = log2(e_prev / e);
	return 0;
}
