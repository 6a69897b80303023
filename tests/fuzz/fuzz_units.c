/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz_units.c - the unit and value parser: hb_units_parse against every
 * dimension a value can have, and hb_scene_set on a key chosen by the first
 * byte (its value the rest).  A value is accepted with a finite result or
 * refused with a message; a refused --set changes nothing; a number
 * formatted by hb_units_format parses back in its own unit.
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"
#include "fuzz.h"

static const struct hb_unit_dim *const dims[] = {
	&hb_unit_none, &hb_unit_length, &hb_unit_time, &hb_unit_mass, &hb_unit_velocity, &hb_unit_accel,
	&hb_unit_force, &hb_unit_pressure, &hb_unit_density, &hb_unit_energy, &hb_unit_impulse,
};
#define NDIMS (sizeof dims / sizeof dims[0])

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text, msg[512], buf[128];
	struct hb_scene sc, before;
	struct hb_scene_keyinfo ki;
	double v;
	size_t i;
	int nk;

	if (size == 0)
		return 0;
	text = fuzz_string(data + 1, size - 1);
	for (i = 0; i < NDIMS; i++) {
		msg[0] = '\0';
		if (hb_units_parse(text, *dims[i], &v, msg, sizeof msg) == HB_OK) {
			/* bare numbers may be inf ("inf m" for a flat); never NaN */
			if (isnan(v))
				abort();
			hb_units_format(v, *dims[i], 6, buf, sizeof buf);
		} else if (msg[0] == '\0') {
			fprintf(stderr, "refusal without a message: '%s'\n", text);
			abort();
		}
	}
	hb_scene_defaults(&sc);
	nk = hb_scene_nkeys(&sc);
	if (nk > 0 && hb_scene_key(&sc, data[0] % nk, &ki) == HB_OK && !ki.readonly) {
		memcpy(&before, &sc, sizeof sc);
		msg[0] = '\0';
		if (hb_scene_set(&sc, ki.key, text, msg, sizeof msg) != HB_OK) {
			if (memcmp(&before, &sc, sizeof sc) != 0 || msg[0] == '\0') {
				fprintf(stderr, "%s = '%s': refused but changed, or no message\n",
				        ki.key, text);
				abort();
			}
		}
	}
	free(text);
	return 0;
}
