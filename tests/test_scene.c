/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_scene.c - scenes (src/core/scene*.c): the defaults, the derived values
 * against the paper's printed 'Inferred' rows (Tables tab:one, tab:two,
 * tab:slow and x_c^s), hb_scene_set and its messages, validation, the panel
 * rows, and the applied loads of the second study: F_er, the kinks, and the
 * closed-form flight increments and centre of mass against numerical
 * quadrature (GSL QAG); typed access to the keys (hb_scene_get) and errors as
 * data (struct hb_scene_error).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"
#include "testutil.h"

static void
set(struct hb_scene *sc, const char *key, const char *text)
{
	char msg[256] = "";

	cr_assert_eq(hb_scene_set(sc, key, text, msg, sizeof msg), HB_OK, "%s = %s: %s", key, text,
	    msg);
}

static void
set_fails(struct hb_scene *sc, const char *key, const char *text, const char *part)
{
	char msg[512] = "";
	struct hb_scene before;

	memcpy(&before, sc, sizeof before);
	cr_assert_eq(hb_scene_set(sc, key, text, msg, sizeof msg), HB_EINVAL, "%s = %s accepted",
	    key, text);
	cr_assert(strstr(msg, part) != NULL, "%s = %s: message \"%s\" lacks \"%s\"", key, text, msg,
	    part);
	cr_assert(strncmp(msg, key, strlen(key)) == 0, "message \"%s\" does not begin with %s", msg,
	    key);
	cr_assert(memcmp(&before, sc, sizeof before) == 0, "%s = %s changed the scene on error", key,
	    text);
}

/* Study 1 (Table tab:one): steel on bitumen, BWMCL. */
static void
study1(struct hb_scene *sc)
{
	hb_scene_defaults(sc);
	set(sc, "scene.law", "bwmcl");
	set(sc, "body1.E", "200 GPa");
	set(sc, "body1.nu", "0.30");
	set(sc, "body1.rho", "7800 kg/m^3");
	set(sc, "body1.R", "20 mm");
	set(sc, "body2.E", "1.0 GPa");
	set(sc, "body2.nu", "0.35");
	set(sc, "body2.R", "inf");
	set(sc, "law.A", "1");
	set(sc, "law.alpha", "0.35");
	set(sc, "law.p", "1.5");
}

/* Study 2 (Table tab:two): PTFE on POM, full system, the ramp loads. */
static void
study2(struct hb_scene *sc)
{
	hb_scene_defaults(sc);
	set(sc, "scene.law", "bwshccl");
	set(sc, "body1.E", "0.50 GPa");
	set(sc, "body1.nu", "0.46");
	set(sc, "body1.rho", "2200 kg/m^3");
	set(sc, "body1.R", "20 mm");
	set(sc, "body2.E", "2.90 GPa");
	set(sc, "body2.nu", "0.35");
	set(sc, "body2.rho", "1410 kg/m^3");
	set(sc, "body2.R", "20 mm");
	set(sc, "law.A", "1");
	set(sc, "law.alpha", "0.35");
	set(sc, "law.n", "2");
	set(sc, "law.p", "1.5");
	set(sc, "law.beta", "2.409e8 m^-2");
	set(sc, "law.gamma", "2.409e8 m^-2");
	set(sc, "law.c", "2.5e7 N s m^-5/2");
	set(sc, "loads.g", "0");
	set(sc, "loads.ramp", "yes");
	set(sc, "loads.F_e0", "0.5759 N");
	set(sc, "loads.T_e", "0.20 s");
	set(sc, "loads.T_s", "0.10 s");
	set(sc, "initial.x0", "1.5 mm");
	set(sc, "initial.v_m0", "120 mm/s");
}

Test(scene, defaults_are_valid)
{
	struct hb_scene sc;
	char msg[256] = "";

	hb_scene_defaults(&sc);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(sc.law, &hb_law_hertz);
	cr_assert_eq(sc.d.system, HB_SCENE_REDUCED);
	cr_assert_eq(sc.body[0].R, 0.020);
	cr_assert_eq(sc.body[0].E, 200e9);
	cr_assert_eq(sc.body[1].R, INFINITY);
	cr_assert(isinf(sc.d.m2));
	cr_assert_eq(sc.init.x0, 0.010);
	cr_assert_eq(sc.run.T, 0.2);
	cr_assert_eq(sc.run.J, 100000);
	cr_assert_eq(sc.run.stepper, HB_STEPPER_RK8PD);
	cr_assert_eq(sc.run.rtol, 1e-10);
	cr_assert_eq(sc.run.atol, 1e-10);
	cr_assert_eq(sc.run.max_samples, 262144);
	cr_assert_eq(sc.run.chatter, 4);
	cr_assert_eq(sc.run.reduce, HB_REDUCE_ALL);
	cr_assert_eq(sc.ext, 1);
	cr_assert_eq(sc.loads.g, 9.81);
	cr_assert_eq(sc.d.k_derived, 1);
	cr_assert_eq(scene_par(&sc, "k"), sc.d.kH);
}

