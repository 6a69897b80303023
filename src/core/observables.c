/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * observables.c - the table of run observables (see observables.h) and
 * its documentation blocks (docs.h: the runs.csv columns of the man page
 * and the README, written by tools/gendoc.c).
 */
#include <math.h>
#include <string.h>

#include "hybounce/observables.h"
#include "hybounce/sim.h"

#include "docs.h"
#include "textbuf.h"
#include "sim_impl.h"

static const struct hb_collision *
first(const struct hb_sim *s)
{
	const struct hb_collision *c = hb_sim_collision(s, 0);

	/* thinning keeps the first; a run truncated before it has none */
	return c != NULL && c->i == 0 ? c : NULL;
}

static const struct hb_collision *
last(const struct hb_sim *s)
{
	size_t n = hb_sim_ncollisions(s);

	/* thinning keeps the newest quarter: the last kept is the last one */
	return n > 0 ? hb_sim_collision(s, n - 1) : NULL;
}

static double
o_collisions(const struct hb_sim *s)
{
	return (double)hb_sim_collisions_total(s);
}

/*
 * The commencement of the contact in progress at the end; a chain's, the
 * latest of its contacts in progress (since then every one has held).
 */
static double
o_t_pc(const struct hb_sim *s)
{
	struct hb_collision live;
	double t = NAN;

	if (hb_sim_end(s) == HB_SIM_END_FAIL)
		return NAN;
	for (size_t k = 0; hb_sim_contact_live_nth(s, k, &live); k++)
		if (!(live.te <= t))
			t = live.te;
	return t;
}

static double
o_e_first(const struct hb_sim *s)
{
	const struct hb_collision *c = first(s);
	return c ? c->e : NAN;
}

static double
o_v_i_first(const struct hb_sim *s)
{
	const struct hb_collision *c = first(s);
	return c ? c->vi : NAN;
}

static double
o_e_last(const struct hb_sim *s)
{
	const struct hb_collision *c = last(s);
	return c ? c->e : NAN;
}

static double
o_v_i_last(const struct hb_sim *s)
{
	const struct hb_collision *c = last(s);
	return c ? c->vi : NAN;
}

static double
o_x_c_r_total(const struct hb_sim *s)
{
	const struct hb_collision *c = last(s);
	return c ? c->xcr_sum : 0.0;
}

#define END(fn, expr, none)                                              \
	static double fn(const struct hb_sim *s)                         \
	{                                                                \
		const struct hb_arc_sample *p = hb_arc_last(hb_sim_arc(s)); \
		return p != NULL ? (double)(expr) : (none);              \
	}
END(o_t_end, p->t, NAN)
END(o_j_end, p->j, 0.0)
END(o_q_c_end, p->q, 0.0)
END(o_x_end, p->x, NAN)
END(o_v_end, p->v, NAN)
END(o_x_c_end, p->xc, NAN)
#undef END

/*
 * A chain's bodies leaving it at the end (observables.h, README Chains):
 * without a floor, counted from body 1 (the end away from the striker)
 * up, each body that moves down (u_i < 0), out of contact with the body
 * above, and faster than it (the gap between them opening), every body
 * below it counting too, the striker (body n) never; on a floor, counted
 * from the striker (body n) down, each body that moves up (u_i > 0), out
 * of contact with the body (or floor) below and faster than it, every body
 * above it counting too.  NAN for the two-body scenes.
 */
static double
o_leaving(const struct hb_sim *s)
{
	int n = s->nbody, i, count = 0;

	if (!s->chain || hb_arc_last(s->arc) == NULL)
		return NAN;
	if (s->k0 == 1) { /* no floor: interface i (index i - 1) is above body i - 1 */
		for (i = 0; i < n - 1; i++) {
			struct hb_sim_body b, up;

			hb_sim_body(s, i, &b);
			hb_sim_body(s, i + 1, &up);
			if (s->ifc[i].q || !(b.u < 0.0) || !(b.u < up.u))
				break;
			count++;
		}
	} else { /* a floor: interface i (index i) is below body i */
		for (i = n - 1; i >= 0; i--) {
			struct hb_sim_body b, lo = { 0 };

			hb_sim_body(s, i, &b);
			if (i > 0)
				hb_sim_body(s, i - 1, &lo);
			if (s->ifc[i].q || !(b.u > 0.0) || !(b.u > lo.u))
				break;
			count++;
		}
	}
	return (double)count;
}

#define STAT(fn, field) \
	static double fn(const struct hb_sim *s) { return (double)hb_sim_stats(s)->field; }
