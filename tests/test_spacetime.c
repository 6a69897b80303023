/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_spacetime.c - the space-time view's buffer (src/tui/spacetime.c),
 * no terminal: on a Newton's cradle with gaps, the shadow run finds each
 * collision's contact at its interface (from the top down) and extent,
 * and the recorded positions are the run's; on a chain of 100 the buffer
 * stays within its bound and still marks every contact.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <criterion/criterion.h>

#include "hybounce/status.h"
#include "spacetime.h"
#include "testutil.h"
#include "tui.h"

static struct app *
app_on(const char *chain, double T)
{
	char ini[2048];
	struct hb_scene sc;
	struct app *a = calloc(1, sizeof *a);

	cr_assert_not_null(a);
	snprintf(ini, sizeof ini,
	         "[scene]\nname = chain\nlaw = hertz\n"
	         "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
	         "[chain]\n%s\n[striker]\nv = -1 m/s\n[loads]\ng = 0\n"
	         "[run]\nT = %.17g\nrtol = 1e-12\natol = 1e-14\n", chain, T);
	scene_from(ini, &sc);
	a->sim = run_scene(&sc);
	a->budget = 0.002;
	a->branch_t = -1;   /* no branch (app_adopt sets it so) */
	act_spacetime(a);
	cr_assert(spacetime_on(a));
	for (int n = 0; spacetime_tick(a); n++)
		cr_assert(n < 100000, "the shadow never ends");
	return a;
}

static void
app_off(struct app *a)
{
	hb_sim_free(a->sim);
	spacetime_free(a);
	log_free(a);
	free(a);
}

Test(spacetime, cradle_contacts_per_interface)
{
	struct app *a = app_on("n = 5\nspacing = 1 mm", 0.01);
	const struct spacetime *st = a->st;
	size_t nc = hb_sim_ncollisions(a->sim), hint = 0;

	cr_assert_eq(st->nb, 5);
	cr_assert_eq(st->k0, 1);
	cr_assert_eq(nc, 4);
	cr_assert_eq(st->nc, nc, "contacts %zu, collisions %zu", st->nc, nc);
	for (size_t i = 0; i < nc; i++) {
		const struct hb_collision *c = hb_sim_collision(a->sim, i);
		/* the striker (body 5) hits body 4 at interface 4, then 3, 2, 1 */
		cr_assert_eq(st->c[i].k, 4 - (int)i, "contact %zu at interface %d", i, st->c[i].k);
		cr_assert_float_eq(st->c[i].t0, c->te, 1e-12, "contact %zu starts at %g, not %g", i,
		                   st->c[i].t0, c->te);
		cr_assert_float_eq(st->c[i].t1, c->ts, 1e-12, "contact %zu ends at %g, not %g", i,
		                   st->c[i].t1, c->ts);
		cr_assert_eq(st->c[i].j, c->j, "contact %zu in interval %ld, not %ld", i, st->c[i].j, c->j);
	}
	/* the gap of interface 4 (bodies 4 and 5) closes at 1 m/s: half of 1 mm at 0.5 ms */
	cr_assert_float_eq(st_gap_at(st, 4, 0.0005), 0.0005, 1e-12);
	cr_assert_float_eq(st_gap_at(st, 3, 0.0005), 0.001, 1e-12);
	/* at the end every body where the run left it */
	cr_assert_eq(st->t[st->nrec - 1], hb_arc_last(hb_sim_arc(a->sim))->t);
	for (int b = 0; b < st->nb; b++) {
		struct hb_sim_body hb;
		cr_assert_eq(hb_sim_body(a->sim, b, &hb), HB_OK);
		cr_assert_float_eq(st_y_at(st, b, st->t[st->nrec - 1], &hint), hb.y, 1e-12);
		hint = 0;
	}
	/* before the first contact the striker flies at 1 m/s, the others rest */
	hint = 0;
	cr_assert_float_eq(st_y_at(st, 4, 0.0005, &hint) - st_y_at(st, 4, 0.0, &hint), -0.0005, 1e-12);
	hint = 0;
	cr_assert_float_eq(st_y_at(st, 0, 0.0005, &hint), st_y_at(st, 0, 0.0, &hint), 1e-15);
	/* gaps at t = 0: the spacing */
	for (int k = 1; k < 5; k++)
		cr_assert_float_eq(st_gap(st, k, 0), 0.001, 1e-12);
	app_off(a);
}

Test(spacetime, chain_of_100_bounded)
{
	struct app *a = app_on("n = 100\nspacing = 1 mm", 0.12);
	const struct spacetime *st = a->st;

	cr_assert_eq(st->nb, 100);
	cr_assert_eq(hb_sim_ncollisions(a->sim), 99);
	cr_assert_eq(st->nc, 99);
	for (size_t i = 0; i < st->nc; i++)
		cr_assert_eq(st->c[i].k, 99 - (int)i);
	cr_assert(st->nrec <= st->cap);
	cr_assert(st->nrec * (size_t)st->nb <= ST_MAX_VALUES + 256 * 100);
	app_off(a);
}

