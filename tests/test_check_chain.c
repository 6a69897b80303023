/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_check_chain.c - hb_check_chain (check.h; docs/chains.md section 5)
 * can fail: a chain's run passes it, then what it reads is corrupted as a
 * real bug would (a collision's W or e, a body's final velocity, an
 * interface's work) and the check must report that failure, and only it,
 * with a message naming what failed.  The run's internal state is reached
 * through sim_impl.h, as the engine's own code reaches it.  And the energy
 * the interfaces absorbed is split honestly into stored (the contacts in
 * progress) and dissipated.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/check.h"
#include "hybounce/status.h"
#include "sim_impl.h"
#include "testutil.h"

/* Three steel Hertz balls 1 mm apart (LAW between them), the top one struck at 1 m/s. */
static struct hb_sim *
cradle(const char *law)
{
	struct hb_scene sc;

	steel_chain(&sc, law, strcmp(law, "shccl") == 0 ? "c = 2e7\n" : "", "n = 3\nspacing = 1 mm",
	            -1.0, 0.0, 0.01);
	return run_scene(&sc);
}

static void
assert_passes(const struct hb_sim *s, struct hb_check_chain *r)
{
	char msg[1400];

	cr_assert_eq(hb_check_chain(s, r, msg, sizeof msg), 0, "%s", msg);
	cr_assert_eq(r->failed, 0);
	cr_assert_str_empty(msg);
	cr_assert_eq(r->ncontacts, 2);
	cr_assert_eq(r->nisolated, 2);
	cr_assert_eq(r->momentum, 1);
	cr_assert_leq(r->eresid, 100.0 * r->tol);
	cr_assert_leq(r->presid, 100.0 * r->tol);
}

/* Checks s and asserts one failure, reported as a message holding each of the NEED strings. */
static void
assert_fails(const struct hb_sim *s, int failed, const char *const *need, size_t nneed)
{
	struct hb_check_chain r;
	char msg[1400];

	cr_assert_eq(hb_check_chain(s, &r, msg, sizeof msg), HB_EINVAL, "the check passed a corrupted run");
	cr_assert_eq(r.failed, failed, "%d checks failed, not %d: %s", r.failed, failed, msg);
	for (size_t i = 0; i < nneed; i++)
		cr_assert_not_null(strstr(msg, need[i]), "'%s' not in the message: %s", need[i], msg);
}

/* The elastic cradle passes every check: the baseline of the corruptions below. */
Test(check_chain, elastic_cradle_passes)
{
	struct hb_sim *s = cradle("hertz");
	struct hb_check_chain r;

	assert_passes(s, &r);
	cr_assert_lt(r.wworst, 1e-10, "elastic W %g of its energy scale", r.wworst);
	cr_assert_lt(r.eworst, 1e-10, "elastic e off by %g", r.eworst);
	/* no contact in progress at the end: nothing stored, nothing dissipated */
	cr_assert_eq(r.stored, 0.0);
	cr_assert_leq(fabs(r.dissipated), 1e-10 * r.kinetic0, "elastic chain dissipated %g J of %g",
	              r.dissipated, r.kinetic0);
	hb_sim_free(s);
}

/*
 * Ended within the first contact (t = 1.01 ms, 10 us after the striker
 * meets its neighbour 1 mm away): that elastic contact holds what the
 * bodies lost, stored = K(0) - K to 1e-10 of K(0), which is its Hertz
 * potential to 1e-10 (1e-13 here), and nothing is dissipated.
 */
Test(check_chain, elastic_contact_in_progress_stores_the_lost_energy)
{
	struct hb_scene sc;
	struct hb_sim *s;
	struct hb_check_chain r;
	char msg[1400];

	steel_chain(&sc, "hertz", "", "n = 3\nspacing = 1 mm", -1.0, 0.0, 1.01e-3);
	s = run_scene(&sc);
	cr_assert_eq(s->ifc[1].q != 0, 1, "the striker's contact is not in progress at the end");
	cr_assert_eq(hb_check_chain(s, &r, msg, sizeof msg), 0, "%s", msg);
	cr_assert_gt(r.stored, 0.01 * r.kinetic0, "stored %g J of %g", r.stored, r.kinetic0);
	assert_rel(r.stored, r.kinetic0 - r.kinetic, 1e-10);
	/* and it is the Hertz potential of the indentation, |Phi(x_c) x_c| / (p + 1) = (2/5) k |x_c|^(5/2) */
	{
		const struct iface *I = &s->ifc[1];
		double Phi = I->law->phi(I->par, I->ext, I->xc, I->z, I->v);

		cr_assert_lt(I->xc, 0.0);
		assert_rel(r.stored, fabs(Phi * I->xc) / 2.5, 1e-10);
	}
	cr_assert_leq(fabs(r.dissipated), 1e-10 * r.kinetic0, "dissipated %g J", r.dissipated);
	hb_sim_free(s);
}

/*
 * A dissipative cradle (shccl) at its end, no contact in progress: nothing
 * stored, and the dissipated energy is the sum of the completed
 * contacts' W, to 1e-9.
 */
Test(check_chain, dissipative_cradle_dissipates_its_contacts_work)
{
	struct hb_sim *s = cradle("shccl");
	struct hb_check_chain r;
	double W = 0.0;

	assert_passes(s, &r);
	for (size_t i = 0; i < hb_sim_ncollisions(s); i++)
		W += hb_sim_collision(s, i)->W;
	cr_assert_gt(W, 1e-3 * r.kinetic0, "shccl absorbed %g J", W);
	cr_assert_eq(r.stored, 0.0);
	assert_rel(r.dissipated, W, 1e-9);
	hb_sim_free(s);
}

/*
 * An elastic law's collision that dissipates 1e-6 of its impact energy (a
 * bug in the recorded work): the law check fails, naming the collision,
 * its interface and the law; the identities (read from the interfaces'
 * works, not the records) still hold.
 */
Test(check_chain, elastic_collision_with_work_fails)
{
	struct hb_sim *s = cradle("hertz");
	struct hb_collision *o = (struct hb_collision *)hb_sim_collision(s, 1);
	const struct iface *I = &s->ifc[o->k - s->k0];
	char where[64];
	const char *need[] = { "elastic law: collision 1 (interface ", where, "hertz dissipates nothing" };
	struct hb_check_chain r;

	assert_passes(s, &r);
	o->W = 1e-6 * 0.5 * I->m * o->vi * o->vi;
	snprintf(where, sizeof where, "(interface %d) has W = ", o->k);
	assert_fails(s, 1, need, 3);
	hb_sim_free(s);
}

/* A passive law's collision that returns energy (W < 0): the passivity check fails. */
Test(check_chain, passive_collision_returning_energy_fails)
{
	struct hb_sim *s = cradle("shccl");
	struct hb_collision *o = (struct hb_collision *)hb_sim_collision(s, 0);
	const char *need[] = { "passivity: collision 0 ", "returns energy", "shccl can only absorb it" };
	struct hb_check_chain r;

	assert_passes(s, &r);
	cr_assert_gt(o->W, 0.0, "shccl absorbed nothing");
	o->W = -o->W;
	assert_fails(s, 1, need, 3);
	hb_sim_free(s);
}

/* An isolated elastic contact whose e is 1e-6 off the law's (1 here): the restitution check fails. */
Test(check_chain, isolated_contact_with_wrong_e_fails)
{
	struct hb_sim *s = cradle("hertz");
	struct hb_collision *o = (struct hb_collision *)hb_sim_collision(s, 0);
	const char *need[] = { "restitution: collision 0 ", "no neighbour in contact", "where its law allows exactly 1" };
	struct hb_check_chain r;

	assert_passes(s, &r);
	o->e *= 1.0 - 1e-6;
	assert_fails(s, 1, need, 3);
	hb_sim_free(s);
}

/*
 * A body's final velocity 1e-6 m/s off (a bug in the flight or in a
 * cluster's centre of mass): both identities fail, the energy balance and
 * momentum, each named with its figures; the contacts still pass.
 */
Test(check_chain, body_velocity_off_breaks_energy_and_momentum)
{
	struct hb_sim *s = cradle("hertz");
	const char *need[] = { "energy: K + absorbed = ", "momentum: ", "plus the loads' impulse" };
	struct hb_check_chain r;

	assert_passes(s, &r);
	cr_assert_eq(s->body[0].cl, -1, "the bottom ball is not in flight at the end");
	s->body[0].u += 1e-6;
	assert_fails(s, 2, need, 3);
	hb_sim_free(s);
}

/*
 * An interface's work of its contact force 1e-6 J off (a bug in the works
 * the flow integrates): the energy balance fails; momentum, which does not
 * read it, holds.
 */
Test(check_chain, interface_work_off_breaks_energy_alone)
{
	struct hb_sim *s = cradle("hertz");
	const char *need[] = { "energy: K + absorbed = ", "work of the loads" };
	struct hb_check_chain r;
	char msg[1400];

	assert_passes(s, &r);
	s->ifc[0].Wc -= 1e-6;
	assert_fails(s, 1, need, 2);
	hb_check_chain(s, &r, msg, sizeof msg);
	cr_assert_null(strstr(msg, "momentum"), "%s", msg);
	hb_sim_free(s);
}

/* A run that is not a chain's is refused by name. */
Test(check_chain, not_a_chain_is_refused)
{
	struct hb_sim *s = run_ini("[scene]\nname = two\nlaw = hertz\n"
	                           "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	                           "[run]\nT = 0.001\n");
	struct hb_check_chain r;
	char msg[256];

	cr_assert_eq(hb_check_chain(s, &r, msg, sizeof msg), HB_EINVAL);
	cr_assert_str_eq(msg, "not a chain's run");
	hb_sim_free(s);
}
