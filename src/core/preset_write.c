/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_write.c - scenes written as presets (preset.h): every value in SI
 * with %.17g and its unit, so that loading the file reproduces the scene
 * bit for bit, written by the atomic writer (atomic.h): a temporary name
 * in its folder, flushed to disk and renamed.  A run (hb_preset_format_run),
 * with its branches, is preset_branch.c's, which writes each scene with
 * hb_preset_format.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/atomic.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "preset_ini.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

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
