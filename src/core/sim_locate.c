/*
 * sim_locate.c - location on a step: the watched functions (the indicator of C, the law's
 * switching functions, the extremum functions), re-steps and the continuous
 * extension, the bracketing root finder, the dip test, the noise filters and
 * the separation that rounding cannot fake (see sim.c for the method).
 */
#include "sim_impl.h"

/* The flow-set indicator of an unscaled state: >= 0 in C. */
static double
indicator(const struct sim *s, int q, double xc, const double *z, double v, double x)
{
	if (q)
		return -fmin(phi_at(s, xc, z, v), v);
	return fmax(x, v);
}

/*
 * Values of the watched functions at a scaled state: [0] the indicator,
 * then the law's switching functions, then v (x_c extremum) and dPhi/dt
 * (F_c extremum).  Returns their number; kinds in kind[].
 */
int
hbs_watch(const struct sim *s, const struct phase *p, double t, const double *u, double *f,
      int *kind)
{
	const struct scene *sc = &s->sc;
	const struct layout *L = &p->L;
	double y[MAXDIM], v, x, xc = 0, z[LAW_MAX_Z] = { 0 };
	int n = 0, i, nz = sc->law->n_z;

	hbs_unscale(p, u, y);
	v = y[L->iv];
	if (p->q) {
		xc = y[L->ixc];
		for (i = 0; i < nz; i++)
			z[i] = y[L->iz + i];
		x = L->ix >= 0 ? y[L->ix] : s->xe + xc;
	} else {
		x = y[L->ix];
	}
	kind[n] = FUN_EVENT;
	f[n++] = indicator(s, p->q, xc, z, v, x);
	if (!p->q)
		return n;
	if (sc->law->n_kinks && sc->run.kinks) {
		sc->law->kinks(sc->par, sc->ext, xc, z, v, &f[n]);
		for (i = 0; i < sc->law->n_kinks; i++)
			kind[n++] = FUN_KINK;
	}
	kind[n] = FUN_XCMAX;
	f[n++] = v;
	{
		double dphi[LAW_MAX_Z + 2], dpsi[LAW_MAX_Z * (LAW_MAX_Z + 2)], dz[LAW_MAX_Z];
		double phi = phi_at(s, xc, z, v), vdot, d;

		sc->law->jac(sc->par, sc->ext, xc, z, v, dphi, nz ? dpsi : NULL);
		if (nz)
			sc->law->psi(sc->par, sc->ext, xc, z, v, dz);
		vdot = (-phi + scene_Fer(sc, t)) / sc->d.m;
		d = dphi[0] * v + dphi[nz + 1] * vdot;
		for (i = 0; i < nz; i++)
			d += dphi[1 + i] * dz[i];
		kind[n] = FUN_FCMAX;
		f[n++] = d;
	}
	return n;
}

