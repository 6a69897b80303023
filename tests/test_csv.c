/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_csv.c - CSV export (src/core/csv.c): the header of each system and
 * law, every number read back with strtod() equal to the double written,
 * the full system's body velocities, the collisions table (t_f empty when
 * unknown), the scene written beside the export reloading to the same
 * scene, and failures that leave no file and keep an existing one intact;
 * the stream writers: byte for byte the file, stopping at the first failed
 * write with its errno (a full disk, a closed pipe).
 */
#define _GNU_SOURCE     /* fopencookie: a stream whose writes fail on cue */
#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <criterion/criterion.h>

#include "hybounce/csv.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "testutil.h"

/* Loads a preset, applies KEY=VALUE overrides, runs it to the end. */
static struct hb_sim *
run(const char *name, const char *const *set)
{
	char path[1024], msg[512] = "";
	struct hb_scene sc;
	struct hb_sim *s;

	snprintf(path, sizeof path, "%s/%s.preset", preset_dir(), name);
	cr_assert_eq(hb_preset_load(path, &sc, msg, sizeof msg), HB_OK, "%s", msg);
	for (int i = 0; set != NULL && set[i] != NULL; i += 2)
		cr_assert_eq(hb_scene_set(&sc, set[i], set[i + 1], msg, sizeof msg), HB_OK, "%s", msg);
	s = hb_sim_new(&sc, msg, sizeof msg);
	cr_assert(s != NULL, "%s", msg);
	cr_assert_eq(hb_sim_run(s), HB_OK, "%s", hb_sim_errmsg(s));
	return s;
}

/* Splits the next line of *p into at most max fields (in place). */
static int
fields(char **p, char **f, int max)
{
	char *line = *p, *e;
	int n = 0;

	if (*line == '\0')
		return -1;
	e = strchr(line, '\n');
	cr_assert(e != NULL, "last record without a line end");
	*e = '\0';
	*p = e + 1;
	for (char *q = line;;) {
		char *c = strchr(q, ',');
		cr_assert(n < max, "too many fields");
		f[n++] = q;
		if (c == NULL)
			break;
		*c = '\0';
		q = c + 1;
	}
	return n;
}

static void
num_is(const char *field, double want, const char *what, size_t row)
{
	char *end;
	double v;

	if (isnan(want)) {
		cr_assert_str_eq(field, "", "%s row %zu: NaN must be an empty field", what, row);
		return;
	}
	v = strtod(field, &end);
	cr_assert(*end == '\0' && end != field, "%s row %zu: '%s' is not a number", what, row, field);
	if (want == 0)
		want = 0; /* -0 is written 0 */
	cr_assert(memcmp(&v, &want, sizeof v) == 0, "%s row %zu: read %.17g, written %.17g", what,
	    row, v, want);
}

static void
check_arc_file(const char *path, const struct hb_sim *s, const char *header)
{
	char *text = slurp(path), *p = text, *f[32];
	const struct hb_arc *a = hb_sim_arc(s);
	const struct hb_scene *sc = hb_sim_scene(s);
	int nz = sc->law->n_z, full = sc->d.system == HB_SCENE_FULL;
	int nf = 8 + nz + (full ? 4 : 0);
	size_t rows = 0;
	char head[256];

	cr_assert(strncmp(text, header, strlen(header)) == 0 && text[strlen(header)] == '\n',
	    "header is \"%.*s\", expected \"%s\"", (int)strcspn(text, "\n"), text, header);
	cr_assert_eq(fields(&p, f, 32), nf);
	snprintf(head, sizeof head, "%s", header);
	for (;;) {
		int n = fields(&p, f, 32);
		const struct hb_arc_sample *x;
		int k = 0;
		if (n < 0)
			break;
		cr_assert_eq(n, nf, "row %zu has %d fields", rows, n);
		cr_assert(rows < hb_arc_len(a), "more rows than samples");
		x = hb_arc_at(a, rows);
		num_is(f[k++], x->t, "t", rows);
		cr_assert_eq(strtol(f[k++], NULL, 10), x->j);
		cr_assert_eq(strtol(f[k++], NULL, 10), x->q);
		num_is(f[k++], x->x, "x", rows);
		num_is(f[k++], x->v, "v", rows);
		num_is(f[k++], x->xc, "x_c", rows);
		for (int z = 0; z < nz; z++)
			num_is(f[k++], x->z[z], "z_c", rows);
		num_is(f[k++], x->Fc, "F_c", rows);
		num_is(f[k++], x->Fer, "F_er", rows);
		if (full) {
			num_is(f[k++], x->xm, "x_m", rows);
			num_is(f[k++], x->vm, "v_m", rows);
			num_is(f[k++], x->vm + sc->d.etac * x->v, "v_m1", rows);
			num_is(f[k++], x->vm - sc->d.eta * x->v, "v_m2", rows);
		}
		rows++;
	}
	cr_assert_eq(rows, hb_arc_len(a), "%zu rows for %zu samples", rows, hb_arc_len(a));
	free(text);
}

