/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_locate.c - location on a step: where a watched function (sim_watch.c)
 * crosses, on re-steps, on the step's continuous extension (dop853) or
 * guided by its Hermite interpolant (the other steppers), with the
 * engine's bracketing root finder (sim_root.c); events stepped over found
 * by the dip test (sim_dip.c; see sim.c for the method).
 */
#include "sim_impl.h"

/*
 * fmax of two numbers >= 0 or NaN, inline (fmax is a call into libm): the
 * other where one is NaN, as fmax.
 */
static inline double
max_abs(double a, double b)
{
	return isnan(a) ? b : (a < b ? b : a);
}

/*
 * Sets the Hermite interpolant of the step up (f at its ends, where the
 * step has not evaluated it already): 0, or the rhs' error.
 */
static int
hermite_setup(struct hb_sim *s)
{
	struct phase *p = s->cur;
	int rc;

	if ((rc = known_eval(&p->known, &p->sys, s->t0, s->u0, s->f0)) != GSL_SUCCESS)
		return rc;
	return known_eval(&p->known, &p->sys, s->t0 + s->H, s->u1, s->f1);
}

/* The whole state one step of length h from (t0, u0) (restep_n). */
static int
restep(struct hb_sim *s, double h, double *u)
{
	return hbs_restep_n(s, h, u, s->cur->L.dim);
}

/*
 * The oriented value of the target function at h for Brent: > 0 where it
 * has not crossed yet (an exact zero counts as not crossed), < 0 where it
 * has; NAN where the state there cannot be computed (struct hbs_root's
 * value).  Not counted in loc_iter (oriented() is).
 */
static double
oriented_value(double h, void *ctx)
{
	struct hb_sim *s = ctx;
	double *u = s->ut, val;
	int kind;

	if (s->fun_kind != FUN_EVENT && s->t0 + h == s->t0)
		return DBL_MIN; /* the step's start has not crossed (a mode's side is its sign there) */
	if (hbs_restep_n(s, h, u, s->cur->L.nread))
		return NAN;
	val = hbs_watch_one(s, s->cur, s->t0 + h, u, s->fun_target, &kind);
	if (kind == FUN_EVENT)
		return val >= 0.0 ? fmax(val, DBL_MIN) : val;
	val *= s->fun_sign0;
	return val > 0.0 ? val : (val == 0.0 ? DBL_MIN : val);
}

/* oriented_value(), counted as one evaluation of the location. */
static double
oriented(double h, struct hb_sim *s)
{
	s->loc_iter++;
	return oriented_value(h, s);
}

/*
 * Brackets the crossing of function k (side sign0 at the step's start) in
 * [lo, hi] with the engine's root finder (sim_root.c) on restep()'s states;
 * its evaluations counted in loc_iter.  The pair's indicator keeps Brent's
 * own steps (see sim_root.c); a chain's clusters close the stalls of every
 * function, and where Brent's bracket closes on a crossing the other way
 * (a gap at the level of its rounding crosses back and forth) bisect.
 */
static int
bracket(struct hb_sim *s, int k, int sign0, double lo, double hi, double htol, double *a, double *b)
{
	int kind = s->lkind[k];
	struct hbs_root r = { oriented_value, s, &s->loc_iter, s->root, s->t0, s->H,
	                      s->chain || kind != FUN_EVENT, 100.0 * DBL_EPSILON * s->gmax[k] };
	int rc;

	s->fun_target = k;
	s->fun_kind = kind;
	s->fun_sign0 = sign0;
	rc = hbs_root_bracket(&r, lo, hi, htol, a, b);
	if (rc != 0 && s->chain && hbs_root_bisect(&r, lo, hi, htol, a, b) == 0)
		rc = 0;
	return rc;
}

/* The state at (t, u) unpacked: the pair's interface, or a chain's clusters. */
static void
unpack(struct hb_sim *s, double t, const double *u)
{
	if (s->chain)
		hbs_cluster_unpack(s, t, u);
	else
		hbs_unpack(s, s->cur, t, u);
}

