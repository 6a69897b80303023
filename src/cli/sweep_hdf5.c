/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_hdf5.c - `hybounce sweep --format hdf5`: the merged runs and
 * collisions as one HDF5 file, DIR/sweep.h5, instead of runs.csv and
 * collisions.csv (see sweep_hdf5.h).
 *
 * The file: datasets /runs and /collisions, each a one-dimensional
 * compound dataset with the columns of the CSV file as its fields (ids and
 * whole numbers int64, numbers float64 with NaN where the CSV field is
 * empty, texts variable-length UTF-8 strings), chunked (CHUNK rows) and
 * compressed (shuffle + deflate), extended as the merge streams the rows:
 * memory holds one chunk of each, whatever the number of points.  Each
 * dataset has the attributes `columns` and `units` (the SI unit of each
 * column, "" for a pure number); the root has `spec` (the text of
 * DIR/sweep.preset: the scene and the axes), `hybounce` (the version) and
 * `provenance` (the command).  h5py reads a dataset as a NumPy structured
 * array, which pandas.DataFrame takes as it is.
 *
 * libhdf5 is opened with dlopen(3) when a sweep first asks for it
 * (sweep_hdf5_load.c); the macros that call into the library
 * (H5F_ACC_TRUNC, H5T_NATIVE_DOUBLE ...) are spelled out here.
 *
 * The file is written under a temporary name beside sweep.h5 (the atomic
 * writer's: sweep.h5.hbtmp-PID-XXXXXX), flushed to disk and renamed over
 * it once complete; a failed merge leaves no sweep.h5.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <hdf5.h>

#include "hybounce/atomic.h"
#include "hybounce/columns.h"
#include "hybounce/input.h"
#include "hybounce/observables.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "hybounce/version.h"

#include "cnum.h"
#include "report.h"
#include "sweep_hdf5.h"
#include "sweep_hdf5_api.h"

#define CHUNK 4096        /* rows a chunk (and in memory) */
#define MAXCOLS 128

/* H5F_ACC_TRUNC, H5S_UNLIMITED, H5T_VARIABLE without the header's calls */
#define ACC_TRUNC 0x0002u
#define UNLIMITED ((hsize_t)(-1))
#define VARIABLE ((size_t)(-1))

/* ------------------------------------------------------------------ */
/* One dataset: its columns, the compound type, a chunk of rows in memory */

enum { COL_INT = 1, COL_NUM, COL_TEXT };

struct table {
	const char *name;          /* "runs", "collisions" */
	int ncols;
	char *col[MAXCOLS];        /* names */
	const char *unit[MAXCOLS];
	int kind[MAXCOLS];
	size_t off[MAXCOLS], size; /* the record's layout in memory */
	hid_t type, dset;
	unsigned char *buf;        /* CHUNK records */
	long nbuf;                 /* records in buf */
	hsize_t rows;              /* records written */
};

struct sweep_hdf5 {
	char dir[4096], path[4200], tmp[4300];
	hid_t file, vstr;
	struct table runs, coll;
	struct hb_scene base;
	int have_base, created;
	char axis_unit[MAXCOLS][32];   /* the axes' SI units */
};

static void
table_init(struct table *t, const char *name)
{
	memset(t, 0, sizeof *t);
	t->name = name;
	t->type = t->dset = -1;
}

static int
is_number(const char *s)
{
	char *end;

	if (s == NULL || s[0] == '\0')
		return 0;
	(void)cnum_strtod(s, &end);
	return *end == '\0';
}

/* The index find gives NAME of a column NAME_err (an error bar, --error), or -1. */
static int
err_of(const char *col, int (*find)(const char *))
{
	char stem[64];
	size_t l = strlen(col);

	if (l <= 4 || l - 4 >= sizeof stem || strcmp(col + l - 4, "_err") != 0)
		return -1;
	snprintf(stem, sizeof stem, "%.*s", (int)(l - 4), col);
	return find(stem);
}

/* Column k of runs: its unit and kind (first: the first row's field, for an axis). */
static void
runs_column(struct sweep_hdf5 *h, int col, const char *first, const char **unit, int *kind)
{
	const char *name = h->runs.col[col];
	struct hb_scene_keyinfo ki;
	int k = hb_observable_find(name), ke = err_of(name, hb_observable_find);

	*unit = "";
	*kind = COL_NUM;
	if (strcmp(name, "id") == 0 || strcmp(name, "refined") == 0) {
		*kind = COL_INT;
	} else if (strcmp(name, "status") == 0 || strcmp(name, "message") == 0) {
		*kind = COL_TEXT;
	} else if (strcmp(name, "cpu_s") == 0) {
		*unit = "s";
	} else if (k >= 0) {
		*unit = hb_observables[k].unit;
		*kind = hb_observables[k].whole ? COL_INT : COL_NUM;
	} else if (ke >= 0) {
		*unit = hb_observables[ke].unit;   /* an error bar (--error): a number */
	} else {
		/* an axis: a number (its SI unit), or a word (a law's name) */
		memset(&ki, 0, sizeof ki);
		if (h->have_base && hb_scene_get(&h->base, name, &ki, NULL) == 0) {
			snprintf(h->axis_unit[col], sizeof h->axis_unit[col], "%s", ki.unit);
			*unit = h->axis_unit[col];
		}
		if (!is_number(first))
			*kind = COL_TEXT;
	}
}

static void
coll_column(const char *name, const char **unit, int *kind)
{
	const struct hb_collision_column *c = hb_collision_column_find(name);
	char stem[64];
	size_t l = strlen(name);

	/* NAME_err (--error): the error bar of NAME, in its unit */
	if (c == NULL && l > 4 && l - 4 < sizeof stem && strcmp(name + l - 4, "_err") == 0) {
		snprintf(stem, sizeof stem, "%.*s", (int)(l - 4), name);
		c = hb_collision_column_find(stem);
	}

	*unit = c != NULL ? c->unit : "";
	*kind = strcmp(name, "id") == 0 || strcmp(name, "i") == 0 ? COL_INT : COL_NUM;
}

/* The next CSV field of *p (quotes undone) into out (n bytes); 0 at the end of the row. */
static int
next_field(const char **p, const char *end, char *out, size_t n)
{
	const char *s = *p;
	size_t w = 0;

	if (s > end)
		return 0;
	if (s < end && *s == '"') {
		for (s++; s < end; s++) {
			if (*s == '"' && s + 1 < end && s[1] == '"')
				s++;
			else if (*s == '"') {
				s++;
				break;
			}
			if (w + 1 < n)
				out[w++] = *s;
		}
	} else {
		for (; s < end && *s != ','; s++)
			if (w + 1 < n)
				out[w++] = *s;
	}
	out[w] = '\0';
	*p = s + 1;    /* past the comma (or one past the end) */
	return 1;
}

static int
split_header(struct table *t, const char *hdr, char *msg, size_t n)
{
	const char *p = hdr, *end = hdr + strlen(hdr);
	char f[256];

	while (next_field(&p, end, f, sizeof f)) {
		if (t->ncols == MAXCOLS)
			return hb_status_set(msg, n, HB_EINVAL, "--format hdf5: more than %d columns",
			                     MAXCOLS);
		if ((t->col[t->ncols++] = strdup(f)) == NULL)
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	return HB_OK;
}

/* A string attribute (scalar) or a string array attribute. */
static int
put_attr(struct sweep_hdf5 *h, hid_t obj, const char *name, const char *const *v, int count)
{
	hsize_t dim = (hsize_t)count;
	hid_t sp = count < 0 ? h5api.H5Screate(H5S_SCALAR) : h5api.H5Screate_simple(1, &dim, NULL);
	hid_t a = sp < 0 ? -1 : h5api.H5Acreate2(obj, name, h->vstr, sp, H5P_DEFAULT, H5P_DEFAULT);
	int rc = a >= 0 && h5api.H5Awrite(a, h->vstr, v) >= 0 ? 0 : -1;

	if (a >= 0)
		h5api.H5Aclose(a);
	if (sp >= 0)
		h5api.H5Sclose(sp);
	return rc;
}

/* The compound type and the chunked, compressed, extendible dataset of t. */
static int
table_create(struct sweep_hdf5 *h, struct table *t, char *msg, size_t n)
{
	hsize_t dim = 0, maxdim = UNLIMITED, chunk = CHUNK;
	hid_t sp, pl;
	size_t off = 0;

	for (int k = 0; k < t->ncols; k++) {
		size_t sz = t->kind[k] == COL_TEXT ? sizeof(char *) : 8;

		off = (off + sz - 1) / sz * sz;
		t->off[k] = off;
		off += sz;
	}
	t->size = (off + 7) / 8 * 8;
	t->buf = calloc(CHUNK, t->size);
	if (t->buf == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	t->type = h5api.H5Tcreate(H5T_COMPOUND, t->size);
	for (int k = 0; t->type >= 0 && k < t->ncols; k++)
		if (h5api.H5Tinsert(t->type, t->col[k], t->off[k],
		                t->kind[k] == COL_TEXT ? h->vstr
		                : t->kind[k] == COL_INT ? *h5api.native_int64 : *h5api.native_double) < 0) {
			h5api.H5Tclose(t->type);
			t->type = -1;
		}
	sp = h5api.H5Screate_simple(1, &dim, &maxdim);
	pl = h5api.H5Pcreate(*h5api.dataset_create);
	if (t->type < 0 || sp < 0 || pl < 0 || h5api.H5Pset_chunk(pl, 1, &chunk) < 0 ||
	    h5api.H5Pset_shuffle(pl) < 0 || h5api.H5Pset_deflate(pl, 4) < 0 ||
	    (t->dset = h5api.H5Dcreate2(h->file, t->name, t->type, sp, H5P_DEFAULT, pl,
	                            H5P_DEFAULT)) < 0) {
		if (sp >= 0)
			h5api.H5Sclose(sp);
		if (pl >= 0)
			h5api.H5Pclose(pl);
		return hb_status_set(msg, n, HB_EIO, "%s: cannot create the dataset /%s", h->path,
		                     t->name);
	}
	h5api.H5Sclose(sp);
	h5api.H5Pclose(pl);
	if (put_attr(h, t->dset, "columns", (const char *const *)t->col, t->ncols) < 0 ||
	    put_attr(h, t->dset, "units", t->unit, t->ncols) < 0)
		return hb_status_set(msg, n, HB_EIO, "%s: cannot write the attributes of /%s",
		                     h->path, t->name);
	return HB_OK;
}

static void
table_free_strings(struct table *t)
{
	for (long r = 0; r < t->nbuf; r++)
		for (int k = 0; k < t->ncols; k++)
			if (t->kind[k] == COL_TEXT) {
				char **s = (char **)(t->buf + (size_t)r * t->size + t->off[k]);

				free(*s);
				*s = NULL;
			}
}

/* Appends the rows in memory to the dataset. */
static int
table_flush(struct sweep_hdf5 *h, struct table *t, char *msg, size_t n)
{
	hsize_t size, start, count;
	hid_t fs, ms;
	int ok;

	if (t->nbuf == 0)
		return HB_OK;
	size = t->rows + (hsize_t)t->nbuf;
	start = t->rows;
	count = (hsize_t)t->nbuf;
	ok = h5api.H5Dset_extent(t->dset, &size) >= 0;
	fs = ok ? h5api.H5Dget_space(t->dset) : -1;
	ms = h5api.H5Screate_simple(1, &count, NULL);
	ok = ok && fs >= 0 && ms >= 0 &&
	     h5api.H5Sselect_hyperslab(fs, H5S_SELECT_SET, &start, NULL, &count, NULL) >= 0 &&
	     h5api.H5Dwrite(t->dset, t->type, ms, fs, H5P_DEFAULT, t->buf) >= 0;
	if (fs >= 0)
		h5api.H5Sclose(fs);
	if (ms >= 0)
		h5api.H5Sclose(ms);
	table_free_strings(t);
	t->rows = size;
	t->nbuf = 0;
	return ok ? HB_OK : hb_status_set(msg, n, HB_EIO, "%s: cannot write /%s (disk full?)",
	                                  h->path, t->name);
}

static int
table_row(struct sweep_hdf5 *h, struct table *t, const char *row, size_t len, char *msg,
          size_t n)
{
	const char *p = row, *end = row + len;
	unsigned char *rec;
	char f[4096];

	if (t->nbuf == CHUNK) {
		int rc = table_flush(h, t, msg, n);

		if (rc != HB_OK)
			return rc;
	}
	rec = t->buf + (size_t)t->nbuf * t->size;
	memset(rec, 0, t->size);
	t->nbuf++;
	for (int k = 0; k < t->ncols; k++) {
		if (!next_field(&p, end, f, sizeof f))
			return hb_status_set(msg, n, HB_EINVAL, "--format hdf5: a row of /%s with %d "
			                     "of its %d columns", t->name, k, t->ncols);
		if (t->kind[k] == COL_TEXT) {
			char *s = strdup(f);

			if (s == NULL)
				return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			memcpy(rec + t->off[k], &s, sizeof s);
		} else if (t->kind[k] == COL_INT) {
			int64_t v = strtoll(f, NULL, 10);

			memcpy(rec + t->off[k], &v, sizeof v);
		} else {
			/* %.17g reads back to the same double; empty: none */
			double v = f[0] ? cnum_strtod(f, NULL) : NAN;

			memcpy(rec + t->off[k], &v, sizeof v);
		}
	}
	return HB_OK;
}

/* ------------------------------------------------------------------ */
/* The sink                                                            */

static int
sink_begin(void *ctx, const char *runs_header, const char *coll_header, char *msg, size_t n)
{
	struct sweep_hdf5 *h = ctx;
	char spec[4200], *text = NULL;
	size_t tl = 0;
	int fd, rc;

	snprintf(spec, sizeof spec, "%s/sweep.preset", h->dir);
	if (hb_input_read(spec, HB_INPUT_PRESET_MAX, &text, &tl, msg, n) != HB_OK)
		return HB_EIO;
	h->have_base = hb_preset_load_string(text, spec, &h->base, NULL, 0) == HB_OK;
	snprintf(h->tmp, sizeof h->tmp, "%s" HB_ATOMIC_TMP_TAG "%ld-XXXXXX", h->path,
	         (long)getpid());
	if ((fd = mkstemp(h->tmp)) < 0) {
		free(text);
		return hb_status_set(msg, n, HB_EIO, "%s: %s", h->tmp, strerror(errno));
	}
	{
		mode_t um = umask(0);   /* mkstemp's 0600: the mode a new file gets */

		umask(um);
		(void)fchmod(fd, 0666 & ~um);
	}
	close(fd);
	h->created = 1;
	h->file = h5api.H5Fcreate(h->tmp, ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
	h->vstr = h5api.H5Tcopy(*h5api.c_s1);
	if (h->file < 0 || h->vstr < 0 || h5api.H5Tset_size(h->vstr, VARIABLE) < 0 ||
	    h5api.H5Tset_cset(h->vstr, H5T_CSET_UTF8) < 0) {
		free(text);
		return hb_status_set(msg, n, HB_EIO, "%s: cannot create an HDF5 file there", h->tmp);
	}
	{
		const char *version = HB_VERSION_STRING, *prov = cli_provenance();
		const char *sp = text;

		if (put_attr(h, h->file, "spec", &sp, -1) < 0 ||
		    put_attr(h, h->file, "hybounce", &version, -1) < 0 ||
		    put_attr(h, h->file, "provenance", &prov, -1) < 0) {
			free(text);
			return hb_status_set(msg, n, HB_EIO, "%s: cannot write the attributes", h->tmp);
		}
	}
	free(text);
	if ((rc = split_header(&h->runs, runs_header, msg, n)) != HB_OK ||
	    (rc = split_header(&h->coll, coll_header, msg, n)) != HB_OK)
		return rc;
	for (int k = 0; k < h->coll.ncols; k++)
		coll_column(h->coll.col[k], &h->coll.unit[k], &h->coll.kind[k]);
	return table_create(h, &h->coll, msg, n);
}

static int
sink_row(void *ctx, int runs, const char *row, size_t len, char *msg, size_t n)
{
	struct sweep_hdf5 *h = ctx;

	if (runs && h->runs.dset < 0) {
		/* the first runs row tells an axis of numbers from one of words */
		const char *p = row, *end = row + len;
		char f[4096];
		int rc;

		for (int k = 0; k < h->runs.ncols; k++) {
			if (!next_field(&p, end, f, sizeof f))
				f[0] = '\0';
			runs_column(h, k, f, &h->runs.unit[k], &h->runs.kind[k]);
		}
		if ((rc = table_create(h, &h->runs, msg, n)) != HB_OK)
			return rc;
	}
	return table_row(h, runs ? &h->runs : &h->coll, row, len, msg, n);
}

static int
sink_end(void *ctx, int ok, char *msg, size_t n)
{
	struct sweep_hdf5 *h = ctx;
	int rc = HB_OK;

	if (ok && (rc = table_flush(h, &h->runs, msg, n)) == HB_OK)
		rc = table_flush(h, &h->coll, msg, n);
	table_free_strings(&h->runs);
	table_free_strings(&h->coll);
	h->runs.nbuf = h->coll.nbuf = 0;
	for (int k = 0; k < 2; k++) {
		struct table *t = k ? &h->coll : &h->runs;

		if (t->dset >= 0)
			h5api.H5Dclose(t->dset);
		if (t->type >= 0)
			h5api.H5Tclose(t->type);
		t->dset = t->type = -1;
	}
	if (h->vstr >= 0)
		h5api.H5Tclose(h->vstr);
	h->vstr = -1;
	if (h->file >= 0 && h5api.H5Fclose(h->file) < 0 && ok && rc == HB_OK)
		rc = hb_status_set(msg, n, HB_EIO, "%s: cannot close it (disk full?)", h->tmp);
	h->file = -1;
	if (ok && rc == HB_OK && h->created) {
		int fd = open(h->tmp, O_RDONLY | O_CLOEXEC);

		if (fd < 0 || fsync(fd) != 0 || rename(h->tmp, h->path) != 0)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", h->path, strerror(errno));
		if (fd >= 0)
			close(fd);
		if (rc == HB_OK)
			h->created = 0;
	}
	if (h->created)
		unlink(h->tmp);
	h->created = 0;
	return rc;
}

const struct hb_sweep_sink sweep_hdf5_sink = {
	.name = SWEEP_HDF5_NAME,
	.begin = sink_begin,
	.row = sink_row,
	.end = sink_end,
};

struct sweep_hdf5 *
sweep_hdf5_new(const char *dir, char *msg, size_t n)
{
	struct sweep_hdf5 *h;

	if (sweep_hdf5_available(msg, n) != HB_OK)
		return NULL;
	if ((h = calloc(1, sizeof *h)) == NULL) {
		hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		return NULL;
	}
	snprintf(h->dir, sizeof h->dir, "%s", dir);
	snprintf(h->path, sizeof h->path, "%s/" SWEEP_HDF5_NAME, dir);
	h->file = h->vstr = -1;
	table_init(&h->runs, "runs");
	table_init(&h->coll, "collisions");
	return h;
}

void
sweep_hdf5_free(struct sweep_hdf5 *h)
{
	if (h == NULL)
		return;
	if (h->file >= 0 || h->created)
		sink_end(h, 0, NULL, 0);
	for (int k = 0; k < 2; k++) {
		struct table *t = k ? &h->coll : &h->runs;

		for (int c = 0; c < t->ncols; c++)
			free(t->col[c]);
		free(t->buf);
	}
	free(h);
}
