/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_list.c - the listings of the command line (batch.h):
 * --list-presets (name, title and description of each preset found) and
 * --list-laws (each law with its parameters: unit, range, default).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/law.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/units.h"

#include "batch.h"
#include "batch_report.h"

#define PROG "hybounce"

int
batch_list_presets(void)
{
	struct hb_preset_info *pi = NULL;
	int n = hb_preset_list(&pi), i, w = 0;

	if (n < 0) {
		fprintf(stderr, PROG ": out of memory listing the presets\n");
		return 1;
	}
	if (n == 0) {
		const char *const *d = hb_preset_dirs();

		fprintf(stderr, PROG ": no presets found; looked in:");
		for (; d != NULL && *d != NULL; d++)
			fprintf(stderr, " %s", *d);
		fprintf(stderr, "\n");
	}
	for (i = 0; i < n; i++)
		if ((int)strlen(pi[i].name) > w)
			w = (int)strlen(pi[i].name);
	for (i = 0; i < n; i++) {
		printf("%-*s  %s\n", w, pi[i].name, pi[i].title);
		if (pi[i].description[0])
			batch_print_wrapped(stdout, "    ", pi[i].description);
	}
	free(pi);
	return 0;
}

int
batch_list_laws(void)
{
	const struct hb_law_type *const *l;

	for (l = hb_law_list(); *l != NULL; l++) {
		const struct hb_law_type *law = *l;
		int i;

		printf("%s  %s\n", law->name, law->title);
		batch_print_wrapped(stdout, "    ", law->description);
		printf("    internal states n_z = %d; parameters (units for the default "
		       "exponents):\n", law->n_z);
		for (i = 0; i < law->n_params; i++) {
			const struct hb_law_param *pp = &law->params[i];
			struct hb_scene_keyinfo ki; /* the typed row: unit, range, default */
			char dv[64];

			hb_scene_law_param_info(law, i, &ki);
			batch_fmt(ki.number, ki.dim, dv, sizeof dv);
			printf("      %-8s %-14s range %-16s default %s%s\n",
			       pp->name, ki.unit[0] ? ki.unit : "(1)", ki.range, dv,
			       (pp->flags & HB_LAW_PARAM_STIFFNESS) && law->k_hertz != NULL
			           ? " (derived from k_H when both bodies have materials)" : "");
			if (ki.help[0])
				printf("      %-8s %s\n", "", ki.help);
		}
		printf("\n");
	}
	return 0;
}
