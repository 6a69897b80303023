/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_chain_engine.c - a chain's contacts stepped and located by the
 * engine's one driver (sim.c, sim_locate.c), with what it does per
 * interface: the separation that rounding cannot fake (sim_snap.c), the
 * dip test for an event stepped over, dense output under dop853.
 */
#include <math.h>
#include <stdio.h>

#include <criterion/criterion.h>

#include "hybounce/check.h"
#include "hybounce/preset.h"
#include "testutil.h"

/* Shipped preset NAME into sc. */
static void
preset_named(const char *name, struct hb_scene *sc)
{
	char path[512], msg[512];

	snprintf(path, sizeof path, "%s/%s.preset", preset_dir(), name);
	cr_assert_eq(hb_preset_load(path, sc, msg, sizeof msg), 0, "%s: %s", path, msg);
}

/*
 * presets/hard-slow-impact-shccl with its damping c 1e7 times larger
 * (c v0 / k about 1e2): Phi is zero to within the noise of v for the whole
 * restitution, and its computed sign says nothing.  The pair snaps the
 * receding state onto Phi = 0 (hbs_snap_separation); a chain's interface
 * is snapped the same way, so that one ball on the floor gives the pair's
 * contact: t_s 0.0773 s.  Without the snap a chain's contact ended where
 * rounding first made Phi positive, t_s 0.0112 s.
 */
static const char heavy[] =
	"[scene]\nname = heavy\nlaw = shccl\nextension = adhesive\n"
	"[body1]\nE = 200 GPa\nnu = 0.30\nrho = 7800 kg/m^3\nR = 20 mm\n"
	"[body2]\nE = 2.0 GPa\nnu = 0.35\nR = inf\n"
	"[law]\np = 1.5\nc = 4.3e16 N s m^-5/2\n[loads]\ng = 0\n"
	"[run]\nT = 20 s\n";

Test(chain_engine, heavy_damping_separates_where_the_pair_does)
{
	struct hb_scene sc;
	struct hb_sim *pair, *chain;
	char ini[1024];

	snprintf(ini, sizeof ini, "%s[initial]\nx0 = 1 nm\nv0 = -1 um/s\n", heavy);
	scene_from(ini, &sc);
	pair = run_scene(&sc);
	snprintf(ini, sizeof ini, "%s[chain]\nn = 1\nfloor = yes\nspacing = 1 nm\n[striker]\nv = -1 um/s\n",
	         heavy);
	scene_from(ini, &sc);
	chain = run_scene(&sc);
	cr_assert_eq(hb_sim_ncollisions(pair), 1);
	cr_assert_eq(hb_sim_ncollisions(chain), 1);
	{
		const struct hb_collision *p = hb_sim_collision(pair, 0), *c = hb_sim_collision(chain, 0);

		cr_assert(fabs(p->ts - 0.0773) < 1e-4, "the pair's t_s %.17g", p->ts);
		cr_assert(fabs(c->ts - p->ts) <= 1e-9 * p->ts, "t_s %.17g against the pair's %.17g", c->ts, p->ts);
		cr_assert(fabs(c->e - p->e) <= 1e-9, "e %.17g against the pair's %.17g", c->e, p->e);
	}
	hb_sim_free(pair);
	hb_sim_free(chain);
}

/*
 * The granular chain at rtol = atol = 1e-6 (longer steps): a contact of
 * two beads in the wave's tail can be in C at both ends of a step and
 * leave C inside it (a separation stepped over).  The dip test finds it
 * per interface, from each contact's indicator -min(Phi, v) and its rate
 * at the step's ends; every pre-jump sample is in D and every flow sample
 * in C.
 */
