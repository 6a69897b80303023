/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * ref.c - an independent high-precision reference for the paper's studies,
 * written from the paper alone (Model: eqs. main, Hr_f .. Hr_init and the
 * relative motion of H_f, the laws BWMCL, SHCCL and BWSHCCL; Simulation:
 * tables 1 to 3, the ramp loads of eqs. ramp .. u_2, the observables
 * t_d .. Lambda and rules R1, R2) and sharing no code with the engine.
 *
 * Arithmetic: IEEE binary128 (__float128, libquadmath).  Method: Gragg-
 * Bulirsch-Stoer extrapolation of the modified midpoint rule (K columns,
 * order 2K), with a step size control on the difference of the last two
 * columns.  Every non-smooth point of the flow (the zeros of x_c, z_c,
 * Psi_2 and v that a law's |.| and |.|^p terms switch at) is a mode: within
 * a step every switching term keeps the sign it had at the step's start,
 * and a step never straddles a zero, which is located to full precision by
 * bracketing on the length of a step from the step's start.  The events
 * (a separation, where the state leaves C by rule R2) and the extrema of
 * x_c and F_c are located the same way.  Flights under constant gravity are
 * parabolas, solved in closed form; under the ramp of study 2 (whose S''
 * jumps at T_e, a switching point in time) they are integrated as the
 * contacts are, to the state leaving C (x < 0 and v < 0).  Study 2 is the
 * relative motion (x, v) of H_f under its reduced load
 * F_e,r = -F_e0 (1 + S(t / T_e)); the centre of mass, which no observable
 * needs, is left out.
 *
 *     hybounce-ref STUDY [--tol TOL] [--collisions N]
 *
 * writes the completed collisions of STUDY as CSV (the columns of
 * hybounce's --collisions) with 25 significant digits.  TOL (default 1e-28)
 * is the local tolerance of a step, relative to each component's size; the
 * run's own error is shown by two tolerances agreeing (tests/reference/
 * README.md).  --collisions N stops after N completed collisions (and the
 * flight that follows the last one).
 */
#include <quadmath.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef __float128 Q;

enum law { BWMCL, SHCCL, BWSHCCL };

struct study {
	const char *name;  /* the preset's name */
	enum law law;
	/* materials and geometry (tables 1 to 3); rho2 = 0: body 2 fixed, R2 = inf */
	double E1, nu1, rho1, R1, E2, nu2, rho2, R2;
	/* chosen */
	double A, alpha, beta, gamma, n, c;
	/* initial conditions, load (g; or the ramp F_e0, T_e of eq. u_1), horizon */
	double x0, g, Fe0, Te, T;
};

/* The paper's studies (tables 1 to 3): H_r, and H_f's relative motion for study 2. */
static const struct study studies[] = {
	{ "steel-on-bitumen", BWMCL, 200e9, 0.30, 7800, 20e-3, 1.0e9, 0.35, 0, 0,
	  1, 0.35, 5.000e7, 5.000e7, 2, 4.400e3, 20e-3, 9.81, 0, 0, 0.5 },
	{ "ptfe-pom", BWSHCCL, 0.50e9, 0.46, 2200, 20e-3, 2.90e9, 0.35, 1410, 20e-3,
	  1, 0.35, 2.409e8, 2.409e8, 2, 2.500e7, 1.5e-3, 0, 0.5759, 0.20, 0.5 },
	{ "permanent-contact-shccl", SHCCL, 200e9, 0.30, 7800, 20e-3, 2.0e9, 0.35, 0, 0,
	  1, 1, 0, 0, 2, 4.300e9, 40e-6, 9.81, 0, 0, 0.1 },
	{ "permanent-contact-bwshccl", BWSHCCL, 200e9, 0.30, 7800, 20e-3, 2.0e9, 0.35, 0, 0,
	  1, 0.35, 5.000e9, 5.000e9, 2, 2.150e9, 40e-6, 9.81, 0, 0, 0.1 },
	{ "permanent-contact-bwmcl", BWMCL, 200e9, 0.30, 7800, 20e-3, 1.0e9, 0.35, 0, 0,
	  1, 0.35, 5.000e7, 5.000e7, 2, 4.400e3, 40e-6, 9.81, 0, 0, 0.1 },
};

/* The scene in binary128. */
static enum law LAW;
static Q K, ALPHA, AA, BETA, GAMMA, NN, P, CC, M, G;
static int RAMP;      /* study 2: F_e,r = -F_e0 (1 + S(t / T_e)), eq. u_1 */
static Q FE0, TE;
enum { FLIGHT, CONTACT };
static int PHASE;

/* State in contact: x_c, v, W, J_Fc, then z_c (n_z components). */
/* In flight the first component is x (and the law's are unused). */
enum { XC, V, W, JFC, Z1, Z2, TT, JFE, NMAX };
static int NY;

/* Switching terms (modes): their signs within a step. */
enum { S_XC, S_Z1, S_Z2, S_PSI, S_V, S_T, NS };
static int mode[NS];

/* F_e,r at t: -m g, or the ramp with the branch of S that mode[S_T] holds
 * (S is continuously differentiable; its second derivative jumps at T_e). */
static Q
fer(Q t)
{
	if (!RAMP)
		return -M * G;
	if (mode[S_T] < 0)
		return -FE0 * (1 + (1 - cosq(M_PIq * t / TE)) / 2);
	return -2 * FE0;
}

static Q
pw(Q u, Q p) /* u^p, u >= 0 */
{
	if (p == 1.5Q)
		return u * sqrtq(u);
	if (p == 2)
		return u * u;
	if (p == 1)
		return u;
	if (p == 0.5Q)
		return sqrtq(u);
	return powq(u, p);
}

/* u |u|^(p-1), odd in u */
static Q
sp(Q u, Q p)
{
	return u >= 0 ? pw(u, p) : -pw(-u, p);
}

/* |u|^p in the mode s (= s u |u|^(p-1); equals |u|^p while sign(u) = s) */
static Q
ap(Q u, Q p, int s)
{
	return s * sp(u, p);
}

/* Phi and the rates; d[] may be NULL.  dphi: dPhi/dt (may be NULL). */
static Q
law_eval(const Q *y, Q *d, Q *dphi)
{
	Q phi, psi2 = 0, psi1 = 0, x = y[XC], v = y[V];

	switch (LAW) {
	case BWMCL: {
		Q z1 = y[Z1], z2 = y[Z2];

		phi = ALPHA * K * sp(z2, P) + (1 - ALPHA) * K * sp(z1, P);
		psi2 = v - phi / CC;
		psi1 = AA * psi2 - BETA * sp(z1, NN) * (mode[S_PSI] * psi2) -
		       GAMMA * ap(z1, NN, mode[S_Z1]) * psi2;
		if (d != NULL) {
			d[Z1] = psi1;
			d[Z2] = psi2;
		}
		if (dphi != NULL)
			*dphi = P * K * (ALPHA * pw(fabsq(z2), P - 1) * psi2 +
			                 (1 - ALPHA) * pw(fabsq(z1), P - 1) * psi1);
		break;
	}
	case SHCCL:
		phi = K * sp(x, P) + CC * ap(x, P, mode[S_XC]) * v;
		if (dphi != NULL) {
			Q a = (-phi + fer(y[TT])) / M;

			*dphi = K * P * pw(fabsq(x), P - 1) * v +
			        CC * (mode[S_XC] * P * pw(fabsq(x), P - 1) * v * v +
			              ap(x, P, mode[S_XC]) * a);
		}
		break;
	case BWSHCCL: {
		Q z = y[Z1], a;

		phi = ALPHA * K * sp(x, P) + (1 - ALPHA) * K * sp(z, P) +
		      CC * ap(x, P, mode[S_XC]) * v;
		psi1 = AA * v - BETA * sp(z, NN) * (mode[S_V] * v) - GAMMA * ap(z, NN, mode[S_Z1]) * v;
		if (d != NULL)
			d[Z1] = psi1;
		a = (-phi + fer(y[TT])) / M;
		if (dphi != NULL)
			*dphi = ALPHA * K * P * pw(fabsq(x), P - 1) * v +
			        (1 - ALPHA) * K * P * pw(fabsq(z), P - 1) * psi1 +
			        CC * (mode[S_XC] * P * pw(fabsq(x), P - 1) * v * v +
			              ap(x, P, mode[S_XC]) * a);
		break;
	}
	default:
		phi = 0;
	}
	(void)psi1;
	return phi;
}

/* The contact flow (eq. Hr_f with q_c = 1) and the quadratures W, J_Fc. */
static void
rhs(const Q *y, Q *d)
{
	Q phi, f = fer(y[TT]);

	memset(d, 0, NMAX * sizeof *d);
	d[TT] = 1;
	d[XC] = y[V];
	if (PHASE == FLIGHT) {   /* q_c = 0: the interface frozen */
		d[V] = f / M;
		return;
	}
	phi = law_eval(y, d, NULL);
	d[V] = (-phi + f) / M;
	d[W] = phi * y[V];       /* W = -int F_c v dt, F_c = -Phi */
	d[JFC] = -phi;           /* J_Fc = int F_c dt */
	d[JFE] = f;              /* J_Fe = int F_e,r dt */
}

/* ------------------------------------------------------------------ */
/* Gragg-Bulirsch-Stoer                                                */

enum { KCOL = 10 };
static Q tol = 1e-28Q;
static long nrhs, nsteps, nrej;
static Q ymax[NMAX]; /* the largest |y_i| so far in the contact */

/* One extrapolated step of length h from y; out = the result, err = the
 * scaled error estimate (0 when not wanted). */
static void
gbs(const Q *y, Q h, Q *out, Q *err)
{
	Q T[KCOL][NMAX], z0[NMAX], z1[NMAX], z2[NMAX], f[NMAX];
	int j, k, i, s;

	for (j = 0; j < KCOL; j++) {
		int n = 2 * (j + 1);
		Q hs = h / n;

		rhs(y, f);
		nrhs++;
		for (i = 0; i < NY; i++) {
			z0[i] = y[i];
			z1[i] = y[i] + hs * f[i];
		}
		for (s = 1; s < n; s++) {
			rhs(z1, f);
			nrhs++;
			for (i = 0; i < NY; i++) {
				z2[i] = z0[i] + 2 * hs * f[i];
				z0[i] = z1[i];
				z1[i] = z2[i];
			}
		}
		for (i = 0; i < NY; i++)
			T[j][i] = z1[i];
	}
	/* Neville tableau done column by column over the stored first column. */
	{
		Q tab[KCOL][NMAX];

		for (j = 0; j < KCOL; j++)
			for (i = 0; i < NY; i++)
				tab[j][i] = T[j][i];
		/* tab[j] holds T_{j,k} after pass k */
		for (k = 1; k < KCOL; k++) {
			for (j = KCOL - 1; j >= k; j--) {
				Q r = (Q)(j + 1) / (Q)(j - k + 1), den = r * r - 1;

				for (i = 0; i < NY; i++)
					tab[j][i] = tab[j][i] + (tab[j][i] - tab[j - 1][i]) / den;
			}
			if (k == KCOL - 2 && err != NULL) {
				/* T_{K-1,K-2}: the estimate compares it with T_{K,K-1} */
				for (i = 0; i < NY; i++)
					z0[i] = tab[KCOL - 2][i];
			}
		}
		for (i = 0; i < NY; i++)
			out[i] = tab[KCOL - 1][i];
		if (err != NULL) {
			Q e = 0;

			for (i = 0; i < NY; i++) {
				Q sc = fabsq(y[i]) > fabsq(out[i]) ? fabsq(y[i]) : fabsq(out[i]);
				Q d = fabsq(out[i] - z0[i]);

				/* relative to the component's size in this contact */
				if (sc < 1e-3Q * ymax[i])
					sc = 1e-3Q * ymax[i];
				if (sc < 1e-300Q)
					sc = 1e-300Q;
				if (d / sc > e)
					e = d / sc;
			}
			*err = e / tol;
		}
	}
}

/* ------------------------------------------------------------------ */
/* Events: the switching terms, the separation, the extrema            */

/* The switching function of mode k at y (0 where the law has none). */
static Q
switching(int k, const Q *y)
{
	if (PHASE == FLIGHT && k != S_T)
		return 0;
	switch (k) {
	case S_XC:
		return LAW == SHCCL || LAW == BWSHCCL ? y[XC] : 0;
	case S_Z1:
		return LAW == BWMCL || LAW == BWSHCCL ? y[Z1] : 0;
	case S_Z2:
		return LAW == BWMCL ? y[Z2] : 0;
	case S_PSI:
		if (LAW == BWMCL) {
			Q d[NMAX];

			law_eval(y, d, NULL);
			return d[Z2];
		}
		return 0;
	case S_V:
		return LAW == BWSHCCL ? y[V] : 0;
	case S_T:
		return RAMP ? y[TT] - TE : 0;
	}
	return 0;
}

static int
has_switch(int k)
{
	if (PHASE == FLIGHT && k != S_T)
		return 0;
	switch (k) {
	case S_XC: return LAW == SHCCL || LAW == BWSHCCL;
	case S_Z1: return LAW == BWMCL || LAW == BWSHCCL;
	case S_Z2: return LAW == BWMCL;
	case S_PSI: return LAW == BWMCL;
	case S_V: return LAW == BWSHCCL;
	case S_T: return RAMP;
	}
	return 0;
}

/* Leaving C (q_c = 1): Phi > 0 and v > 0 (eq. H_C); rule R2. */
static Q
separation(const Q *y)
{
	Q phi;

	if (PHASE == FLIGHT) /* leaving C with q_c = 0: x < 0 and v < 0 (eq. H_C) */
		return -(y[XC] > y[V] ? y[XC] : y[V]);
	phi = law_eval(y, NULL, NULL);

	return phi < y[V] ? phi : y[V];
}

enum { EV_SWITCH0 = 0, EV_SEP = NS, EV_XMAX, EV_FMAX, NEV };

static Q
event_fn(int ev, const Q *y)
{
	Q dphi;

	if (ev < NS)
		return switching(ev, y);
	if (ev == EV_SEP)
		return separation(y);
	if (ev == EV_XMAX)
		return y[V];
	law_eval(y, NULL, &dphi);
	return dphi;
}

/* Does event ev happen between a (value at the step's start) and b? */
static int
crossed(int ev, Q a, Q b)
{
	if (ev < NS)
		return has_switch(ev) && b * mode[ev] < 0;
	if (ev == EV_SEP)
		return a <= 0 && b > 0;
	if (PHASE == FLIGHT)
		return 0;
	return (a < 0 && b >= 0) || (a > 0 && b <= 0);
}

/*
 * The zero of event ev in (0, h] from y: bracketed (Illinois, with a
 * bisection every third iteration) until the bracket is a few ulps of
 * t0 + h.  *lo and *hi: the bracket; yhi the state at *hi (far side).
 */
static void
locate(int ev, const Q *y, Q t0, Q h, Q ga, Q *lo, Q *hi, Q *yhi)
{
	Q a = 0, b = h, fa = ga, fb, ym[NMAX];
	int it, side = 0;

	gbs(y, b, yhi, NULL);
	fb = event_fn(ev, yhi);
	if (ev == EV_SEP) { /* sign convention: <= 0 before, > 0 after */
		if (fa > 0)
			fa = 0;
	}
	for (it = 0; it < 400; it++) {
		Q m, fm;

		if (b - a <= 8 * FLT128_EPSILON * (fabsq(t0) + b))
			break;
		if (it % 3 == 2 || fa == fb)
			m = (a + b) / 2;
		else {
			m = a - fa * (b - a) / (fb - fa);
			if (!(m > a && m < b))
				m = (a + b) / 2;
		}
		gbs(y, m, ym, NULL);
		fm = event_fn(ev, ym);
		if (ev == EV_SEP ? fm > 0 : (fm > 0) == (fb > 0) && fm != 0) {
			b = m;
			fb = fm;
			memcpy(yhi, ym, sizeof ym);
			if (side == 1)
				fa /= 2;
			side = 1;
		} else {
			a = m;
			fa = fm;
			if (side == -1)
				fb /= 2;
			side = -1;
		}
	}
	*lo = a;
	*hi = b;
}

/* ------------------------------------------------------------------ */
/* One contact                                                         */

struct contact {
	Q te, ts, vi, vs, xcs, xcr, xcmax, Fcmax, W, JFc, JFe;
	int complete;
};

static void
set_modes(const Q *y, const Q *dy)
{
	for (int k = 0; k < NS; k++) {
		Q g = switching(k, y);

		if (g == 0) /* at the start: the direction of motion */
			g = k == S_XC ? dy[XC] : k == S_Z1 ? dy[Z1] : k == S_Z2 ? dy[Z2]
			  : k == S_V ? dy[V] : k == S_T ? 1 : -1;
		mode[k] = g > 0 ? 1 : -1;
	}
}

static void
candidate(struct contact *c, const Q *y)
{
	Q F;

	if (PHASE == FLIGHT)
		return;
	F = -law_eval(y, NULL, NULL);

	if (fabsq(y[XC]) > c->xcmax)
		c->xcmax = fabsq(y[XC]);
	if (F > c->Fcmax)
		c->Fcmax = F;
}

/*
 * Integrates the phase (FLIGHT: q_c = 0, CONTACT: q_c = 1) from (*tp, y)
 * to the event that ends it (the state leaving C, rule R2) or to T; y and
 * *tp are then the state and time there.  Returns 1 at the event, 0 at T.
 * In contact the extrema go to c.
 */
static int
run_phase(int phase, Q *tp, Q *y, Q T, struct contact *c)
{
	Q dy[NMAX], y1[NMAX], t = *tp, h = 1e-12Q, err;
	/* the accelerations the error scales start from */
	const Q acc = RAMP ? FE0 / M : G;

	PHASE = phase;
	/* the modes: the signs of the switching terms, or the direction of motion at 0 */
	{
		Q yy[NMAX];

		memcpy(yy, y, sizeof yy);
		if (yy[V] == 0)
			yy[V] = -1e-30Q;
		for (int k = 0; k < NS; k++)
			mode[k] = -1;
		mode[S_T] = y[TT] < TE ? -1 : 1;
		rhs(yy, dy);
		dy[XC] = yy[V];
		set_modes(y, dy);
	}
	candidate(c, y);
	{
		/* the sizes the error is measured against at the start, where
		 * x_c, z_c, W, J_Fc and J_Fe are 0: those of a contact of 0.1 ms */
		Q vs = fabsq(y[V]) > acc * 1e-4Q ? fabsq(y[V]) : acc * 1e-4Q;

		for (int i = 0; i < NMAX; i++)
			ymax[i] = fabsq(y[i]);
		if (ymax[XC] < vs * 1e-4Q)
			ymax[XC] = vs * 1e-4Q;
		ymax[Z1] = ymax[Z2] = vs * 1e-4Q;
		ymax[V] = vs;
		ymax[W] = M * vs * vs;
		ymax[JFC] = ymax[JFE] = M * vs;
		if (ymax[TT] < 1e-3Q)
			ymax[TT] = 1e-3Q;
	}
	for (;;) {
		Q g0[NEV], g1[NEV], hmin, lo, hi, yb[NMAX], yfar[NMAX];
		int ev, first = -1;

		if (t + h > T)
			h = T - t;
		gbs(y, h, y1, &err);
		if (!(err <= 1)) {
			Q f = err != err ? 0.1Q : 0.9Q * powq(1 / err, 1.0Q / (2 * KCOL - 1));

			h *= f < 0.1Q ? 0.1Q : f;
			nrej++;
			if (h < 1e-40Q) {
				fprintf(stderr, "hybounce-ref: step size underflow at t = %.6e\n",
				        (double)t);
				exit(1);
			}
			continue;
		}
		nsteps++;
		/* events within the step */
		for (ev = 0; ev < NEV; ev++) {
			g0[ev] = event_fn(ev, y);
			g1[ev] = event_fn(ev, y1);
		}
		hmin = h;
		for (ev = 0; ev <= EV_SEP; ev++) {
			if (!crossed(ev, g0[ev], g1[ev]))
				continue;
			locate(ev, y, t, h, g0[ev], &lo, &hi, yb);
			if (first < 0 || hi < hmin || (hi == hmin && ev == EV_SEP)) {
				first = ev;
				hmin = hi;
				memcpy(yfar, yb, sizeof yb);
			}
		}
		/* the extrema within [0, hmin] */
		for (ev = EV_XMAX; ev < NEV; ev++) {
			Q ge;

			if (first >= 0) {
				ge = event_fn(ev, yfar);
				if (!crossed(ev, g0[ev], ge))
					continue;
				locate(ev, y, t, hmin, g0[ev], &lo, &hi, yb);
			} else {
				if (!crossed(ev, g0[ev], g1[ev]))
					continue;
				locate(ev, y, t, h, g0[ev], &lo, &hi, yb);
			}
			{
				Q ym[NMAX];

				gbs(y, (lo + hi) / 2, ym, NULL);
				candidate(c, ym);
			}
		}
		if (first >= 0) {
			memcpy(y, yfar, sizeof yfar);
			t += hmin;
			candidate(c, y);
			/* a switch that the separation coincides with: R2 jumps there */
			if (first != EV_SEP && separation(y) > 0)
				first = EV_SEP;
			if (first == EV_SEP) {
				*tp = t;
				return 1;
			}
			/* a switching term changed sign: its new mode */
			mode[first] = -mode[first];
			/* restart small: the flow is not smooth at the switch */
			h = hmin * 1e-6Q > 1e-13Q ? 1e-13Q : hmin * 1e-6Q;
			if (h < 1e-20Q)
				h = 1e-20Q;
			continue;
		}
		memcpy(y, y1, sizeof y1);
		t += h;
		candidate(c, y);
		for (int i = 0; i < NY; i++)
			if (fabsq(y[i]) > ymax[i])
				ymax[i] = fabsq(y[i]);
		if (t >= T) {
			*tp = t;
			return 0;
		}
		{
			Q f = 0.9Q * powq(1 / (err > 1e-30Q ? err : 1e-30Q), 1.0Q / (2 * KCOL - 1));

			h *= f > 4 ? 4 : f;
		}
	}
}

/* A contact from t_e with approach velocity vi: 1 when it separated before T. */
static int
contact(Q te, Q vi, Q T, struct contact *c)
{
	Q y[NMAX] = { 0 }, t = te;

	memset(c, 0, sizeof *c);
	c->te = te;
	c->vi = vi;
	y[V] = vi;
	y[TT] = te;
	if (!run_phase(CONTACT, &t, y, T, c))
		return 0;
	c->ts = t;
	c->vs = y[V];
	c->xcs = y[XC];
	c->xcr = fabsq(y[XC]);
	c->W = y[W];
	c->JFc = y[JFC];
	c->JFe = y[JFE];
	c->complete = 1;
	return 1;
}

/* A flight from (*t, *x, *v) to the next contact's commencement: 1 before T. */
static int
flight(Q *t, Q *x, Q *v, Q T)
{
	Q y[NMAX] = { 0 };

	y[XC] = *x;
	y[V] = *v;
	y[TT] = *t;
	if (!run_phase(FLIGHT, t, y, T, NULL))
		return 0;
	*x = y[XC];
	*v = y[V];
	return 1;
}

/* ------------------------------------------------------------------ */

static void
qprint(Q v)
{
	char b[64];

	quadmath_snprintf(b, sizeof b, "%.24Qe", v);
	fputs(b, stdout);
}

int
main(int argc, char **argv)
{
	const struct study *st = NULL;
	long maxcoll = -1;
	Q Estar, Re, kH, t, x, v, T;
	long i = 0;
	int a;

	for (a = 1; a < argc; a++) {
		if (strcmp(argv[a], "--tol") == 0 && a + 1 < argc)
			tol = strtoflt128(argv[++a], NULL);
		else if (strcmp(argv[a], "--collisions") == 0 && a + 1 < argc)
			maxcoll = atol(argv[++a]);
		else if (st == NULL) {
			for (size_t k = 0; k < sizeof studies / sizeof studies[0]; k++)
				if (strcmp(argv[a], studies[k].name) == 0)
					st = &studies[k];
			if (st == NULL) {
				fprintf(stderr, "hybounce-ref: unknown study '%s'; accepted:", argv[a]);
				for (size_t k = 0; k < sizeof studies / sizeof studies[0]; k++)
					fprintf(stderr, " %s", studies[k].name);
				fprintf(stderr, "\n");
				return 2;
			}
		} else {
			fprintf(stderr, "usage: hybounce-ref STUDY [--tol TOL] [--collisions N]\n");
			return 2;
		}
	}
	if (st == NULL || !(tol > 0)) {
		fprintf(stderr, "usage: hybounce-ref STUDY [--tol TOL] [--collisions N]\n");
		return 2;
	}

	/* Derived (study 1, eqs. E*, R_e, m_i, m, k_H, k); rho2 = 0: body 2
	 * fixed (R_2 = inf, m = m_1). */
	LAW = st->law;
	Estar = 1 / ((1 - (Q)st->nu1 * st->nu1) / st->E1 + (1 - (Q)st->nu2 * st->nu2) / st->E2);
	if (st->rho2 > 0) {
		Q m1 = 4 * M_PIq / 3 * (Q)st->R1 * st->R1 * st->R1 * st->rho1;
		Q m2 = 4 * M_PIq / 3 * (Q)st->R2 * st->R2 * st->R2 * st->rho2;

		Re = 1 / (1 / (Q)st->R1 + 1 / (Q)st->R2);
		M = m1 * m2 / (m1 + m2);
	} else {
		Re = st->R1;
		M = 4 * M_PIq / 3 * (Q)st->R1 * st->R1 * st->R1 * st->rho1;
	}
	P = 1.5Q;
	kH = 4 * Estar * sqrtq(Re) / 3;
	AA = st->A;
	ALPHA = st->alpha;
	BETA = st->beta;
	GAMMA = st->gamma;
	NN = st->n;
	CC = st->c;
	G = st->g;
	K = LAW == SHCCL ? kH : kH / (ALPHA + (1 - ALPHA) * pw(AA, P));
	NY = NMAX;
	T = st->T;
	RAMP = st->Fe0 > 0;
	FE0 = st->Fe0;
	TE = RAMP ? st->Te : 0;

	printf("# hybounce-ref %s --tol %g: collisions to 25 digits (binary128, GBS order %d)\n",
	       st->name, (double)tol, 2 * KCOL);
	printf("i,t_e,t_s,t_d,t_f,v_i,e,x_c_max,F_c_max,x_c_r,W,J_Fc,J_Fe,Lambda\n");

	/* The first flight: from rest at x0, under gravity in closed form, or
	 * under the ramp integrated. */
	x = st->x0;
	v = 0;
	t = 0;
	if (RAMP) {
		if (!flight(&t, &x, &v, T))
			t = T;
	} else {
		t = sqrtq(2 * x / G);
		v = -G * t;
		x = 0;
	}
	while (t < T) {
		struct contact c;
		Q xe = x, ts, xs, vs, tv, te2;

		if (!contact(t, v, T, &c))
			break;
		ts = c.ts;
		vs = c.vs;
		xs = xe + c.xcs; /* x = x(t_e) + x_c */
		/* the flight (q_c = 0) until x <= 0 and v <= 0 (eq. H_D), rule R2 */
		tv = RAMP ? 0 : vs / G;
		if (RAMP) {
			te2 = ts;
			x = xs;
			v = vs;
			if (!flight(&te2, &x, &v, T))
				te2 = T;
		} else if (xs + vs * tv - G * tv * tv / 2 <= 0) {
			te2 = ts + tv;
			x = xs + vs * tv - G * tv * tv / 2;
			v = 0;
		} else {
			Q tau = (vs + sqrtq(vs * vs + 2 * G * xs)) / G;

			te2 = ts + tau;
			x = 0;
			v = vs - G * tau;
		}
		printf("%ld,", i);
		qprint(c.te); putchar(',');
		qprint(ts); putchar(',');
		qprint(ts - c.te); putchar(',');
		if (te2 < T)
			qprint(te2 - ts);
		else
			fputs("nan", stdout);
		putchar(',');
		qprint(c.vi); putchar(',');
		qprint(-vs / c.vi); putchar(',');
		qprint(c.xcmax); putchar(',');
		qprint(c.Fcmax); putchar(',');
		qprint(c.xcr); putchar(',');
		qprint(c.W); putchar(',');
		qprint(c.JFc); putchar(',');
		qprint(c.JFe); putchar(',');
		qprint(c.JFe / c.JFc); putchar('\n');
		fflush(stdout);
		i++;
		if (maxcoll >= 0 && i >= maxcoll)
			break;
		t = te2;
	}
	fprintf(stderr, "hybounce-ref: %ld collisions, %ld steps, %ld rejected, %ld rhs\n", i,
	        nsteps, nrej, nrhs);
	return 0;
}
