/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * csv.c - export of a run as RFC 4180 CSV (see csv.h).
 *
 * One header row, fields separated by commas, records ended by "\n" (RFC
 * 4180 allows CRLF; LF is what every tool reads), fields quoted when they
 * hold a comma, a quote or a line break.  Numbers are %.17g in SI units, so
 * that strtod() gives back the same doubles; an unknown value (NaN, e.g.
 * t_f of the last collision) is an empty field.
 *
 * Files.  Every file goes through the atomic writer (atomic.h): a set of
 * files written to temporary names and renamed together, a device or FIFO
 * written in place, a symbolic link kept and written through.  An export
 * never overwrites the preset being run nor a shipped preset (one in the
 * preset folders), and the scene is saved beside the first CSV that is a
 * file, with the export's identifier, which is also every file's
 * modification time.
 *
 * The same row writers serve the files and the streams (csv_stream_*),
 * so a CSV on stdout is byte for byte the file's.  They check the stream
 * after every row and stop at the first failed write.
 */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "hybounce/atomic.h"
#include "hybounce/columns.h"
#include "hybounce/csv.h"
#include "hybounce/error.h"
#include "hybounce/outputs.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"
#include "csv_impl.h"
#include "cnum.h"

/* Writes one field, quoted as RFC 4180 asks when it needs to be. */
void
csv_put_field(FILE *f, const char *s)
{
	if (strpbrk(s, ",\"\r\n") == NULL) {
		fputs(s, f);
		return;
	}
	fputc('"', f);
	for (; *s != '\0'; s++) {
		if (*s == '"')
			fputc('"', f);
		fputc(*s, f);
	}
	fputc('"', f);
}

static void
put_field(FILE *f, const char *s, int first)
{
	if (!first)
		fputc(',', f);
	csv_put_field(f, s);
}

/* A number as %.17g, a negative zero as 0 (a sign that carries nothing). */
static void
print_num(FILE *f, double v)
{
	char b[CNUM_G17_MAX];

	fwrite(b, 1, cnum_g17(b, v == 0 ? 0.0 : v), f);
}

void
csv_put_num(FILE *f, double v)
{
	fputc(',', f);
	if (!isnan(v))
		print_num(f, v);
}

/* 0 while f is good, else the error of its failed write (EIO if unknown). */
static int
stream_err(FILE *f)
{
	return ferror(f) ? (errno != 0 ? errno : EIO) : 0;
}

/*
 * Writes the arc CSV to f.  Returns 0, or the errno of the first failed
 * write, after which it writes no further row.
 */
static int
write_arc(FILE *f, const struct hb_sim *s)
{
	const struct hb_scene *sc = hb_sim_scene(s);
	const struct hb_arc *a = hb_sim_arc(s);
	int nz = sc->law != NULL ? sc->law->n_z : 0;
	int full = sc->d.system == HB_SCENE_FULL;
	size_t len = hb_arc_len(a);
	char name[16];
	int e;

	put_field(f, "t", 1);
	put_field(f, "j", 0);
	put_field(f, "q_c", 0);
	put_field(f, "x", 0);
	put_field(f, "v", 0);
	put_field(f, "x_c", 0);
	for (int k = 0; k < nz; k++) {
		snprintf(name, sizeof name, "z_c%d", k + 1);
		put_field(f, name, 0);
	}
	put_field(f, "F_c", 0);
	put_field(f, "F_er", 0);
	if (full) {
		put_field(f, "x_m", 0);
		put_field(f, "v_m", 0);
		put_field(f, "v_m1", 0);
		put_field(f, "v_m2", 0);
	}
	fputc('\n', f);
	if ((e = stream_err(f)) != 0)
		return e;
	for (size_t i = 0; i < len; i++) {
		const struct hb_arc_sample *p = hb_arc_at(a, i);
		print_num(f, p->t);
		fprintf(f, ",%ld,%d", p->j, p->q);
		csv_put_num(f, p->x);
		csv_put_num(f, p->v);
		csv_put_num(f, p->xc);
		for (int k = 0; k < nz; k++)
			csv_put_num(f, p->z[k]);
		csv_put_num(f, p->Fc);
		csv_put_num(f, p->Fer);
		if (full) {
			csv_put_num(f, p->xm);
			csv_put_num(f, p->vm);
			csv_put_num(f, p->vm + sc->d.etac * p->v);  /* eq. v_m_1 */
			csv_put_num(f, p->vm - sc->d.eta * p->v);   /* eq. v_m_2 */
		}
		fputc('\n', f);
		if ((e = stream_err(f)) != 0)
			return e;
	}
	return 0;
}

