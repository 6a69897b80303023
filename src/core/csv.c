/*
 * csv.c - export of a run as RFC 4180 CSV (see csv.h).
 *
 * One header row, fields separated by commas, records ended by "\n" (RFC
 * 4180 allows CRLF; LF is what every tool reads), fields quoted when they
 * hold a comma, a quote or a line break.  Numbers are %.17g in SI units, so
 * that strtod() gives back the same doubles; an unknown value (NaN, e.g.
 * t_f of the last collision) is an empty field.
 *
 * Atomicity.  Each file is written to PATH.tmpXXXXXX in its own folder,
 * flushed to disk, and only then renamed over PATH.  csv_export() writes
 * every temporary file first and renames them only when all are complete;
 * on any failure it removes the temporary files, so no new file is left
 * and an existing file is untouched.  The renames themselves are not one
 * atomic step: should a later one fail, the earlier ones are undone, from
 * hard links to the replaced files made just before (a file that did not
 * exist is removed).
 *
 * The same row writers serve the files and the streams (csv_stream_*),
 * so a CSV on stdout is byte for byte the file's.  They check the stream
 * after every row and stop at the first failed write.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hybounce/columns.h"
#include "hybounce/csv.h"
#include "hybounce/preset.h"
#include "hybounce/status.h"

/* A file being written under a temporary name. */
struct tmpfile {
	char path[1024];
	char tmp[1040];
	FILE *f;
	int open;
};

static int
tmp_open(struct tmpfile *t, const char *path, char *msg, size_t n)
{
	int fd;
	mode_t um;

	memset(t, 0, sizeof *t);
	if (strlen(path) >= sizeof t->path)
		return status_set(msg, n, HB_EIO, "%s: %s", path, strerror(ENAMETOOLONG));
	strcpy(t->path, path);
	snprintf(t->tmp, sizeof t->tmp, "%s.tmpXXXXXX", path);
	fd = mkstemp(t->tmp);
	if (fd < 0)
		return status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	um = umask(0);
	umask(um);
	(void)fchmod(fd, 0666 & ~um);
	t->f = fdopen(fd, "w");
	if (t->f == NULL) {
		int e = errno;
		close(fd);
		unlink(t->tmp);
		return status_set(msg, n, HB_EIO, "%s: %s", path, strerror(e));
	}
	t->open = 1;
	return HB_OK;
}

/* Flushes and closes the temporary file; on failure removes it. */
static int
tmp_close(struct tmpfile *t, char *msg, size_t n)
{
	int e = 0;

	if (ferror(t->f))
		e = errno ? errno : EIO;
	if (fflush(t->f) != 0 && e == 0)
		e = errno;
	if (e == 0 && fsync(fileno(t->f)) != 0)
		e = errno;
	if (fclose(t->f) != 0 && e == 0)
		e = errno;
	t->f = NULL;
	if (e != 0) {
		unlink(t->tmp);
		t->open = 0;
		return status_set(msg, n, HB_EIO, "%s: %s", t->path, strerror(e));
	}
	return HB_OK;
}

/* Removes the temporary file (closing it first if still open). */
static void
tmp_discard(struct tmpfile *t)
{
	if (t->f != NULL)
		fclose(t->f);
	t->f = NULL;
	if (t->open)
		unlink(t->tmp);
	t->open = 0;
}

static int
tmp_commit(struct tmpfile *t, char *msg, size_t n)
{
	if (rename(t->tmp, t->path) != 0) {
		int e = errno;
		unlink(t->tmp);
		t->open = 0;
		return status_set(msg, n, HB_EIO, "%s: %s", t->path, strerror(e));
	}
	t->open = 0;
	return HB_OK;
}