Test(scene, study1_inferred)
{
	struct hb_scene sc;
	char msg[256] = "";

	study1(&sc);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(sc.d.system, HB_SCENE_REDUCED);
	printed(sc.d.Estar, 1.134e9, 4, "E*");
	printed(sc.d.Re, 20e-3, 2, "R_e");
	printed(sc.d.m, 2.614e-1, 4, "m");
	printed(sc.d.kH, 2.138e8, 4, "k_H");
	cr_assert_eq(sc.d.k_derived, 1);
	printed(scene_par(&sc, "k"), 2.138e8, 4, "k");
	cr_assert(fabs(scene_par(&sc, "k") - sc.d.kH) <= 1e-15 * sc.d.kH, "k = k_H when A = 1");
	/* x_c^s of the substrate of the first study (eq. x_static). */
	printed(pow(sc.d.m * 9.81 / sc.d.kH, 1 / 1.5), 5.240e-6, 4, "x_c^s");
}

Test(scene, study2_inferred)
{
	struct hb_scene sc;
	char msg[256] = "";

	study2(&sc);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	study2_printed(&sc);
	cr_assert(fabs(sc.d.eta + sc.d.etac - 1) < 1e-15);
}

Test(scene, study3_inferred)
{
	struct hb_scene sc;
	char msg[256] = "";

	study1(&sc);
	set(&sc, "body2.E", "2.0 GPa");
	set(&sc, "scene.law", "shccl");
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	printed(sc.d.Estar, 2.256e9, 4, "E*");
	printed(sc.d.m, 2.614e-1, 4, "m");
	printed(sc.d.kH, 4.254e8, 4, "k_H");
	printed(scene_par(&sc, "k"), 4.254e8, 4, "k");
	printed(pow(sc.d.m * 9.81 / sc.d.kH, 1 / 1.5), 3.312e-6, 4, "x_c^s");
}

Test(scene, k_hertz_with_A_and_alpha)
{
	struct hb_scene sc;

	study1(&sc);
	set(&sc, "law.A", "2.385");
	set(&sc, "law.alpha", "0.6");
	/* eq. k_hertz: k = k_H / (alpha + (1 - alpha) A^p) */
	double want = sc.d.kH / (0.6 + 0.4 * pow(2.385, 1.5));
	cr_assert(fabs(scene_par(&sc, "k") - want) <= 1e-14 * want, "k = %g, want %g", scene_par(&sc, "k"), want);
}

Test(scene, reduced_and_full_by_the_bodies)
{
	struct hb_scene sc;
	char msg[256] = "";

	hb_scene_defaults(&sc);
	set(&sc, "body2.R", "20 mm");
	set(&sc, "body2.rho", "7800 kg/m^3");
	cr_assert_eq(sc.d.system, HB_SCENE_FULL);
	cr_assert(fabs(sc.d.eta - 0.5) < 1e-15);
	cr_assert(fabs(sc.d.m - sc.d.m1 / 2) < 1e-15);
	set(&sc, "body2.mass", "inf");
	cr_assert_eq(sc.d.system, HB_SCENE_REDUCED);
	cr_assert(isinf(sc.d.m2));
	cr_assert_eq(sc.d.m, sc.d.m1);
	set(&sc, "body2.mass", "0.5 kg");
	cr_assert_eq(sc.d.system, HB_SCENE_FULL);
	cr_assert_eq(sc.d.m2, 0.5);
	cr_assert_eq(sc.body[1].rho, 0, "typing a mass forgets rho");
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
}

Test(scene, set_messages)
{
	struct hb_scene sc;

	study1(&sc);
	set_fails(&sc, "law.alpha", "20 mm/s", "has unit m/s");
	set_fails(&sc, "law.alpha", "1.5", "law.alpha: value 1.5 is out of range; accepted: (0, 1)");
	set_fails(&sc, "law.alpha", "abc", "'abc' is not a number");
	set_fails(&sc, "law.n", "0.5", "accepted: [1, 1e+12]");
	set_fails(&sc, "law.p", "0.9", "accepted: [1, 1e+12]");
	set_fails(&sc, "law.k", "1e8", "derived from the materials by Hertz contact theory");
	set_fails(&sc, "law.k", "1e8", "give masses instead of materials");
	set_fails(&sc, "law.foo", "1", "unknown key");
	set_fails(&sc, "body1.E", "20 mm", "a pressure");
	set_fails(&sc, "body1.E", "-3 GPa", "accepted: (0, inf) Pa");
	set_fails(&sc, "body1.nu", "0.5", "accepted: (-1, 0.5)");
	set_fails(&sc, "body1.mass", "-1 kg", "out of range");
	set_fails(&sc, "body1.R", "20 furlong", "unknown unit 'furlong'");
	set_fails(&sc, "initial.x0", "-1 mm", "initial.x0: value -1 mm is out of range; accepted: [0, 1e+06] m");
	set_fails(&sc, "run.T", "0", "accepted: (0, inf) s");
	set_fails(&sc, "run.J", "0", "accepted");
	set_fails(&sc, "run.J", "2.5", "whole number");
	set_fails(&sc, "run.rtol", "1", "accepted: (0, 1)");
	set_fails(&sc, "run.max_samples", "1000", ">= 1024");
	set_fails(&sc, "run.chatter", "1", ">= 2");
	set_fails(&sc, "run.stepper", "euler", "rk8pd");
	set_fails(&sc, "run.reductions", "flight,warp", "flight, contact, com");
	set_fails(&sc, "scene.law", "newton", "accepted: shccl, bwshccl, bwmcl, hertz, linear");
	set_fails(&sc, "scene.extension", "sticky", "adhesive, none");
	set_fails(&sc, "loads.ramp", "maybe", "yes");
	set_fails(&sc, "derived.k", "1", "derived");
	set_fails(&sc, "nosuch.key", "1", "unknown key");
	set_fails(&sc, "scene.description", "a ; b", "comment");
	set_fails(&sc, "body1.name", "a\tb", "control characters");
}