/*
 * As write_arc, for the completed collisions; with err (error.h, may be
 * NULL) a NAME_err column after the others for each value column: the
 * estimated error of that value (empty where there is none).
 */
static int
write_collisions_err(FILE *f, const struct hb_sim *s, const struct hb_error_estimate *err)
{
	size_t nc = hb_sim_ncollisions(s);
	int e, chain = hb_sim_scene(s)->chain.n > 0;

	for (int k = 0; k < hb_collision_ncolumns; k++) { /* the columns of columns.h */
		put_field(f, hb_collision_columns[k].name, k == 0);
		if (hb_collision_columns[k].index && chain) /* a chain's: the interface after i */
			fputs(",k", f);
	}
	for (int k = 0; err != NULL && k < hb_collision_ncolumns; k++)
		if (!hb_collision_columns[k].index)
			fprintf(f, ",%s_err", hb_collision_columns[k].name);
	fputc('\n', f);
	if ((e = stream_err(f)) != 0)
		return e;
	for (size_t i = 0; i < nc; i++) {
		const struct hb_collision *c = hb_sim_collision(s, i), *d;
		if (c == NULL || !c->complete)
			continue;
		for (int k = 0; k < hb_collision_ncolumns; k++) {
			if (hb_collision_columns[k].index) {
				fprintf(f, "%s%ld", k ? "," : "", c->i);
				if (chain)
					fprintf(f, ",%d", c->k);
			} else
				csv_put_num(f, hb_collision_value(c, &hb_collision_columns[k]));
		}
		d = err != NULL ? hb_error_find(err, c->i) : NULL;
		for (int k = 0; err != NULL && k < hb_collision_ncolumns; k++)
			if (!hb_collision_columns[k].index)
				csv_put_num(f, d != NULL ? hb_collision_value(d, &hb_collision_columns[k])
				                         : NAN);
		fputc('\n', f);
		if ((e = stream_err(f)) != 0)
			return e;
	}
	return 0;
}

static int
write_collisions(FILE *f, const struct hb_sim *s)
{
	return write_collisions_err(f, s, NULL);
}

typedef int (*rows_fn)(FILE *, const struct hb_sim *);

static void
fill_arc(FILE *f, const void *s)
{
	(void)write_arc(f, s);
}

static void
fill_collisions(FILE *f, const void *s)
{
	(void)write_collisions(f, s);
}

int
hb_csv_write_arc(const char *path, const struct hb_sim *s, char *msg, size_t n)
{
	return hb_atomic_write_with(path, fill_arc, s, msg, n);
}

int
hb_csv_write_collisions(const char *path, const struct hb_sim *s, char *msg, size_t n)
{
	return hb_atomic_write_with(path, fill_collisions, s, msg, n);
}

/* After a writer returned e (errno is 0 before it): flushes f and reports (see csv.h). */
static int
stream_done(FILE *f, int e, char *msg, size_t n)
{
	if (e == 0 && fflush(f) != 0)
		e = errno != 0 ? errno : EIO;
	if (e == 0)
		e = stream_err(f);
	if (e == 0)
		return HB_OK;
	hb_status_set(msg, n, HB_EIO, "write error: %s", strerror(e));
	errno = e;
	return HB_EIO;
}

/* Writes fn's CSV to the stream f and flushes it (see csv.h). */
static int
stream_one(FILE *f, const struct hb_sim *s, rows_fn fn, char *msg, size_t n)
{
	errno = 0;
	return stream_done(f, fn(f, s), msg, n);
}

int
hb_csv_stream_arc(FILE *f, const struct hb_sim *s, char *msg, size_t n)
{
	return stream_one(f, s, write_arc, msg, n);
}

int
hb_csv_stream_collisions(FILE *f, const struct hb_sim *s, char *msg, size_t n)
{
	return stream_one(f, s, write_collisions, msg, n);
}

