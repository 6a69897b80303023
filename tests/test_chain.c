/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_chain.c - chains of bodies (docs/chains.md): Newton's cradle of
 * three equal elastic balls conserves energy and momentum, apart or
 * touching (several contacts at once); a long touching chain carries
 * Nesterenko's solitary wave; a chain of two bodies and a chain of one on
 * the floor are the full and the reduced system, and the scenes this
 * version cannot run are refused by name.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/check.h"
#include "hybounce/status.h"
#include "solitary.h"
#include "testutil.h"

/* Steel balls (R 10 mm) with the Hertz elastic law, in a chain (CHAIN: the [chain] lines). */
static void
chain_scene(struct hb_scene *sc, const char *chain, double v, double g, double T)
{
	steel_chain(sc, "hertz", "", chain, v, g, T);
}

static void
energy_momentum(const struct hb_sim *s, double *K, double *P)
{
	struct hb_sim_body b;

	*K = *P = 0.0;
	for (int i = 0; i < hb_sim_nbodies(s); i++) {
		cr_assert_eq(hb_sim_body(s, i, &b), HB_OK);
		*K += 0.5 * b.m * b.u * b.u;
		*P += b.m * b.u;
	}
}

/*
 * Three equal balls 1 mm apart, the top one struck at 1 m/s: two binary
 * elastic collisions of equal masses, each exchanging the velocities.
 * Kinetic energy and momentum at the end equal the striker's to 1e-10,
 * and the bottom ball leaves with its velocity.
 */
Test(chain, cradle_of_three_conserves_energy_and_momentum)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct hb_sim_body b;
	double v = -1.0, K, P, m;

	chain_scene(&sc, "n = 3\nspacing = 1 mm", v, 0.0, 0.01);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_nbodies(s), 3);
	cr_assert_eq(hb_sim_ncollisions(s), 2, "two collisions, one per interface");
	cr_assert_eq(hb_sim_body(s, 3, &b), HB_EINVAL);
	hb_sim_body(s, 0, &b);
	m = b.m;
	energy_momentum(s, &K, &P);
	assert_rel(K, 0.5 * m * v * v, 1e-10);
	assert_rel(P, m * v, 1e-10);
	assert_rel(b.u, v, 1e-10);
	for (int i = 1; i < 3; i++) {
		hb_sim_body(s, i, &b);
		assert_abs(b.u, 0.0, 1e-10);
	}
	for (size_t i = 0; i < 2; i++)
		assert_rel(hb_sim_collision(s, i)->e, 1.0, 1e-10);
	/* the balls are in order and apart at the end */
	for (int i = 0; i + 1 < 3; i++) {
		struct hb_sim_body lo, hi;

		hb_sim_body(s, i, &lo);
		hb_sim_body(s, i + 1, &hi);
		assert_rel(lo.R, 0.01, 1e-15); /* R = 10 mm: the half-length the engine binds */
		assert_rel(hi.R, 0.01, 1e-15);
		cr_assert_gt((hi.y - hi.R) - (lo.y + lo.R), 0.0, "bodies %d and %d overlap at the end",
		             i + 1, i + 2);
	}
	hb_sim_free(s);
}

/*
 * Touching cradles of 3 and 5 equal Hertz balls, the top one struck at
 * 1 m/s: the contacts overlap in time (clusters of several contacts), so
 * the impulse is not passed on as by rigid collisions (Hinch and
 * Saint-Jean 1999): the bottom ball leaves with most but not all of the
 * striker's velocity, the striker recoils a little, and every ball moves
 * at the end.  Energy and momentum are conserved to 1e-10 relative, the
 * balls are in order and apart at the end, and every collision names its
 * interface (1 .. n - 1).
 */
