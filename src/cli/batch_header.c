/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_header.c - the header block of the batch report (batch_report.h):
 * preset, law, system, bodies, a chain's overrides, loads, initial state,
 * derived values and the run settings, with the per-component scales of
 * the absolute tolerance.
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/law.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "batch_report.h"

/* N m^-3/2: the Hertz coefficient k_H = 4/3 E* sqrt(R_e). */
static const struct hb_unit_dim dim_kH = { 1, -0.5, -2, 0, 0 };

static void
print_law(FILE *out, const struct hb_scene *sc)
{
	const struct hb_law_type *law = sc->law;
	double p = hb_law_exponent_p(law, sc->par), nn = hb_law_exponent_n(law, sc->par);
	char b[64];
	int i;

	fprintf(out, "law         %s: %s\n", law->name, law->title);
	fprintf(out, "            extension beyond x_c = 0 (rule R1): %s\n",
	        sc->ext ? "adhesive" : "none (clamped)");
	for (i = 0; i < law->n_params; i++) {
		const struct hb_law_param *pp = &law->params[i];

		fprintf(out, "            %-8s = %s%s\n", pp->name,
		        batch_fmt(sc->par[i], hb_units_resolve(pp->dim, p, nn), b, sizeof b),
		        (pp->flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived
		            ? "  (derived from k_H)" : "");
	}
}

static void
print_body(FILE *out, int k, const struct hb_scene_body *bd)
{
	char e[64], r[64], rho[64], m[64];

	fprintf(out, "body %d      %s:", k + 1, bd->name[0] ? bd->name : "(unnamed)");
	if (bd->has_material)
		fprintf(out, " E = %s, nu = %g,", batch_fmt(bd->E, hb_unit_pressure, e, sizeof e), bd->nu);
	if (bd->rho > 0)
		fprintf(out, " rho = %s,", batch_fmt(bd->rho, hb_unit_density, rho, sizeof rho));
	fprintf(out, " R = %s%s, m = %s%s\n", batch_fmt(bd->R, hb_unit_length, r, sizeof r),
	        isinf(bd->R) ? " (flat)" : "",
	        batch_fmt(bd->mass, hb_unit_mass, m, sizeof m),
	        isinf(bd->mass) ? " (fixed obstacle)" : bd->mass_given ? " (given)" : "");
}

/* A chain's overrides (scene.h: body.I.*, interface.K.*, initial.body.I.*), wrapped at 79 columns. */
static void
print_overrides(FILE *out, const struct hb_scene *sc)
{
	int col = 0;

	for (int i = 0; i < sc->over.n && i < HB_SCENE_MAX_OVERRIDES; i++) {
		const struct hb_scene_override *o = &sc->over.o[i];
		struct hb_scene_keyinfo ki;
		char key[64], b[128];
		int len;

		snprintf(key, sizeof key, "%s%d.%s", o->kind == HB_OVERRIDE_BODY ? "body." :
		         o->kind == HB_OVERRIDE_IFACE ? "interface." : "initial.body.", o->index, o->name);
		if (hb_scene_get(sc, key, &ki, NULL) != HB_OK)
			continue;
		len = snprintf(b, sizeof b, "%s = %s", key, ki.value);
		if (col == 0) {
			fprintf(out, "overrides   %s", b);
			col = 12 + len;
		} else if (col + 2 + len > 79) {
			fprintf(out, ",\n            %s", b);
			col = 12 + len;
		} else {
			fprintf(out, ", %s", b);
			col += 2 + len;
		}
	}
	if (col > 0)
		fprintf(out, "\n");
}

void
batch_print_header(FILE *out, const char *preset, const char *path,
             const struct hb_scene *sc, const struct hb_sim_stats *st)
{
	const struct hb_scene_derived *d = &sc->d;
	char a[64], b[64], c[64], e[64];
	int i, k;

	fprintf(out, "hybounce %s batch run\n", HYBOUNCE_VERSION);
	fprintf(out, "preset      %s (%s)\n", preset, path);
	fprintf(out, "title       %s\n", sc->name);
	if (sc->description[0])
		batch_print_wrapped(out, "            ", sc->description);
	print_law(out, sc);
	if (sc->chain.n > 0) {
		/* chain.spacing = 0: the bodies touch */
		if (sc->chain.spacing == 0.0)
			snprintf(c, sizeof c, "touching");
		else
			snprintf(c, sizeof c, "%s apart", batch_fmt(sc->chain.spacing, hb_unit_length, a, sizeof a));
		fprintf(out, "system      chain of %d bodies (each body 1, the law between neighbours%s)%s, "
		        "%s, striker (body %d) at %s\n", sc->chain.n,
		        sc->over.n > 0 ? ", but for the overrides" : "",
		        sc->chain.floor ? " on a floor" : "", c, sc->chain.n,
		        batch_fmt(sc->chain.v, hb_unit_velocity, b, sizeof b));
	}
	else if (d->system == HB_SCENE_REDUCED)
		fprintf(out, "system      reduced H_r: body 2 is a fixed obstacle\n");
	else
		fprintf(out, "system      full H_f: two finite masses on a common axis\n");
	for (k = 0; k < (sc->chain.n > 0 ? 1 : 2); k++)
		print_body(out, k, &sc->body[k]);
	print_overrides(out, sc);
	fprintf(out, "loads       g = %s, F1 = %s, F2 = %s",
	        batch_fmt(sc->loads.g, hb_unit_accel, a, sizeof a),
	        batch_fmt(sc->loads.F1, hb_unit_force, b, sizeof b),
	        batch_fmt(sc->loads.F2, hb_unit_force, c, sizeof c));
	if (sc->loads.ramp)
		fprintf(out, ", ramp: F_e0 = %s, T_s = %s, T_e = %s",
		        batch_fmt(sc->loads.Fe0, hb_unit_force, a, sizeof a),
		        batch_fmt(sc->loads.Ts, hb_unit_time, b, sizeof b),
		        batch_fmt(sc->loads.Te, hb_unit_time, c, sizeof c));
	fprintf(out, "\n");
	if (sc->chain.n == 0) {
		fprintf(out, "initial     x0 = %s, v0 = %s",
		        batch_fmt(sc->init.x0, hb_unit_length, a, sizeof a),
		        batch_fmt(sc->init.v0, hb_unit_velocity, b, sizeof b));
		if (d->system == HB_SCENE_FULL)
			fprintf(out, ", x_m0 = %s, v_m0 = %s",
			        batch_fmt(sc->init.xm0, hb_unit_length, a, sizeof a),
			        batch_fmt(sc->init.vm0, hb_unit_velocity, b, sizeof b));
		fprintf(out, "\n");
	}
	fprintf(out, "derived     E* = %s, R_e = %s, m = %s",
	        batch_fmt(d->Estar, hb_unit_pressure, a, sizeof a),
	        batch_fmt(d->Re, hb_unit_length, b, sizeof b),
	        batch_fmt(d->m, hb_unit_mass, c, sizeof c));
	if (d->system == HB_SCENE_FULL)
		fprintf(out, "\n            m1 = %s, m2 = %s, eta = %.6g",
		        batch_fmt(d->m1, hb_unit_mass, a, sizeof a),
		        batch_fmt(d->m2, hb_unit_mass, b, sizeof b), d->eta);
	fprintf(out, "\n            k_H = %s", batch_fmt(d->kH, dim_kH, e, sizeof e));
	for (i = 0; i < sc->law->n_params; i++) {
		const struct hb_law_param *pp = &sc->law->params[i];

		if (pp->flags & HB_LAW_PARAM_STIFFNESS)
			fprintf(out, ", %s = %s%s", pp->name,
			        batch_fmt(sc->par[i], hb_units_resolve(pp->dim,
			            hb_law_exponent_p(sc->law, sc->par),
			            hb_law_exponent_n(sc->law, sc->par)), a, sizeof a),
			        d->k_derived ? " (from the materials, Hertz)" : " (typed)");
	}
	fprintf(out, "\n");
	fprintf(out, "run         T = %s, J = %ld, stepper %s, rtol = %.3g, atol = %.3g",
	        batch_fmt(sc->run.T, hb_unit_time, a, sizeof a), sc->run.J,
	        hb_scene_stepper_name(sc->run.stepper), sc->run.rtol, sc->run.atol);
	if (sc->run.h_max > 0)
		fprintf(out, ", h_max = %s", batch_fmt(sc->run.h_max, hb_unit_time, b, sizeof b));
	fprintf(out, "\n");
	if (st != NULL && st->ncomp > 0) {
		char line[512];
		size_t len = 0;

		fprintf(out, "            absolute tolerance = atol x scale (scales of the last contact):\n");
		line[0] = '\0';
		for (i = 0; i < st->ncomp && i < HB_SIM_MAXCOMP && len < sizeof line; i++)
			len += (size_t)snprintf(line + len, sizeof line - len, "%s%s %.3g",
			                        i ? ", " : "", st->comp[i] ? st->comp[i] : "?",
			                        st->scale[i]);
		batch_print_wrapped(out, "            ", line);
	}
	fprintf(out, "\n");
}