/* Did function i cross between values a (step start) and b? */
static int
crossed(int kind, double a, double b)
{
	switch (kind) {
	case FUN_EVENT: return a >= 0.0 && b < 0.0;
	case FUN_KINK: return (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
	default: return a < 0.0 && b > 0.0; /* minima of x_c and of Phi */
	}
}

static void snap_stick(struct sim *s, double *u);
static int snap_separation(struct sim *s, double *u);

/* The state one step of length h from (t0, u0), cached. */
static int
restep(struct sim *s, double h, double *u)
{
	struct phase *p = s->cur;
	double yerr[MAXDIM];
	int i, rc;

	if (s->t0 + h == s->t0) { /* h below the resolution of t: the start (bsimp refuses such a step) */
		memcpy(u, s->u0, sizeof s->u0);
		return 0;
	}
	if (h == s->H) {
		memcpy(u, s->u1, sizeof s->u1);
		return 0;
	}
	if (s->use_dense) {
		/* on the step's continuous extension: no evaluation of f */
		if ((rc = hb_dop853_dense(p->d->s, s->t0 + h, u)) != GSL_SUCCESS)
			return rc;
		for (i = 0; i < p->L.dim; i++)
			if (!isfinite(u[i]))
				return GSL_FAILURE;
		if (p->q) {
			snap_stick(s, u);
			if (s->hug)
				snap_separation(s, u);
		}
		return 0;
	}
	for (i = 0; i < s->ncache; i++)
		if (s->cache[i].h == h) {
			memcpy(u, s->cache[i].u, sizeof s->u0);
			return 0;
		}
	memcpy(u, s->u0, sizeof s->u0);
	gsl_odeiv2_step_reset(p->loc->s);
	rc = gsl_odeiv2_step_apply(p->loc->s, s->t0, h, u, yerr, NULL, NULL, &p->sys);
	if (rc != GSL_SUCCESS)
		return rc;
	/* a step whose error estimate is not finite was not made (bsimp's divergence) */
	for (i = 0; i < p->L.dim; i++)
		if (!isfinite(u[i]) || !isfinite(yerr[i]))
			return GSL_FAILURE;
	if (p->q) {
		snap_stick(s, u);
		if (s->hug)
			snap_separation(s, u);
	}
	i = s->cache_next;
	s->cache_next = (s->cache_next + 1) % CACHE;
	if (s->ncache < CACHE)
		s->ncache++;
	s->cache[i].h = h;
	memcpy(s->cache[i].u, u, sizeof s->u0);
	return 0;
}

/* The kind of the function being located (fun_target): 0 is the indicator, the event. */
static int
kind_of_target(const struct sim *s)
{
	return s->fun_target == 0 ? FUN_EVENT : FUN_KINK;
}

/*
 * The oriented value of the target function at h for Brent: > 0 where it
 * has not crossed yet (an exact zero counts as not crossed), < 0 where it
 * has.
 */
static double
oriented(double h, void *params)
{
	struct sim *s = params;
	double u[MAXDIM], f[MAXFUN], val;
	int kind[MAXFUN];

	s->loc_iter++;
	if (kind_of_target(s) != FUN_EVENT && s->t0 + h == s->t0)
		return DBL_MIN; /* the step's start has not crossed (a mode's side is its sign there) */
	if (restep(s, h, u))
		return NAN;
	hbs_watch(s, s->cur, s->t0 + h, u, f, kind);
	val = f[s->fun_target];
	if (kind[s->fun_target] == FUN_EVENT)
		return val >= 0.0 ? fmax(val, DBL_MIN) : val;
	val *= s->fun_sign0;
	return val > 0.0 ? val : (val == 0.0 ? DBL_MIN : val);
}

/*
 * Brackets the crossing of function k in [lo, hi] (not crossed at lo,
 * crossed at hi) down to a few ulps of t.  Returns 0, with the bracket in
 * *a, *b.
 */
static int
bracket(struct sim *s, int k, int sign0, double lo, double hi, double *a, double *b)
{
	gsl_function F = { oriented, s };
	double tol = 4.0 * DBL_EPSILON * fmax(fabs(s->t0 + hi), 1e-300);
	int it = 0, rc;

	s->fun_target = k;
	s->fun_sign0 = sign0;
	if (!(oriented(lo, s) > 0) || !(oriented(hi, s) < 0))
		return GSL_FAILURE;
	if ((rc = gsl_root_fsolver_set(s->root, &F, lo, hi)) != GSL_SUCCESS)
		return rc;
	*a = lo;
	*b = hi;
	while (it++ < MAX_BRENT) {
		double xl, xu;

		if ((rc = gsl_root_fsolver_iterate(s->root)) != GSL_SUCCESS)
			return rc;
		xl = gsl_root_fsolver_x_lower(s->root);
		xu = gsl_root_fsolver_x_upper(s->root);
		if (xu - xl <= tol)
			break;
	}
	{
		double xl = gsl_root_fsolver_x_lower(s->root);
		double xu = gsl_root_fsolver_x_upper(s->root);
		double fl = oriented(xl, s), fu = oriented(xu, s);

		/* GSL keeps opposite signs at the ends; order them as (not crossed, crossed) */
		if (fl > 0 && fu < 0) {
			*a = xl;
			*b = xu;
		} else if (fu > 0 && fl < 0) {
			*a = xu;
			*b = xl;
		} else {
			return GSL_FAILURE;
		}
		if (*b < *a) /* a crossing cannot come back: take the earlier crossed point */
			return GSL_FAILURE;
	}
	return 0;
}

/* Accepts the state at h (a located point) as the current state and restarts the stepper. */
static void
accept_at(struct sim *s, double h)
{
	double u[MAXDIM];

	restep(s, h, u);
	memcpy(s->u, u, sizeof u);
	hbs_unpack(s, s->cur, s->t0 + h, u);
	gsl_odeiv2_driver_reset(s->cur->d);
}

/*
 * Round-off at a sticking contact.  When the force and the velocity both
 * decay towards zero without changing sign (a Maxwell element with c below
 * sqrt(k m)/2), the computed values eventually wander about zero at the
 * level of round-off and may both turn positive, which would be read as a
 * separation.  A state whose v and Phi are both positive but below
 * eta = 100 max(rtol, atol) of the contact's largest |v| and F_c (the noise
 * of the integration, whose components are controlled to atol of their
 * scales) is on
 * the boundary of C to the precision of the computation: its v is set to 0,
 * which keeps it in C (rule R2) and changes it by less than the tolerance.
 */
static void
snap_stick(struct sim *s, double *u)
{
	struct phase *p = s->cur;
	const struct layout *L = &p->L;
	double y[MAXDIM], eta = fmax(64 * DBL_EPSILON, 100 * fmax(s->sc.run.rtol, s->sc.run.atol)), phi, v;
	double z[LAW_MAX_Z] = { 0 };
	int i;

	hbs_unscale(p, u, y);
	v = y[L->iv];
	for (i = 0; i < s->sc.law->n_z; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, v);
	if (v > 0 && phi > 0 && v <= eta * s->vmax && phi <= eta * s->Fcmax)
		u[L->iv] = 0.0;
}

/*
 * The noise of v at a scaled state: NOISE times the tolerance the control
 * allows it (atol + rtol |u_v| of its scale).
 */
enum { NOISE = 100 };

static double
v_noise(const struct sim *s, const double *u)
{
	int iv = s->cur->L.iv;

	return NOISE * s->scale[iv] * (s->sc.run.atol + s->sc.run.rtol * fabs(u[iv]));
}

/*
 * A separation that rounding cannot fake.  Under heavy damping (SHCCL
 * with c v0 / k beyond about 35) the receding velocity creeps up to the
 * value at which Phi = 0 (k / c for SHCCL) while x_c returns to 0: Phi is
 * then zero to within the integration's noise for the whole restitution,
 * and its computed sign says nothing.  A receding state (v > 0) whose Phi
 * is positive but vanishes within the noise of v (Newton's step on Phi in
 * v, Phi / (dPhi/dv), below v_noise) is on the boundary of C to the
 * precision of the computation: its v is moved by that step (and ulps)
 * until Phi <= 0, so that it stays in C (rule R2).  The contact then ends where Phi turns positive beyond
 * the noise, which is where the exact law ends it (x_c = 0 for SHCCL).
 * Laws whose Phi does not grow with v are left alone.  Returns 1 if the
 * state was moved.
 */
static int
snap_separation(struct sim *s, double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	double y[MAXDIM], z[LAW_MAX_Z] = { 0 }, dphi[LAW_MAX_Z + 2], phi, v, vn, dv;
	int nz = sc->law->n_z, i;

	if (!p->q)
		return 0;
	hbs_unscale(p, u, y);
	v = y[L->iv];
	if (!(v > 0))
		return 0;
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, v);
	if (!(phi > 0))
		return 0;
	sc->law->jac(sc->par, sc->ext, y[L->ixc], z, v, dphi, NULL);
	dv = dphi[nz + 1];
	if (!(dv > 0) || phi > dv * v_noise(s, u))
		return 0;
	vn = v - phi / dv;
	for (i = 0; i < 8 && phi_at(s, y[L->ixc], z, vn) > 0; i++)
		vn -= ldexp(fabs(vn) * DBL_EPSILON, i);
	if (phi_at(s, y[L->ixc], z, vn) > 0)
		return 0;
	u[L->iv] = vn * s->iscale[L->iv];
	return 1;
}