static void
touching_cradle(int n)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct hb_sim_body b, top;
	double v = -1.0, K, P, m;
	char chain[64];
	int seen[8] = { 0 };

	snprintf(chain, sizeof chain, "n = %d\nspacing = 0 m", n);
	chain_scene(&sc, chain, v, 0.0, 0.01);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_end(s), HB_SIM_END_T, "%s", hb_sim_end_str(s));
	hb_sim_body(s, 0, &b);
	m = b.m;
	energy_momentum(s, &K, &P);
	assert_rel(K, 0.5 * m * v * v, 1e-10);
	assert_rel(P, m * v, 1e-10);
	cr_assert(b.u < 0.97 * v && b.u > v * (1 - 1e-3),
	          "cradle of %d: the bottom ball leaves at %.9g m/s: not most but not all of %g", n, b.u, v);
	hb_sim_body(s, n - 1, &top);
	cr_assert(top.u > 1e-3 && top.u < 0.2, "cradle of %d: the striker recoils at %.9g m/s", n, top.u);
	for (int i = 0; i + 1 < n; i++) {
		struct hb_sim_body lo, hi;

		hb_sim_body(s, i, &lo);
		hb_sim_body(s, i + 1, &hi);
		cr_assert_gt(hi.y - lo.y, 0.02, "bodies %d and %d overlap at the end", i + 1, i + 2);
		cr_assert_gt(hi.u, lo.u, "bodies %d and %d still approach at the end", i + 1, i + 2);
	}
	cr_assert_geq(hb_sim_ncollisions(s), (size_t)(n - 1));
	for (size_t i = 0; i < hb_sim_ncollisions(s); i++) {
		int k = hb_sim_collision(s, i)->k;

		cr_assert(k >= 1 && k <= n - 1, "collision %zu names interface %d", i, k);
		seen[k] = 1;
	}
	for (int k = 1; k < n; k++)
		cr_assert(seen[k], "cradle of %d: interface %d has no collision", n, k);
	hb_sim_free(s);
}

Test(chain, touching_cradle_of_three)
{
	touching_cradle(3);
}

Test(chain, touching_cradle_of_five)
{
	touching_cradle(5);
}

/*
 * A touching cradle of 5 with a dissipative law whose flow has kinks
 * (BWMCL: modes per interface, kinks located): momentum is conserved to
 * 1e-10, kinetic energy is lost, the kinks are located, no two
 * neighbours still approach at the end, and the solution pair holds on
 * the arc.
 */
Test(chain, dissipative_touching_cradle_keeps_momentum)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct hb_sim_body b;
	double v = -1.0, K, P, m;
	char ini[1024], msg[512];

	snprintf(ini, sizeof ini,
	         "[scene]\nname = chain\nlaw = bwmcl\n"
	         "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	         "[chain]\nn = 5\nspacing = 0 m\n[striker]\nv = -1\n[loads]\ng = 0\n"
	         "[run]\nT = 0.01\nrtol = 1e-12\natol = 1e-14\n");
	scene_from(ini, &sc);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_end(s), HB_SIM_END_T, "%s", hb_sim_end_str(s));
	hb_sim_body(s, 0, &b);
	m = b.m;
	energy_momentum(s, &K, &P);
	assert_rel(P, m * v, 1e-10);
	cr_assert(K < 0.9 * 0.5 * m * v * v, "kinetic energy %g of %g: nothing dissipated", K, 0.5 * m * v * v);
	cr_assert_gt(hb_sim_stats(s)->kinks, 0, "no kink located");
	for (int i = 0; i + 1 < 5; i++) {
		struct hb_sim_body lo, hi;

		hb_sim_body(s, i, &lo);
		hb_sim_body(s, i + 1, &hi);
		cr_assert_geq(hi.u, lo.u, "bodies %d and %d still approach at the end", i + 1, i + 2);
	}
	cr_assert_eq(hb_check_solution_pair(&sc, hb_sim_arc(s), msg, sizeof msg), 0, "%s", msg);
	hb_sim_free(s);
}

/* The stiff Maxwell interface (presets/hard-stiff-maxwell's law, c = 0.44 N s/m) in a cradle of 5. */
static struct hb_sim *
stiff_cradle(const char *stepper)
{
	struct hb_scene sc;
	char ini[1024];

	snprintf(ini, sizeof ini,
	         "[scene]\nname = chain\nlaw = bwmcl\n"
	         "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	         "[law]\nA = 1\nalpha = 0.35\nbeta = 5e7\ngamma = 5e7\nn = 2\np = 1.5\nc = 0.44\n"
	         "[chain]\nn = 5\nspacing = 0 m\n[striker]\nv = -1\n[loads]\ng = 0\n"
	         "[run]\nT = 0.5 ms\nrtol = 1e-12\natol = 1e-14\nstepper = %s\n", stepper);
	scene_from(ini, &sc);
	return run_scene(&sc);
}