/* Accepts the state at h (a located point) as the current state and restarts the stepper. */
static void
accept_at(struct hb_sim *s, double h)
{
	double *u = s->uc;

	restep(s, h, u);
	hbs_ucopy(s, s->u, u);
	unpack(s, s->t0 + h, u);
	gsl_odeiv2_driver_reset(s->cur->d);
}



/*
 * From a point located on the continuous extension to the step's own
 * state there.  A kink or an extremum: the state at b is recomputed by one
 * step of the method from the step's start (it is then as accurate as any
 * step end), unless that state has left C, when the interpolated one
 * (which has not) is kept.  An event: the indicator of the recomputed
 * states is bracketed again in a window about b, widened until it holds
 * the crossing, so that the pre-jump state is a step's state in D; if no
 * window does, the interpolated bracket stands (its end is in D too).
 * Leaves use_dense set when the interpolated points stand.
 */
static void
real_point(struct hb_sim *s, int event, double hi, double *a, double *b)
{
	double w = fmax(16.0 * (*b - *a), 1e-10 * s->H), ra, rb;
	int tries;

	s->use_dense = 0;
	if (event < 0) {
		double *u = s->uc, *f = s->lfa;
		int i, n;

		if (restep(s, *b, u) != 0)
			goto keep;
		if (!s->chain) { /* the pair's indicator alone */
			if (!(hbs_watch_one(s, s->cur, s->t0 + *b, u, 0, &i) >= 0.0))
				goto keep;
			return;
		}
		n = hbs_watch(s, s->cur, s->t0 + *b, u, f, s->lka);
		for (i = 0; i < n; i++)
			if (s->lka[i] == FUN_EVENT && !(f[i] >= 0.0))
				goto keep;
		return;
	}
	for (tries = 0; tries < 5; tries++, w *= 64.0) {
		double lo = fmax(0.0, *b - w), up = fmin(hi, *b + w);

		if (up <= *b || tries == 4) /* the last window: the whole step */
			up = hi;
		if (tries == 4)
			lo = 0.0;
		if (bracket(s, event, 1, lo, up, 0.0, &ra, &rb) == 0) {
			*a = ra;
			*b = rb;
			return;
		}
	}
keep:
	s->use_dense = 1;
}

/*
 * How closely a crossing of a function of this kind is bracketed (see
 * bracket): events to ulps of t, since the pre-jump state must be in D and
 * the jump's time is an observable.  A kink or an extremum ends the step
 * at the crossed end b of its bracket, and to 0.1 sqrt(rtol) of the step:
 * the flow is continuous across a kink (law.h) and an extremum's value is
 * stationary, so a point off by delta changes the state, or the extremum,
 * by O(delta^2) only (about rtol (H/tau)^2 / 200 of its scale, tau the
 * time scale of the motion, at least H).  Where an event crosses inside
 * such a bracket, or F_c's extremum sits at a kink where dF_c/dt jumps,
 * the location is done again to ulps (tight, see hbs_after_step).  On
 * the Hermite interpolant, to well within its own error, 1e-10 of the step.
 */
static double
htol_of(const struct hb_sim *s, int kind, int tight)
{
	double h = 0.0;

	if (!tight && kind != FUN_EVENT)
		h = 0.1 * sqrt(s->sc.run.rtol) * s->H;
	if (s->use_herm)
		h = fmax(h, 1e-10 * s->H);
	return h;
}

/*
 * From a crossing of function k (side sign0 at the step's start) found on
 * the Hermite interpolant at about b to the same crossing bracketed on the
 * method's own steps, in [0, hi]: the value of k on a step to b and the
 * interpolant's slope there give a Newton estimate of the root; b is one
 * end of the bracket, the other lies just beyond the estimate, and moves
 * away until the bracket holds the crossing (at last the whole [0, hi]),
 * then narrowed to htol (see bracket).  Returns 0 with the bracket in *a, *b.
 */