/* Does the step from the scaled state u begin on Phi = 0 to the noise, receding? */
int
hbs_hugging(struct sim *s, const double *u)
{
	const struct phase *p = s->cur;
	const struct layout *L = &p->L;
	const struct scene *sc = &s->sc;
	double y[MAXDIM], z[LAW_MAX_Z] = { 0 }, dphi[LAW_MAX_Z + 2], phi;
	int nz = sc->law->n_z, i;

	if (!p->q)
		return 0;
	hbs_unscale(p, u, y);
	if (!(y[L->iv] > 0))
		return 0;
	for (i = 0; i < nz; i++)
		z[i] = y[L->iz + i];
	phi = phi_at(s, y[L->ixc], z, y[L->iv]);
	sc->law->jac(sc->par, sc->ext, y[L->ixc], z, y[L->iv], dphi, NULL);
	return dphi[nz + 1] > 0 && fabs(phi) <= dphi[nz + 1] * v_noise(s, u);
}

/* Is function i a candidate crossing from f0 to fx (with the noise filter of after_step)? */
static int
candidate(const struct sim *s, int kind, int i, double f0, double fx)
{
	/*
	 * A switching or extremum function that only wanders about zero at the
	 * level of the tolerance (|Psi_2| while a Maxwell element creeps,
	 * dPhi/dt at rest) marks no real kink or extremum.
	 */
	if (kind != FUN_EVENT && fmax(fabs(f0), fabs(fx)) <= s->sc.run.rtol * s->gmax[i])
		return 0;
	return crossed(kind, f0, fx);
}