/*
 * Stiffness per cluster (docs/chains.md section 8, point 6): rk8pd on a
 * cradle of stiff Maxwell interfaces is found held back by stability and
 * stays rk8pd; auto goes over to bsimp (the clusters' Jacobian) and takes
 * far fewer steps for the same motion (every body's velocity within 1e-9
 * m/s), with momentum kept to 1e-10.
 */
Test(chain, stiff_clusters_go_implicit)
{
	struct hb_sim *e = stiff_cradle("rk8pd"), *a = stiff_cradle("auto");
	const struct hb_sim_stats *se = hb_sim_stats(e), *sa = hb_sim_stats(a);
	double K, P;
	struct hb_sim_body b;

	cr_assert_eq(hb_sim_end(e), HB_SIM_END_T, "%s", hb_sim_end_str(e));
	cr_assert_eq(hb_sim_end(a), HB_SIM_END_T, "%s", hb_sim_end_str(a));
	cr_assert_eq(se->stiff, 1, "rk8pd not found stiff (h rho up to %g)", se->stiff_hrho);
	cr_assert_eq(se->switched, 0);
	cr_assert_eq(sa->switched, 1, "auto did not go over to bsimp");
	cr_assert_gt(sa->jac, 0);
	cr_assert_lt(2 * sa->steps, se->steps, "auto %ld steps, rk8pd %ld", sa->steps, se->steps);
	for (int i = 0; i < 5; i++) {
		struct hb_sim_body be, ba;

		hb_sim_body(e, i, &be);
		hb_sim_body(a, i, &ba);
		assert_abs(ba.u, be.u, 1e-9);
	}
	hb_sim_body(a, 0, &b);
	energy_momentum(a, &K, &P);
	assert_rel(P, -b.m, 1e-10);
	hb_sim_free(e);
	hb_sim_free(a);
}

/*
 * A chain and its mirror image give mirrored motions: a touching cradle of
 * 5 struck from the top at 1 m/s, and the same struck from the bottom at
 * +1 m/s (the scene's per-body keys: striker.v = 0, initial.body.1.v =
 * 1 m/s).  Body i's final velocity in one is minus body n + 1 - i's in the
 * other, to 1e-10 m/s, and the collisions are as many, each interface k of
 * one matching n - k of the other.
 */
Test(chain, mirror_image_gives_mirrored_motion)
{
	struct hb_scene sc, sm;
	struct hb_sim *a, *b;
	const int n = 5;
	int ka[8] = { 0 }, kb[8] = { 0 };

	chain_scene(&sc, "n = 5\nspacing = 0 m", -1.0, 0.0, 0.01);
	a = run_scene(&sc);
	scene_from("[scene]\nname = mirror\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[chain]\nn = 5\nspacing = 0 m\n[striker]\nv = 0 m/s\n"
	           "[initial]\nbody.1.v = 1 m/s\n[loads]\ng = 0\n"
	           "[run]\nT = 0.01\nrtol = 1e-12\natol = 1e-14\n", &sm);
	b = run_scene(&sm);
	for (int i = 0; i < n; i++) {
		struct hb_sim_body ba, bb;

		hb_sim_body(a, i, &ba);
		hb_sim_body(b, n - 1 - i, &bb);
		assert_abs(ba.u, -bb.u, 1e-10);
	}
	cr_assert_eq(hb_sim_ncollisions(a), hb_sim_ncollisions(b));
	for (size_t i = 0; i < hb_sim_ncollisions(a); i++) {
		ka[hb_sim_collision(a, i)->k]++;
		kb[n - hb_sim_collision(b, i)->k]++;
	}
	for (int k = 1; k < n; k++)
		cr_assert_eq(ka[k], kb[k], "interface %d: %d collisions, its mirror %d", k, ka[k], kb[k]);
	hb_sim_free(a);
	hb_sim_free(b);
}

/* Interface k's overlap (> 0 when the bodies press) from bodies k - 1 and k (R 10 mm). */
static double
overlap(const double *y, int k)
{
	return -(y[k] - y[k - 1] - 0.02);
}

struct wave {
	double Vs;    /* speed between interfaces n - 20 and 20, m/s */
	double Fm;    /* F_c^max at interface n / 2, N */
	double width; /* in diameters: 5 x the rms width of the overlaps / that of cos^4 over 5 */
};

