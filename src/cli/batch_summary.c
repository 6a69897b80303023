/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_summary.c - the end of the batch report (batch_report.h): the
 * jumps' location records (--jumps), and the summary: why the run ended,
 * the end state, the run observables, the work done and, for a chain, its
 * bodies.
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/arc.h"
#include "hybounce/check.h"
#include "hybounce/error.h"
#include "hybounce/law.h"
#include "hybounce/observables.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/units.h"

#include "batch_report.h"
#include "signals.h"

static const char *
how_str(int how)
{
	switch (how) {
	case HB_LOCATE_START: return "start";
	case HB_LOCATE_CLOSED_FORM: return "closed-form";
	case HB_LOCATE_BRENT: return "brent";
	default: return "?";
	}
}

void
batch_print_jumps(FILE *out, const struct hb_arc *a)
{
	size_t k, n = hb_arc_njumps(a);

	fprintf(out, "jumps (%zu): t [s], j before the jump, the part of C that was left, "
	        "how it was located,\n"
	        "root-finder iterations, final bracket width [s], flow-set indicator "
	        "on the C side and on the D side\n", n);
	fprintf(out, "%6s  %22s  %6s  %-28s  %-11s  %5s  %10s  %11s  %11s\n",
	        "k", "t [s]", "j", "left", "how", "iter", "width [s]",
	        "ind (C)", "ind (D)");
	for (k = 0; k < n; k++) {
		const struct hb_arc_jump *jp = hb_arc_jump_at(a, k);

		fprintf(out, "%6zu  %22.17g  %6ld  %-28s  %-11s  %5d  %10.3e  %11.3e  %11.3e\n",
		        k, jp->t, jp->j, jp->left ? jp->left : "?", how_str(jp->how),
		        jp->iterations, jp->width, jp->ind_lo, jp->ind_hi);
	}
	fprintf(out, "\n");
}

/*
 * Significant digits of a value v with error bar err: down to the error's
 * first digit, 6 at least, 17 at most.
 */
static int
value_digits(double v, double err)
{
	int d = 6;

	if (err > 0 && isfinite(err) && v != 0 && isfinite(v))
		d = (int)floor(log10(fabs(v))) - (int)floor(log10(err)) + 1;
	return d < 6 ? 6 : d > 17 ? 17 : d;
}

/*
 * The run observables (observables.h), "name = value unit" in SI as a
 * sweep's runs.csv has them (6 digits; "-" where there is none), as many
 * to a line as fit in 79 columns.
 */
static void
print_observables(FILE *out, const struct hb_sim *s, const struct hb_error_estimate *est)
{
	int col = 12; /* "  observables" less the blank that each pair brings */

	fprintf(out, "  observables");
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		const struct hb_observable_def *d = &hb_observables[k];
		double v = hb_observable_value(s, k);
		char b[96];
		int len;

		if (isnan(v))
			len = snprintf(b, sizeof b, "%s = -", d->name);
		else if (d->whole)
			len = est != NULL && !isnan(est->obs[k])
			    ? snprintf(b, sizeof b, "%s = %ld +- %ld", d->name, (long)v, (long)est->obs[k])
			    : snprintf(b, sizeof b, "%s = %ld", d->name, (long)v);
		else if (est != NULL && !isnan(est->obs[k]))
			len = snprintf(b, sizeof b, "%s = %.*g +- %.0e%s%s", d->name,
			               value_digits(v, est->obs[k]), v, est->obs[k],
			               d->unit[0] ? " " : "", d->unit);
		else
			len = snprintf(b, sizeof b, "%s = %.6g%s%s", d->name, v, d->unit[0] ? " " : "",
			               d->unit);
		if (k > 0 && col + 2 + len > 79) {
			fprintf(out, ",\n              %s", b);
			col = 14 + len;
		} else {
			fprintf(out, "%s %s", k ? "," : "", b);
			col += 2 + len;
		}
	}
	fprintf(out, "\n");
}

/*
 * A chain's bodies at the end: velocity and kinetic energy of each, the
 * totals, the energy the interfaces hold (stored) and took for good
 * (dissipated) (hb_check_chain; "-" on a failed run), and momentum.
 */
static void
print_bodies(FILE *out, const struct hb_sim *s)
{
	char b1[64], b2[64], b3[64];
	double K = 0.0, P = 0.0;
	int i, n = hb_sim_nbodies(s);
	struct hb_check_chain r;

	for (i = 0; i < n; i++) {
		struct hb_sim_body b;

		hb_sim_body(s, i, &b);
		K += 0.5 * b.m * b.u * b.u;
		P += b.m * b.u;
		if (n <= 12 || i < 5 || i >= n - 5)
			fprintf(out, "  body %-6d u = %s, kinetic energy %s\n", i + 1,
			        batch_fmt(b.u, hb_unit_velocity, b1, sizeof b1),
			        batch_fmt(0.5 * b.m * b.u * b.u, hb_unit_energy, b2, sizeof b2));
		else if (i == 5)
			fprintf(out, "  ...\n");
	}
	hb_check_chain(s, &r, NULL, 0);
	fprintf(out, "  chain       kinetic energy %s, stored %s, dissipated %s, momentum %.9g kg m/s\n",
	        batch_fmt(K, hb_unit_energy, b1, sizeof b1),
	        batch_fmt(r.stored, hb_unit_energy, b2, sizeof b2),
	        batch_fmt(r.dissipated, hb_unit_energy, b3, sizeof b3), P);
	{
		long nlim;
		const char *note = hb_sim_limits(s, &nlim);

		if (nlim > 0) /* run.chain_limits = warn */
			fprintf(out, "  limits      passed %ld time%s (run.chain_limits = warn); the first: %s\n",
			        nlim, nlim == 1 ? "" : "s", note);
	}
}