STAT(o_steps, steps)
STAT(o_rejected, rejected)
STAT(o_rhs, rhs)
STAT(o_jac, jac)
#undef STAT

const struct hb_observable_def hb_observables[HB_OBS_COUNT] = {
	[HB_OBS_COLLISIONS] = { "collisions", "", &hb_unit_none,
	    "completed collisions, every one (also those thinned out of the kept list)", 1,
	    o_collisions },
	[HB_OBS_T_PC] = { "t_pc", "s", &hb_unit_time,
	    "time of permanent contact: commencement of the contact still in progress at the "
	    "end, a chain's latest (none if the run ends apart or failed)", 0, o_t_pc },
	[HB_OBS_E_FIRST] = { "e_first", "", &hb_unit_none,
	    "coefficient of restitution of the first collision", 0, o_e_first },
	[HB_OBS_V_I_FIRST] = { "v_i_first", "m/s", &hb_unit_velocity,
	    "approach velocity of the first collision", 0, o_v_i_first },
	[HB_OBS_E_LAST] = { "e_last", "", &hb_unit_none,
	    "coefficient of restitution of the last completed collision", 0, o_e_last },
	[HB_OBS_V_I_LAST] = { "v_i_last", "m/s", &hb_unit_velocity,
	    "approach velocity of the last completed collision", 0, o_v_i_last },
	[HB_OBS_X_C_R_TOTAL] = { "x_c_r_total", "m", &hb_unit_length,
	    "sum of the residual indentations x_c^r of every collision", 0, o_x_c_r_total },
	[HB_OBS_T_END] = { "t_end", "s", &hb_unit_time, "time at the end of the run", 0, o_t_end },
	[HB_OBS_J_END] = { "j_end", "", &hb_unit_none, "flow interval at the end", 1, o_j_end },
	[HB_OBS_Q_C_END] = { "q_c_end", "", &hb_unit_none, "contact mode at the end (1: in contact)",
	    1, o_q_c_end },
	[HB_OBS_X_END] = { "x_end", "m", &hb_unit_length, "gap x at the end", 0, o_x_end },
	[HB_OBS_V_END] = { "v_end", "m/s", &hb_unit_velocity, "relative velocity v at the end",
	    0, o_v_end },
	[HB_OBS_X_C_END] = { "x_c_end", "m", &hb_unit_length, "indentation x_c at the end", 0,
	    o_x_c_end },
	[HB_OBS_LEAVING] = { "leaving", "", &hb_unit_none,
	    "a chain's bodies leaving it at the end: without a floor from body 1 up, each moving "
	    "down, out of contact with the body above and faster than it (the striker never); on "
	    "a floor from the striker down, each moving up, out of contact with the body or floor "
	    "below and faster than it (none for two bodies)", 0, o_leaving },
	[HB_OBS_STEPS] = { "steps", "", &hb_unit_none, "accepted integration steps", 1, o_steps },
	[HB_OBS_REJECTED] = { "rejected", "", &hb_unit_none, "rejected integration steps", 1,
	    o_rejected },
	[HB_OBS_RHS] = { "rhs", "", &hb_unit_none, "right-hand side evaluations", 1, o_rhs },
	[HB_OBS_JAC] = { "jac", "", &hb_unit_none, "Jacobian evaluations", 1, o_jac },
};

double
hb_observable_value(const struct hb_sim *s, int k)
{
	return k >= 0 && k < HB_OBS_COUNT ? hb_observables[k].value(s) : NAN;
}

int
hb_observable_find(const char *name)
{
	for (int k = 0; name != NULL && k < HB_OBS_COUNT; k++)
		if (strcmp(hb_observables[k].name, name) == 0)
			return k;
	return -1;
}

size_t
run_observables_mdoc(char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };

	if (buf != NULL && n > 0)
		buf[0] = '\0';
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		const struct hb_observable_def *d = &hb_observables[k];
		textbuf_printf(&o, ".It Li %s\n%s%s%s\n", d->name, d->meaning, d->unit[0] ? ", " : "",
		    d->unit);
	}
	return o.len;
}

size_t
run_observables_markdown(char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };

	if (buf != NULL && n > 0)
		buf[0] = '\0';
	textbuf_printf(&o, "| column | meaning | unit |\n|---|---|---|\n");
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		const struct hb_observable_def *d = &hb_observables[k];
		textbuf_printf(&o, "| `%s` | %s | %s |\n", d->name, d->meaning,
		    d->unit[0] ? d->unit : "–");
	}
	return o.len;
}
