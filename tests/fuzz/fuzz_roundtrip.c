/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz_roundtrip.c - "a saved scene loads back to the same scene": any
 * preset text that loads is formatted as a preset (hb_preset_format, what
 * --trace/--collisions save beside the CSV), loaded again, and the two
 * scenes must agree in every value, to the bit (abort otherwise).
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "fuzz.h"

static int bad;

static void
same_d(const char *what, double a, double b)
{
	/* to the bit, NaN and the sign of zero included */
	if (memcmp(&a, &b, sizeof a) != 0) {
		fprintf(stderr, "%s: %.17g saved, %.17g loaded back\n", what, a, b);
		bad = 1;
	}
}

static void
same_i(const char *what, long a, long b)
{
	if (a != b) {
		fprintf(stderr, "%s: %ld saved, %ld loaded back\n", what, a, b);
		bad = 1;
	}
}

static void
same_s(const char *what, const char *a, const char *b)
{
	if (strcmp(a, b) != 0) {
		fprintf(stderr, "%s: '%s' saved, '%s' loaded back\n", what, a, b);
		bad = 1;
	}
}

static void
same_scene(const struct hb_scene *a, const struct hb_scene *b)
{
	static const char *const bn[2] = { "body1", "body2" };
	char w[64];

	same_s("scene.name", a->name, b->name);
	same_s("scene.description", a->description, b->description);
	for (int i = 0; i < 2; i++) {
		const struct hb_scene_body *x = &a->body[i], *y = &b->body[i];

#define W(f) (snprintf(w, sizeof w, "%s.%s", bn[i], f), w)
		same_s(W("name"), x->name, y->name);
		same_i(W("has_material"), x->has_material, y->has_material);
		if (x->has_material) {
			same_d(W("E"), x->E, y->E);
			same_d(W("nu"), x->nu, y->nu);
		}
		same_d(W("rho"), x->rho, y->rho);
		same_d(W("R"), x->R, y->R);
		same_d(W("mass"), x->mass, y->mass);
		same_i(W("mass_given"), x->mass_given, y->mass_given);
#undef W
	}
	if (a->law != b->law) {
		fprintf(stderr, "scene.law: %s saved, %s loaded back\n", a->law->name,
		        b->law ? b->law->name : "?");
		bad = 1;
		return;
	}
	for (int i = 0; i < a->law->n_params; i++) {
		snprintf(w, sizeof w, "law.%s", a->law->params[i].name);
		same_d(w, a->par[i], b->par[i]);
	}
	same_i("scene.extension", a->ext, b->ext);
	same_d("loads.g", a->loads.g, b->loads.g);
	same_d("loads.F1", a->loads.F1, b->loads.F1);
	same_d("loads.F2", a->loads.F2, b->loads.F2);
	same_i("loads.ramp", a->loads.ramp, b->loads.ramp);
	if (a->loads.ramp) {
		same_d("loads.F_e0", a->loads.Fe0, b->loads.Fe0);
		same_d("loads.T_e", a->loads.Te, b->loads.Te);
		same_d("loads.T_s", a->loads.Ts, b->loads.Ts);
	}
	same_d("initial.x0", a->init.x0, b->init.x0);
	same_d("initial.v0", a->init.v0, b->init.v0);
	if (a->d.system == HB_SCENE_FULL) {
		same_d("initial.x_m0", a->init.xm0, b->init.xm0);
		same_d("initial.v_m0", a->init.vm0, b->init.vm0);
	}
	same_d("run.T", a->run.T, b->run.T);
	same_i("run.J", a->run.J, b->run.J);
	same_i("run.stepper", a->run.stepper, b->run.stepper);
	same_d("run.rtol", a->run.rtol, b->run.rtol);
	same_d("run.atol", a->run.atol, b->run.atol);
	same_d("run.h_max", a->run.h_max, b->run.h_max);
	same_i("run.max_samples", a->run.max_samples, b->run.max_samples);
	same_i("run.chatter", a->run.chatter, b->run.chatter);
	same_i("run.reduce", a->run.reduce, b->run.reduce);
	same_i("run.kinks", a->run.kinks, b->run.kinks);
	same_i("run.limits", a->run.limits, b->run.limits);
	same_i("system", a->d.system, b->d.system);
	same_d("derived m", a->d.m, b->d.m);
}

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_string(data, size), msg[1024], *saved;
	struct hb_scene sc, back;
	size_t need;

	if (hb_preset_load_string(text, "fuzz.preset", &sc, msg, sizeof msg) != HB_OK) {
		free(text);
		return 0;
	}
	need = hb_preset_format(&sc, NULL, 0);
	saved = malloc(need + 1);
	if (saved == NULL)
		abort();
	hb_preset_format(&sc, saved, need + 1);
	if (hb_preset_load_string(saved, "saved.preset", &back, msg, sizeof msg) != HB_OK) {
		fprintf(stderr, "the saved scene does not load back: %s\n--- saved:\n%s\n---\n",
		        msg, saved);
		abort();
	}
	bad = 0;
	same_scene(&sc, &back);
	if (bad) {
		fprintf(stderr, "--- saved:\n%s\n---\n", saved);
		abort();
	}
	free(saved);
	free(text);
	return 0;
}
