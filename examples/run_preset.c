/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * run_preset.c - the smallest complete use of libhybounce from C: load a
 * preset, run it to its end, print its completed collisions.
 *
 *     cc run_preset.c $(pkg-config --cflags --libs hybounce) -o run_preset
 *     ./run_preset steel-on-bitumen
 *
 * PRESET is a path or a name looked up in the preset folders
 * ($HYBOUNCE_PRESETS, ./presets, the installed presets).  One line per
 * collision: index, commencement t_e and separation t_s (s), approach
 * velocity v_i (m/s) and restitution e, as %.17g (the numbers of
 * `hybounce --batch PRESET --collisions -`, exactly).
 *
 * Exit status: 0 success, 1 the run failed (what was computed is printed),
 * 2 bad usage or a bad preset.
 */
#include <stdio.h>

#include <hybounce/preset.h>
#include <hybounce/sim.h>
#include <hybounce/status.h>

int
main(int argc, char **argv)
{
	char path[512], msg[1024];
	struct hb_scene sc;          /* plain data, owned by the caller */
	struct hb_sim *s;            /* opaque, owned by the caller: hb_sim_free */
	size_t i, n;
	int status;

	if (argc != 2) {
		fprintf(stderr, "usage: %s PRESET\n", argv[0]);
		return 2;
	}
	/* Every function returns 0 or an hb_status, with the reason in msg. */
	if (hb_preset_resolve(argv[1], path, sizeof path, msg, sizeof msg) != 0 ||
	    hb_preset_load(path, &sc, msg, sizeof msg) != 0) {
		fprintf(stderr, "%s: %s\n", argv[0], msg);
		return 2;
	}
	s = hb_sim_new(&sc, msg, sizeof msg);   /* copies sc: it may go now */
	if (s == NULL) {
		fprintf(stderr, "%s: %s\n", argv[0], msg);
		return 2;
	}
	status = hb_sim_run(s);

	printf("# %s: %s\n", path, sc.name);
	printf("# i t_e[s] t_s[s] v_i[m/s] e\n");
	n = hb_sim_ncollisions(s);
	for (i = 0; i < n; i++) {
		/* borrowed from s: valid until the sim changes or is freed */
		const struct hb_collision *c = hb_sim_collision(s, i);
		printf("%ld %.17g %.17g %.17g %.17g\n", c->i, c->te, c->ts, c->vi, c->e);
	}
	printf("# %zu collisions, %s\n", n, hb_sim_end_str(s));
	if (status != 0)
		fprintf(stderr, "%s: %s: %s\n", argv[0], hb_status_str(status), hb_sim_errmsg(s));
	hb_sim_free(s);
	return status != 0 ? 1 : 0;
}
