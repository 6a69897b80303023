/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_doc.c - the PRESETS reference of the man page, generated from the
 * key table and the laws' parameter tables (scene_keys_mdoc, written into
 * man/hybounce.1 by tools/gendoc.c).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/units.h"

#include "docs.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

/* ---------------------------------------------------------------- */
/* The man page's PRESETS reference */

/* "Default: D." (no second period after a text that ends in one) */
static void
mdoc_default(struct textbuf *o, const char *def)
{
	size_t l = strlen(def);

	textbuf_printf(o, "Default: %s%s\n", def, l > 0 && def[l - 1] == '.' ? "" : ".");
}

/* The [law] items: each law's parameters (units at the default exponents). */
static void
mdoc_laws(struct textbuf *o)
{
	for (const struct hb_law_type *const *l = hb_law_list(); *l != NULL; l++) {
		const struct hb_law_type *law = *l;
		textbuf_printf(o, ".It Li [law] No with Cm law No = Cm %s\n%s: %s.\n", law->name, law->title,
		    law->description);
		textbuf_printf(o, ".Bl -tag -width \"description\" -compact\n");
		for (int i = 0; i < law->n_params; i++) {
			struct hb_scene_keyinfo ki;
			char def[64];
			hb_scene_law_param_info(law, i, &ki);
			hb_units_format(ki.number, ki.dim, 6, def, sizeof def);
			textbuf_printf(o, ".It Cm %s\n%s%s\n", law->params[i].name, ki.help,
			    ki.help[0] && ki.help[strlen(ki.help) - 1] == '.' ? "" : ".");
			if ((law->params[i].flags & HB_LAW_PARAM_STIFFNESS) && law->k_hertz != NULL)
				textbuf_printf(o, "Derived from the materials by Hertz contact theory when both bodies "
				    "have them; typed otherwise.\n");
			textbuf_printf(o, "Accepted: %s%s%s.\n", ki.range, ki.unit[0] ? ", in " : "",
			    ki.unit[0] ? ki.unit : "");
			mdoc_default(o, def);
		}
		textbuf_printf(o, ".El\n");
	}
}

size_t
scene_keys_mdoc(char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };
	struct hb_scene sc;
	char sec[16], prev[16] = "";

	if (buf != NULL && n > 0)
		buf[0] = '\0';
	hb_scene_defaults(&sc);
	for (int i = 0; i < scene_nkeydefs; i++) {
		const struct scene_keydef *kd = &scene_keydefs[i];
		struct hb_scene_keyinfo ki;
		char def[96];

		scene_keydef_section(kd, sec, sizeof sec);
		if (strcmp(sec, prev) != 0) {
			if (strcmp(prev, "initial") == 0)
				scene_override_mdoc(&o, "initial");
			if (prev[0])
				textbuf_printf(&o, ".El\n");
			if (strcmp(prev, "body2") == 0)
				mdoc_laws(&o);
			if (strcmp(prev, "striker") == 0)
				scene_override_mdoc(&o, NULL);
			textbuf_printf(&o, ".It Li [%s]\n.Bl -tag -width \"description\" -compact\n", sec);
			snprintf(prev, sizeof prev, "%s", sec);
		}
		scene_key_info(&sc, kd, &ki);
		if (kd->store == ST_DOUBLE) {
			if (isnan(kd->def))
				snprintf(def, sizeof def, "not given");
			else
				hb_units_format(kd->def, *kd->dim, 6, def, sizeof def);
		} else if (kd->store == ST_LONG || kd->store == ST_INT)
			cnum_snprintf(def, sizeof def, "%.0f", kd->def);
		else
			snprintf(def, sizeof def, "%s", kd->deftext);
		textbuf_printf(&o, ".It Cm %s\n%s.\n", kd->key + strlen(sec) + 1, kd->help);
		if (ki.kind == HB_SCENE_KEY_CHOICE) {
			textbuf_printf(&o, "Accepted:");
			for (int c = 0; c < ki.nchoices; c++)
				textbuf_printf(&o, "%s %s", c ? "," : "", ki.choices[c]);
			textbuf_printf(&o, ".\n");
		} else if (ki.kind == HB_SCENE_KEY_TEXT)
			textbuf_printf(&o, "Accepted: text of at most %zu bytes.\n", kd->size - 1);
		else
			textbuf_printf(&o, "Accepted: %s.\n", ki.range);
		mdoc_default(&o, def);
	}
	textbuf_printf(&o, ".El\n");
	return o.len;
}