static const char *const coll_header =
    "i,t_e,t_s,t_d,t_f,v_i,e,x_c_max,F_c_max,x_c_r,W,J_Fc,J_Fe,Lambda";

static size_t
check_coll_file(const char *path, const struct hb_sim *s)
{
	char *text = slurp(path), *p = text, *f[32];
	size_t rows = 0, nc = hb_sim_ncollisions(s), k = 0;

	cr_assert(strncmp(text, coll_header, strlen(coll_header)) == 0);
	cr_assert_eq(fields(&p, f, 32), 14);
	for (size_t i = 0; i < nc; i++) {
		const struct hb_collision *c = hb_sim_collision(s, i);
		if (!c->complete)
			continue;
		cr_assert_eq(fields(&p, f, 32), 14, "collision %zu", i);
		k = 0;
		cr_assert_eq(strtol(f[k++], NULL, 10), c->i);
		num_is(f[k++], c->te, "t_e", rows);
		num_is(f[k++], c->ts, "t_s", rows);
		num_is(f[k++], c->td, "t_d", rows);
		num_is(f[k++], c->tf, "t_f", rows);
		num_is(f[k++], c->vi, "v_i", rows);
		num_is(f[k++], c->e, "e", rows);
		num_is(f[k++], c->xcmax, "x_c_max", rows);
		num_is(f[k++], c->Fcmax, "F_c_max", rows);
		num_is(f[k++], c->xcr, "x_c_r", rows);
		num_is(f[k++], c->W, "W", rows);
		num_is(f[k++], c->JFc, "J_Fc", rows);
		num_is(f[k++], c->JFe, "J_Fe", rows);
		num_is(f[k++], c->Lambda, "Lambda", rows);
		rows++;
	}
	cr_assert_eq(fields(&p, f, 32), -1, "rows beyond the completed collisions");
	free(text);
	return rows;
}

static int
count_entries(const char *dir)
{
	DIR *d = opendir(dir);
	struct dirent *de;
	int n = 0;

	cr_assert(d != NULL);
	while ((de = readdir(d)) != NULL)
		if (de->d_name[0] != '.')
			n++;
	closedir(d);
	return n;
}

Test(csv, reduced_linear_law)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], msg[512] = "";
	struct hb_sim *s = run("nonunique-separation", NULL);

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/arc.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	cr_assert_eq(hb_csv_write_arc(path, s, msg, sizeof msg), HB_OK, "%s", msg);
	check_arc_file(path, s, "t,j,q_c,x,v,x_c,F_c,F_er");
	cr_assert_eq(hb_csv_write_collisions(cpath, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert(hb_sim_ncollisions(s) >= 1, "the example separates once");
	cr_assert(check_coll_file(cpath, s) >= 1);
	/* Only the CSV files: no temporary left. */
	cr_assert_eq(count_entries(dir), 2);
	unlink(path);
	unlink(cpath);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, full_system_columns)
{
	static const char *const set[] = { "run.T", "0.05 s", "run.rtol", "1e-9", "run.atol",
		"1e-9", NULL };
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], msg[512] = "";
	struct hb_sim *s = run("ptfe-pom", set);

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/arc.csv", dir);
	cr_assert_eq(hb_csv_write_arc(path, s, msg, sizeof msg), HB_OK, "%s", msg);
	check_arc_file(path, s, "t,j,q_c,x,v,x_c,z_c1,F_c,F_er,x_m,v_m,v_m1,v_m2");
	unlink(path);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, two_internal_states)
{
	static const char *const set[] = { "run.T", "1 ms", NULL };
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], msg[512] = "";
	struct hb_sim *s = run("steel-on-bitumen", set);

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/arc.csv", dir);
	cr_assert_eq(hb_csv_write_arc(path, s, msg, sizeof msg), HB_OK, "%s", msg);
	check_arc_file(path, s, "t,j,q_c,x,v,x_c,z_c1,z_c2,F_c,F_er");
	unlink(path);
	rmdir(dir);
	hb_sim_free(s);
}

