/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz_preset.c - the preset parser (hb_preset_load_string) on any text: it
 * loads or refuses with a message, never crashes; a loaded scene is valid
 * (hb_scene_validate agrees) and can be formatted and listed in the panel.
 */
#include <stdio.h>

#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "fuzz.h"

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_string(data, size), msg[1024], buf[8192];
	struct hb_scene sc;
	int rc;

	msg[0] = '\0';
	rc = hb_preset_load_string(text, "fuzz.preset", &sc, msg, sizeof msg);
	if (rc != HB_OK) {
		/* a refusal names the file and says what is wrong */
		if (strncmp(msg, "fuzz.preset", 11) != 0 || strlen(msg) < 16) {
			fprintf(stderr, "refusal without a proper message: '%s'\n", msg);
			abort();
		}
	} else {
		struct hb_scene_keyinfo ki;

		if (hb_scene_validate(&sc, msg, sizeof msg) != HB_OK) {
			fprintf(stderr, "loaded but not valid: %s\n", msg);
			abort();
		}
		hb_preset_format(&sc, buf, sizeof buf);
		for (int i = 0; i < hb_scene_nkeys(&sc); i++)
			hb_scene_key(&sc, i, &ki);
	}
	free(text);
	return 0;
}