Test(chain_engine, a_separation_stepped_over_is_found)
{
	struct hb_scene sc;
	struct hb_sim *s;
	char msg[512];

	preset_named("granular-chain", &sc);
	sc.run.rtol = sc.run.atol = 1e-6;
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_end(s), HB_SIM_END_T, "%s", hb_sim_end_str(s));
	cr_assert_gt(hb_sim_stats(s)->dips, 0, "no event found inside a step whose ends were in C");
	cr_assert_eq(hb_check_solution_pair(&sc, hb_sim_arc(s), msg, sizeof msg), 0, "%s", msg);
	hb_sim_free(s);
}

/*
 * Dense output per interface: a touching cradle of 5 under dop853 (its
 * crossings located on the step's continuous extension, then on its own
 * steps about the point found) gives rk8pd's table: the contacts' ends,
 * extrema and restitution to 1e-9.
 */
Test(chain_engine, dop853_locates_on_its_dense_output)
{
	struct hb_scene sc;
	struct hb_sim *a, *b;

	preset_named("newtons-cradle-5", &sc);
	a = run_scene(&sc);
	sc.run.stepper = HB_STEPPER_DOP853;
	b = run_scene(&sc);
	cr_assert_eq(hb_sim_ncollisions(a), hb_sim_ncollisions(b));
	for (size_t i = 0; i < hb_sim_ncollisions(a); i++) {
		const struct hb_collision *x = hb_sim_collision(a, i), *y = hb_sim_collision(b, i);

		cr_assert_eq(x->k, y->k);
		cr_assert(fabs(x->ts - y->ts) <= 1e-9 * x->ts, "collision %zu: t_s %.17g, %.17g", i, x->ts, y->ts);
		cr_assert(fabs(x->xcmax - y->xcmax) <= 1e-9 * x->xcmax, "collision %zu: x_c^max", i);
		cr_assert(fabs(x->Fcmax - y->Fcmax) <= 1e-9 * x->Fcmax, "collision %zu: F_c^max", i);
	}
	cr_assert_gt(hb_sim_stats(b)->located, 0);
	hb_sim_free(a);
	hb_sim_free(b);
}

/*
 * The driver's arrays are the pair's (MAXDIM components, its scales in the
 * simulator, where its right-hand side reads them) or grown for a chain's
 * clusters (sim_work.c): a simulator that ran a granular chain and is given
 * a two-body scene runs it as a new simulator does, bit for bit; and back.
 */
Test(chain_engine, a_simulator_goes_from_a_chain_to_two_bodies_and_back)
{
	struct hb_scene chain, pair;
	struct hb_sim *s, *fresh;
	char msg[512];
	int restarted = 0;

	preset_named("granular-chain", &chain);
	preset_named("hertz-elastic", &pair);
	s = run_scene(&chain);
	cr_assert_eq(hb_sim_set_scene(s, &pair, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert(restarted);
	cr_assert_eq(hb_sim_run(s), HB_OK, "%s", hb_sim_errmsg(s));
	fresh = run_scene(&pair);
	cr_assert_eq(hb_sim_ncollisions(s), hb_sim_ncollisions(fresh));
	cr_assert_eq(hb_sim_stats(s)->rhs, hb_sim_stats(fresh)->rhs);
	for (size_t i = 0; i < hb_sim_ncollisions(s); i++) {
		const struct hb_collision *a = hb_sim_collision(s, i), *b = hb_sim_collision(fresh, i);

		cr_assert(a->ts == b->ts && a->e == b->e && a->xcmax == b->xcmax, "collision %zu", i);
	}
	hb_sim_free(fresh);
	cr_assert_eq(hb_sim_set_scene(s, &chain, &restarted, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_sim_run(s), HB_OK, "%s", hb_sim_errmsg(s));
	fresh = run_scene(&chain);
	cr_assert_eq(hb_sim_ncollisions(s), hb_sim_ncollisions(fresh));
	cr_assert_eq(hb_sim_stats(s)->rhs, hb_sim_stats(fresh)->rhs);
	hb_sim_free(fresh);
	hb_sim_free(s);
}