/* 1 if a field of the CSV text is a negative zero ("-0", "-0.0", "-0e+00"). */
static int
has_negative_zero(const char *text)
{
	for (const char *p = text; (p = strstr(p, "-0")) != NULL; p++) {
		char *end;
		if (p != text && p[-1] != ',' && p[-1] != '\n')
			continue;
		if (strtod(p, &end) == 0 && end != p && (*end == ',' || *end == '\n' || *end == 0))
			return 1;
	}
	return 0;
}

/* Zero forces of the flights (-0 in the engine) are written 0. */
Test(csv, no_negative_zero)
{
	static const char *const set[] = { "run.T", "20 ms", NULL };
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], msg[512] = "", *text;
	struct hb_sim *s = run("steel-on-bitumen", set);
	const struct hb_arc *a = hb_sim_arc(s);
	int engine_has = 0;

	cr_assert(has_negative_zero("1,-0,2\n") && has_negative_zero("-0.0\n") &&
	    !has_negative_zero("1,-0.5,2\n") && !has_negative_zero("1e-05,0\n"));
	for (size_t i = 0; i < hb_arc_len(a); i++)
		engine_has |= hb_arc_at(a, i)->Fc == 0 && signbit(hb_arc_at(a, i)->Fc);
	cr_assert(engine_has, "no -0 in the engine's arc: the test checks nothing");
	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/arc.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	cr_assert_eq(hb_csv_write_arc(path, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_csv_write_collisions(cpath, s, msg, sizeof msg), HB_OK, "%s", msg);
	text = slurp(path);
	cr_assert(!has_negative_zero(text), "the trace holds a -0");
	free(text);
	text = slurp(cpath);
	cr_assert(!has_negative_zero(text), "the collisions hold a -0");
	free(text);
	unlink(path);
	unlink(cpath);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, export_writes_scene_beside)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], sout[256] = "", want[256];
	char msg[512] = "";
	struct hb_sim *s = run("hertz-elastic", NULL);
	struct hb_scene back;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/run.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/run-collisions.csv", dir);
	snprintf(want, sizeof want, "%s/run.preset", dir);
	cr_assert_eq(hb_csv_export(s, path, cpath, sout, sizeof sout, msg, sizeof msg), HB_OK, "%s",
	    msg);
	cr_assert_str_eq(sout, want);
	check_arc_file(path, s, "t,j,q_c,x,v,x_c,F_c,F_er");
	cr_assert(check_coll_file(cpath, s) >= 2, "the elastic ball bounces more than once");
	cr_assert_eq(hb_preset_load(want, &back, msg, sizeof msg), HB_OK, "%s", msg);
	const struct hb_scene *sc = hb_sim_scene(s);
	cr_assert_eq(back.law, sc->law);
	cr_assert(memcmp(back.par, sc->par, sizeof back.par) == 0);
	cr_assert(memcmp(&back.init, &sc->init, sizeof back.init) == 0);
	cr_assert(memcmp(&back.loads, &sc->loads, sizeof back.loads) == 0);
	cr_assert(memcmp(&back.run, &sc->run, sizeof back.run) == 0);
	cr_assert_eq(count_entries(dir), 3);
	/* Only the collisions: the scene goes beside them. */
	unlink(want);
	cr_assert_eq(hb_csv_export(s, NULL, cpath, sout, sizeof sout, msg, sizeof msg), HB_OK);
	snprintf(want, sizeof want, "%s/run-collisions.preset", dir);
	cr_assert_str_eq(sout, want);
	unlink(want);
	unlink(path);
	unlink(cpath);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, failure_leaves_nothing)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], spath[256], msg[512] = "";
	struct hb_sim *s = run("nonunique-separation", NULL);
	FILE *f;
	char *old;

	cr_assert_eq(hb_csv_write_arc("/nonexistent/dir/x.csv", s, msg, sizeof msg), HB_EIO);
	cr_assert(strncmp(msg, "/nonexistent/dir/x.csv: ", 24) == 0, "%s", msg);
	cr_assert(access("/nonexistent/dir/x.csv", F_OK) != 0);
	cr_assert_eq(hb_csv_write_collisions("/nonexistent/dir/c.csv", s, msg, sizeof msg), HB_EIO);

	/* An export whose second file cannot be written: the first is not
	 * left behind, the existing good file is untouched, no scene file. */
	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/good.csv", dir);
	snprintf(spath, sizeof spath, "%s/good.preset", dir);
	f = fopen(path, "w");
	fputs("t,x\n1,2\n", f);
	fclose(f);
	snprintf(cpath, sizeof cpath, "/nonexistent/dir/c.csv");
	cr_assert_eq(hb_csv_export(s, path, cpath, NULL, 0, msg, sizeof msg), HB_EIO);
	cr_assert(strncmp(msg, cpath, strlen(cpath)) == 0, "%s", msg);
	old = slurp(path);
	cr_assert_str_eq(old, "t,x\n1,2\n");
	free(old);
	cr_assert(access(spath, F_OK) != 0, "the scene file was left");
	cr_assert_eq(count_entries(dir), 1, "a temporary file was left");

	/* A folder in the way of the collisions: refused before anything is
	 * written (a failed rename is undone too: tests/cli/export-kill.sh). */
	snprintf(cpath, sizeof cpath, "%s/busy.csv", dir);
	cr_assert_eq(mkdir(cpath, 0700), 0);
	snprintf(spath, sizeof spath, "%.200s/k", cpath);
	f = fopen(spath, "w");
	fclose(f);
	cr_assert_eq(hb_csv_export(s, path, cpath, NULL, 0, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "is a folder") != NULL, "%s", msg);
	old = slurp(path);
	cr_assert_str_eq(old, "t,x\n1,2\n", "the good file was replaced by a failed export");
	free(old);
	cr_assert_eq(count_entries(dir), 2, "files were left");
	unlink(spath);
	rmdir(cpath);

	/* Refuses to write the scene over the export itself. */
	snprintf(cpath, sizeof cpath, "%s/x.preset", dir);
	cr_assert_eq(hb_csv_export(s, cpath, NULL, NULL, 0, msg, sizeof msg), HB_EINVAL);
	unlink(path);
	rmdir(dir);
	hb_sim_free(s);
}