/*
 * A touching chain of n steel beads struck at v: the time each interface
 * is most compressed (v_k crossing 0 upwards at its largest overlap,
 * interpolated between the samples, where the extremum is located), the
 * speed between two interfaces 20 from either end, the force at the middle
 * (its collision's F_c^max), and the width of the overlaps when the middle
 * is most compressed.  The continuum profile is cos^4 on a support of 5
 * diameters (Nesterenko 2001, ch. 1), whose rms width is 0.70724 diameters.
 */
static struct wave
solitary_wave(int n, double v, double T)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct wave w = { 0 };
	double *y = calloc((size_t)n, sizeof *y), *u = calloc((size_t)n, sizeof *u);
	double *pv = calloc((size_t)n, sizeof *pv), *dmax = calloc((size_t)n, sizeof *dmax);
	double *tp = calloc((size_t)n, sizeof *tp), tprev = 0.0;
	char chain[64];
	int k1 = n - 20, k2 = 20, kmid = n / 2;

	cr_assert(y && u && pv && dmax && tp);
	snprintf(chain, sizeof chain, "n = %d\nspacing = 0 m", n);
	chain_scene(&sc, chain, v, 0.0, T);
	s = hb_sim_new(&sc, NULL, 0);
	cr_assert_not_null(s);
	while (hb_sim_end(s) == HB_SIM_RUNNING) {
		const struct hb_arc *a;
		double t;

		cr_assert_eq(hb_sim_advance(s, 1, 0.0), 0, "%s", hb_sim_errmsg(s));
		a = hb_sim_arc(s);
		t = hb_arc_at(a, hb_arc_len(a) - 1)->t;
		for (int i = 0; i < n; i++) {
			struct hb_sim_body b;

			hb_sim_body(s, i, &b);
			y[i] = b.y;
			u[i] = b.u;
		}
		for (int k = 1; k < n; k++) {
			double vk = u[k] - u[k - 1], d = overlap(y, k);

			if (d > dmax[k])
				dmax[k] = d;
			/* at its largest overlap, to the rounding of positions about 1.6 m (4 ulps) */
			if (pv[k] < 0 && vk >= 0 && d >= dmax[k] - 1e-15) {
				tp[k] = t - vk * (t - tprev) / (vk - pv[k]);
				if (k == kmid) {
					double m0 = 0, m1 = 0, m2 = 0;

					for (int j = 1; j < n; j++) {
						double dj = fmax(overlap(y, j), 0.0);

						m0 += dj;
						m1 += dj * j;
						m2 += dj * j * j;
					}
					w.width = 5.0 * sqrt(m2 / m0 - (m1 / m0) * (m1 / m0)) / 0.70724;
				}
			}
			pv[k] = vk;
		}
		tprev = t;
	}
	cr_assert_eq(hb_sim_end(s), HB_SIM_END_T, "%s", hb_sim_end_str(s));
	cr_assert(tp[k1] > 0 && tp[k2] > tp[k1], "the wave reached neither interface %d nor %d", k1, k2);
	w.Vs = (k1 - k2) * 0.02 / (tp[k2] - tp[k1]);
	for (size_t i = 0; i < hb_sim_ncollisions(s); i++)
		if (hb_sim_collision(s, i)->k == kmid)
			w.Fm = fmax(w.Fm, hb_sim_collision(s, i)->Fcmax);
	cr_assert_gt(w.Fm, 0.0);
	hb_sim_free(s);
	free(y);
	free(u);
	free(pv);
	free(dmax);
	free(tp);
	return w;
}

/*
 * Nesterenko's solitary wave in a touching chain of 80 beads: by the
 * homogeneity of F = k d^(3/2), V_s is proportional to F_m^(1/6) exactly;
 * two striker velocities a decade apart give it within 1%.  Its width is
 * about five diameters.
 */