/* dI/dt of the indicator of C at a scaled state (one-sided where I has a corner). */
static double
indicator_rate(const struct sim *s, const struct phase *p, double t, const double *u,
               const double *f, int n)
{
	const struct layout *L = &p->L;
	double y[MAXDIM], v, vdot;

	hbs_unscale(p, u, y);
	v = y[L->iv];
	if (p->q) {
		double z[LAW_MAX_Z] = { 0 }, phi;
		int i;

		for (i = 0; i < s->sc.law->n_z; i++)
			z[i] = y[L->iz + i];
		phi = phi_at(s, y[L->ixc], z, v);
		vdot = (-phi + scene_Fer(&s->sc, t)) / s->sc.d.m;
		return phi < v ? -f[n - 1] : -vdot; /* f[n - 1] = dPhi/dt */
	}
	vdot = scene_Fer(&s->sc, t) / s->sc.d.m;
	return y[L->ix] > v ? v : vdot;
}

/*
 * An event inside a step whose ends are both in C (the indicator dips
 * below zero and comes back: a separation or an impact stepped over).  The
 * cubic Hermite interpolant of the indicator from its values and rates at
 * the ends predicts where it is least; if it predicts a negative value,
 * the state there is computed.  Returns the fraction theta of the step
 * where the indicator was found negative (with the watched values there in
 * fx), or 0.
 */
