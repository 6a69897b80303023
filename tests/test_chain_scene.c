/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_chain_scene.c - a chain's overrides (docs/chains.md section 7):
 * body.I.*, interface.K.* and initial.body.I.* read from a preset and by
 * key, what they resolve to for each body and interface (an interface's
 * stiffness derived from ITS two bodies), the scene copied by assignment,
 * the panel rows, written and read back bit for bit, and refused beyond the
 * table's 64 entries or outside the chain.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"

static const char cradle[] =
    "[scene]\nname = cradle\nlaw = hertz\n"
    "[body1]\nE = 200 GPa\nnu = 0.3\nrho = 7800 kg/m^3\nR = 10 mm\n"
    "[chain]\nn = 5\nspacing = 1 mm\n[striker]\nv = -1 m/s\n"
    "[body.3]\nR = 5 mm\n"
    "[body.4]\nE = 70 GPa\nnu = 0.33\nrho = 2700\nF = 2 N\n"
    "[interface.2]\nlaw = shccl\nc = 2e7\n"
    "[initial]\nbody.5.v = -2 m/s\nbody.1.gap = 2 mm\n"
    "[loads]\ng = 0\n";

static void
load(struct hb_scene *sc)
{
	char msg[512] = "";

	cr_assert_eq(hb_preset_load_string(cradle, "c.preset", sc, msg, sizeof msg), HB_OK, "%s", msg);
}

static double
num(const struct hb_scene *sc, const char *key)
{
	struct hb_scene_keyinfo ki;
	struct hb_scene_error e;

	cr_assert_eq(hb_scene_get(sc, key, &ki, &e), HB_OK, "%s: %s", key, e.what);
	return ki.number;
}

Test(chain_scene, overrides_resolve_per_body_and_interface)
{
	struct hb_scene sc;
	double m = 4.0 / 3.0 * M_PI * 0.01 * 0.01 * 0.01 * 7800;
	double Es = 1.0 / ((1 - 0.09) / 200e9 + (1 - 0.09) / 200e9), kH;
	struct hb_scene_keyinfo ki;

	load(&sc);
	cr_assert_eq(sc.over.n, 9);
	cr_assert_eq(num(&sc, "body.1.mass"), sc.d.m1);
	cr_assert_float_eq(num(&sc, "body.1.mass"), m, 1e-15 * m);
	cr_assert_float_eq(num(&sc, "body.3.mass"), m / 8, 1e-15 * m);
	cr_assert_float_eq(num(&sc, "body.4.mass"), m * 2700 / 7800, 1e-15 * m);
	cr_assert_eq(num(&sc, "body.4.F"), 2.0);
	cr_assert_eq(num(&sc, "body.2.F"), 0.0);
	cr_assert_eq(num(&sc, "initial.body.5.v"), -2.0);
	cr_assert_eq(num(&sc, "initial.body.4.v"), 0.0);
	cr_assert_eq(num(&sc, "initial.body.1.gap"), 0.002);
	cr_assert_eq(num(&sc, "initial.body.2.gap"), 0.001);
	/* interface 1 joins two equal balls: the scene's k, to the bit */
	cr_assert_eq(num(&sc, "interface.1.k"), sc.par[0]);
	/* interface 2: bodies 2 (R 10 mm) and 3 (R 5 mm), the law SHCCL with its c */
	kH = 4.0 / 3.0 * Es * sqrt(1.0 / (1.0 / 0.005 + 1.0 / 0.01));
	cr_assert_float_eq(num(&sc, "interface.2.k"), kH, 1e-12 * kH);
	cr_assert_eq(num(&sc, "interface.2.c"), 2e7);
	cr_assert_eq(hb_scene_get(&sc, "interface.2.law", &ki, NULL), HB_OK);
	cr_assert_str_eq(ki.value, "shccl");
	cr_assert_eq(hb_scene_get(&sc, "interface.2.k", &ki, NULL), HB_OK);
	cr_assert(ki.readonly, "a derived interface stiffness is read-only");
	/* interface 3: aluminium (body 4) on a 5 mm steel ball (body 3) */
	Es = 1.0 / ((1 - 0.33 * 0.33) / 70e9 + (1 - 0.09) / 200e9);
	kH = 4.0 / 3.0 * Es * sqrt(1.0 / (1.0 / 0.01 + 1.0 / 0.005));
	cr_assert_float_eq(num(&sc, "interface.3.k"), kH, 1e-12 * kH);
}

