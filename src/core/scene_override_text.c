/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_override_text.c - a chain's overrides as preset text ([body.I], [interface.K], [initial]
 * body.I.*) and as the man page's PRESETS items
 * (scene_override.h; the keys themselves are scene_override.c's).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_chain.h"
#include "scene_keys.h"
#include "scene_override.h"
#include "textbuf.h"
#include "cnum.h"

/* ---------------------------------------------------------------- */
/* Preset text */

static void
write_value(const struct hb_scene *sc, const struct hb_scene_override *o, const char *prefix,
            struct textbuf *t)
{
	char v[96], u[48];
	struct hb_unit_dim dim = hb_unit_none;

	if (o->kind == HB_OVERRIDE_IFACE && strcmp(o->name, "law") == 0) {
		textbuf_printf(t, "%slaw = %s\n", prefix, scene_override_iface_law(sc, o->index, NULL)->name);
		return;
	}
	if (o->kind == HB_OVERRIDE_IFACE && strcmp(o->name, "extension") == 0) {
		textbuf_printf(t, "%sextension = %s\n", prefix, scene_override_ext_words[o->value != 0]);
		return;
	}
	if (o->kind == HB_OVERRIDE_IFACE) {
		double par[HB_LAW_MAX_PARAMS];
		const struct hb_law_type *law = scene_override_iface_law(sc, o->index, par);
		int pi = scene_override_param(law, o->name);
		if (pi >= 0)
			dim = hb_units_resolve(law->params[pi].dim, hb_law_exponent_p(law, par),
			    hb_law_exponent_n(law, par));
	} else {
		const struct scene_override_field *f = scene_override_field(o->kind, o->name);
		if (f != NULL)
			dim = *f->dim;
	}
	hb_units_dim_str(dim, u, sizeof u);
	cnum_snprintf(v, sizeof v, "%.17g%s%s", o->value, u[0] ? " " : "", u);
	textbuf_printf(t, "%s%s = %s\n", prefix, o->name, v);
}

void
scene_override_write(const struct hb_scene *sc, const char *section, struct textbuf *t)
{
	char prefix[32];

	if (section != NULL) {
		if (strcmp(section, "initial") != 0)
			return;
		for (int idx = 1; idx <= SCENE_OVERRIDE_MAX_INDEX; idx++) /* ascending bodies, each in typed order */
			for (int i = 0; i < sc->over.n; i++)
				if (sc->over.o[i].kind == HB_OVERRIDE_INITIAL && sc->over.o[i].index == idx) {
					snprintf(prefix, sizeof prefix, "body.%d.", idx);
					write_value(sc, &sc->over.o[i], prefix, t);
				}
		return;
	}
	for (int kind = HB_OVERRIDE_BODY; kind <= HB_OVERRIDE_IFACE; kind++) {
		int last = -1;
		for (;;) { /* the next index above last that has an override of this kind */
			int idx = -1;
			for (int i = 0; i < sc->over.n; i++)
				if (sc->over.o[i].kind == kind && sc->over.o[i].index > last &&
				    (idx < 0 || sc->over.o[i].index < idx))
					idx = sc->over.o[i].index;
			if (idx < 0)
				break;
			textbuf_printf(t, "\n[%s.%d]\n", kind == HB_OVERRIDE_BODY ? "body" : "interface", idx);
			for (int pass = 0; pass < 2; pass++) /* an interface's law first */
				for (int i = 0; i < sc->over.n; i++) {
					const struct hb_scene_override *o = &sc->over.o[i];
					int first = o->kind == HB_OVERRIDE_IFACE && (strcmp(o->name, "law") == 0 ||
					    strcmp(o->name, "extension") == 0);
					if (o->kind == kind && o->index == idx && first == (pass == 0))
						write_value(sc, o, "", t);
				}
			last = idx;
		}
	}
}

/* ---------------------------------------------------------------- */
/* The man page's PRESETS reference */

static void
mdoc_field(struct textbuf *t, const char *prefix, const struct scene_override_field *f)
{
	char r[64];

	hb_units_range_str(&f->range, f->dim, r, sizeof r);
	textbuf_printf(t, ".It Cm %s%s\n%s.\nAccepted: %s.\n", prefix, f->name, f->help, r);
}

void
scene_override_mdoc(struct textbuf *t, const char *section)
{
	if (section != NULL) { /* [initial] */
		int nf;
		const struct scene_override_field *f = scene_override_fields(HB_OVERRIDE_INITIAL, &nf);
		for (int i = 0; i < nf; i++)
			mdoc_field(t, "body.I.", &f[i]);
		textbuf_printf(t, "Default: the chain's (the striker's velocity for body n, rest "
		    "for the others; chain.spacing).\n");
		return;
	}
	textbuf_printf(t, ".It Li [body.I]\nBody I of a chain (1 the lowest, n the striker), where it "
	    "differs from [body1]: its material, its radius, its mass (given, or 4/3 pi R^3 rho "
	    "from its density and radius), a constant force besides gravity.\nAt most %d keys of "
	    "[body.I], [interface.K] and [initial] body.I.* in a scene.\n"
	    ".Bl -tag -width \"description\" -compact\n", HB_SCENE_MAX_OVERRIDES);
	{
		int nf;
		const struct scene_override_field *f = scene_override_fields(HB_OVERRIDE_BODY, &nf);
		for (int i = 0; i < nf; i++)
			mdoc_field(t, "", &f[i]);
	}
	textbuf_printf(t, ".El\n.It Li [interface.K]\nInterface K of a chain (between bodies K and "
	    "K + 1; 0 the floor's), where it differs from the scene's law:\n"
	    ".Cm law ,\n.Cm extension\nand any parameter of its law (the law's defaults when it "
	    "differs from the scene's).\nIts stiffness is derived from ITS two bodies' materials "
	    "(the floor's is body2) when they have them.\n");
}
