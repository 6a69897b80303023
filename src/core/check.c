/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * check.c - the paper's checks of a computed solution pair (section
 * Simulation): the definition of a solution pair, and forward Euler as an
 * independent integrator.  Written from the paper's equations directly
 * (eqs. H_f, H_g, H_C, H_D and their reduced forms), not from the engine's
 * reduced phases, so that it checks them.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/check.h"
#include "hybounce/status.h"
#include "cnum.h"
#include "scene_chain.h"
#include "check_impl.h"

/*
 * The law of the interface sample a is of: the scene's, or in a chain
 * interface a->k's own (its overrides applied, its stiffness derived for
 * its pair of bodies), so that each interface is judged by its own law.
 */
static const struct hb_law_type *
law_of(const struct hb_scene *sc, const struct hb_arc_sample *a, struct scene_chain_iface *ci)
{
	if (sc->chain.n > 0 && scene_chain_iface(sc, a->k, ci) == HB_OK)
		return ci->law;
	ci->law = sc->law;
	memcpy(ci->par, sc->par, sizeof ci->par);
	ci->ext = sc->ext;
	return sc->law;
}

static double
phi_of(const struct hb_scene *sc, const struct hb_arc_sample *a)
{
	struct scene_chain_iface ci;
	const struct hb_law_type *law = law_of(sc, a, &ci);

	return law->phi(ci.par, ci.ext, a->xc, a->z, a->v);
}

int
hb_check_in_C(const struct hb_scene *sc, const struct hb_arc_sample *a)
{
	if (a->q == 0)
		return a->x >= 0.0 || a->v >= 0.0;
	return phi_of(sc, a) <= 0.0 || a->v <= 0.0;
}

int
hb_check_in_D(const struct hb_scene *sc, const struct hb_arc_sample *a)
{
	if (a->q == 0)
		return a->x <= 0.0 && a->v <= 0.0;
	return phi_of(sc, a) >= 0.0 && a->v >= 0.0;
}

/*
 * 1 when the flow interval of sample i ends at its instant (the samples
 * after it at the same t and j are followed by a jump).  A chain's samples
 * show one interface each: at the instant an interval ends, every
 * interface that has reached its jump set is in D (located to the
 * resolution of t, not snapped onto the boundary as a pair's are), and
 * those that jump after the first are recorded there, each taking its
 * turn (docs/chains.md section 3).
 */
static int
ends_here(const struct hb_arc *arc, size_t i)
{
	const struct hb_arc_sample *a = hb_arc_at(arc, i);
	size_t k = i + 1, len = hb_arc_len(arc);

	while (k < len && hb_arc_at(arc, k)->j == a->j && hb_arc_at(arc, k)->t == a->t)
		k++;
	return k < len && hb_arc_at(arc, k)->j > a->j && hb_arc_at(arc, k)->t == a->t;
}