Test(scene, set_values)
{
	struct hb_scene sc;

	hb_scene_defaults(&sc);
	set(&sc, "run.stepper", "msbdf");
	cr_assert_eq(sc.run.stepper, HB_STEPPER_MSBDF);
	set(&sc, "run.reductions", "flight, com");
	cr_assert_eq(sc.run.reduce, HB_REDUCE_FLIGHT | HB_REDUCE_COM);
	set(&sc, "run.reductions", "none");
	cr_assert_eq(sc.run.reduce, 0);
	set(&sc, "run.reductions", "all");
	cr_assert_eq(sc.run.reduce, HB_REDUCE_ALL);
	set(&sc, "run.J", "1e5");
	cr_assert_eq(sc.run.J, 100000);
	set(&sc, "scene.extension", "none");
	cr_assert_eq(sc.ext, 0);
	set(&sc, "loads.ramp", "1");
	cr_assert_eq(sc.loads.ramp, 1);
	set(&sc, "scene.name", "  a name  ");
	cr_assert_str_eq(sc.name, "a name");
	set(&sc, "initial.v0", "-28.0 mm/s");
	cr_assert(fabs(sc.init.v0 + 0.028) < 1e-17);
}

Test(scene, law_switch_loads_defaults_and_rederives)
{
	struct hb_scene sc;

	study1(&sc);
	set(&sc, "law.c", "1234 N s/m");
	set(&sc, "scene.law", "shccl");
	cr_assert_eq(sc.law, &hb_law_shccl);
	cr_assert_eq(scene_par(&sc, "c"), hb_law_shccl.params[hb_law_param_index(&hb_law_shccl, "c")].def);
	cr_assert_eq(sc.d.k_derived, 1);
	cr_assert(fabs(scene_par(&sc, "k") - sc.d.kH) <= 1e-15 * sc.d.kH);
	/* The linear law has no k_hertz: k is typed (N/m). */
	set(&sc, "scene.law", "linear");
	cr_assert_eq(sc.d.k_derived, 0);
	set(&sc, "law.k", "1e4 N/m");
	cr_assert_eq(scene_par(&sc, "k"), 1e4);
}

Test(scene, k_typed_with_masses)
{
	struct hb_scene sc;
	char msg[256] = "";

	hb_scene_defaults(&sc);
	sc.body[0].has_material = 0;
	sc.body[0].mass_given = 1;
	sc.body[0].mass = 1;
	hb_scene_derive(&sc, NULL, 0);
	cr_assert_eq(sc.d.k_derived, 0);
	cr_assert(isnan(sc.d.Estar));
	set(&sc, "law.k", "3e9 N m^-3/2");
	cr_assert_eq(scene_par(&sc, "k"), 3e9);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
}

static void
validate_fails(struct hb_scene *sc, const char *part)
{
	char msg[512] = "";

	cr_assert_eq(hb_scene_validate(sc, msg, sizeof msg), HB_EINVAL, "accepted, expected \"%s\"",
	    part);
	cr_assert(strstr(msg, part) != NULL, "message \"%s\" lacks \"%s\"", msg, part);
}