Test(chain, solitary_wave_speed_and_width)
{
	struct wave a = solitary_wave(80, -1.0, 0.004), b = solitary_wave(80, -0.1, 0.004);
	double ratio = a.Vs / b.Vs, law = pow(a.Fm / b.Fm, 1.0 / 6.0);

	cr_assert(fabs(ratio / law - 1) < 0.01, "V_s ratio %.6g against (F_m ratio)^(1/6) %.6g", ratio, law);
	cr_assert(fabs(log(ratio) / log(a.Fm / b.Fm) - 1.0 / 6.0) < 0.01 / 6,
	          "exponent %.6g", log(ratio) / log(a.Fm / b.Fm));
	cr_assert(a.width > 4.5 && a.width < 5.5, "width %.3g diameters", a.width);
	cr_assert(b.width > 4.5 && b.width < 5.5, "width %.3g diameters", b.width);
	/*
	 * The speed (README, Chains): with F = k d^(3/2),
	 * k = (4/3) E / (2 (1 - nu^2)) sqrt(R / 2), bead mass m and diameter a,
	 * V_s = sqrt(kappa) k^(1/3) a m^(-1/2) F_m^(1/6), where kappa is 4/5 in
	 * Nesterenko's long-wave limit and is solved for the discrete chain's
	 * own travelling wave by tests/solitary.h, from the chain's equations
	 * alone.  The discrete wave, five beads wide, runs 1.24% faster than the
	 * continuum's; the engine's wave is the discrete one: its speed within
	 * 1e-6 and its width within 1e-3 at both amplitudes.
	 */
	{
		const double E = 200e9, nu = 0.3, R = 0.01, rho = 7800, d = 2 * R;
		double k = 4.0 / 3.0 * E / (2 * (1 - nu * nu)) * sqrt(R / 2);
		double m = 4.0 / 3.0 * M_PI * R * R * R * rho, rms, rms2;
		double kappa = solitary_kappa(1.5, 40, 8, &rms), kappa2 = solitary_kappa(1.5, 80, 8, &rms2);
		double width = 5 * rms / 0.70724;

		cr_assert(kappa > 0 && fabs(kappa2 / kappa - 1) < 1e-7,
		          "the discrete wave's kappa %.12g (at 40 points a bead) against %.12g (at 80)", kappa, kappa2);
		cr_assert(sqrt(kappa / 0.8) > 1.005 && sqrt(kappa / 0.8) < 1.02,
		          "the discrete wave against the continuum's speed: ratio %.8g", sqrt(kappa / 0.8));
		for (int i = 0; i < 2; i++) {
			const struct wave *x = i ? &b : &a;
			double Vd = sqrt(kappa) * cbrt(k) * d / sqrt(m) * pow(x->Fm, 1.0 / 6.0);

			cr_assert(fabs(x->Vs / Vd - 1) < 1e-6, "V_s %.8g m/s against the discrete wave's %.8g m/s "
			          "(ratio %.8g)", x->Vs, Vd, x->Vs / Vd);
			cr_assert(fabs(x->width / width - 1) < 1e-3, "width %.5g diameters against the discrete "
			          "wave's %.5g", x->width, width);
		}
	}
}

/*
 * The stacked drop's rigid, sequential limit (README, Chains): a ball of
 * m1 = 100 g on the floor side and one of m2 = 10 g above it, 10 um apart
 * and 10 um above the floor, both falling at v = 1 m/s (no gravity), with
 * elastic linear contacts of stiffness k.  Once the floor's contact
 * (pi sqrt(m1 / k)) is short against the closing of the 10 um gap, the two
 * collisions are sequential and the top ball leaves at
 * v (3 m1 - m2) / (m1 + m2) = 2.63636 m/s.  At k = 1e7 N/m the contacts
 * overlap in time (1.186 m/s); each tenfold stiffening brings it closer
 * (1.341 m/s at 1e8, 2.203 at 1e9), to 1e-6 at 1e10.
 */
static double
stacked_top_velocity(double k)
{
	char ini[1024];
	struct hb_sim *s;
	struct hb_sim_body top;

	snprintf(ini, sizeof ini,
	         "[scene]\nname = stacked\nlaw = linear\n"
	         "[body1]\nmass = 100 g\nR = 10 mm\n[body2]\nmass = inf\nR = inf\n"
	         "[law]\nk = %.17g N/m\n"
	         "[chain]\nn = 2\nfloor = yes\nspacing = 10 um\n"
	         "[body.2]\nmass = 10 g\nR = 5 mm\n[striker]\nv = -1 m/s\n"
	         "[initial]\nbody.1.v = -1 m/s\n[loads]\ng = 0\n"
	         "[run]\nT = 20 ms\nrtol = 1e-12\natol = 1e-14\n", k);
	s = run_ini(ini);
	cr_assert_eq(hb_sim_body(s, 1, &top), HB_OK);
	hb_sim_free(s);
	return top.u;
}