Test(chain_scene, set_copy_write_and_read_back)
{
	struct hb_scene sc, copy, back;
	char msg[512] = "", buf[8192];
	size_t len;

	load(&sc);
	cr_assert_eq(hb_scene_set(&sc, "body.2.R", "8 mm", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_scene_set(&sc, "body.2.R", "9 mm", msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(sc.over.n, 10, "setting a key again replaces its value");
	cr_assert_eq(hb_scene_set_number(&sc, "interface.4.k", 1e9, NULL), HB_EINVAL,
	    "interface.4.k is derived from the materials");
	copy = sc; /* a plain value */
	cr_assert_eq(hb_scene_set(&sc, "body.2.R", "1 mm", msg, sizeof msg), HB_OK);
	cr_assert_float_eq(num(&copy, "body.2.R"), 0.009, 1e-15);
	cr_assert_eq(hb_scene_validate(&copy, msg, sizeof msg), HB_OK, "%s", msg);
	len = hb_preset_format(&copy, buf, sizeof buf);
	cr_assert(len < sizeof buf);
	cr_assert(strstr(buf, "\n[body.2]\nR = 0.0") != NULL, "%s", buf);
	cr_assert(strstr(buf, "\n[interface.2]\nlaw = shccl\nc = 20000000 N s m^-5/2\n") != NULL, "%s", buf);
	cr_assert(strstr(buf, "body.5.v = -2 m/s\n") != NULL, "%s", buf);
	cr_assert_eq(hb_preset_load_string(buf, "w.preset", &back, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(back.over.n, copy.over.n);
	for (int i = 0; i < copy.over.n; i++) { /* the same entries, maybe in another order */
		int found = 0;
		for (int j = 0; j < back.over.n; j++)
			found |= back.over.o[j].kind == copy.over.o[i].kind &&
			    back.over.o[j].index == copy.over.o[i].index &&
			    strcmp(back.over.o[j].name, copy.over.o[i].name) == 0 &&
			    memcmp(&back.over.o[j].value, &copy.over.o[i].value, sizeof(double)) == 0;
		cr_assert(found, "override %d (%s) not read back", i, copy.over.o[i].name);
	}
}

Test(chain_scene, panel_lists_the_overrides)
{
	struct hb_scene sc;
	struct hb_scene_keyinfo ki;
	int n, seen = 0;

	load(&sc);
	n = hb_scene_nkeys(&sc);
	for (int i = 0; i < n; i++) {
		cr_assert_eq(hb_scene_key(&sc, i, &ki), HB_OK);
		if (strcmp(ki.key, "body.3.R") == 0) {
			cr_assert_str_eq(ki.section, "chain");
			cr_assert_str_eq(ki.value, "5 mm");
			seen |= 1;
		}
		if (strcmp(ki.key, "interface.2.law") == 0)
			seen |= 2;
		if (strcmp(ki.key, "initial.body.5.v") == 0)
			seen |= 4;
	}
	cr_assert_eq(seen, 7, "panel rows of body.3.R, interface.2.law, initial.body.5.v: %d", seen);
}

Test(chain_scene, refusals)
{
	struct hb_scene sc;
	struct hb_scene_error e;
	char key[32];
	int i;

	load(&sc);
	cr_assert_eq(hb_scene_set_text(&sc, "body.6.R", "1 mm", &e), HB_EINVAL);
	cr_assert(strstr(e.accepted, "body.1 .. body.5") != NULL, "%s", e.accepted);
	cr_assert_eq(hb_scene_set_text(&sc, "interface.0.k", "1", &e), HB_EINVAL);
	cr_assert(strstr(e.accepted, "interface.1 .. interface.4") != NULL, "%s", e.accepted);
	cr_assert_eq(hb_scene_set_text(&sc, "body.2.colour", "red", &e), HB_EINVAL);
	cr_assert_eq(hb_scene_set_text(&sc, "interface.1.alpha", "0.5", &e), HB_EINVAL);
	cr_assert(strstr(e.what, "law hertz") != NULL, "%s", e.what);
	cr_assert_eq(hb_scene_set_text(&sc, "body.2.nu", "0.7", &e), HB_EINVAL);
	cr_assert_eq(hb_scene_set_text(&sc, "interface.3.law", "bwmcl", &e), HB_OK);
	cr_assert_eq(hb_scene_check(&sc, &e), HB_EINVAL, "a law of other internal states");
	cr_assert_str_eq(e.key, "interface.3.law");
	load(&sc);
	/* the table is full at 64 */
	cr_assert_eq(hb_scene_set_text(&sc, "chain.n", "100", &e), HB_OK);
	for (i = 1; sc.over.n < HB_SCENE_MAX_OVERRIDES; i++) {
		snprintf(key, sizeof key, "body.%d.F", 20 + i);
		cr_assert_eq(hb_scene_set_text(&sc, key, "1 mN", &e), HB_OK, "%s", e.what);
	}
	snprintf(key, sizeof key, "body.%d.F", 20 + i);
	cr_assert_eq(hb_scene_set_text(&sc, key, "1 mN", &e), HB_EINVAL);
	cr_assert(strstr(e.what, "too many overrides") != NULL, "%s", e.what);
	cr_assert(strstr(e.accepted, "at most 64") != NULL, "%s", e.accepted);
	cr_assert_eq(hb_scene_set_text(&sc, "body.21.F", "2 mN", &e), HB_OK, "an existing key still takes a value");
	/* a two-body scene has no numbered bodies */
	hb_scene_defaults(&sc);
	cr_assert_eq(hb_scene_set_text(&sc, "body.1.R", "1 mm", &e), HB_OK);
	cr_assert_eq(hb_scene_check(&sc, &e), HB_EINVAL);
	cr_assert(strstr(e.what, "only a chain") != NULL, "%s", e.what);
}