Test(scene, validate_ranges)
{
	struct hb_scene sc;
	int ig, ia;

	study1(&sc);
	ig = hb_law_param_index(sc.law, "gamma");
	ia = hb_law_param_index(sc.law, "alpha");
	sc.par[ig] = 2 * sc.par[hb_law_param_index(sc.law, "beta")];
	validate_fails(&sc, "law.gamma: ");
	validate_fails(&sc, "[-beta, beta]");

	study1(&sc);
	sc.par[ia] = 1;
	validate_fails(&sc, "law.alpha: value 1 is out of range; accepted: (0, 1)");

	study1(&sc);
	sc.init.x0 = -1e-3;
	validate_fails(&sc, "initial.x0: value -1 mm is out of range; accepted: [0, 1e+06] m");

	study1(&sc);
	sc.body[0].nu = 0.5;
	validate_fails(&sc, "body1.nu: value 0.5 is out of range; accepted: (-1, 0.5)");

	study1(&sc);
	sc.body[0].mass_given = 1;
	sc.body[0].mass = INFINITY;
	validate_fails(&sc, "body1.mass: ");

	study1(&sc);
	sc.body[0].rho = 0;
	validate_fails(&sc, "body1.mass: body 1 has no mass");

	study1(&sc);
	sc.loads.ramp = 1;
	sc.loads.Fe0 = 0;
	validate_fails(&sc, "loads.F_e0: ");

	study1(&sc);
	sc.run.atol = 0;
	validate_fails(&sc, "run.atol: ");

	study1(&sc);
	sc.run.chatter = 1;
	validate_fails(&sc, "run.chatter: ");

	study1(&sc);
	sc.run.max_samples = 10;
	validate_fails(&sc, "run.max_samples: ");

	study1(&sc);
	sc.run.h_max = -1;
	validate_fails(&sc, "run.h_max: ");

	study1(&sc);
	sc.run.J = 0;
	validate_fails(&sc, "run.J: ");
}

Test(scene, panel_rows)
{
	struct hb_scene sc;
	struct hb_scene_keyinfo ki;
	int nk, has_derived_k = 0, has_law_k = 0, has_xcs = 0, ro_law = 0;

	study1(&sc);
	sc.loads.g = 9.81;
	nk = hb_scene_nkeys(&sc);
	cr_assert(nk > 30);
	for (int i = 0; i < nk; i++) {
		cr_assert_eq(hb_scene_key(&sc, i, &ki), HB_OK);
		if (strcmp(ki.key, "derived.k") == 0) {
			has_derived_k = 1;
			cr_assert_eq(ki.readonly, 1);
			cr_assert_str_eq(ki.value, "2.138e+08 N m^-3/2");
		}
		if (strcmp(ki.key, "derived.xcs") == 0) {
			has_xcs = 1;
			cr_assert_str_eq(ki.value, "5.24 um");
		}
		if (strcmp(ki.key, "derived.Estar") == 0)
			cr_assert_str_eq(ki.value, "1.134 GPa");
		if (strcmp(ki.key, "body1.R") == 0)
			cr_assert_str_eq(ki.value, "20 mm");
		if (strcmp(ki.key, "law.k") == 0)
			has_law_k = 1;
		if (strcmp(ki.section, "law") == 0 && ki.readonly)
			ro_law = 1;
		if (strcmp(ki.key, "law.alpha") == 0) {
			cr_assert_str_eq(ki.value, "0.35");
			cr_assert_str_eq(ki.range, "(0, 1)");
		}
		cr_assert(strcmp(ki.section, "bodies") == 0 || strcmp(ki.section, "derived") == 0 ||
		    strcmp(ki.section, "law") == 0 || strcmp(ki.section, "loads") == 0 ||
		    strcmp(ki.section, "initial") == 0 || strcmp(ki.section, "run") == 0,
		    "section %s", ki.section);
	}
	cr_assert(has_derived_k && has_xcs && !has_law_k && !ro_law);
	cr_assert_eq(hb_scene_key(&sc, nk, &ki), HB_EINVAL);
	cr_assert_eq(hb_scene_key(&sc, -1, &ki), HB_EINVAL);

	/* Every editable row can be set back to the value it shows. */
	for (int i = 0; i < nk; i++) {
		char msg[256] = "";
		hb_scene_key(&sc, i, &ki);
		if (ki.readonly || strcmp(ki.value, "-") == 0 || strcmp(ki.key, "scene.law") == 0)
			continue;
		cr_assert_eq(hb_scene_set(&sc, ki.key, ki.value, msg, sizeof msg), HB_OK,
		    "%s = %s: %s", ki.key, ki.value, msg);
	}
}

/* ---------------------------------------------------------------- */
/* Loads */

static double
S(double w)
{
	return w < 0 ? 0 : w > 1 ? 1 : 0.5 * (1 - cos(M_PI * w));
}