Test(chain, stacked_drop_approaches_the_rigid_sequential_limit)
{
	const double m1 = 0.1, m2 = 0.01, v = 1.0, limit = v * (3 * m1 - m2) / (m1 + m2);
	double prev = INFINITY;

	for (double k = 1e7; k <= 1e10 * 1.5; k *= 10) {
		double u = stacked_top_velocity(k), dev = fabs(u - limit);

		cr_assert(dev < prev, "k = %g N/m: the top ball leaves at %.9g m/s, "
		          "%.3g from the limit %.9g, not closer than at k / 10 (%.3g)", k, u, dev,
		          limit, prev);
		prev = dev;
	}
	cr_assert_lt(prev, 1e-6, "at k = 1e10 N/m the top ball is %.3g m/s from the limit", prev);
}

/*
 * A touching cradle of five cut 30 us after the strike: several interfaces
 * are in contact side by side, and hb_sim_contacts_live and
 * hb_sim_contact_live_nth give each, by increasing k, with its values so
 * far; hb_sim_contact_live's is one of them.  Run on to 10 ms, every
 * contact has ended: none.  In a two-body scene, the one of
 * hb_sim_contact_live.
 */
Test(chain, contacts_in_progress_side_by_side)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct hb_collision c, one;
	size_t n;
	int found = 0, prevk = -1;

	chain_scene(&sc, "n = 5\nspacing = 0 m", -1.0, 0.0, 3e-5);
	s = run_scene(&sc);
	n = hb_sim_contacts_live(s);
	cr_assert(n >= 2 && n <= 4, "%zu contacts in progress 30 us after the strike", n);
	cr_assert_eq(hb_sim_contact_live(s, &one), 1);
	for (size_t i = 0; i < n; i++) {
		cr_assert_eq(hb_sim_contact_live_nth(s, i, &c), 1, "contact %zu of %zu", i, n);
		cr_assert(c.k > prevk && c.k >= 1 && c.k <= 4, "contact %zu: interface %d after %d", i, c.k, prevk);
		cr_assert(!c.complete && c.te <= c.ts && c.ts == hb_arc_last(hb_sim_arc(s))->t && c.Fcmax > 0,
		          "contact %zu (k = %d): t_e %.17g, t_s %.17g, F_c^max %g", i, c.k, c.te, c.ts, c.Fcmax);
		cr_assert_eq(c.i, hb_sim_collisions_total(s) + (long)i);
		found += c.k == one.k && c.te == one.te && c.vi == one.vi;
		prevk = c.k;
	}
	cr_assert_eq(found, 1, "hb_sim_contact_live's (k = %d) is one of them", one.k);
	cr_assert_eq(hb_sim_contact_live_nth(s, n, &c), 0);
	hb_sim_free(s);

	chain_scene(&sc, "n = 5\nspacing = 0 m", -1.0, 0.0, 0.01);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_contacts_live(s), 0);
	cr_assert_eq(hb_sim_contact_live_nth(s, 0, &c), 0);
	hb_sim_free(s);

	scene_from("[scene]\nname = pair\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[body2]\nE = 200 GPa\nnu = 0.3\nR = inf\n"
	           "[loads]\ng = 9.81\n[initial]\nx0 = 5 mm\n[run]\nT = 0.03197\n", &sc);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_contacts_live(s), (size_t)hb_sim_contact_live(s, &one));
	cr_assert_eq(hb_sim_contact_live_nth(s, 0, &c), hb_sim_contact_live(s, &one));
	cr_assert_eq(hb_sim_contact_live_nth(s, 1, &c), 0);
	hb_sim_free(s);
}