static int
locate_on_steps(struct hb_sim *s, int k, int sign0, double hi, double htol, double *a, double *b)
{
	double x0 = *b, g0, gl, gu, d = 1e-3 * s->H, xl, xu, slope, x1, w;
	int tries;

	s->fun_target = k;
	s->fun_kind = s->lkind[k];
	s->fun_sign0 = sign0;
	s->use_herm = 1;
	xl = fmax(0.0, x0 - d);
	xu = fmin(hi, x0 + d);
	gl = oriented(xl, s);
	gu = oriented(xu, s);
	s->use_herm = 0;
	g0 = oriented(x0, s);
	if (!isfinite(g0))
		return GSL_FAILURE;
	slope = xu > xl ? (gu - gl) / (xu - xl) : NAN;
	x1 = isfinite(slope) && slope < 0 ? x0 - g0 / slope : x0;
	w = fmax(0.05 * fabs(x1 - x0), 16.0 * DBL_EPSILON * fmax(fabs(s->t0 + x0), 1e-300));
	if (htol > 0.0 && x1 != x0 && fabs(x1 - x0) + 0.5 * htol <= 10.0 * htol) {
		/*
		 * A kink or an extremum: the Newton estimate from a real value
		 * is far closer to the root than htol (its error is the
		 * Hermite's times the slope's), so one more step, htol/2 beyond
		 * it, closes a bracket of at most 10 htol whose crossed end is
		 * about htol/2 past the root.
		 */
		double xe = g0 > 0 ? fmin(hi, x1 + 0.5 * htol) : fmax(0.0, x1 - 0.5 * htol);

		if (g0 > 0 ? xe > x0 : xe < x0) {
			double ge = oriented(xe, s);

			if (g0 > 0 ? ge < 0 : ge > 0) { /* crossed between x0 and xe */
				*a = fmin(x0, xe);
				*b = fmax(x0, xe);
				return 0;
			}
		}
	}
	for (tries = 0; tries < 6; tries++, w *= 16.0) {
		double lo_, up;

		if (tries == 5) { /* the whole step */
			lo_ = 0.0;
			up = hi;
		} else if (g0 > 0) { /* not crossed at x0: the root lies after it */
			lo_ = x0;
			up = fmin(hi, fmax(x0, x1) + w);
		} else {
			lo_ = fmax(0.0, fmin(x0, x1) - w);
			up = x0;
		}
		if (bracket(s, k, sign0, lo_, up, htol, a, b) == 0)
			return 0;
	}
	return GSL_FAILURE;
}

/*
 * Which functions but k have crossed at a?  Any of them, not only the
 * candidates: one that crossed and came back within the step (the
 * indicator, most of all) is found here.  Their indices into cand (if not
 * NULL); returns how many, or -1 if the state at a cannot be computed.
 */
static int
crossed_at(struct hb_sim *s, int k, const double *f0, int n, const int *kind, double a, int *cand)
{
	double *ua = s->ua, *fa = s->lfa;
	int *kk = s->lka, i, nb = 0;

	if (restep(s, a, ua))
		return -1;
	hbs_watch(s, s->cur, s->t0 + a, ua, fa, kk);
	for (i = 0; i < n; i++)
		if (i != k && hbs_candidate(s, kind[i], s->gmax[i], f0[i], fa[i])) {
			if (cand != NULL)
				cand[nb] = i;
			nb++;
		}
	return nb;
}

/*
 * The mode's side is its frozen sign (the pair's s->msign, a chain's
 * interface's I->msign), even where the switching function is still zero
 * to rounding on the other side (a step that begins on a located
 * crossing): it crosses when its sign differs from the mode's.  f0: the
 * watched values at the step's start.
 */
static void
mode_sides(struct hb_sim *s, double *f0)
{
	int p;

	if (!s->chain) {
		int k = 1 + s->I->law->mode_kink;

		if (s->msign && !(f0[k] * s->msign > 0))
			f0[k] = s->msign * DBL_MIN;
		return;
	}
	for (p = 0; p < s->cx.nact; p++) {
		const struct iface *I = &s->ifc[s->cx.act[p]];
		int k = I->fo + 1 + I->law->mode_kink;

		if (I->msign && !(f0[k] * I->msign > 0))
			f0[k] = I->msign * DBL_MIN;
	}
}