Test(scene, study2_loads)
{
	struct hb_scene sc;
	double ts[] = { 0, 0.013, 0.05, 0.1, 0.137, 0.2, 0.31 };

	study2(&sc);
	for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++) {
		double t = ts[i], f1, f2, xm, vm, want = -0.5759 * (1 + S(t / 0.2));
		hb_scene_loads_at(&sc, t, &f1, &f2);
		/* eq. u: F_er = (m2 F_e1 - m1 F_e2)/(m1 + m2) = -F_e0 (1 + S(t/T_e)) */
		cr_assert(fabs(hb_scene_Fer(&sc, t) - want) < 1e-14, "F_er(%g)", t);
		cr_assert(fabs((sc.d.m2 * f1 - sc.d.m1 * f2) / (sc.d.m1 + sc.d.m2) - want) < 1e-14);
		/* v_m(t) = v_m0 (1 - S(t/T_s)) */
		hb_scene_com(&sc, t, &xm, &vm);
		cr_assert(fabs(vm - 0.12 * (1 - S(t / 0.1))) < 1e-15, "v_m(%g) = %g", t, vm);
	}
	double k[4];
	cr_assert_eq(hb_scene_load_kinks(&sc, 0, 0.5, k, 4), 2);
	cr_assert_eq(k[0], 0.1);
	cr_assert_eq(k[1], 0.2);
	cr_assert_eq(hb_scene_load_kinks(&sc, 0.1, 0.5, k, 4), 1);
	cr_assert_eq(k[0], 0.2);
	cr_assert_eq(hb_scene_load_kinks(&sc, 0.2, 0.5, k, 4), 0);
	cr_assert_eq(hb_scene_Fer_constant(&sc, 0.15, 0.3), 0);
	cr_assert_eq(hb_scene_Fer_constant(&sc, 0.2, 0.3), 1);
	cr_assert_eq(hb_scene_Fer_constant(&sc, 0.25, 0.3), 1);
	set(&sc, "loads.ramp", "no");
	cr_assert_eq(hb_scene_load_kinks(&sc, 0, 0.5, k, 4), 0);
	cr_assert_eq(hb_scene_Fer_constant(&sc, 0, 0.3), 1);
}

Test(scene, reduced_loads)
{
	struct hb_scene sc;
	double f1, f2;

	study1(&sc);
	hb_scene_loads_at(&sc, 0.3, &f1, &f2);
	cr_assert(fabs(f1 + sc.d.m1 * 9.81) < 1e-15);
	cr_assert_eq(hb_scene_Fer(&sc, 0.3), f1);
	set(&sc, "loads.F1", "2.385 N");
	cr_assert(fabs(hb_scene_Fer(&sc, 0.3) - (2.385 - sc.d.m1 * 9.81)) < 1e-15);
	double xm = 1, vm = 1;
	hb_scene_com(&sc, 0.3, &xm, &vm);
	cr_assert(xm == 0 && vm == 0);
}

struct qparams {
	const struct hb_scene *sc;
	double t1;
	int weighted;
	int com;
};

static double
integrand(double s, void *p)
{
	const struct qparams *q = p;
	double f;

	if (q->com) {
		double f1, f2;
		hb_scene_loads_at(q->sc, s, &f1, &f2);
		f = (f1 + f2) / (q->sc->d.m1 + q->sc->d.m2);
	} else
		f = hb_scene_Fer(q->sc, s) / q->sc->d.m;
	return q->weighted ? (q->t1 - s) * f : f;
}

/* int_{t0}^{t1} of the integrand, splitting at the load kinks. */
static double
quad(const struct hb_scene *sc, double t0, double t1, int weighted, int com)
{
	struct qparams q = { sc, t1, weighted, com };
	gsl_function F = { integrand, &q };
	gsl_integration_workspace *w = gsl_integration_workspace_alloc(1000);
	double pts[5], total = 0;
	int np = 0;

	pts[np++] = t0;
	np += hb_scene_load_kinks(sc, t0, t1, pts + np, 3);
	pts[np++] = t1;
	for (int i = 0; i + 1 < np; i++) {
		double r, err;
		gsl_integration_qag(&F, pts[i], pts[i + 1], 0, 1e-13, 1000, GSL_INTEG_GAUSS61, w, &r,
		    &err);
		total += r;
	}
	gsl_integration_workspace_free(w);
	return total;
}

static void
check_increments(const struct hb_scene *sc)
{
	static const double iv[][2] = {
		{ 0, 0.05 }, { 0.03, 0.17 }, { 0.05, 0.1 }, { 0.09, 0.11 }, { 0.15, 0.25 },
		{ 0.0, 0.5 }, { 0.19999, 0.20003 }, { 0.2, 0.3 }, { 0.31, 0.4137 }, { 0.1, 0.2 },
		{ 0.0999, 0.1000001 },
	};

	gsl_set_error_handler_off();
	for (size_t i = 0; i < sizeof iv / sizeof iv[0]; i++) {
		double t0 = iv[i][0], t1 = iv[i][1], dx, dv, qx, qv;
		hb_scene_flight_increment(sc, t0, t1, &dx, &dv);
		qv = quad(sc, t0, t1, 0, 0);
		qx = quad(sc, t0, t1, 1, 0);
		cr_assert(fabs(dv - qv) <= 1e-12 * fmax(fabs(qv), 1e-12),
		    "dv on [%g, %g]: %.15g, quadrature %.15g", t0, t1, dv, qv);
		cr_assert(fabs(dx - qx) <= 1e-11 * fmax(fabs(qx), 1e-15),
		    "dx on [%g, %g]: %.15g, quadrature %.15g", t0, t1, dx, qx);
	}
}

Test(scene, flight_increment_full_ramp)
{
	struct hb_scene sc;

	study2(&sc);
	set(&sc, "loads.F1", "0.3 N");
	set(&sc, "loads.F2", "-0.17 N");
	check_increments(&sc);
}