int
hb_check_solution_pair(const struct hb_scene *sc, const struct hb_arc *arc, char *msg, size_t n)
{
	size_t i, len = hb_arc_len(arc);
	int nz, k;
	long skipped = 0;   /* flow intervals thinned out so far */
	struct scene_chain_iface ci;

	if (len == 0)
		return hb_status_set(msg, n, HB_EINVAL, "empty arc");
	if (hb_arc_at(arc, 0)->j != 0 || hb_arc_at(arc, 0)->t != 0.0 || hb_arc_at(arc, 0)->q != 0)
		return hb_status_set(msg, n, HB_EINVAL, "the arc does not start at (0, 0) with q_c = 0");
	for (i = 0; i < len; i++) {
		const struct hb_arc_sample *a = hb_arc_at(arc, i), *b = i + 1 < len ? hb_arc_at(arc, i + 1) : NULL;

		nz = b != NULL ? law_of(sc, b, &ci)->n_z : 0;
		if (b != NULL) {
			if (b->j == a->j) {
				if (!(b->t >= a->t))
					return hb_status_set(msg, n, HB_EINVAL,
					                  "sample %zu: t decreases within j = %ld (%.17g -> %.17g)",
					                  i, a->j, a->t, b->t);
				/*
				 * a chain's samples are of the interface that jumped last,
				 * or of the one that jumps next: its q_c may differ
				 */
				if (b->q != a->q && sc->chain.n == 0)
					return hb_status_set(msg, n, HB_EINVAL, "sample %zu: q_c changes without a jump", i);

			} else if (b->j == a->j + 1) {
				if (b->t != a->t)
					return hb_status_set(msg, n, HB_EINVAL,
					                  "sample %zu: a jump changes t (%.17g -> %.17g)", i, a->t, b->t);
				if (!hb_check_in_D(sc, a))
					return hb_status_set(msg, n, HB_EINVAL,
					                  "sample %zu (t = %.17g, j = %ld): the pre-jump state is not in D",
					                  i, a->t, a->j);
				/* g: x, v, x_m, v_m unchanged, x_c = 0, z_c = 0, q_c = 1 - q_c, exactly */
				if (b->x != a->x || b->v != a->v || b->xm != a->xm || b->vm != a->vm ||
				    b->xc != 0.0 || b->q != 1 - a->q || b->k != a->k)
					return hb_status_set(msg, n, HB_EINVAL,
					                  "sample %zu (t = %.17g, j = %ld): the post-jump state is not g of the pre-jump state",
					                  i + 1, b->t, b->j);
				for (k = 0; k < nz; k++)
					if (b->z[k] != 0.0)
						return hb_status_set(msg, n, HB_EINVAL,
						                  "sample %zu: z_c is not reset by the jump", i + 1);
				continue;
			} else if (b->j > a->j + 1 && skipped + (b->j - a->j - 1) <= hb_arc_skipped(arc)) {
				/*
				 * Flow intervals thinned out (arc.h): a is still a
				 * pre-jump state in D, b a post-jump one (x_c = 0,
				 * z_c = 0, q_c alternating), later or at once.
				 */
				skipped += b->j - a->j - 1;
				if (!(b->t >= a->t) || !hb_check_in_D(sc, a) || b->xc != 0.0 ||
				    b->q != (int)((a->q + b->j - a->j) % 2))
					return hb_status_set(msg, n, HB_EINVAL,
					                  "sample %zu: the jumps thinned out between j = %ld "
					                  "and j = %ld do not join", i, a->j, b->j);
				for (k = 0; k < nz; k++)
					if (b->z[k] != 0.0)
						return hb_status_set(msg, n, HB_EINVAL,
						                  "sample %zu: z_c is not reset by the jump", i + 1);
				continue;
			} else {
				return hb_status_set(msg, n, HB_EINVAL, "sample %zu: j goes from %ld to %ld",
				                  i, a->j, b->j);
			}
		}
		if (!hb_check_in_C(sc, a) && !(sc->chain.n > 0 && ends_here(arc, i) && hb_check_in_D(sc, a)))
			return hb_status_set(msg, n, HB_EINVAL,
			                  "sample %zu (t = %.17g, j = %ld, q_c = %d) is not in C",
			                  i, a->t, a->j, a->q);
	}
	if (skipped != hb_arc_skipped(arc))
		return hb_status_set(msg, n, HB_EINVAL, "%ld flow intervals are missing, but the arc "
		                  "thinned out %ld", skipped, hb_arc_skipped(arc));
	return 0;
}

/* The state vector of the paper's H_r / H_f: x, v, x_c, z..., x_m, v_m. */
enum { EX, EV, EXC, EZ };

static int
euler_dim(const struct hb_scene *sc)
{
	return EZ + sc->law->n_z + (sc->d.system == HB_SCENE_FULL ? 2 : 0);
}

static void
euler_f(const struct hb_scene *sc, int q, double t, const double *y, double *dy)
{
	int nz = sc->law->n_z, k;
	double phi = 0.0, Fer = hb_scene_Fer(sc, t);

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
	if (sc->d.system == HB_SCENE_FULL) {
		double F1, F2;

		hb_scene_loads_at(sc, t, &F1, &F2);
		dy[EZ + nz] = y[EZ + nz + 1];
		dy[EZ + nz + 1] = (F1 + F2) / (sc->d.m1 + sc->d.m2);
	}
}

