/*
 * fuzz_run.c - preset plus a short run: any preset text that loads is run
 * for a bounded amount of work (at most 400 accepted steps and 50 ms of
 * CPU, with T and J as the preset says), then checked (solution pair and
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
	struct scene sc;
	struct sim *s;

	if (preset_load_string(text, "fuzz.preset", &sc, msg, sizeof msg) == HB_OK) {
		/* keep each input short: a small arc bound too */
		if (sc.run.max_samples > 4096)
			sc.run.max_samples = 4096;
		s = sim_new(&sc, msg, sizeof msg);
		if (s != NULL) {
			struct collision live;
			struct check_physics ph;
			int rc = sim_advance(s, 400, 0.05);

			if (rc != HB_OK && rc != HB_EDONE && sim_errmsg(s)[0] == '\0') {
				fprintf(stderr, "failed (%d) without a message\n", rc);
				abort();
			}
			check_solution_pair(sim_scene(s), sim_arc(s), msg, sizeof msg);
			check_physics(sim_scene(s), sim_arc(s), &ph, msg, sizeof msg);
			for (size_t i = 0; i < sim_ncollisions(s); i++)
				(void)sim_collision(s, i)->e;
			sim_contact_live(s, &live);
			if (arc_len(sim_arc(s)) > 1)
				sim_seek(s, arc_len(sim_arc(s)) / 2);
			sim_advance(s, 50, 0.01);
			sim_free(s);
		}
	}
	free(text);
	return 0;
}