Test(scene, flight_increment_reduced_ramp)
{
	struct hb_scene sc;

	/* The ramp in the reduced system: F_e1 keeps its m1 a(t) term. */
	study1(&sc);
	set(&sc, "loads.ramp", "yes");
	set(&sc, "loads.F_e0", "0.5759 N");
	set(&sc, "loads.T_e", "0.2 s");
	set(&sc, "loads.T_s", "0.1 s");
	set(&sc, "initial.v_m0", "120 mm/s");
	check_increments(&sc);
	set(&sc, "loads.T_e", "0.07 s");
	check_increments(&sc);
}

Test(scene, flight_increment_constant_is_exact)
{
	struct hb_scene sc;
	double dx, dv, F;

	study1(&sc);
	F = hb_scene_Fer(&sc, 0);
	/* A short interval late in a run: F tau^2 / 2m, no cancellation. */
	hb_scene_flight_increment(&sc, 1e6, 1e6 + 1e-9, &dx, &dv);
	double tau = (1e6 + 1e-9) - 1e6;
	cr_assert(fabs(dv - F * tau / sc.d.m) <= 1e-15 * fabs(F * tau / sc.d.m));
	cr_assert(fabs(dx - F * tau * tau / (2 * sc.d.m)) <= 1e-15 * fabs(F * tau * tau / sc.d.m));
	/* Late in a ramp run, after T_e, the same. */
	study2(&sc);
	F = hb_scene_Fer(&sc, 1e3);
	hb_scene_flight_increment(&sc, 1e3, 1e3 + 1e-7, &dx, &dv);
	tau = (1e3 + 1e-7) - 1e3;
	cr_assert(fabs(dx - F * tau * tau / (2 * sc.d.m)) <= 1e-15 * fabs(F * tau * tau / sc.d.m));
	/* A short interval inside the ramp: against a Taylor expansion. */
	double t0 = 0.137, h = 1e-6, a0 = hb_scene_Fer(&sc, t0) / sc.d.m;
	double a1 = (hb_scene_Fer(&sc, t0 + 1e-7) - hb_scene_Fer(&sc, t0 - 1e-7)) / 2e-7 / sc.d.m;
	hb_scene_flight_increment(&sc, t0, t0 + h, &dx, &dv);
	double wx = a0 * h * h / 2 + a1 * h * h * h / 6;
	cr_assert(fabs(dx - wx) <= 1e-9 * fabs(wx), "dx %.17g vs %.17g", dx, wx);
}

Test(scene, com_against_quadrature)
{
	struct hb_scene sc;
	double ts[] = { 0, 0.037, 0.1, 0.15, 0.2, 0.4137 };

	gsl_set_error_handler_off();
	study2(&sc);
	set(&sc, "loads.g", "9.81");
	set(&sc, "loads.F1", "0.3 N");
	set(&sc, "loads.F2", "0.1 N");
	set(&sc, "initial.x_m0", "2.385 mm");
	for (size_t i = 0; i < sizeof ts / sizeof ts[0]; i++) {
		double t = ts[i], xm, vm, wv, wx;
		hb_scene_com(&sc, t, &xm, &vm);
		wv = sc.init.vm0 + (t > 0 ? quad(&sc, 0, t, 0, 1) : 0);
		wx = sc.init.xm0 + sc.init.vm0 * t + (t > 0 ? quad(&sc, 0, t, 1, 1) : 0);
		cr_assert(fabs(vm - wv) < 1e-13, "v_m(%g) = %.15g, quadrature %.15g", t, vm, wv);
		cr_assert(fabs(xm - wx) < 1e-14, "x_m(%g) = %.15g, quadrature %.15g", t, xm, wx);
	}
}

Test(scene, steppers)
{
	static const char *const names[] = { "rk8pd", "rkf45", "rkck", "msbdf", "rk4imp", "bsimp", "auto",
	                                     "dop853", "vern98" };

	cr_assert_eq(sizeof names / sizeof names[0], HB_STEPPER_COUNT);

	for (int i = 0; i < HB_STEPPER_COUNT; i++) {
		cr_assert_str_eq(hb_scene_stepper_name(i), names[i]);
		cr_assert_eq(hb_scene_stepper_find(names[i]), i);
	}
	cr_assert_eq(hb_scene_stepper_find("euler"), -1);
	cr_assert_eq(hb_scene_stepper_find(NULL), -1);
}

/* ---------------------------------------------------------------- */
/* Typed access and errors as data */

