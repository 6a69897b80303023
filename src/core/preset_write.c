/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_write.c - scenes written as presets (preset.h): every value in SI
 * with %.17g and its unit, so that loading the file reproduces the scene
 * bit for bit, written by the atomic writer (atomic.h): a temporary name
 * in its folder, flushed to disk and renamed.  A run with branches is
 * written as its first scene and a [branch N] section per branch
 * (preset_branch.c).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "preset_ini.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

#ifdef HYBOUNCE_VERSION
#define HB_PRESET_VERSION HYBOUNCE_VERSION
#else
#define HB_PRESET_VERSION "(unknown version)"
#endif

/*
 * "key = VALUE".  A value that begins with ';' or '#' is written right
 * after the '=': inih takes those for a comment only after white space.
 */
static void
out_entry(struct textbuf *o, const char *key, const char *value)
{
	textbuf_printf(o, "%s =%s%s\n", key, value[0] == ';' || value[0] == '#' ? "" : " ", value);
}

size_t
hb_preset_format(const struct hb_scene *sc, char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };
	char v[512], sec[16], u[64];

	if (buf != NULL && n > 0)
		buf[0] = '\0';
#ifdef HYBOUNCE_VERSION
	textbuf_printf(&o, "; hybounce %s preset: SI values that reproduce the scene exactly\n",
	    HYBOUNCE_VERSION);
#else
	textbuf_printf(&o, "; hybounce preset: SI values that reproduce the scene exactly\n");
#endif
	for (size_t s = 0; s < PRESET_NSECTIONS; s++) {
		int any = strcmp(preset_sections[s], "law") == 0;

		if (strcmp(preset_sections[s], "loads") == 0) /* a chain's [body.I], [interface.K] */
			scene_override_write(sc, NULL, &o);

		for (int k = 0; k < scene_nkeydefs && !any; k++) /* a section with no key is left out */
			any = strcmp(scene_keydef_section(&scene_keydefs[k], sec, sizeof sec),
			             preset_sections[s]) == 0 && scene_keydef_present(sc, &scene_keydefs[k]);
		if (!any)
			continue;
		textbuf_printf(&o, "\n[%s]\n", preset_sections[s]);
		if (strcmp(preset_sections[s], "law") == 0) {
			for (int i = 0; sc->law != NULL && i < sc->law->n_params; i++) {
				const struct hb_law_param *pp = &sc->law->params[i];
				if ((pp->flags & HB_LAW_PARAM_STIFFNESS) && sc->d.k_derived)
					continue;
				hb_units_dim_str(scene_lawpar_dim(sc, i), u, sizeof u);
				cnum_snprintf(v, sizeof v, "%.17g%s%s", sc->par[i], u[0] ? " " : "", u);
				out_entry(&o, pp->name, v);
			}
			continue;
		}
		for (int k = 0; k < scene_nkeydefs; k++) {
			const struct scene_keydef *kd = &scene_keydefs[k];
			if (strcmp(scene_keydef_section(kd, sec, sizeof sec), preset_sections[s]) != 0 ||
			    !scene_keydef_present(sc, kd))
				continue;
			scene_keydef_print(sc, kd, v, sizeof v);
			out_entry(&o, kd->key + strlen(sec) + 1, v);
		}
		scene_override_write(sc, preset_sections[s], &o); /* [initial] body.I.v ... */
	}
	return o.len;
}

int
hb_preset_save(const char *path, const struct hb_scene *sc, char *msg, size_t n)
{
	size_t len = hb_preset_format(sc, NULL, 0);
	char *buf = malloc(len + 1);
	int st;

	if (buf == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", path);
	hb_preset_format(sc, buf, len + 1);
	st = hb_atomic_write_file(path, buf, len, msg, n);
	free(buf);
	return st == HB_OK ? HB_OK : HB_EIO;
}

/* hb_preset_format's text less its first line (the header), appended to o. */
static void
body_of(struct textbuf *o, const struct hb_scene *sc)
{
	size_t len = hb_preset_format(sc, NULL, 0);
	char *buf = malloc(len + 1);
	const char *nl;

	if (buf == NULL) {
		o->len += len;   /* as textbuf does when the text does not fit */
		return;
	}
	hb_preset_format(sc, buf, len + 1);
	nl = strchr(buf, '\n');
	textbuf_printf(o, "%s", nl != NULL ? nl + 1 : buf);
	free(buf);
}

size_t
hb_preset_format_run(const struct hb_sim *s, char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };
	size_t nb = hb_sim_nbranches(s);
	double un = hb_sim_unrecorded(s);
	char tb[48];
	int exact = 1;

	if (nb == 0 && un < 0)
		return hb_preset_format(hb_sim_scene(s), buf, n);
	if (buf != NULL && n > 0)
		buf[0] = '\0';
	if (un >= 0) {
		hb_units_format_exact(un, hb_unit_time, tb, sizeof tb);
		textbuf_printf(&o, "; hybounce %s preset: does NOT reproduce the run: its values "
		    "changed at t = %s in a way a preset cannot record; these are the values at its "
		    "end\n", HB_PRESET_VERSION, tb);
		body_of(&o, hb_sim_scene(s));
		return o.len;
	}
	/* the branches first, to know whether each reads back; the header then goes before them */
	{
		struct textbuf b = { NULL, 0, 0 };
		char *bbuf;

		for (size_t k = 0; k < nb; k++)
			exact &= preset_branch_format(&b, (int)k + 1, k ? &hb_sim_branch_get(s, k - 1)->sc
			                                               : hb_sim_scene0(s), hb_sim_branch_get(s, k));
		bbuf = malloc(b.len + 1);
		if (bbuf != NULL) {
			b = (struct textbuf){ bbuf, b.len + 1, 0 };
			for (size_t k = 0; k < nb; k++)
				preset_branch_format(&b, (int)k + 1, k ? &hb_sim_branch_get(s, k - 1)->sc
				                                       : hb_sim_scene0(s), hb_sim_branch_get(s, k));
		}
		if (exact)
			textbuf_printf(&o, "; hybounce %s preset: a run with %zu branch%s: the scene below "
			    "from t = 0, then each [branch N] from its sample (t, j) on with the values it "
			    "names; hybounce --batch and the explorer replay them exactly\n",
			    HB_PRESET_VERSION, nb, nb == 1 ? "" : "es");
		else
			textbuf_printf(&o, "; hybounce %s preset: does NOT reproduce the run exactly: a "
			    "[branch N] below does not read back to the values the run took there\n",
			    HB_PRESET_VERSION);
		body_of(&o, hb_sim_scene0(s));
		if (bbuf != NULL)
			textbuf_printf(&o, "%s", bbuf);
		else
			o.len += b.len;
		free(bbuf);
	}
	return o.len;
}