/* ------------------------------------------------------------------ */
/* Streams (csv_stream_*): what batch mode writes for "--trace -"       */

/* Reads what was written to the temporary stream f, from its start. */
static char *
slurp_stream(FILE *f)
{
	long len;
	char *buf;

	cr_assert_eq(fflush(f), 0);
	len = ftell(f);
	cr_assert(len >= 0);
	rewind(f);
	buf = malloc((size_t)len + 1);
	cr_assert(buf != NULL);
	cr_assert_eq(fread(buf, 1, (size_t)len, f), (size_t)len);
	buf[len] = '\0';
	return buf;
}

Test(csv, stream_is_byte_for_byte_the_file)
{
	static const char *const set[] = { "run.T", "0.05 s", NULL };
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], msg[512] = "";
	struct hb_sim *s = run("ptfe-pom", set);
	FILE *fa = tmpfile(), *fc = tmpfile();
	char *file, *stream;

	cr_assert(fa != NULL && fc != NULL);
	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/arc.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	cr_assert_eq(hb_csv_write_arc(path, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_csv_write_collisions(cpath, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_csv_stream_arc(fa, s, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(hb_csv_stream_collisions(fc, s, msg, sizeof msg), HB_OK, "%s", msg);

	file = slurp(path);
	stream = slurp_stream(fa);
	cr_assert(strlen(file) > 1000, "the arc is more than a header");
	cr_assert_str_eq(stream, file, "the arc on a stream differs from the file");
	free(file);
	free(stream);
	file = slurp(cpath);
	stream = slurp_stream(fc);
	cr_assert(strchr(strchr(file, '\n') + 1, '\n') != NULL, "at least one collision row");
	cr_assert_str_eq(stream, file, "the collisions on a stream differ from the file");
	free(file);
	free(stream);
	/* The stream is borrowed: still open and usable after the call. */
	cr_assert(fputs("x", fa) >= 0);
	fclose(fa);
	fclose(fc);
	unlink(path);
	unlink(cpath);
	rmdir(dir);
	hb_sim_free(s);
}

/* A stream that takes room bytes, then fails every write with err. */
struct sink {
	size_t room, got;
	int err, fails;
};

static ssize_t
sink_write(void *cookie, const char *buf, size_t len)
{
	struct sink *k = cookie;

	(void)buf;
	if (k->got + len > k->room) {
		k->fails++;
		errno = k->err;
		return -1;
	}
	k->got += len;
	return (ssize_t)len;
}

Test(csv, stream_write_error_stops_and_keeps_errno)
{
	static const cookie_io_functions_t io = { NULL, sink_write, NULL, NULL };
	struct sink k = { 2000, 0, ENOSPC, 0 };
	struct hb_sim *s = run("steel-on-bitumen", NULL);
	char msg[512] = "";
	FILE *f = fopencookie(&k, "w", io);

	cr_assert(f != NULL);
	cr_assert(setvbuf(f, NULL, _IOFBF, 256) == 0);
	cr_assert(hb_arc_len(hb_sim_arc(s)) > 1000, "an arc far longer than the room");
	errno = 0;
	cr_assert_eq(hb_csv_stream_arc(f, s, msg, sizeof msg), HB_EIO);
	cr_assert_eq(errno, ENOSPC, "errno is %d, expected ENOSPC", errno);
	cr_assert_str_eq(msg, "write error: No space left on device");
	/* Stopped at the first failed row, not one failed write per buffer. */
	cr_assert(k.fails >= 1 && k.fails <= 3, "%d failed writes", k.fails);
	cr_assert(k.got <= k.room);
	fclose(f);
	hb_sim_free(s);
}

Test(csv, stream_to_a_closed_pipe_is_epipe)
{
	struct hb_sim *s = run("nonunique-separation", NULL);
	char msg[512] = "";
	int fd[2];
	FILE *f;

	signal(SIGPIPE, SIG_IGN);   /* this test's own process (Criterion forks) */
	cr_assert_eq(pipe(fd), 0);
	close(fd[0]);
	f = fdopen(fd[1], "w");
	cr_assert(f != NULL);
	errno = 0;
	/* A short table: the failure shows at the final flush. */
	cr_assert_eq(hb_csv_stream_collisions(f, s, msg, sizeof msg), HB_EIO);
	cr_assert_eq(errno, EPIPE, "errno is %d, expected EPIPE", errno);
	cr_assert(strncmp(msg, "write error: ", 13) == 0, "%s", msg);
	/* A stream already in error fails too. */
	cr_assert_eq(hb_csv_stream_arc(f, s, msg, sizeof msg), HB_EIO);
	fclose(f);
	hb_sim_free(s);
}

/* ------------------------------------------------------------------ */
/* The export's rules: links, devices, protected presets, stale files   */

static void
put(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");

	cr_assert(f != NULL, "%s", path);
	fputs(text, f);
	fclose(f);
}

Test(csv, export_keeps_a_link_and_writes_through_it)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", real[256], link[256], cpath[256], msg[512] = "";
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;
	struct stat st;
	char *text;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(real, sizeof real, "%s/real.csv", dir);
	snprintf(link, sizeof link, "%s/link.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	put(real, "old\n");
	cr_assert_eq(symlink("real.csv", link), 0);
	cr_assert_eq(hb_csv_export_files(s, link, cpath, NULL, &r, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(lstat(link, &st), 0);
	cr_assert(S_ISLNK(st.st_mode), "the link was replaced by a file");
	cr_assert(r.target[0].via_link && r.target[0].how == HB_ATOMIC_REPLACE);
	text = slurp(real);
	cr_assert(strncmp(text, "t,j,q_c", 7) == 0, "the linked file was not written");
	free(text);
	cr_assert_eq(r.target[1].how, HB_ATOMIC_NEW);
	/* A dangling link: the file it names is created. */
	unlink(real);
	cr_assert_eq(hb_csv_export_files(s, link, NULL, NULL, &r, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(lstat(link, &st), 0);
	cr_assert(S_ISLNK(st.st_mode));
	cr_assert_eq(access(real, F_OK), 0);
	cr_assert_eq(r.target[0].how, HB_ATOMIC_NEW);
	unlink(real);
	unlink(link);
	unlink(cpath);
	snprintf(real, sizeof real, "%s/link.preset", dir);
	unlink(real);
	cr_assert_eq(count_entries(dir), 0);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, export_writes_a_device_in_place_and_no_scene_beside_it)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", cpath[256], want[256], msg[512] = "";
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;
	struct stat st;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	snprintf(want, sizeof want, "%s/coll.preset", dir);
	cr_assert_eq(hb_csv_export_files(s, "/dev/null", cpath, NULL, &r, msg, sizeof msg), HB_OK,
	    "%s", msg);
	cr_assert_eq(r.target[0].how, HB_ATOMIC_IN_PLACE);
	cr_assert_str_eq(r.scene, want, "the scene goes beside the file, not the device");
	cr_assert_eq(stat("/dev/null", &st), 0);
	cr_assert(S_ISCHR(st.st_mode));
	cr_assert_eq(access("/dev/null.preset", F_OK), -1);
	/* A device alone: no scene at all. */
	cr_assert_eq(hb_csv_export_files(s, NULL, "/dev/null", NULL, &r, msg, sizeof msg), HB_OK);
	cr_assert_str_eq(r.scene, "");
	/* A device that refuses the bytes fails the export. */
	if (access("/dev/full", W_OK) == 0)
		cr_assert_eq(hb_csv_export_files(s, "/dev/full", NULL, NULL, &r, msg, sizeof msg),
		    HB_EIO);
	unlink(cpath);
	unlink(want);
	rmdir(dir);
	hb_sim_free(s);
}

Test(csv, export_never_overwrites_the_preset_being_run)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", pre[256], cpath[256], msg[512] = "";
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;
	char *text;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(pre, sizeof pre, "%s/my.preset", dir);
	snprintf(cpath, sizeof cpath, "%s/my.csv", dir);
	put(pre, "; my comments\n");
	cr_assert_eq(hb_csv_export_check(NULL, cpath, pre, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "is the preset being run") != NULL, "%s", msg);
	cr_assert_eq(hb_csv_export_files(s, NULL, cpath, pre, &r, msg, sizeof msg), HB_EINVAL);
	text = slurp(pre);
	cr_assert_str_eq(text, "; my comments\n");
	free(text);
	cr_assert_eq(count_entries(dir), 1, "a file was written");
	/* Another name is fine. */
	snprintf(cpath, sizeof cpath, "%s/my-run.csv", dir);
	cr_assert_eq(hb_csv_export_files(s, NULL, cpath, pre, &r, msg, sizeof msg), HB_OK, "%s", msg);
	unlink(cpath);
	unlink(r.scene);
	unlink(pre);
	rmdir(dir);
	hb_sim_free(s);
}

/* The explorer names the scene BASE.preset; the rules of an export still hold for it. */
Test(csv, export_scene_named_by_the_caller)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", pre[256], tpath[256], cpath[256], scene[256];
	char msg[512] = "", *text;
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(tpath, sizeof tpath, "%s/x-trace.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/x-collisions.csv", dir);
	snprintf(scene, sizeof scene, "%s/x.preset", dir);
	cr_assert_eq(hb_csv_export_files_scene(s, tpath, cpath, scene, NULL, &r, msg, sizeof msg),
	    HB_OK, "%s", msg);
	cr_assert_str_eq(r.scene, scene);
	cr_assert_eq(r.scene_of, 0);
	text = slurp(scene);
	cr_assert(strstr(text, "x-trace.csv") != NULL && strstr(text, "[scene]") != NULL, "%s", text);
	free(text);
	cr_assert_eq(count_entries(dir), 3);
	/* BASE.preset that is the preset being run: refused, nothing written. */
	snprintf(pre, sizeof pre, "%s/my.preset", dir);
	put(pre, "; my comments\n");
	snprintf(tpath, sizeof tpath, "%s/my-trace.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/my-collisions.csv", dir);
	cr_assert_eq(hb_csv_export_files_scene(s, tpath, cpath, pre, pre, &r, msg, sizeof msg),
	    HB_EINVAL);
	cr_assert(strstr(msg, "is the preset being run") != NULL, "%s", msg);
	cr_assert_eq(count_entries(dir), 4, "a file was written");
	text = slurp(pre);
	cr_assert_str_eq(text, "; my comments\n");
	free(text);
	/* NULL: the scene is derived from the first CSV, as before. */
	cr_assert_eq(hb_csv_export_files_scene(s, tpath, NULL, NULL, NULL, &r, msg, sizeof msg),
	    HB_OK, "%s", msg);
	snprintf(scene, sizeof scene, "%s/my-trace.preset", dir);
	cr_assert_str_eq(r.scene, scene);
	hb_sim_free(s);
	{
		static const char *const made[] = { "x-trace.csv", "x-collisions.csv", "x.preset",
		                                    "my.preset", "my-trace.csv", "my-trace.preset" };
		for (size_t i = 0; i < sizeof made / sizeof made[0]; i++) {
			snprintf(pre, sizeof pre, "%s/%s", dir, made[i]);
			cr_assert_eq(unlink(pre), 0, "%s", pre);
		}
	}
	cr_assert_eq(rmdir(dir), 0);
}

Test(csv, export_never_overwrites_a_shipped_preset)
{
	char msg[512] = "", path[1024];
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;
	const char *const *d;

	cr_assert_eq(hb_preset_resolve("steel-on-bitumen", path, sizeof path, msg, sizeof msg), HB_OK,
	    "%s", msg);
	d = hb_preset_dirs();   /* after hb_preset_resolve, which renews the per-thread list */
	cr_assert(d != NULL && d[0] != NULL);
	strcpy(strrchr(path, '.'), ".csv");
	cr_assert_eq(hb_csv_export_files(s, path, NULL, NULL, &r, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "is a shipped preset") != NULL, "%s", msg);
	cr_assert_eq(access(path, F_OK), -1, "the CSV was written");
	hb_sim_free(s);
}

Test(csv, export_stamps_every_file_alike_and_cleans_stale_temporaries)
{
	char dir[] = "/tmp/hb-csv-XXXXXX", path[256], cpath[256], stale[300], live[300];
	char msg[512] = "", *text;
	struct hb_sim *s = run("nonunique-separation", NULL);
	struct hb_csv_export_report r;
	struct stat a, b, c;
	pid_t dead;

	cr_assert(mkdtemp(dir) != NULL);
	snprintf(path, sizeof path, "%s/run.csv", dir);
	snprintf(cpath, sizeof cpath, "%s/coll.csv", dir);
	/* What a killed writer leaves: a temporary of a process that is gone
	 * (a child that exited), and one of a live process (ours: kept). */
	dead = fork();
	if (dead == 0)
		_exit(0);
	cr_assert(dead > 0);
	waitpid(dead, NULL, 0);
	snprintf(stale, sizeof stale, "%s.hbtmp-%ld-abcdef", path, (long)dead);
	snprintf(live, sizeof live, "%s.hbtmp-%ld-abcdef", path, (long)getppid());
	put(stale, "half");
	put(live, "half");
	put(cpath, "old\n");
	chmod(cpath, 0640);
	cr_assert_eq(hb_csv_export_files(s, path, cpath, NULL, &r, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(access(stale, F_OK), -1, "the stale temporary file is still there");
	cr_assert_eq(access(live, F_OK), 0, "a live process's temporary file was removed");
	unlink(live);
	cr_assert_eq(r.target[1].how, HB_ATOMIC_REPLACE);
	cr_assert_eq(stat(path, &a), 0);
	cr_assert_eq(stat(cpath, &b), 0);
	cr_assert_eq(stat(r.scene, &c), 0);
	cr_assert((b.st_mode & 0777) == 0640, "the replaced file's mode is kept");
	cr_assert(a.st_mtim.tv_sec == b.st_mtim.tv_sec && a.st_mtim.tv_nsec == b.st_mtim.tv_nsec &&
	    a.st_mtim.tv_sec == c.st_mtim.tv_sec && a.st_mtim.tv_nsec == c.st_mtim.tv_nsec,
	    "the files of one export have different modification times");
	text = slurp(r.scene);
	cr_assert(strstr(text, r.id) != NULL, "the scene does not name the export %s", r.id);
	free(text);
	unlink(path);
	unlink(cpath);
	unlink(r.scene);
	cr_assert_eq(count_entries(dir), 0);
	rmdir(dir);
	hb_sim_free(s);
}