/* The collision of a two-body chain is the full system's with x0 = the spacing. */
Test(chain, two_bodies_are_the_full_system)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;

	chain_scene(&sc, "n = 2\nspacing = 0.5 mm", -0.7, 9.81, 0.003);
	a = run_scene(&sc);
	scene_from("[scene]\nname = pair\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[body2]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[loads]\ng = 9.81\n[initial]\nx0 = 0.5 mm\nv0 = -0.7\nv_m0 = -0.35\n"
	           "[run]\nT = 0.003\nrtol = 1e-12\natol = 1e-14\n", &sc);
	b = run_scene(&sc);
	cr_assert_eq(hb_sim_ncollisions(b), 1);
	assert_collisions_match(a, b, (struct coll_tol){ .te = 1e-12, .td = 1e-9, .vi = 1e-12,
	                                                 .e = 1e-10, .xcmax = 1e-9, .Fcmax = 1e-9 });
	hb_sim_free(a);
	hb_sim_free(b);
}

/*
 * One body on the floor under gravity is the reduced system dropped from
 * the spacing (the floor is the scene's body2: by default a steel flat).
 */
Test(chain, one_body_on_the_floor_is_the_reduced_system)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;

	chain_scene(&sc, "n = 1\nfloor = yes\nspacing = 5 mm", 0.0, 9.81, 0.15);
	a = run_scene(&sc);
	cr_assert_eq(hb_sim_nbodies(a), 1);
	scene_from("[scene]\nname = drop\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[body2]\nE = 200 GPa\nnu = 0.3\nR = inf\n"
	           "[loads]\ng = 9.81\n[initial]\nx0 = 5 mm\n"
	           "[run]\nT = 0.15\nrtol = 1e-12\natol = 1e-14\n", &sc);
	b = run_scene(&sc);
	cr_assert_geq(hb_sim_ncollisions(b), 2);
	assert_collisions_match(a, b, (struct coll_tol){ .te = 1e-11, .td = 1e-9, .e = 1e-10,
	                                                 .Fcmax = 1e-9 });
	hb_sim_free(a);
	hb_sim_free(b);
}

/* What a chain does not run in this version is refused, naming the key. */
Test(chain, refusals_name_the_key)
{
	static const struct {
		const char *text, *key;
	} cases[] = {
		{ "[chain]\nn = 1\n", "[chain] n:" },
		{ "[chain]\nn = 3\nspacing = -1 mm\n", "[chain] spacing:" },
		{ "[chain]\nn = 3\n[loads]\nF1 = 1 N\n", "[loads] F1:" },
		{ "[chain]\nn = 3\n[loads]\nramp = yes\nF_e0 = 1 N\n", "[loads] ramp:" },
		{ "[chain]\nn = 3\n[run]\nreductions = flight\n", "[run] reductions:" },
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		struct hb_scene sc;
		char ini[512], msg[1024];

		snprintf(ini, sizeof ini, "[scene]\nname = c\nlaw = hertz\n%s", cases[i].text);
		cr_assert_neq(hb_preset_load_string(ini, "c.preset", &sc, msg, sizeof msg), 0,
		              "accepted: %s", cases[i].text);
		cr_assert(strstr(msg, cases[i].key) != NULL, "%s: the message '%s' names no %s",
		          cases[i].text, msg, cases[i].key);
	}
}

/* A chain's scene is written with its [chain] and [striker] sections, and read back the same. */
Test(chain, preset_round_trip)
{
	struct hb_scene sc, back;
	char buf[8192], msg[1024];

	chain_scene(&sc, "n = 4\nfloor = yes\nspacing = 2 mm", -0.5, 9.81, 0.01);
	hb_preset_format(&sc, buf, sizeof buf);
	cr_assert(strstr(buf, "[chain]\nn = 4\nfloor = yes\n") != NULL, "%s", buf);
	cr_assert(strstr(buf, "[striker]\nv = -0.5 m/s\n") != NULL, "%s", buf);
	cr_assert_eq(hb_preset_load_string(buf, "w.preset", &back, msg, sizeof msg), 0, "%s", msg);
	cr_assert_eq(back.chain.n, 4);
	cr_assert_eq(back.chain.floor, 1);
	cr_assert_eq(back.chain.spacing, 0.002);
	cr_assert_eq(back.chain.v, -0.5);
	/* a two-body scene has neither section */
	scene_from("[scene]\nname = p\nlaw = hertz\n", &sc);
	hb_preset_format(&sc, buf, sizeof buf);
	cr_assert(strstr(buf, "[chain]") == NULL && strstr(buf, "[striker]") == NULL, "%s", buf);
}