Test(spacetime, off_frees)
{
	struct app *a = app_on("n = 3\nspacing = 1 mm", 0.01);

	act_spacetime(a);
	cr_assert(!spacetime_on(a));
	cr_assert_null(a->st->sh);
	cr_assert_eq(a->st->nrec, 0);
	app_off(a);
}

/* K cycles the interfaces 1 .. 4 of a chain of five, then back to the run's own. */
Test(spacetime, iface_cycles)
{
	struct app *a = app_on("n = 5\nspacing = 1 mm", 0.01);
	char buf[32];

	act_spacetime(a);   /* the view off: the interface still needs the buffer */
	cr_assert_eq(spacetime_iface(a), -1);
	cr_assert_str_empty(spacetime_state(a, buf, sizeof buf));
	for (int k = 1; k <= 4; k++) {
		act_iface(a);
		cr_assert_eq(spacetime_iface(a), k);
		char want[24];
		snprintf(want, sizeof want, " k=%d", k);
		cr_assert_str_eq(spacetime_state(a, buf, sizeof buf), want);
	}
	for (int n = 0; spacetime_tick(a); n++)
		cr_assert(n < 100000);
	cr_assert_eq(a->st->nc, 4, "the buffer computed for the interface without the view");
	act_iface(a);
	cr_assert_eq(spacetime_iface(a), -1);
	cr_assert_null(a->st->sh, "back to the run's own, the view off: the buffer freed");
	app_off(a);
}

/*
 * The reduced system (one body over the floor) over a long horizon, its
 * arc thinned many times: every contact is interface 0's, and each of the
 * 12 collisions is a contact with its t_e and t_s; the 13th is the
 * permanent contact the run ends in.
 */
Test(spacetime, reduced_system_thinned_arc)
{
	struct hb_scene sc;
	struct app *a = calloc(1, sizeof *a);

	cr_assert_not_null(a);
	scene_preset("steel-on-bitumen", &sc);
	sc.run.T = 20;
	sc.run.max_samples = 2000;
	a->sim = run_scene(&sc);
	a->budget = 0.002;
	a->branch_t = -1;
	act_spacetime(a);
	for (int n = 0; spacetime_tick(a); n++)
		cr_assert(n < 1000000, "the shadow never ends");
	cr_assert(hb_arc_thinned(hb_sim_arc(a->st->sh)) > 0, "the shadow's arc was not thinned");
	cr_assert_eq(a->st->nb, 1);
	cr_assert_eq(a->st->k0, 0);
	cr_assert_eq(hb_sim_ncollisions(a->sim), 12);
	cr_assert_eq(a->st->nc, 13, "contacts %zu", a->st->nc);
	for (size_t i = 0; i < a->st->nc; i++) {
		cr_assert_eq(a->st->c[i].k, 0);
		if (i < 12) {
			const struct hb_collision *c = hb_sim_collision(a->sim, i);
			cr_assert_float_eq(a->st->c[i].t0, c->te, 1e-12);
			cr_assert_float_eq(a->st->c[i].t1, c->ts, 1e-12);
		}
	}
	app_off(a);
}

/*
 * B: the body whose y and u the plots show.  st_u_at is the derivative of
 * st_y_at's cubic: the recorded velocity at each record, and in free
 * flight (no load here) the constant velocity between records; B cycles
 * the bodies, then the run's own, and K takes an interface instead.
 */
Test(spacetime, body_velocity_and_cycle)
{
	struct app *a = app_on("n = 3\nspacing = 1 mm", 0.01);
	const struct spacetime *st = a->st;
	size_t nb = (size_t)st->nb, hint = 0;
	char buf[16];

	cr_assert_eq(st->nb, 3);
	for (size_t k = 0; k < st->nrec; k++)
		for (int b = 0; b < st->nb; b++) {
			double u = st->u[k * nb + (size_t)b];
			cr_assert(fabs(st_u_at(st, b, st->t[k], &hint) - u) <= 1e-9 * (1 + fabs(u)),
			          "record %zu body %d", k, b);
		}
	/* between two records in flight: the mean velocity (y1 - y0) / h */
	for (size_t k = 0; k + 1 < st->nrec; k++) {
		double h = st->t[k + 1] - st->t[k], t = st->t[k] + 0.37 * h;
		double u0 = st->u[k * nb + 2], u1 = st->u[(k + 1) * nb + 2];
		if (!(h > 0) || fabs(u0 - u1) > 1e-12)
			continue;
		cr_assert(fabs(st_u_at(st, 2, t, &hint) - u0) <= 1e-9, "between records %zu and %zu", k, k + 1);
	}
	cr_assert_eq(spacetime_body(a), -1);
	for (int b = 0; b < 3; b++) {
		act_body(a);
		cr_assert_eq(spacetime_body(a), b);
		cr_assert_eq(spacetime_iface(a), -1);
		snprintf(buf, sizeof buf, " b=%d", b + 1);
		cr_assert_str_eq(spacetime_state(a, buf + 8, 8), buf);
	}
	act_body(a);
	cr_assert_eq(spacetime_body(a), -1, "after the last body: the run's own");
	act_body(a);
	act_iface(a);
	cr_assert_eq(spacetime_body(a), -1, "K takes an interface instead of the body");
	cr_assert_geq(spacetime_iface(a), 0);
	app_off(a);
}