/* ... and where a mode's switching function crossed (f0 to fb), the next step is on the other side. */
static void
mode_crossed(struct hb_sim *s, const double *f0, const double *fb)
{
	int p;

	if (!s->chain) {
		if (s->msign && hbs_crossed(FUN_KINK, f0[1 + s->I->law->mode_kink],
		                            fb[1 + s->I->law->mode_kink])) {
			s->mforce = -s->msign;
			s->mforce_t = s->t;
		}
		return;
	}
	for (p = 0; p < s->cx.nact; p++) {
		struct iface *I = &s->ifc[s->cx.act[p]];
		int k = I->fo + 1 + I->law->mode_kink;

		if (I->msign && hbs_crossed(FUN_KINK, f0[k], fb[k])) {
			I->mforce = -I->msign;
			I->mforce_t = s->t;
		}
	}
}

/*
 * Handles an accepted step (t0, u0) -> (t0 + H, u1): finds the earliest
 * crossing of the watched functions, if any, and acts on it.
 */
int
hbs_after_step(struct hb_sim *s, int load_kink)
{
	struct phase *p = s->cur;
	double *f0 = s->lf0, *f1 = s->lf1;
	int *kind = s->lkind, n, i, rc, any = 0;
	int *cand = s->cand, ncand = 0, *cand0 = s->cand0, ncand0;
	double lo = 0.0, hi = s->H, a = 0, b = 0, hi0, *r0 = s->lr0, *r1 = s->lr1;
	int first = -1, first_sign = 1, herm, tight = 0;
	const size_t nu = (size_t)p->L.dim * sizeof *s->u;

	s->ncache = 0;
	s->cache_next = 0;
	if (p->q) {
		hbs_snap_stick(s, s->u1);
		hbs_snap_separation(s, s->u1);
		if (!s->chain)
			s->vmax = fmax(s->vmax, fabs(s->u1[p->L.iv] * s->scale[p->L.iv]));
		else
			for (i = 0; i < s->cx.nact; i++) {
				struct iface *I = &s->ifc[s->cx.act[i]];

				I->vmax = fmax(I->vmax, fabs(s->u1[I->off + 1] * s->scale[I->off + 1]));
			}
	}
	n = hbs_watch_at(s, p, s->t0, s->u0, f0, kind, r0);
	hbs_watch_at(s, p, s->t0 + s->H, s->u1, f1, kind, r1);
	mode_sides(s, f0);
	for (i = 0; i < n; i++)
		if (hbs_candidate(s, kind[i], s->gmax[i], f0[i], f1[i]))
			cand[ncand++] = i;
	{
		/* an event stepped over: locate everything that crossed before the dip */
		double *fx = s->lfb, th = hbs_dip(s, f0, f1, r0, r1, kind, n, cand, ncand, fx);

		if (th > 0.0) {
			s->st.dips++;
			hi = th * s->H;
			for (ncand = 0, i = 0; i < n; i++)
				if (hbs_candidate(s, kind[i], s->gmax[i], f0[i], fx[i]))
					cand[ncand++] = i;
		}
	}
	for (i = 0; i < n; i++)
		s->gmax[i] = max_abs(s->gmax[i], max_abs(fabs(f0[i]), fabs(f1[i])));
	if (ncand == 0) {
		/*
		 * GSL's evolve hands the derivative at the step's end to the next
		 * step as its first stage (rk8pd, rkck, rkf45): a state moved by
		 * the snaps above needs it evaluated again.
		 */
		if (memcmp(s->u, s->u1, nu) != 0)
			gsl_odeiv2_evolve_reset(p->d->e);
		hbs_ucopy(s, s->u, s->u1);
		unpack(s, s->t0 + s->H, s->u1);
		if (s->chain && (rc = hbs_cluster_limits(s)))
			return rc;
		if (load_kink) {
			gsl_odeiv2_driver_reset(p->d);
			s->st.kinks++;
		}
		return hbs_push_sample(s, load_kink ? HB_ARC_KINK : HB_ARC_STEP);
	}
	/* the earliest crossing: bracket one, then look for earlier ones before it */
	s->loc_iter = 0;
	s->st.located++;
	/*
	 * A stepper without a continuous extension: the crossings are first
	 * found on the step's Hermite interpolant, then on the method's own
	 * steps about that point (locate_on_steps); where that fails, or some
	 * other function has crossed before the point found, the whole
	 * location is done again on steps alone.
	 */
	herm = !s->use_dense && !s->hug && hermite_setup(s) == GSL_SUCCESS;
	memcpy(cand0, cand, (size_t)ncand * sizeof *cand);
	ncand0 = ncand;
	hi0 = hi;
again:
	s->use_herm = herm;
	memcpy(cand, cand0, (size_t)ncand0 * sizeof *cand);
	ncand = ncand0;
	lo = 0.0;
	hi = hi0;
	first = -1;
	while (ncand > 0) {
		int k = cand[0], nb, sign0 = f0[k] > 0 ? 1 : -1;

		if ((rc = bracket(s, k, sign0, lo, hi, htol_of(s, kind[k], tight), &a, &b)) != 0) {
			if (rc == GSL_FAILURE && first >= 0)
				break;
			if (herm) {
				herm = 0;
				goto again;
			}
			return hbs_fail(s, HB_ENUMERIC, "event location failed (no bracket)");
		}
		first = k;
		first_sign = sign0;
		hi = b;
		if ((nb = crossed_at(s, k, f0, n, kind, a, cand)) <= 0)
			break;
		ncand = nb;
		hi = a;
	}
	if (herm) {
		s->use_herm = 0;
		if (locate_on_steps(s, first, first_sign, hi0, htol_of(s, kind[first], tight), &a, &b) != 0
		    || crossed_at(s, first, f0, n, kind, a, NULL) != 0) {
			herm = 0;
			goto again;
		}
	}
	/* everything that has crossed at b happens here; the event wins */
	{
		double *ub = s->ub, *fb = s->lfb;
		int *kb = s->lka, event = -1, kink = 0;

		restep(s, b, ub);
		hbs_watch(s, p, s->t0 + b, ub, fb, kb);
		if (!tight && kind[first] != FUN_EVENT) {
			int ev = 0, kk = kind[first] == FUN_KINK, fc = kind[first] == FUN_FCMAX ? first : -1;

			for (i = 0; i < n; i++)
				if (i != first && hbs_candidate(s, kind[i], s->gmax[i], f0[i], fb[i])) {
					ev |= kind[i] == FUN_EVENT;
					kk |= kind[i] == FUN_KINK;
					if (kind[i] == FUN_FCMAX)
						fc = i;
				}
			if (ev || (kk && fc >= 0 && fabs(fb[fc]) > sqrt(s->sc.run.rtol) * s->gmax[fc])) {
				/*
				 * an event inside the bracket of a kink or an extremum, or
				 * the extremum of F_c at a kink where dF_c/dt jumps (it
				 * has not come near zero at b), so that F_c at b is off
				 * by O(delta): to ulps again
				 */
				tight = 1;
				goto again;
			}
		}
		for (i = 0; i < n; i++)
			if (hbs_crossed(kind[i], f0[i], fb[i])) {
				any = 1;
				if (kind[i] == FUN_EVENT) {
					if (event < 0) /* the lowest k first */
						event = i;
				} else if (kind[i] == FUN_KINK) {
					kink = 1;
				}
			}
		if (!any)
			return hbs_fail(s, HB_ENUMERIC, "event location lost its bracket");
		if (s->use_dense)
			real_point(s, event, hi, &a, &b);
		if (event >= 0) {
			double *ua = s->ua, fa0;
			int ka;

			restep(s, a, ua);
			fa0 = hbs_watch_one(s, p, s->t0 + a, ua, event, &ka);
			accept_at(s, b);
			if (!s->chain)
				return hbs_jump(s, HB_LOCATE_BRENT, s->loc_iter, b - a, fa0, fb[event]);
			if ((rc = hbs_cluster_limits(s)) || s->end != HB_SIM_RUNNING)
				return rc;
			return hbs_cluster_jump(s, s->cx.fif[event], HB_LOCATE_BRENT, s->loc_iter, b - a, fa0,
			                        fb[event]);
		}
		accept_at(s, b);
		mode_crossed(s, f0, fb);
		if (s->chain && (rc = hbs_cluster_limits(s)))
			return rc;
		s->st.kinks += kink;
		return hbs_push_sample(s, kink ? HB_ARC_KINK : HB_ARC_EXTREMUM);
	}
}
