/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_sweep.c - the sweep engine: axes from specs, point order, the spec
 * file, one point equal to a plain run, the journal (resume, torn block,
 * damage), the threads and the merge.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/csv.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "sweeptest.h"

static void
vary(struct hb_sweep *sw, const char *arg)
{
	char msg[512];

	cr_assert_eq(hb_sweep_vary(sw, arg, msg, sizeof msg), HB_OK, "%s: %s", arg, msg);
}

static double
value(const struct hb_sweep *sw, long id, int k)
{
	char buf[64];

	cr_assert_eq(hb_sweep_point_value(sw, id, k, buf, sizeof buf), HB_OK);
	return strtod(buf, NULL);
}

Test(sweep, linear_range_hits_both_ends)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");

	vary(sw, "law.c=1e9:3e9:5");
	cr_assert_eq(hb_sweep_npoints(sw), 5);
	cr_assert_eq(value(sw, 0, 0), 1e9);
	cr_assert_eq(value(sw, 2, 0), 2e9);
	cr_assert_eq(value(sw, 4, 0), 3e9);
	hb_sweep_free(sw);
}

Test(sweep, log_range_and_units)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");

	vary(sw, "initial.v0=-1mm/s:-1m/s:4:log");
	cr_assert_eq(value(sw, 0, 0), -1e-3);
	assert_rel(value(sw, 1, 0), -1e-2, 1e-14);
	assert_rel(value(sw, 2, 0), -1e-1, 1e-14);
	cr_assert_eq(value(sw, 3, 0), -1.0);
	hb_sweep_free(sw);
}

Test(sweep, list_values_are_canonical_si)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");
	char buf[64];

	vary(sw, "initial.x0=10 um, 40um ,0.001");
	cr_assert_eq(hb_sweep_npoints(sw), 3);
	cr_assert_eq(value(sw, 0, 0), 10 * 1e-6);
	cr_assert_eq(value(sw, 2, 0), 1e-3);
	vary(sw, "scene.law=shccl,bwshccl");
	cr_assert_eq(hb_sweep_npoints(sw), 6);
	cr_assert_eq(hb_sweep_point_value(sw, 1, 1, buf, sizeof buf), HB_OK);
	cr_assert_str_eq(buf, "bwshccl");
	hb_sweep_free(sw);
}

Test(sweep, last_axis_varies_fastest_and_same_key_replaces)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");

	vary(sw, "law.c=1e9,2e9");
	vary(sw, "initial.x0=1um,2um,3um");
	cr_assert_eq(hb_sweep_npoints(sw), 6);
	cr_assert_eq(value(sw, 0, 0), 1e9);
	cr_assert_eq(value(sw, 2, 0), 1e9);
	cr_assert_eq(value(sw, 3, 0), 2e9);
	cr_assert_eq(value(sw, 4, 1), 2e-6);
	vary(sw, "law.c=5e9,6e9,7e9");   /* replaces axis 0 in place */
	cr_assert_eq(hb_sweep_naxes(sw), 2);
	cr_assert_eq(hb_sweep_npoints(sw), 9);
	cr_assert_eq(value(sw, 8, 0), 7e9);
	hb_sweep_free(sw);
}

Test(sweep, bad_specs_name_the_key)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");
	static const char *bad[] = {
		"law.c", "=1,2", "law.nope=1,2", "law.c=1:2", "law.c=1:2:0", "law.c=1:2:3:cubic",
		"law.c=0:1:3:log", "law.c=-1:1:3:log", "law.c=-5,1", "initial.x0=1kg",
		"initial.x0=1um,,2um", "scene.law=shccl:bwmcl:2", "law.c=1:inf:3",
	};
	char msg[512];

	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
		msg[0] = '\0';
		cr_assert_eq(hb_sweep_vary(sw, bad[i], msg, sizeof msg), HB_EINVAL, "%s accepted", bad[i]);
		cr_assert(strstr(msg, "--vary") != NULL, "%s: message '%s'", bad[i], msg);
	}
	cr_assert_eq(hb_sweep_npoints(sw), 0);
	cr_assert_eq(hb_sweep_check(sw, msg, sizeof msg), HB_EINVAL);
	hb_sweep_free(sw);
}