Test(scene, get_is_typed)
{
	struct hb_scene sc;
	struct hb_scene_keyinfo ki;
	struct hb_scene_error err;

	study1(&sc);
	cr_assert_eq(hb_scene_get(&sc, "law.alpha", &ki, &err), HB_OK);
	cr_assert_eq(ki.kind, HB_SCENE_KEY_NUMBER);
	cr_assert_eq(ki.number, sc.par[hb_law_param_index(sc.law, "alpha")]);
	cr_assert_str_eq(ki.unit, "");
	cr_assert(ki.limits.lo == 0 && ki.limits.hi == 1 && ki.limits.lo_open && ki.limits.hi_open);

	cr_assert_eq(hb_scene_get(&sc, "law.beta", &ki, &err), HB_OK);
	cr_assert_str_eq(ki.unit, "m^-2"); /* n = 2 applied */

	cr_assert_eq(hb_scene_get(&sc, "body1.R", &ki, &err), HB_OK);
	cr_assert_eq(ki.number, 0.020);
	cr_assert_str_eq(ki.unit, "m");
	cr_assert(ki.limits.lo == 0 && isinf(ki.limits.hi) && !ki.limits.hi_open);

	cr_assert_eq(hb_scene_get(&sc, "run.J", &ki, &err), HB_OK);
	cr_assert_eq(ki.kind, HB_SCENE_KEY_WHOLE);
	cr_assert(ki.limits.whole && ki.limits.lo == 1);

	cr_assert_eq(hb_scene_get(&sc, "run.stepper", &ki, &err), HB_OK);
	cr_assert_eq(ki.kind, HB_SCENE_KEY_CHOICE);
	cr_assert_eq(ki.nchoices, HB_STEPPER_COUNT);
	cr_assert_str_eq(ki.choices[ki.choice], "rk8pd");
	cr_assert_str_eq(ki.choices[HB_STEPPER_AUTO], "auto");

	cr_assert_eq(hb_scene_get(&sc, "scene.law", &ki, &err), HB_OK);
	cr_assert_str_eq(ki.choices[ki.choice], "bwmcl");
	cr_assert_eq(hb_scene_get(&sc, "run.reductions", &ki, &err), HB_OK);
	cr_assert_eq(ki.nchoices, 8);

	/* Hidden by the panel, still readable: F2 in the reduced system. */
	cr_assert_eq(hb_scene_get(&sc, "loads.F2", &ki, &err), HB_OK);
	cr_assert_str_eq(ki.unit, "N");

	cr_assert_eq(hb_scene_get(&sc, "law.nosuch", &ki, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "law.nosuch");
	cr_assert(strstr(err.accepted, "law.alpha") != NULL, "%s", err.accepted);
}

Test(scene, errors_are_data)
{
	struct hb_scene sc;
	struct hb_scene_error err;
	char buf[512];

	study1(&sc);
	cr_assert_eq(hb_scene_set_text(&sc, "law.alpha", "1.5", &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "law.alpha");
	cr_assert_eq(err.has_range, 1);
	cr_assert(err.range.lo == 0 && err.range.hi == 1);
	cr_assert_str_eq(err.accepted, "(0, 1)");
	cr_assert_str_eq(hb_scene_error_str(&err, buf, sizeof buf),
	    "law.alpha: value 1.5 is out of range; accepted: (0, 1)");

	cr_assert_eq(hb_scene_set_number(&sc, "initial.x0", -1e-3, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "initial.x0");
	cr_assert(err.has_range && err.range.lo == 0 && !err.range.lo_open);

	cr_assert_eq(hb_scene_set_text(&sc, "run.stepper", "euler", &err), HB_EINVAL);
	cr_assert_eq(err.has_range, 0);
	cr_assert(strstr(err.accepted, "bsimp") != NULL);
	/* An empty value still says what is accepted: the choices, or the unit. */
	cr_assert_eq(hb_scene_set_text(&sc, "run.stepper", " ", &err), HB_EINVAL);
	cr_assert(strstr(err.accepted, "dop853") != NULL, "%s", err.accepted);
	cr_assert_eq(hb_scene_set_text(&sc, "initial.x0", "", &err), HB_EINVAL);
	cr_assert(strstr(err.accepted, "m") != NULL && strstr(err.what, "empty") != NULL);
	cr_assert_eq(hb_scene_set_text(&sc, "derived.m", "1", &err), HB_EINVAL);
	cr_assert(err.accepted[0] != '\0');

	/* The initial state and the loads are bounded, so that no flight overflows. */
	cr_assert_eq(hb_scene_set_number(&sc, "initial.v0", -1e300, &err), HB_EINVAL);
	cr_assert(err.has_range && err.range.lo == -1e5 && err.range.hi == 1e5);
	cr_assert_eq(hb_scene_set_number(&sc, "initial.v0", -1e5, &err), HB_OK);
	cr_assert_eq(hb_scene_set_number(&sc, "initial.x0", 1e300, &err), HB_EINVAL);
	cr_assert_eq(hb_scene_set_number(&sc, "loads.g", 1e300, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "loads.g");
	study1(&sc);
	sc.loads.F1 = 1e300;
	cr_assert_eq(hb_scene_check(&sc, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "loads.F1");
	cr_assert(err.has_range && err.range.hi == 1e7 * sc.d.m1, "%g", err.range.hi);
	sc.loads.F1 = 0.5e7 * sc.d.m1;
	cr_assert_eq(hb_scene_check(&sc, &err), HB_OK);
	study1(&sc);

	/* Validation names the key at fault, as data. */
	sc.par[hb_law_param_index(sc.law, "gamma")] = 2 * sc.par[hb_law_param_index(sc.law, "beta")];
	cr_assert_eq(hb_scene_check(&sc, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "law.gamma");
	study1(&sc);
	sc.run.chatter = 1;
	cr_assert_eq(hb_scene_check(&sc, &err), HB_EINVAL);
	cr_assert_str_eq(err.key, "run.chatter");
	cr_assert(err.has_range && err.range.whole && err.range.lo == 2);
}

Test(scene, set_number_is_set_text)
{
	struct hb_scene a, b;
	struct hb_scene_error err;

	study1(&a);
	b = a;
	cr_assert_eq(hb_scene_set_number(&a, "body1.R", 0.0125, &err), HB_OK);
	cr_assert_eq(hb_scene_set_text(&b, "body1.R", "12.5 mm", &err), HB_OK);
	cr_assert_eq(a.body[0].R, b.body[0].R);
	cr_assert_eq(a.d.m1, b.d.m1);
	cr_assert_eq(hb_scene_set_number(&a, "run.J", 7, &err), HB_OK);
	cr_assert_eq(a.run.J, 7);
	cr_assert_eq(hb_scene_set_number(&a, "run.J", 7.5, &err), HB_EINVAL);
	cr_assert_eq(hb_scene_set_number(&a, "run.stepper", 1, &err), HB_EINVAL);
	cr_assert_eq(hb_scene_set_number(&a, "body1.mass", 2, &err), HB_OK);
	cr_assert_eq(a.body[0].mass_given, 1);
}

/* Every key of the table has a default that is valid, and the defaults are the scene's. */
Test(scene, table_defaults_are_the_default_scene)
{
	struct hb_scene sc;
	char msg[512];

	hb_scene_defaults(&sc);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(sc.law, &hb_law_hertz);
	cr_assert_eq(sc.body[0].R, 0.020);
	cr_assert(isinf(sc.body[1].R));
	cr_assert_eq(sc.body[1].rho, 0);
	cr_assert_eq(sc.run.reduce, HB_REDUCE_ALL);
	cr_assert_eq(sc.run.kinks, 1);
	cr_assert_eq(sc.ext, 1);
	cr_assert_eq(sc.run.stepper, HB_STEPPER_RK8PD);
}

/*
 * The range the panel advertises and what a key takes agree at infinity:
 * every key shown with "inf]" takes inf, every key shown with "inf)"
 * refuses it, for each law's keys too.
 */
Test(scene, advertised_infinity_is_what_is_taken)
{
	static const char *laws[] = { "hertz", "bwmcl", "bwshccl", "shccl", "linear" };
	int checked = 0;

	for (size_t l = 0; l < sizeof laws / sizeof laws[0]; l++) {
		struct hb_scene sc;
		char msg[256];
		hb_scene_defaults(&sc);
		cr_assert_eq(hb_scene_set(&sc, "scene.law", laws[l], msg, sizeof msg), HB_OK, "%s", msg);
		for (int i = 0; i < hb_scene_nkeys(&sc); i++) {
			struct hb_scene_keyinfo ki;
			struct hb_scene trial = sc;
			int took;
			cr_assert_eq(hb_scene_key(&sc, i, &ki), HB_OK);
			if (ki.kind != HB_SCENE_KEY_NUMBER || ki.readonly || !isinf(ki.limits.hi))
				continue;
			took = hb_scene_set(&trial, ki.key, "inf", msg, sizeof msg) == HB_OK;
			cr_assert_eq(took, !ki.limits.hi_open,
			    "%s (law %s) advertises %s but %s inf: %s", ki.key, laws[l], ki.range,
			    took ? "takes" : "refuses", msg);
			if (strstr(ki.range, "inf") != NULL) /* "any finite value" names no bound */
				cr_assert_eq(strstr(ki.range, "inf]") != NULL, !ki.limits.hi_open,
				    "%s: range text %s", ki.key, ki.range);
			checked++;
		}
	}
	cr_assert_gt(checked, 20, "only %d keys with an infinite bound checked", checked);
}

/* A mass whose weight overflows is refused before the run, naming the mass. */
Test(scene, weight_must_be_finite)
{
	struct hb_scene sc;
	char msg[256];

	hb_scene_defaults(&sc);
	cr_assert_eq(hb_scene_set(&sc, "body1.mass", "1e308 kg", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_EINVAL);
	cr_assert(strncmp(msg, "body1.mass: its weight m g (1e+308 kg", 37) == 0, "%s", msg);
	cr_assert(strstr(msg, "accepted: 1.833e+307 kg or less at g = 9.81 m/s^2") != NULL, "%s", msg);
	cr_assert(strstr(msg, "inf") == NULL, "%s", msg);
	/* Without gravity the same mass is fine. */
	cr_assert_eq(hb_scene_set(&sc, "loads.g", "0", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
	/* A fixed obstacle (body 2 of infinite mass) carries no weight. */
	hb_scene_defaults(&sc);
	cr_assert_eq(hb_scene_set(&sc, "body2.mass", "inf", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_validate(&sc, msg, sizeof msg), HB_OK, "%s", msg);
}