int
hb_csv_stream_collisions_err(FILE *f, const struct hb_sim *s,
                             const struct hb_error_estimate *err, char *msg, size_t n)
{
	errno = 0;
	return stream_done(f, write_collisions_err(f, s, err), msg, n);
}

int
csv_scene_path(const char *path, char *out, size_t n)
{
	const char *slash = strrchr(path, '/');
	const char *base = slash != NULL ? slash + 1 : path;
	const char *dot = strrchr(base, '.');
	size_t stem = dot != NULL && dot != base ? (size_t)(dot - path) : strlen(path);

	if (stem + 8 > n)
		return -1;
	memcpy(out, path, stem);
	strcpy(out + stem, ".preset");
	return 0;
}

/*
 * Where each file of an export goes: r->target[0] trace, [1] collisions,
 * [2] the scene (r->scene "" when none), checked by the output policy
 * (outputs.h) against the command's inputs (the preset being run, and
 * those of o->outputs) and its other outputs.  Every check that can be
 * made before writing.
 */
static int
plan(const struct hb_csv_export_opts *o, struct hb_csv_export_report *r, char *msg, size_t n)
{
	const char *csv[2] = { o->trace, o->coll };
	static const char *const csv_what[2] = { "the trace", "the collisions" };
	struct hb_outputs *pol = malloc(sizeof *pol);
	char what[4200];
	int st = HB_OK;

	memset(r, 0, sizeof *r);
	r->scene_of = -1;
	if (pol == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	if (o->outputs != NULL)
		*pol = *o->outputs;
	else
		hb_outputs_init(pol);
	if (o->trace == NULL && o->coll == NULL) {
		st = hb_status_set(msg, n, HB_EINVAL, "nothing to export: no file named");
		goto out;
	}
	if (o->trace != NULL && o->coll != NULL && hb_outputs_same_file(o->trace, o->coll)) {
		st = hb_status_set(msg, n, HB_EINVAL,
		    "%s: the trace and the collisions need two different files", o->trace);
		goto out;
	}
	if (hb_outputs_input(pol, o->run_preset, "the preset being run") != HB_OK) {
		st = hb_status_set(msg, n, HB_EINVAL, "too many inputs");
		goto out;
	}
	for (int k = 0; k < 2; k++) {
		if (csv[k] == NULL)
			continue;
		if ((st = hb_outputs_add(pol, csv[k], csv_what[k], msg, n)) != HB_OK)
			goto out;
		r->target[k] = pol->out[pol->nout - 1].target;
		/* The scene goes beside the first CSV that is a file. */
		if (r->scene_of < 0 && r->target[k].how != HB_ATOMIC_IN_PLACE) {
			if (o->scene != NULL) {
				if (strlen(o->scene) >= sizeof r->scene) {
					st = hb_status_set(msg, n, HB_EIO, "%s: %s", o->scene,
					                   strerror(ENAMETOOLONG));
					goto out;
				}
				snprintf(r->scene, sizeof r->scene, "%s", o->scene);
			} else if (csv_scene_path(csv[k], r->scene, sizeof r->scene) != 0) {
				st = hb_status_set(msg, n, HB_EIO, "%s: %s", csv[k],
				                   strerror(ENAMETOOLONG));
				goto out;
			}
			r->scene_of = k;
		}
	}
	if (r->scene[0] == '\0')
		goto out;
	snprintf(what, sizeof what, "the scene saved beside %s", csv[r->scene_of]);
	if ((st = hb_outputs_add(pol, r->scene, what, msg, n)) != HB_OK)
		goto out;
	r->target[2] = pol->out[pol->nout - 1].target;
out:
	free(pol);
	return st;
}

int
hb_csv_export_check(const char *trace, const char *coll, const char *run_preset,
                 char *msg, size_t n)
{
	struct hb_csv_export_opts o = { 0 };

	o.trace = trace;
	o.coll = coll;
	o.run_preset = run_preset;
	return hb_csv_export_check_with(&o, msg, n);
}

int
hb_csv_export_check_with(const struct hb_csv_export_opts *o, char *msg, size_t n)
{
	struct hb_csv_export_report *r = malloc(sizeof *r);
	int st;

	if (r == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	st = plan(o, r, msg, n);
	free(r);
	return st;
}

/* ", the trace PATH (cksum CRC LENGTH)": one CSV of the export, file k of set. */
static void
name_csv(FILE *f, struct hb_atomic_set *set, int k, const char *what, const char *path)
{
	unsigned long crc;
	unsigned long long len;

	fprintf(f, ", the %s %s", what, path);
	if (k >= 0 && hb_atomic_cksum(set, k, &crc, &len) == HB_OK)
		fprintf(f, " (cksum %lu %llu)", crc, len);
}

/*
 * The scene as a preset, then one line naming the export: its identifier
 * and each CSV with its cksum, so that a set mixed by a kill between two
 * renames shows (each file of set is index k_trace, k_coll or -1).
 */
static int
write_scene(FILE *f, const struct hb_sim *s, struct hb_atomic_set *set, const char *prov,
            const char *trace, int k_trace, const char *coll, int k_coll)
{
	size_t len = hb_preset_format_run(s, NULL, 0);
	char *buf = malloc(len + 1);

	if (buf == NULL)
		return ENOMEM;
	hb_preset_format_run(s, buf, len + 1);
	fwrite(buf, 1, len, f);
	free(buf);
	if (prov != NULL && prov[0] != '\0')
		fprintf(f, "\n%s", prov);
	fprintf(f, "\n; export %s: this scene", set->id);
	if (trace != NULL)
		name_csv(f, set, k_trace, "trace", trace);
	if (coll != NULL)
		name_csv(f, set, k_coll, "collisions", coll);
	fprintf(f, "; every file of the export has this modification time\n");
	return 0;
}

int
hb_csv_export_files(const struct hb_sim *s, const char *trace, const char *coll,
                 const char *run_preset, struct hb_csv_export_report *r, char *msg, size_t n)
{
	return hb_csv_export_files_scene(s, trace, coll, NULL, run_preset, r, msg, n);
}

int
hb_csv_export_files_scene(const struct hb_sim *s, const char *trace, const char *coll,
                       const char *scene, const char *run_preset,
                       struct hb_csv_export_report *r, char *msg, size_t n)
{
	struct hb_csv_export_opts o = { 0 };

	o.trace = trace;
	o.coll = coll;
	o.scene = scene;
	o.run_preset = run_preset;
	return hb_csv_export_with(s, &o, r, msg, n);
}

int
hb_csv_export_with(const struct hb_sim *s, const struct hb_csv_export_opts *o,
                   struct hb_csv_export_report *r, char *msg, size_t n)
{
	struct hb_atomic_set set;
	const char *paths[3];
	int st, index[2] = { -1, -1 };   /* trace, collisions: their file in set */

	if ((st = plan(o, r, msg, n)) != HB_OK)
		return st;
	paths[0] = o->trace;
	paths[1] = o->coll;
	paths[2] = r->scene[0] ? r->scene : NULL;
	hb_atomic_begin(&set);
	snprintf(r->id, sizeof r->id, "%s", set.id);
	for (int k = 0; k < 3; k++) {
		FILE *f;
		int e;

		if (paths[k] == NULL)
			continue;
		f = hb_atomic_add(&set, paths[k], msg, n);
		if (f == NULL) {
			hb_atomic_abort(&set);
			return HB_EIO;
		}
		r->target[k] = set.file[set.n - 1].target;
		if (k < 2)
			index[k] = set.n - 1;
		errno = 0;
		e = k == 0 ? write_arc(f, s) : k == 1 ? write_collisions_err(f, s, o->errors)
		           : write_scene(f, s, &set, o->provenance, o->trace, index[0], o->coll,
		                         index[1]);
		if (e == ENOMEM) {
			hb_atomic_abort(&set);
			return hb_status_set(msg, n, HB_ENOMEM, "%s: out of memory", paths[k]);
		}
	}
	return hb_atomic_commit(&set, msg, n);
}

int
hb_csv_export(const struct hb_sim *s, const char *trace_path, const char *coll_path,
           char *scene_out, size_t sn, char *msg, size_t n)
{
	struct hb_csv_export_report r;
	int st = hb_csv_export_files(s, trace_path, coll_path, NULL, &r, msg, n);

	if (st == HB_OK && scene_out != NULL && sn > 0)
		snprintf(scene_out, sn, "%s", r.scene);
	return st;
}
