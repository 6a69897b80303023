/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_chain.c - chains of bodies (docs/chains.md): Newton's cradle of
 * three equal elastic balls conserves energy and momentum, a chain of two
 * bodies and a chain of one on the floor are the full and the reduced
 * system, and the scenes this version cannot run are refused by name.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/status.h"
#include "testutil.h"

/* Steel balls (R 10 mm) with the Hertz elastic law, in a chain (CHAIN: the [chain] lines). */
static void
chain_scene(struct hb_scene *sc, const char *chain, double v, double g, double T)
{
	char ini[2048];

	snprintf(ini, sizeof ini,
	         "[scene]\nname = chain\nlaw = hertz\n"
	         "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	         "[chain]\n%s\n[striker]\nv = %.17g\n[loads]\ng = %.17g\n"
	         "[run]\nT = %.17g\nrtol = 1e-12\natol = 1e-14\n",
	         chain, v, g, T);
	scene_from(ini, sc);
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

/* The collision of a two-body chain is the full system's with x0 = the spacing. */
Test(chain, two_bodies_are_the_full_system)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;
	const struct hb_collision *ca, *cb;

	chain_scene(&sc, "n = 2\nspacing = 0.5 mm", -0.7, 9.81, 0.003);
	a = run_scene(&sc);
	scene_from("[scene]\nname = pair\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[body2]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[loads]\ng = 9.81\n[initial]\nx0 = 0.5 mm\nv0 = -0.7\nv_m0 = -0.35\n"
	           "[run]\nT = 0.003\nrtol = 1e-12\natol = 1e-14\n", &sc);
	b = run_scene(&sc);
	cr_assert_eq(hb_sim_ncollisions(a), 1);
	cr_assert_eq(hb_sim_ncollisions(b), 1);
	ca = hb_sim_collision(a, 0);
	cb = hb_sim_collision(b, 0);
	assert_rel(ca->te, cb->te, 1e-12);
	assert_rel(ca->td, cb->td, 1e-9);
	assert_rel(ca->vi, cb->vi, 1e-12);
	assert_rel(ca->e, cb->e, 1e-10);
	assert_rel(ca->xcmax, cb->xcmax, 1e-9);
	assert_rel(ca->Fcmax, cb->Fcmax, 1e-9);
	hb_sim_free(a);
	hb_sim_free(b);
}

/* One body on the floor under gravity is the reduced system dropped from the spacing. */
Test(chain, one_body_on_the_floor_is_the_reduced_system)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;

	chain_scene(&sc, "n = 1\nfloor = yes\nspacing = 5 mm", 0.0, 9.81, 0.15);
	a = run_scene(&sc);
	cr_assert_eq(hb_sim_nbodies(a), 1);
	scene_from("[scene]\nname = drop\nlaw = hertz\n"
	           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	           "[body2]\nE = 200 GPa\nnu = 0.3\nR = 10 mm\nmass = inf\n"
	           "[loads]\ng = 9.81\n[initial]\nx0 = 5 mm\n"
	           "[run]\nT = 0.15\nrtol = 1e-12\natol = 1e-14\n", &sc);
	b = run_scene(&sc);
	cr_assert_eq(hb_sim_ncollisions(a), hb_sim_ncollisions(b));
	cr_assert_geq(hb_sim_ncollisions(a), 2);
	for (size_t i = 0; i < hb_sim_ncollisions(a); i++) {
		const struct hb_collision *ca = hb_sim_collision(a, i), *cb = hb_sim_collision(b, i);

		assert_rel(ca->te, cb->te, 1e-11);
		assert_rel(ca->td, cb->td, 1e-9);
		assert_rel(ca->e, cb->e, 1e-10);
		assert_rel(ca->Fcmax, cb->Fcmax, 1e-9);
	}
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
		{ "[chain]\nn = 3\nspacing = 0 m\n", "[chain] spacing:" },
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