/* Writes one field, quoted as RFC 4180 asks when it needs to be. */
static void
put_field(FILE *f, const char *s, int first)
{
	if (!first)
		fputc(',', f);
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

/* Writes a number as %.17g; NaN (unknown) as an empty field. */
static void
put_num(FILE *f, double v)
{
	fputc(',', f);
	if (!isnan(v))
		fprintf(f, "%.17g", v);
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
write_arc(FILE *f, const struct sim *s)
{
	const struct scene *sc = sim_scene(s);
	const struct arc *a = sim_arc(s);
	int nz = sc->law != NULL ? sc->law->n_z : 0;
	int full = sc->d.system == SCENE_FULL;
	size_t len = arc_len(a);
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
		const struct arc_sample *p = arc_at(a, i);
		fprintf(f, "%.17g,%ld,%d", p->t, p->j, p->q);
		put_num(f, p->x);
		put_num(f, p->v);
		put_num(f, p->xc);
		for (int k = 0; k < nz; k++)
			put_num(f, p->z[k]);
		put_num(f, p->Fc);
		put_num(f, p->Fer);
		if (full) {
			put_num(f, p->xm);
			put_num(f, p->vm);
			put_num(f, p->vm + sc->d.etac * p->v);  /* eq. v_m_1 */
			put_num(f, p->vm - sc->d.eta * p->v);   /* eq. v_m_2 */
		}
		fputc('\n', f);
		if ((e = stream_err(f)) != 0)
			return e;
	}
	return 0;
}

/* As write_arc, for the completed collisions. */
static int
write_collisions(FILE *f, const struct sim *s)
{
	size_t nc = sim_ncollisions(s);
	int e;

	for (int k = 0; k < collision_ncolumns; k++) /* the columns of columns.h */
		put_field(f, collision_columns[k].name, k == 0);
	fputc('\n', f);
	if ((e = stream_err(f)) != 0)
		return e;
	for (size_t i = 0; i < nc; i++) {
		const struct collision *c = sim_collision(s, i);
		if (c == NULL || !c->complete)
			continue;
		for (int k = 0; k < collision_ncolumns; k++) {
			if (collision_columns[k].index)
				fprintf(f, "%s%ld", k ? "," : "", c->i);
			else
				put_num(f, collision_value(c, &collision_columns[k]));
		}
		fputc('\n', f);
		if ((e = stream_err(f)) != 0)
			return e;
	}
	return 0;
}

typedef int (*rows_fn)(FILE *, const struct sim *);

static int
write_one(const char *path, const struct sim *s, rows_fn fn, char *msg, size_t n)
{
	struct tmpfile t;
	int st = tmp_open(&t, path, msg, n), e;

	if (st != HB_OK)
		return st;
	errno = 0;
	if ((e = fn(t.f, s)) != 0)
		errno = e;      /* for tmp_close's message */
	st = tmp_close(&t, msg, n);
	if (st == HB_OK)
		st = tmp_commit(&t, msg, n);
	return st;
}

int
csv_write_arc(const char *path, const struct sim *s, char *msg, size_t n)
{
	return write_one(path, s, write_arc, msg, n);
}

int
csv_write_collisions(const char *path, const struct sim *s, char *msg, size_t n)
{
	return write_one(path, s, write_collisions, msg, n);
}

/* Writes fn's CSV to the stream f and flushes it (see csv.h). */
static int
stream_one(FILE *f, const struct sim *s, rows_fn fn, char *msg, size_t n)
{
	int e;

	errno = 0;
	e = fn(f, s);
	if (e == 0 && fflush(f) != 0)
		e = errno != 0 ? errno : EIO;
	if (e == 0)
		e = stream_err(f);
	if (e == 0)
		return HB_OK;
	status_set(msg, n, HB_EIO, "write error: %s", strerror(e));
	errno = e;
	return HB_EIO;
}

int
csv_stream_arc(FILE *f, const struct sim *s, char *msg, size_t n)
{
	return stream_one(f, s, write_arc, msg, n);
}

int
csv_stream_collisions(FILE *f, const struct sim *s, char *msg, size_t n)
{
	return stream_one(f, s, write_collisions, msg, n);
}

/* PATH with the extension of its last component replaced by ".preset". */
static int
scene_path(const char *path, char *out, size_t n)
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

int
csv_export(const struct sim *s, const char *trace_path, const char *coll_path,
           char *scene_out, size_t sn, char *msg, size_t n)
{
	struct tmpfile t[3];
	const char *paths[3];
	char spath[1024];
	int nt = 0, st = HB_OK, committed = 0;
	const char *first = trace_path != NULL ? trace_path : coll_path;

	if (first == NULL)
		return status_set(msg, n, HB_EINVAL, "nothing to export: no file named");
	if (scene_path(first, spath, sizeof spath) != 0)
		return status_set(msg, n, HB_EIO, "%s: %s", first, strerror(ENAMETOOLONG));
	if ((trace_path != NULL && strcmp(spath, trace_path) == 0) ||
	    (coll_path != NULL && strcmp(spath, coll_path) == 0))
		return status_set(msg, n, HB_EINVAL,
		    "%s: the scene would overwrite this export; name the CSV file otherwise "
		    "(e.g. run.csv)", spath);
	if (trace_path != NULL && coll_path != NULL && strcmp(trace_path, coll_path) == 0)
		return status_set(msg, n, HB_EINVAL,
		    "%s: the trace and the collisions need two different files", trace_path);
	paths[0] = trace_path;
	paths[1] = coll_path;
	paths[2] = spath;

	memset(t, 0, sizeof t);
	for (int k = 0; k < 3 && st == HB_OK; k++) {
		if (paths[k] == NULL)
			continue;
		st = tmp_open(&t[nt], paths[k], msg, n);
		if (st != HB_OK)
			break;
		errno = 0;
		if (k == 0)
			errno = write_arc(t[nt].f, s);
		else if (k == 1)
			errno = write_collisions(t[nt].f, s);
		else {
			size_t len = preset_format(sim_scene(s), NULL, 0);
			char *buf = malloc(len + 1);
			if (buf == NULL) {
				nt++;
				st = status_set(msg, n, HB_ENOMEM, "%s: out of memory", paths[k]);
				break;
			}
			preset_format(sim_scene(s), buf, len + 1);
			fwrite(buf, 1, len, t[nt].f);
			free(buf);
		}
		st = tmp_close(&t[nt], msg, n);
		nt++;
	}
	/*
	 * Before the renames, keep a hard link to each file about to be
	 * replaced, so that a failed rename can put the earlier ones back.
	 */
	char bak[3][1060];
	int has_bak[3] = { 0, 0, 0 };
	for (int k = 0; k < nt && st == HB_OK; k++) {
		snprintf(bak[k], sizeof bak[k], "%s.old", t[k].tmp);
		has_bak[k] = link(t[k].path, bak[k]) == 0;
	}
	for (int k = 0; k < nt && st == HB_OK; k++) {
		st = tmp_commit(&t[k], msg, n);
		if (st == HB_OK)
			committed = k + 1;
	}
	if (st != HB_OK) {
		for (int k = 0; k < nt; k++)
			tmp_discard(&t[k]);
		/* Undo the renames already done: no new file is left. */
		for (int k = 0; k < committed; k++)
			if (!has_bak[k] || rename(bak[k], t[k].path) != 0)
				unlink(t[k].path);
	}
	for (int k = 0; k < nt; k++)
		if (has_bak[k])
			unlink(bak[k]);
	if (st != HB_OK)
		return st;
	if (scene_out != NULL && sn > 0)
		snprintf(scene_out, sn, "%s", spath);
	return HB_OK;
}