Test(sweep, check_finds_a_bad_combination)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-bwshccl");
	char msg[512];

	vary(sw, "law.beta=1e9,5e9");
	vary(sw, "law.gamma=2e9,5e9");   /* gamma in [-beta, beta]: point 0 is out */
	cr_assert_eq(hb_sweep_check(sw, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "point 0 (law.beta=1000000000 law.gamma=2000000000)") != NULL, "%s", msg);
	hb_sweep_free(sw);
}

Test(sweep, spec_round_trips)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl"), *back;
	struct hb_scene sc;
	char a[32768], b[32768], msg[512];

	vary(sw, "law.c=1e9:2e9:3");
	vary(sw, "initial.x0=10um,20um");
	cr_assert_lt(hb_sweep_spec_format(sw, a, sizeof a), sizeof a);
	cr_assert(strstr(a, "\n; sweep: --vary law.c=1e9:2e9:3\n; sweep: --vary initial.x0=10um,20um\n"));
	cr_assert_eq(hb_preset_load_string(a, "spec", &sc, msg, sizeof msg), HB_OK, "%s", msg);
	back = hb_sweep_new(&sc, msg, sizeof msg);
	cr_assert_eq(hb_sweep_vary_from_preset(back, a, "spec", msg, sizeof msg), HB_OK, "%s", msg);
	hb_sweep_spec_format(back, b, sizeof b);
	cr_assert_str_eq(a, b);
	cr_assert_eq(hb_sweep_npoints(back), 6);
	hb_sweep_free(back);
	hb_sweep_free(sw);
}