void
batch_print_summary(FILE *out, const struct hb_sim *s, int sig, const struct hb_error_estimate *est)
{
	const struct hb_scene *sc = hb_sim_scene(s);
	const struct hb_arc *a = hb_sim_arc(s);
	const struct hb_arc_sample *last = hb_arc_last(a);
	const struct hb_sim_stats *st = hb_sim_stats(s);
	char b1[64], b2[64], b3[64], b4[64];
	int i;

	fprintf(out, "summary\n");
	if (sig != 0)
		fprintf(out, "  ended       interrupted by %s at t = %s, j = %ld (run.T = %s)\n",
		        cli_signal_name(sig),
		        batch_fmt(last != NULL ? last->t : 0, hb_unit_time, b1, sizeof b1),
		        last != NULL ? last->j : 0L, batch_fmt(sc->run.T, hb_unit_time, b2, sizeof b2));
	else
		fprintf(out, "  ended       %s\n", hb_sim_end_str(s));
	if (last != NULL) {
		fprintf(out, "  end state   t = %s, j = %ld, q_c = %d, x = %s, v = %s, x_c = %s",
		        batch_fmt(last->t, hb_unit_time, b1, sizeof b1), last->j, last->q,
		        batch_fmt(last->x, hb_unit_length, b2, sizeof b2),
		        batch_fmt(last->v, hb_unit_velocity, b3, sizeof b3),
		        batch_fmt(last->xc, hb_unit_length, b4, sizeof b4));
		for (i = 0; i < sc->law->n_z && i < HB_LAW_MAX_Z; i++)
			fprintf(out, ", z_c%d = %.6g", i + 1, last->z[i]);
		fprintf(out, "\n");
	}
	if (hb_sim_collisions_total(s) > (long)hb_sim_ncollisions(s))
		fprintf(out, "  collisions  %ld (%zu kept in the table and CSV: the older ones are "
		        "thinned, each row keeps its index i)\n", hb_sim_collisions_total(s),
		        hb_sim_ncollisions(s));
	else
		fprintf(out, "  collisions  %zu\n", hb_sim_ncollisions(s));
	print_observables(out, s, est);
	fprintf(out, "  run time    %s CPU", batch_fmt(st->seconds, hb_unit_time, b1, sizeof b1));
	fprintf(out, ", %s wall\n", batch_fmt(st->wall, hb_unit_time, b1, sizeof b1));
	fprintf(out, "  steps       %ld accepted, %ld rejected\n", st->steps, st->rejected);
	fprintf(out, "  evaluations %ld right-hand side, %ld Jacobian\n", st->rhs, st->jac);
	fprintf(out, "  events      %ld jumps, %ld kinks, %ld located by root finding, "
	        "%ld flights in closed form\n",
	        st->jumps, st->kinks, st->located, st->flights_closed);
	if (st->stiff) {
		char tb[32];

		batch_fmt(st->stiff_t, hb_unit_time, tb, sizeof tb);
		if (st->switched)
			fprintf(out, "  stiffness   the contact flow is stiff from t = %s (h |lambda| up to "
			        "%.3g): run.stepper = auto went over to bsimp\n", tb, st->stiff_hrho);
		else
			fprintf(out, "  stiffness   the contact flow is stiff from t = %s: %s is held back by "
			        "stability (h |lambda| up to %.3g);\n"
			        "              --set run.stepper=auto (or bsimp) takes far fewer steps\n",
			        tb, hb_scene_stepper_name(sc->run.stepper), st->stiff_hrho);
	}
	if (st->dips > 0)
		fprintf(out, "              %ld events found inside a step whose ends were both in C\n",
		        st->dips);
	fprintf(out, "  arc         %zu samples, %zu flow intervals",
	        hb_arc_len(a), hb_arc_nintervals(a));
	if (hb_arc_thinned(a) > 0)
		fprintf(out, ", thinned %d times (past run.max_samples = %ld)",
		        hb_arc_thinned(a), sc->run.max_samples);
	if (hb_arc_skipped(a) > 0)
		fprintf(out, ", %ld flow intervals thinned out with their jumps", hb_arc_skipped(a));
	else
		fprintf(out, ", not thinned");
	fprintf(out, "\n");
	if (sc->chain.n > 0)
		print_bodies(out, s);
}
