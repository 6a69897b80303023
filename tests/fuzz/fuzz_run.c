/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz_run.c - preset plus a short run: any preset text that loads is run
 * for a bounded amount of work (at most 400 accepted steps and 50 ms of
 * CPU, with T and J as the preset says; a chain of at most 6 bodies),
 * then checked (solution pair and
 * physics) and its collisions read.  The engine must fail cleanly (a
 * status and a message) rather than crash, leak or hit undefined
 * behaviour, whatever the scene.
 */
#include <stdio.h>

#include "hybounce/check.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "fuzz.h"

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	char *text = fuzz_string(data, size), msg[2048];
	struct hb_scene sc;
	struct hb_sim *s;

	if (hb_preset_load_string(text, "fuzz.preset", &sc, msg, sizeof msg) == HB_OK) {
		/* keep each input short: a small arc bound too, and chains of a
		 * few bodies (a step's work grows with the contacts: a mutated
		 * 50-bead chain made an input 20 times dearer than a two-body one) */
		if (sc.run.max_samples > 4096)
			sc.run.max_samples = 4096;
		if (sc.chain.n > 6)
			sc.chain.n = 6;
		s = hb_sim_new(&sc, msg, sizeof msg);
		if (s != NULL) {
			struct hb_collision live;
			struct hb_check_physics ph;
			int rc = hb_sim_advance(s, 400, 0.05);

			if (rc != HB_OK && rc != HB_EDONE && hb_sim_errmsg(s)[0] == '\0') {
				fprintf(stderr, "failed (%d) without a message\n", rc);
				abort();
			}
			hb_check_solution_pair(hb_sim_scene(s), hb_sim_arc(s), msg, sizeof msg);
			hb_check_physics(hb_sim_scene(s), hb_sim_arc(s), &ph, msg, sizeof msg);
			for (size_t i = 0; i < hb_sim_ncollisions(s); i++)
				(void)hb_sim_collision(s, i)->e;
			hb_sim_contact_live(s, &live);
			if (hb_arc_len(hb_sim_arc(s)) > 1)
				hb_sim_seek(s, hb_arc_len(hb_sim_arc(s)) / 2);
			hb_sim_advance(s, 50, 0.01);
			hb_sim_free(s);
		}
	}
	free(text);
	return 0;
}
