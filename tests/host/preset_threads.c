/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset_threads.c - presets loaded and run on many threads at once, for
 * ThreadSanitizer (make check-tsan links it with build-tsan/libhybounce.a).
 * Each of NTHREADS threads lists the presets (hb_preset_list: inih reads
 * every title), then loads every shipped preset by name (hb_preset_resolve,
 * hb_preset_load: inih again), runs it and keeps its collision count and
 * last collision, starting from a different preset on each thread so that
 * the same and different presets are read at the same time.  Every thread
 * must see every preset and get the same results, to the bit.
 *
 *     preset_threads NTHREADS        (HYBOUNCE_PRESETS: the presets)
 *
 * Prints TAP lines ("ok - ...", "not ok - ..."); exit 0 when all hold.
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <hybounce/preset.h>
#include <hybounce/sim.h>
#include <hybounce/status.h>

#define MAXP 64
#define MAXT 64

struct outcome {
	int ok;
	size_t ncoll;
	double te, vi;
	char msg[256];
};

struct worker {
	int k, nthreads, npresets;
	char (*names)[64];
	int listed;                   /* presets hb_preset_list gave this thread */
	struct outcome out[MAXP];
};

static void *
work(void *arg)
{
	struct worker *w = arg;
	struct hb_preset_info *list = NULL;
	int n = hb_preset_list(&list);

	w->listed = n;
	free(list);
	for (int m = 0; m < w->npresets; m++) {
		int i = (m + w->k) % w->npresets;
		struct outcome *o = &w->out[i];
		char path[4096];
		struct hb_scene sc;
		struct hb_sim *s;

		if (hb_preset_resolve(w->names[i], path, sizeof path, o->msg, sizeof o->msg) != 0 ||
		    hb_preset_load(path, &sc, o->msg, sizeof o->msg) != 0 ||
		    (s = hb_sim_new(&sc, o->msg, sizeof o->msg)) == NULL)
			continue;
		hb_sim_run(s); /* a preset that ends in a failure gives the same failure */
		o->ncoll = hb_sim_ncollisions(s);
		if (o->ncoll > 0) {
			const struct hb_collision *c = hb_sim_collision(s, o->ncoll - 1);

			o->te = c->te;
			o->vi = c->vi;
		}
		snprintf(o->msg, sizeof o->msg, "%s", hb_sim_end_str(s));
		o->ok = 1;
		hb_sim_free(s);
	}
	return NULL;
}

int
main(int argc, char **argv)
{
	static struct worker w[MAXT];
	static char names[MAXP][64];
	pthread_t th[MAXT];
	struct hb_preset_info *list = NULL;
	int nthreads = argc > 1 ? atoi(argv[1]) : 16, np, bad = 0;

	if (nthreads < 1 || nthreads > MAXT) {
		fprintf(stderr, "usage: %s NTHREADS (1 to %d)\n", argv[0], MAXT);
		return 2;
	}
	np = hb_preset_list(&list);
	if (np < 1 || np > MAXP) {
		printf("not ok - the presets are listed (%d)\n", np);
		free(list);
		return 1;
	}
	for (int i = 0; i < np; i++)
		snprintf(names[i], sizeof names[i], "%s", list[i].name);
	free(list);
	for (int k = 0; k < nthreads; k++) {
		w[k] = (struct worker){ .k = k, .nthreads = nthreads, .npresets = np, .names = names };
		if (pthread_create(&th[k], NULL, work, &w[k]) != 0) {
			printf("not ok - thread %d starts\n", k);
			return 1;
		}
	}
	for (int k = 0; k < nthreads; k++)
		pthread_join(th[k], NULL);
	for (int k = 0; k < nthreads; k++) {
		if (w[k].listed != np) {
			printf("not ok - thread %d lists %d presets, not %d\n", k, w[k].listed, np);
			bad++;
		}
		for (int i = 0; i < np; i++) {
			const struct outcome *a = &w[k].out[i], *b = &w[0].out[i];

			if (!a->ok) {
				printf("not ok - thread %d: %s: %s\n", k, names[i], a->msg);
				bad++;
			} else if (a->ncoll != b->ncoll || memcmp(&a->te, &b->te, sizeof a->te) != 0 ||
			    memcmp(&a->vi, &b->vi, sizeof a->vi) != 0 || strcmp(a->msg, b->msg) != 0) {
				printf("not ok - thread %d: %s: %zu collisions, last t_e %.17g, not thread "
				    "0's %zu, %.17g\n", k, names[i], a->ncoll, a->te, b->ncoll, b->te);
				bad++;
			}
		}
	}
	if (bad == 0)
		printf("ok - %d threads each loaded and ran the %d shipped presets at once: "
		    "the same results on every thread\n", nthreads, np);
	return bad != 0;
}