/* The block of a point is the plain run's collisions and work, to the byte. */
Test(sweep, point_equals_a_plain_run)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");
	struct hb_sim *s;
	char *blk, *coll = NULL, msg[512], line[4096];
	size_t len = 0;
	int failed;
	FILE *f;

	vary(sw, "initial.x0=10um,30um");
	cr_assert_eq(hb_sweep_point_block(sw, 1, &blk, &failed, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(failed, 0);
	s = plain_run_with("permanent-contact-shccl", "initial.x0", "30um");
	f = open_memstream(&coll, &len);
	cr_assert_eq(hb_csv_stream_collisions(f, s, msg, sizeof msg), HB_OK);
	fclose(f);
	{
		const char *q;

		cr_assert(hb_sim_ncollisions(s) > 0);
		q = block_has_collisions(blk, coll);
		snprintf(line, sizeof line, ",%ld,%ld,%ld,%ld,", hb_sim_stats(s)->steps,
		         hb_sim_stats(s)->rejected, hb_sim_stats(s)->rhs, hb_sim_stats(s)->jac);
		cr_assert(strncmp(q, "r,1,", 4) == 0 && strstr(q, line) != NULL, "%s", q);
	}
	free(coll);
	free(blk);
	hb_sim_free(s);
	hb_sweep_free(sw);
}

static char *
slurp_file(const char *path)
{
	FILE *f = fopen(path, "r");
	char *buf = NULL;
	size_t len = 0;

	cr_assert_not_null(f, "%s", path);
	cr_assert_eq(getdelim(&buf, &len, '\0', f) > 0, 1);
	fclose(f);
	return buf;
}

/* runs.csv without the cpu_s column. */
static char *
runs_nocpu(const char *dir)
{
	char path[512], *t, *o, *p;

	snprintf(path, sizeof path, "%s/runs.csv", dir);
	t = slurp_file(path);
	o = calloc(strlen(t) + 1, 1);
	for (p = t; *p; ) {
		char *e = strchr(p, '\n'), *c = e;

		while (c > p && c[-1] != ',')
			c--;
		strncat(o, p, (size_t)(c - p));
		strcat(o, "\n");
		p = e + 1;
	}
	free(t);
	return o;
}

struct count { long calls, last_done, total, resumed; };

static void
count_progress(void *ctx, const struct hb_sweep_progress *p)
{
	struct count *c = ctx;

	c->calls++;
	c->last_done = p->done;
	c->total = p->total;
	c->resumed = p->resumed;
}

Test(sweep, threads_journal_resume_and_merge)
{
	struct hb_sweep *sw = sweep_of("permanent-contact-shccl");
	struct hb_sweep_options o = { 0 };
	struct count c = { 0 };
	char tmpl[] = "/tmp/hybounce-sweep-XXXXXX", d1[600], d2[600], d3[600], path[700], msg[512];
	char *a, *b, *ca, *cb;
	FILE *f;

	cr_assert_not_null(mkdtemp(tmpl));
	snprintf(d1, sizeof d1, "%s/a", tmpl);
	snprintf(d2, sizeof d2, "%s/b", tmpl);
	snprintf(d3, sizeof d3, "%s/c", tmpl);
	vary(sw, "initial.x0=5um:50um:7");
	o.progress = count_progress;
	o.ctx = &c;
	o.shard_n = 1;

	/* Three threads. */
	o.dir = d1;
	o.jobs = 3;
	cr_assert_eq(hb_sweep_run(sw, &o, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(c.last_done, 7);
	cr_assert_eq(c.calls, 8);   /* the start, then one per point */

	/* One thread, resuming from a journal of two points and a torn block. */
	o.dir = d2;
	o.jobs = 1;
	cr_assert_eq(hb_sweep_prepare_dir(sw, d2, msg, sizeof msg), HB_OK, "%s", msg);
	snprintf(path, sizeof path, "%s/points.journal", d2);
	f = fopen(path, "w");
	for (long id = 3; id <= 4; id++) {
		char *blk;
		int failed;

		cr_assert_eq(hb_sweep_point_block(sw, id, &blk, &failed, msg, sizeof msg), HB_OK);
		fputs(blk, f);
		free(blk);
	}
	fputs("c,5,0,0.001", f);   /* a kill in the middle of a write */
	fclose(f);
	memset(&c, 0, sizeof c);
	cr_assert_eq(hb_sweep_run(sw, &o, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(c.resumed, 2);
	cr_assert_eq(c.calls, 1 + 5);
	cr_assert_eq(access(path, F_OK), -1, "the journal is removed after the merge");
	a = runs_nocpu(d1);
	b = runs_nocpu(d2);
	cr_assert_str_eq(a, b);
	snprintf(path, sizeof path, "%s/collisions.csv", d1);
	ca = slurp_file(path);
	snprintf(path, sizeof path, "%s/collisions.csv", d2);
	cb = slurp_file(path);
	cr_assert_str_eq(ca, cb);
	free(a);
	free(b);
	free(cb);

	/* Two shards, then the merge. */
	o.dir = d3;
	o.shard_n = 2;
	for (o.shard_k = 0; o.shard_k < 2; o.shard_k++) {
		cr_assert_eq(hb_sweep_run(sw, &o, msg, sizeof msg), HB_OK, "%s", msg);
		if (o.shard_k == 0) {
			unsigned char done[4] = { 9, 9, 9, 9 };

			cr_assert_eq(hb_sweep_merge(d3, msg, sizeof msg), HB_EINVAL);
			cr_assert(strstr(msg, "1 of 2 shards incomplete: shard 1 (not started); 3 of "
			                 "7 points missing"), "%s", msg);
			cr_assert_eq(hb_sweep_shards_done(sw, d3, 2, done, msg, sizeof msg), 1, "%s", msg);
			cr_assert(done[0] == 1 && done[1] == 0);
			/* Counted in 4 shards: 0 (ids 0, 4) and 2 (ids 2, 6) are done. */
			cr_assert_eq(hb_sweep_shards_done(sw, d3, 4, done, msg, sizeof msg), 2, "%s", msg);
			cr_assert(done[0] == 1 && done[1] == 0 && done[2] == 1 && done[3] == 0);
			cr_assert_eq(hb_sweep_merge_shards(d3, 7, msg, sizeof msg), HB_EINVAL);
			cr_assert(strstr(msg, "3 of 7 shards incomplete: shard 1 (not started), shard 3 "
			                 "(not started), shard 5 (not started)"), "%s", msg);
		}
	}
	cr_assert_eq(hb_sweep_merge(d3, msg, sizeof msg), HB_OK, "%s", msg);
	snprintf(path, sizeof path, "%s/collisions.csv", d3);
	cb = slurp_file(path);
	cr_assert_str_eq(ca, cb);
	free(ca);
	free(cb);

	/* A damaged journal is refused, not silently skipped. */
	snprintf(path, sizeof path, "%s/shard-0-of-2.journal", d3);
	f = fopen(path, "a");
	fputs("garbage line\n", f);
	fclose(f);
	cr_assert_eq(hb_sweep_merge(d3, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "not a line of this sweep's journal"), "%s", msg);

	/* Another sweep in the same folder is refused. */
	vary(sw, "initial.x0=5um:50um:8");
	o.dir = d1;
	o.shard_n = 1;
	o.shard_k = 0;
	cr_assert_eq(hb_sweep_run(sw, &o, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "holds a different sweep"), "%s", msg);
	hb_sweep_free(sw);
	{
		char cmd[700];

		snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpl);
		cr_assert_eq(system(cmd), 0);
	}
}

/* The explorer's curve: the same runs as the sweep (e to the bit), in the background. */
Test(sweep, curve_matches_the_sweep_and_exports, .timeout = 60)
{
	struct hb_scene sc;
	struct hb_sweep_curve *c;
	struct hb_sweep *sw;
	double x[6], y[6];
	int st[6];
	char msg[512], path[] = "/tmp/hybounce-curve-XXXXXX", *csv;
	long done;
	int fd;

	scene_preset("permanent-contact-shccl", &sc);
	cr_assert_eq(hb_scene_set(&sc, "initial.x0", "0", msg, sizeof msg), HB_OK);
	cr_assert_eq(hb_scene_set(&sc, "run.J", "2", msg, sizeof msg), HB_OK);
	c = hb_sweep_curve_start(&sc, "initial.v0", "-5mm/s:-0.5m/s:6:log", HB_CURVE_E, 0, 2, msg,
	                      sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	cr_assert_eq(hb_sweep_curve_npoints(c), 6);
	while ((done = hb_sweep_curve_poll(c, x, y, st, 6)) < 6)
		nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
	sw = hb_sweep_new(&sc, msg, sizeof msg);
	vary(sw, "initial.v0=-5mm/s:-0.5m/s:6:log");
	for (long i = 0; i < 6; i++) {
		char *blk, want[64];
		int failed;

		cr_assert_eq(st[i], HB_CURVE_DONE);
		cr_assert_eq(x[i], value(sw, i, 0));
		cr_assert_eq(hb_sweep_point_block(sw, i, &blk, &failed, msg, sizeof msg), HB_OK);
		snprintf(want, sizeof want, ",%.17g,", y[i]);
		cr_assert(y[i] > 0 && y[i] < 1 && strstr(blk, want) != NULL, "point %ld: e %.17g, %s",
		          i, y[i], blk);
		free(blk);
	}
	fd = mkstemp(path);
	close(fd);
	cr_assert_eq(hb_sweep_curve_write_csv(c, path, msg, sizeof msg), HB_OK, "%s", msg);
	csv = slurp_file(path);
	{
		const char *head = "initial.v0,i,e\n-0.0050000000000000001,0,";

		cr_assert(strncmp(csv, head, strlen(head)) == 0, "%s", csv);
	}
	unlink(path);
	free(csv);
	hb_sweep_curve_free(c);
	hb_sweep_free(sw);
}

/* Freeing a curve cancels it: the workers stop within a slice of their run. */
Test(sweep, curve_cancels, .timeout = 30)
{
	struct hb_scene sc;
	struct hb_sweep_curve *c;
	char msg[512];

	scene_preset("steel-on-bitumen", &sc);
	c = hb_sweep_curve_start(&sc, "law.c", "440:44000:400:log", HB_CURVE_COLLISIONS, 0, 2, msg,
	                      sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	cr_assert_lt(hb_sweep_curve_poll(c, NULL, NULL, NULL, 0), 400);
	hb_sweep_curve_free(c);
	cr_assert_null(hb_sweep_curve_start(&sc, "law.nope", "1,2", HB_CURVE_E, 0, 1, msg, sizeof msg));
	cr_assert(strstr(msg, "law.nope") != NULL, "%s", msg);
}

/*
 * The sweep view counts as the batch summary and runs.csv do: its run
 * observables are the table's (observables.h), every collision counted
 * (hertz-elastic over 30 s with max_samples 1024: 469 collisions, 85 kept),
 * and "collision i" is the one numbered i among all (none once thinned out).
 */
Test(sweep, curve_observables_are_the_table, .timeout = 60)
{
	struct hb_scene sc;
	struct hb_sweep_curve *c;
	struct hb_sim *s;
	char msg[512];
	double x[1], y[1];
	int st[1];
	long kept_i = -1, thinned_i = -1;

	scene_preset("hertz-elastic", &sc);
	cr_assert_eq(hb_scene_set(&sc, "run.T", "30", msg, sizeof msg), HB_OK);
	cr_assert_eq(hb_scene_set(&sc, "run.max_samples", "1024", msg, sizeof msg), HB_OK);
	s = run_scene(&sc);
	cr_assert_eq(hb_sim_collisions_total(s), 469);
	cr_assert_eq(hb_sim_ncollisions(s), 85);
	cr_assert_eq(hb_sweep_observe(s, HB_CURVE_COLLISIONS, 0), 469.0);
	cr_assert_eq(hb_observable_find("collisions"), HB_OBS_COLLISIONS);
	for (int k = 0; k < HB_OBS_COUNT; k++) {
		double a = hb_observable_value(s, k), b = hb_sweep_observe(s, HB_CURVE_RUN + k, 0);

		cr_assert(a == b || (isnan(a) && isnan(b)), "%s: %g %g", hb_observables[k].name, a, b);
		cr_assert_str_eq(hb_sweep_observable_name(HB_CURVE_RUN + k), hb_observables[k].name);
	}
	for (size_t r = 1; r < hb_sim_ncollisions(s) && thinned_i < 0; r++) {
		const struct hb_collision *p = hb_sim_collision(s, r - 1), *q = hb_sim_collision(s, r);

		if (q->i > p->i + 1) {
			thinned_i = p->i + 1;
			kept_i = q->i;
			cr_assert_eq(hb_sweep_observe(s, HB_CURVE_E, kept_i), q->e);
			cr_assert_eq(hb_sweep_observe(s, HB_CURVE_VI, kept_i), q->vi);
		}
	}
	cr_assert_geq(thinned_i, 0);
	cr_assert(isnan(hb_sweep_observe(s, HB_CURVE_E, thinned_i)));
	hb_sim_free(s);

	c = hb_sweep_curve_start(&sc, "run.T", "30", HB_CURVE_COLLISIONS, 0, 1, msg, sizeof msg);
	cr_assert_not_null(c, "%s", msg);
	while (hb_sweep_curve_poll(c, x, y, st, 1) < 1)
		nanosleep(&(struct timespec){ 0, 1000000 }, NULL);
	cr_assert_eq(st[0], HB_CURVE_DONE);
	cr_assert_eq(y[0], 469.0);
	hb_sweep_curve_free(c);
}

/*
 * A point's scene made by storing its values and deriving once (every axis
 * a range of a number) is the scene that hb_scene_set of the values as
 * runs.csv shows them makes: the same preset text, derived values and law
 * parameters, for keys of the bodies (a material, so k is derived), the
 * law, the loads and the initial state, one axis and two.
 */
Test(sweep, point_scene_equals_the_set_values)
{
	static const char *const axes[][2] = {
		{ "initial.x0=10mm:30mm:4", NULL },
		{ "law.c=440:44000:4:log", NULL },
		{ "body1.E=100GPa:300GPa:3", NULL },
		{ "body1.R=10mm:30mm:3", "law.alpha=0.2:0.5:3" },
		{ "loads.g=0:20:3", "initial.v0=-1m/s:-0.1m/s:3" },
	};

	for (size_t c = 0; c < sizeof axes / sizeof axes[0]; c++) {
		struct hb_sweep *sw = sweep_of("steel-on-bitumen");
		long np;

		vary(sw, axes[c][0]);
		if (axes[c][1] != NULL)
			vary(sw, axes[c][1]);
		np = hb_sweep_npoints(sw);
		for (long id = 0; id < np; id++) {
			struct hb_scene a, b;
			char msg[512], ta[8192], tb[8192];

			cr_assert_eq(hb_sweep_point_scene(sw, id, &a, msg, sizeof msg), HB_OK, "%s", msg);
			scene_preset("steel-on-bitumen", &b);
			for (int k = 0; k < hb_sweep_naxes(sw); k++) {
				char v[64], key[64];
				const char *spec = axes[c][k];

				snprintf(key, sizeof key, "%.*s", (int)(strchr(spec, '=') - spec), spec);
				cr_assert_eq(hb_sweep_point_value(sw, id, k, v, sizeof v), HB_OK);
				cr_assert_eq(hb_scene_set(&b, key, v, msg, sizeof msg), HB_OK, "%s", msg);
			}
			hb_preset_format(&a, ta, sizeof ta);
			hb_preset_format(&b, tb, sizeof tb);
			cr_assert_str_eq(ta, tb, "%s point %ld", axes[c][0], id);
			cr_assert(memcmp(&a.d, &b.d, sizeof a.d) == 0, "%s point %ld: derived", axes[c][0], id);
			cr_assert(memcmp(a.par, b.par, sizeof a.par) == 0, "%s point %ld: law", axes[c][0], id);
		}
		hb_sweep_free(sw);
	}
}