static double
dip(struct sim *s, const double *f0, const double *f1, int n, double *fx)
{
	struct phase *p = s->cur;
	double H = s->H, d0, d1, c2, c3, th[2], u[MAXDIM];
	int kind[MAXFUN], nt, i;

	if (!(f0[0] >= 0.0 && f1[0] >= 0.0))
		return 0.0;
	d0 = H * indicator_rate(s, p, s->t0, s->u0, f0, n);
	d1 = H * indicator_rate(s, p, s->t0 + H, s->u1, f1, n);
	if (d0 >= 0.0 && d1 <= 0.0)
		return 0.0; /* rising then falling: no interior minimum */
	/* P(th) = f0 + d0 th + c2 th^2 + c3 th^3; its critical points solve P'(th) = 0 */
	c2 = 3.0 * (f1[0] - f0[0]) - 2.0 * d0 - d1;
	c3 = 2.0 * (f0[0] - f1[0]) + d0 + d1;
	nt = gsl_poly_solve_quadratic(3.0 * c3, 2.0 * c2, d0, &th[0], &th[1]);
	for (i = 0; i < nt; i++) {
		double t = th[i], P;

		if (!(t > 0.0 && t < 1.0))
			continue;
		P = f0[0] + t * (d0 + t * (c2 + t * c3));
		if (P >= 0.0)
			continue;
		if (restep(s, t * H, u))
			continue;
		hbs_watch(s, p, s->t0 + t * H, u, fx, kind);
		if (fx[0] < 0.0)
			return t;
	}
	return 0.0;
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
real_point(struct sim *s, int event, double hi, double *a, double *b)
{
	double w = fmax(16.0 * (*b - *a), 1e-10 * s->H), ra, rb;
	int tries;

	s->use_dense = 0;
	if (!event) {
		double u[MAXDIM], f[MAXFUN];
		int kind[MAXFUN];

		if (restep(s, *b, u) != 0)
			goto keep;
		hbs_watch(s, s->cur, s->t0 + *b, u, f, kind);
		if (!(f[0] >= 0.0))
			goto keep;
		return;
	}
	for (tries = 0; tries < 5; tries++, w *= 64.0) {
		double lo = fmax(0.0, *b - w), up = fmin(hi, *b + w);

		if (up <= *b || tries == 4) /* the last window: the whole step */
			up = hi;
		if (tries == 4)
			lo = 0.0;
		if (bracket(s, 0, 1, lo, up, &ra, &rb) == 0) {
			*a = ra;
			*b = rb;
			return;
		}
	}
keep:
	s->use_dense = 1;
}

/*
 * Handles an accepted step (t0, u0) -> (t0 + H, u1): finds the earliest
 * crossing of the watched functions, if any, and acts on it.
 */
int
hbs_after_step(struct sim *s, int load_kink)
{
	struct phase *p = s->cur;
	double f0[MAXFUN], f1[MAXFUN];
	int kind[MAXFUN], n, i, rc, any = 0;
	int cand[MAXFUN], ncand = 0;
	double lo = 0.0, hi = s->H, a = 0, b = 0;
	int first = -1;

	s->ncache = 0;
	s->cache_next = 0;
	if (p->q) {
		snap_stick(s, s->u1);
		snap_separation(s, s->u1);
		s->vmax = fmax(s->vmax, fabs(s->u1[p->L.iv] * s->scale[p->L.iv]));
	}
	n = hbs_watch(s, p, s->t0, s->u0, f0, kind);
	hbs_watch(s, p, s->t0 + s->H, s->u1, f1, kind);
	if (s->msign) {
		/*
		 * The mode's side is its frozen sign, even where the switching
		 * function is still zero to rounding on the other side (a step
		 * that begins on a located crossing): it crosses when its sign
		 * differs from the mode's.
		 */
		int k = 1 + s->sc.law->mode_kink;

		if (!(f0[k] * s->msign > 0))
			f0[k] = s->msign * DBL_MIN;
	}
	for (i = 0; i < n; i++)
		if (candidate(s, kind[i], i, f0[i], f1[i]))
			cand[ncand++] = i;
	if (ncand == 0 || cand[0] != 0) {
		/* the event stepped over: locate everything that crossed before the dip */
		double fx[MAXFUN], th = dip(s, f0, f1, n, fx);

		if (th > 0.0) {
			s->st.dips++;
			hi = th * s->H;
			for (ncand = 0, i = 0; i < n; i++)
				if (candidate(s, kind[i], i, f0[i], fx[i]))
					cand[ncand++] = i;
		}
	}
	for (i = 0; i < n; i++)
		s->gmax[i] = fmax(s->gmax[i], fmax(fabs(f0[i]), fabs(f1[i])));
	if (ncand == 0) {
		/*
		 * GSL's evolve hands the derivative at the step's end to the next
		 * step as its first stage (rk8pd, rkck, rkf45): a state moved by
		 * the snaps above needs it evaluated again.
		 */
		if (memcmp(s->u, s->u1, sizeof s->u1) != 0)
			gsl_odeiv2_evolve_reset(p->d->e);
		memcpy(s->u, s->u1, sizeof s->u1);
		hbs_unpack(s, p, s->t0 + s->H, s->u1);
		if (load_kink) {
			gsl_odeiv2_driver_reset(p->d);
			s->st.kinks++;
		}
		return hbs_push_sample(s, load_kink ? ARC_KINK : ARC_STEP);
	}
	/* the earliest crossing: bracket one, then look for earlier ones before it */
	s->loc_iter = 0;
	s->st.located++;
	while (ncand > 0) {
		int k = cand[0], nb = 0;
		double fa[MAXFUN];
		int kk[MAXFUN], sign0 = f0[k] > 0 ? 1 : -1;
		double ua[MAXDIM];

		if ((rc = bracket(s, k, sign0, lo, hi, &a, &b)) != 0) {
			if (rc == GSL_FAILURE && first >= 0)
				break;
			return hbs_fail(s, HB_ENUMERIC, "event location failed (no bracket)");
		}
		first = k;
		hi = b;
		/*
		 * Which functions have already crossed at a?  Any of them, not only
		 * the candidates: one that crossed and came back within the step
		 * (the indicator, most of all) is found here.
		 */
		restep(s, a, ua);
		hbs_watch(s, p, s->t0 + a, ua, fa, kk);
		for (i = 0; i < n; i++)
			if (i != k && candidate(s, kind[i], i, f0[i], fa[i]))
				cand[nb++] = i;
		if (nb == 0)
			break;
		ncand = nb;
		hi = a;
	}
	/* everything that has crossed at b happens here; the event wins */
	{
		double ub[MAXDIM], fb[MAXFUN], ua[MAXDIM], fa[MAXFUN];
		int kb[MAXFUN], event = 0, kink = 0;

		restep(s, b, ub);
		hbs_watch(s, p, s->t0 + b, ub, fb, kb);
		for (i = 0; i < n; i++)
			if (crossed(kind[i], f0[i], fb[i])) {
				any = 1;
				if (kind[i] == FUN_EVENT)
					event = 1;
				else if (kind[i] == FUN_KINK)
					kink = 1;
			}
		if (!any)
			return hbs_fail(s, HB_ENUMERIC, "event location lost its bracket");
		if (s->use_dense)
			real_point(s, event, hi, &a, &b);
		restep(s, a, ua);
		hbs_watch(s, p, s->t0 + a, ua, fa, kb);
		accept_at(s, b);
		if (event)
			return hbs_jump(s, LOCATE_BRENT, s->loc_iter, b - a, fa[0], fb[0]);
		if (s->msign && crossed(FUN_KINK, f0[1 + s->sc.law->mode_kink],
		                        fb[1 + s->sc.law->mode_kink])) {
			/* the mode's switching function crossed: the next step is on the other side */
			s->mforce = -s->msign;
			s->mforce_t = s->t;
		}
		s->st.kinks += kink;
		return hbs_push_sample(s, kink ? ARC_KINK : ARC_EXTREMUM);
	}
}