static void
euler_pack(const struct hb_scene *sc, const struct hb_arc_sample *a, double *y)
{
	int nz = sc->law->n_z, k;

	y[EX] = a->x;
	y[EV] = a->v;
	y[EXC] = a->xc;
	for (k = 0; k < nz; k++)
		y[EZ + k] = a->z[k];
	if (sc->d.system == HB_SCENE_FULL) {
		y[EZ + nz] = a->xm;
		y[EZ + nz + 1] = a->vm;
	}
}

int
hb_check_euler(const struct hb_scene *sc, const struct hb_arc *arc, size_t k, double *order,
            char *msg, size_t n)
{
	const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);
	double y0[16], y1[16], scale[16], y[16], dy[16], e_prev = NAN, e = NAN;
	int dim = euler_dim(sc), i, levels = 0;
	long N;
	size_t s;

	if (iv == NULL)
		return hb_status_set(msg, n, HB_EINVAL, "no interval %zu", k);
	if (!(iv->t1 > iv->t0))
		return hb_status_set(msg, n, HB_EINVAL, "interval %zu has no length", k);
	euler_pack(sc, hb_arc_at(arc, iv->first), y0);
	euler_pack(sc, hb_arc_at(arc, iv->last), y1);
	/* each component's size over the interval, for a scaled norm */
	for (i = 0; i < dim; i++)
		scale[i] = 0.0;
	for (s = iv->first; s <= iv->last; s++) {
		euler_pack(sc, hb_arc_at(arc, s), y);
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
		return e == 0.0 ? 0 : hb_status_set(msg, n, HB_EINVAL,
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

/* ------------------------------------------------------------------ */
/* Physics: work-energy identity, passivity, restitution (check.h)     */

/*
 * How the registered laws handle energy.  Every law so far is passive
 * (Bouc-Wen with |gamma| <= beta, which the laws' check enforces, is); the
 * elastic ones dissipate nothing either.  A law not listed is not checked
 * for passivity.
 */
static const struct {
	const char *name;
	int passive, elastic;
} law_energy[] = {
	{ "shccl", 1, 0 }, { "bwshccl", 1, 0 }, { "bwmcl", 1, 0 },
	{ "hertz", 1, 1 }, { "linear", 1, 1 },
};

void
check_law_energy(const char *name, int *passive, int *elastic)
{
	size_t i;

	*passive = *elastic = 0;
	for (i = 0; i < sizeof law_energy / sizeof law_energy[0]; i++)
		if (strcmp(name, law_energy[i].name) == 0) {
			*passive = law_energy[i].passive;
			*elastic = law_energy[i].elastic;
		}
}

void
check_append_msg(char *msg, size_t n, const char *fmt_, ...)
{
	size_t l;
	va_list ap;

	if (msg == NULL || n == 0)
		return;
	l = strlen(msg);
	if (l > 0 && l + 3 < n) {
		memcpy(msg + l, "; ", 3);
		l += 2;
	}
	if (l + 1 < n) {
		va_start(ap, fmt_);
		cnum_vsnprintf(msg + l, n - l, fmt_, ap);
		va_end(ap);
	}
}

/*
 * One completed contact, interval k of the arc: its collision index, W
 * relative to its impact energy (elastic laws: -|W|), e and its bound.
 * Needs r's tol, escale, elastic.  Returns 0 when interval k is not a
 * completed contact.
 */
struct contact {
	long ci;
	double W, w, vi, e, ebound, dev;
	int have_w, have_e;
};

static int
contact_eval(const struct hb_scene *sc, const struct hb_arc *arc, size_t k,
             const struct hb_check_physics *r, struct contact *c)
{
	const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);
	const struct hb_arc_sample *a0, *a1;
	double m = sc->d.m, Ei, Eec, eref;

	if (iv->q != 1)
		return 0;
	a0 = hb_arc_at(arc, iv->first);
	a1 = hb_arc_at(arc, iv->last);
	if (a1->kind != HB_ARC_PRE_JUMP)
		return 0;
	memset(c, 0, sizeof *c);
	c->ci = (iv->j - 1) / 2;
	c->W = a1->W;
	c->vi = a0->v;
	Ei = 0.5 * m * a0->v * a0->v;
	Eec = a1->Ee - a0->Ee;
	eref = fmax(Ei, fabs(Eec));
	if (!(eref > 0.0))
		eref = r->escale;
	if (eref > 0.0) {
		/* dissipative: W / E_i, smallest; elastic: -|W| / E_i */
		c->w = r->elastic ? -fabs(a1->W) / eref : a1->W / eref;
		c->have_w = 1;
	}
	/*
	 * An impact energy below what the run resolves (v_i = 0, or a
	 * round-off v_i like -1e-285 m/s): e = -v(t_s)/v_i says nothing.
	 */
	if (a0->v < 0.0 && Ei > r->tol * r->escale) {
		c->e = -a1->v / a0->v;
		c->ebound = sqrt(1.0 + fmax(Eec, 0.0) / Ei);
		/* elastic: e = ebound exactly, so an e below it is an error too */
		c->dev = r->elastic ? fabs(c->e - c->ebound) : c->e - c->ebound;
		c->have_e = 1;
	}
	return 1;
}

int
hb_check_physics(const struct hb_scene *sc, const struct hb_arc *arc, struct hb_check_physics *r,
              char *msg, size_t n)
{
	const double m = sc->d.m, K = HB_CHECK_PHYS_FACTOR;
	size_t i, k, len = hb_arc_len(arc), nint = hb_arc_nintervals(arc);
	double v0, escale = 0.0, eworst = 0.0;
	long ci;

	memset(r, 0, sizeof *r);
	r->tol = fmax(sc->run.rtol, sc->run.atol);
	r->wmin = INFINITY;
	r->wmin_at = r->emax_at = r->zero_at = -1;
	r->emax = -INFINITY;
	if (msg != NULL && n > 0)
		msg[0] = '\0';
	check_law_energy(sc->law->name, &r->passive, &r->elastic);
	if (len == 0 || !(m > 0.0) || !isfinite(m))
		return 0;

	/* the work-energy identity at every sample */
	v0 = hb_arc_at(arc, 0)->v;
	for (i = 0; i < len; i++) {
		const struct hb_arc_sample *a = hb_arc_at(arc, i);

		escale = fmax(escale, fmax(0.5 * m * a->v * a->v, fmax(fabs(a->Ee), fabs(a->Wc))));
		/*
		 * The work of the applied force is F (x - x0) to the rounding of x:
		 * on a horizon too short for the bodies to move by more than that
		 * (T = 1 ns from rest at 20 mm), F x is the scale it is known to.
		 */
		escale = fmax(escale, fabs(a->Fer * a->x));
	}
	r->escale = escale;
	/*
	 * A chain's arc records one interface at a time, whose relative motion
	 * the other interfaces change too: the identity is the chain's, over
	 * its bodies, not checked on the arc (docs/chains.md section 5).
	 */
	for (i = 0; i < len && escale > 0.0 && sc->chain.n == 0; i++) {
		const struct hb_arc_sample *a = hb_arc_at(arc, i);
		/* (v - v0)(v + v0) keeps the difference exact when v is near v0 */
		double res = fabs(0.5 * m * (a->v - v0) * (a->v + v0) - (a->Ee + a->Wc)) / escale;

		if (!(res <= eworst)) {  /* NaN counts as the worst */
			eworst = isnan(res) ? INFINITY : res;
			r->resid_at = i;
		}
	}
	r->resid = eworst;
	if (!(r->resid <= K * r->tol)) {
		const struct hb_arc_sample *a = hb_arc_at(arc, r->resid_at);

		r->failed++;
		check_append_msg(msg, n, "work-energy identity: the residual of m v^2/2 - m v0^2/2 = "
		           "E_e + W_c reaches %.3g of the energy scale %.3g J (t = %.9g s, "
		           "j = %ld): the error estimate is %.3g times the tolerance %.3g asked "
		           "(at most %g accepted)", r->resid, escale, a->t, a->j,
		           r->resid / r->tol, r->tol, K);
	}

	/*
	 * Each completed contact: a contact interval that ends in a jump.
	 * Collision i occupies interval j = 2i + 1 (collisions.h); intervals
	 * thinned out of a long run are simply not there.  A chain's flow
	 * interval ends with the jump of whichever interface comes next and
	 * its samples are of several interfaces: an interval is not one
	 * contact there, and is not checked on the arc (the bodies' energy
	 * and momentum are the chain's tests).
	 */
	for (k = 0; k < nint && sc->chain.n == 0; k++) {
		struct contact c;

		if (!contact_eval(sc, arc, k, r, &c))
			continue;
		ci = c.ci;
		r->ncontacts++;
		if (r->passive && c.have_w && !(c.w >= r->wmin)) {
			r->wmin = isnan(c.w) ? -INFINITY : c.w;
			r->wmin_at = ci;
			r->W_at = c.W;
		}
		if (c.have_e) {
			if (r->passive && !(c.dev <= r->emax)) {
				r->emax = isnan(c.dev) ? INFINITY : c.dev;
				r->emax_at = ci;
				r->e_at = c.e;
				r->e_bound = c.ebound;
			}
		} else {
			if (r->nzero++ == 0) {
				r->zero_at = ci;
				r->vi_zero = c.vi;
			}
		}
	}
	if (r->passive && r->wmin_at >= 0 && !(r->wmin >= -K * r->tol)) {
		r->failed++;
		if (r->elastic)
			check_append_msg(msg, n, "elastic law: collision %ld has W = %.6g J, %.3g of its "
			           "impact energy, where %s dissipates nothing: the error estimate is "
			           "%.3g times the tolerance %.3g asked (at most %g accepted)",
			           r->wmin_at, r->W_at, -r->wmin, sc->law->name, -r->wmin / r->tol,
			           r->tol, K);
		else
			check_append_msg(msg, n, "passivity: collision %ld returns energy, W = %.6g J "
			           "(%.3g of its impact energy), where %s can only absorb it "
			           "(W >= 0 up to %g x the tolerance %.3g)", r->wmin_at, r->W_at,
			           r->wmin, sc->law->name, K, r->tol);
	}
	if (r->passive && r->emax_at >= 0 && !(r->emax <= K * r->tol)) {
		r->failed++;
		if (r->elastic)
			check_append_msg(msg, n, "restitution: collision %ld has e = %.9g where the elastic "
			           "%s gives exactly %.9g: the error estimate is %.3g times the "
			           "tolerance %.3g asked (at most %g accepted)", r->emax_at, r->e_at,
			           sc->law->name, r->e_bound, r->emax / r->tol, r->tol, K);
		else
			check_append_msg(msg, n, "restitution: collision %ld has e = %.9g, above the %.9g "
			           "that %s allows (it cannot give energy back, counting the applied "
			           "force's work over the contact), beyond %g x the tolerance %.3g",
			           r->emax_at, r->e_at, r->e_bound, sc->law->name, K, r->tol);
	}
	return r->failed ? HB_EINVAL : 0;
}

size_t
hb_check_physics_flags(const struct hb_scene *sc, const struct hb_arc *arc,
                       const struct hb_check_physics *r, unsigned char *flags, size_t nflags)
{
	const double K = HB_CHECK_PHYS_FACTOR;
	size_t k, nint = hb_arc_nintervals(arc), nbad = 0;

	if (flags != NULL && nflags > 0)
		memset(flags, 0, nflags);
	if (!r->passive || !(sc->d.m > 0.0) || !isfinite(sc->d.m) || sc->chain.n > 0)
		return 0;
	for (k = 0; k < nint; k++) {
		struct contact c;
		unsigned char f = 0;

		if (!contact_eval(sc, arc, k, r, &c) || c.ci < 0)
			continue;
		if (c.have_w && !(c.w >= -K * r->tol))
			f |= HB_CHECK_BAD_W;
		if (c.have_e && !(c.dev <= K * r->tol))
			f |= HB_CHECK_BAD_E;
		if (f == 0)
			continue;
		nbad++;
		if (flags != NULL && (size_t)c.ci < nflags)
			flags[c.ci] = f;
	}
	return nbad;
}

void
hb_check_physics_summary(const struct hb_check_physics *r, char *buf, size_t n)
{
	if (buf == NULL || n == 0)
		return;
	if (r->failed == 0)
		snprintf(buf, n, "the computed run passes the physics checks");
	else
		snprintf(buf, n, "the computed run fails %d physics check%s; a tighter run.rtol "
		         "and run.atol, or another run.stepper, should fix it", r->failed,
		         r->failed == 1 ? "" : "s");
}
