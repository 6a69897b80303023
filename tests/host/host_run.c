/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * host_run.c - a host program of libhybounce (tests/cli/host.sh): loads
 * PRESET, runs it, exports the trace and the collisions as hybounce
 * --batch does (with the scene's .preset beside the trace) and saves the
 * scene with hb_preset_save, all into OUT.  Linked with names.c (the
 * host's own functions named as the library's internal ones) or public.c
 * (named as public ones), statically or dynamically.
 *
 *     host_run PRESET OUT
 *
 * Prints "version HEADER LIBRARY COMMIT"; exit 0, or 1 with a message.
 */
#include <stdio.h>
#include <string.h>

#include <hybounce/csv.h>
#include <hybounce/preset.h>
#include <hybounce/sim.h>
#include <hybounce/status.h>
#include <hybounce/version.h>

int
main(int argc, char **argv)
{
	char path[4096], trace[4096], coll[4096], saved[4096], msg[1024];
	struct hb_csv_export_report rep;
	struct hb_scene sc;
	struct hb_sim *s;
	int st;

	if (argc != 3) {
		fprintf(stderr, "usage: %s PRESET OUT\n", argv[0]);
		return 2;
	}
	printf("version %s %s %s\n", HB_VERSION_STRING, hb_version(), hb_version_commit());
	snprintf(trace, sizeof trace, "%s/trace.csv", argv[2]);
	snprintf(coll, sizeof coll, "%s/collisions.csv", argv[2]);
	snprintf(saved, sizeof saved, "%s/saved.preset", argv[2]);
	if (hb_preset_resolve(argv[1], path, sizeof path, msg, sizeof msg) != 0 ||
	    hb_preset_load(path, &sc, msg, sizeof msg) != 0 ||
	    (s = hb_sim_new(&sc, msg, sizeof msg)) == NULL) {
		fprintf(stderr, "host_run: %s\n", msg);
		return 1;
	}
	if ((st = hb_sim_run(s)) != 0) {
		fprintf(stderr, "host_run: %s: %s\n", hb_status_str(st), hb_sim_errmsg(s));
		hb_sim_free(s);
		return 1;
	}
	memset(&rep, 0, sizeof rep);
	if (hb_csv_export_files(s, trace, coll, path, &rep, msg, sizeof msg) != 0 ||
	    hb_preset_save(saved, hb_sim_scene(s), msg, sizeof msg) != 0) {
		fprintf(stderr, "host_run: %s\n", msg);
		hb_sim_free(s);
		return 1;
	}
	printf("collisions %zu\nscene %s\n", hb_sim_ncollisions(s), rep.scene);
	hb_sim_free(s);
	return 0;
}
