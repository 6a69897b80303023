/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_run.c - running a sweep into a folder: the folder's identity
 * (sweep.preset), the journal that makes it resumable and the worker
 * threads (see sweep.h); the merge is in sweep_merge.c.
 *
 * Journal.  Each shard appends to its own journal (points.journal for a
 * one-machine sweep, shard-K-of-N.journal otherwise) one block per point,
 * in the order the points complete: its collision rows "c,ID,...", then
 * its runs row "r,ID,...", the whole block in one write(2) from the
 * calling thread.  A block counts once its runs row is complete (ends in a
 * newline); a SIGKILL can leave at most one partial block at the end, which
 * the next start cuts off before it appends.  Nothing is cached in memory
 * but one bit per point (the workers take the next id not in the journal
 * from those bits), and the merge keeps 8 bytes per point, so memory
 * stays flat in the number of points computed.
 *
 * Threads.  Workers take the next id under a mutex, run the point on their
 * own scene and sim (hb_sweep_point_block), and queue the block (the queue
 * is unbounded: a worker never waits for the writer); the calling thread
 * writes blocks and reports progress.  The mutex is held for a few
 * instructions per point and the writer is signalled after it is released.  The results do not depend on
 * the number of threads or the order of completion: each point's bytes come
 * from its own run alone, and the files are sorted by id.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "hybounce/atomic.h"
#include "hybounce/csv.h"
#include "hybounce/input.h"
#include "hybounce/preset.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "sweep_impl.h"

/* See sweep_impl.h. */
char *
sweep_slurp(const char *path, size_t *len, char *msg, size_t n)
{
	char *buf = NULL;

	errno = 0;
	if (access(path, F_OK) != 0 && errno == ENOENT)
		return NULL;
	if (hb_input_read(path, HB_INPUT_PRESET_MAX, &buf, len, msg, n) != HB_OK) {
		errno = EIO;
		return NULL;
	}
	return buf;
}

/*
 * 1 for a provenance comment (outputs.h: "; hybounce V (commit C): ..."):
 * it says which command wrote the file, not what the sweep is, and is left
 * out when a folder's sweep.preset is compared with a command's sweep.
 */
static int
provenance_line(const char *p, const char *end)
{
	const char *colon;

	if ((size_t)(end - p) < 12 || strncmp(p, "; hybounce ", 11) != 0)
		return 0;
	colon = memchr(p, ':', (size_t)(end - p));
	if (colon == NULL)
		return 0;
	for (const char *q = p; q + 8 <= colon; q++)
		if (memcmp(q, "(commit ", 8) == 0)
			return 1;
	return 0;
}

/* Removes the provenance lines of text (len bytes) in place; the new length. */
static size_t
strip_provenance(char *text, size_t len)
{
	size_t w = 0;

	for (size_t r = 0; r < len; ) {
		const char *nl = memchr(text + r, '\n', len - r);
		size_t l = nl != NULL ? (size_t)(nl - (text + r)) + 1 : len - r;

		if (!provenance_line(text + r, text + r + l)) {
			memmove(text + w, text + r, l);
			w += l;
		}
		r += l;
	}
	text[w] = '\0';
	return w;
}

static int
write_all(int fd, const char *p, size_t len)
{
	while (len > 0) {
		ssize_t w = write(fd, p, len);

		if (w < 0) {
			if (errno == EINTR)
				continue;
			return -1;
		}
		p += w;
		len -= (size_t)w;
	}
	return 0;
}

static char *
spec_text(const struct hb_sweep *sw, size_t *len)
{
	size_t l = hb_sweep_spec_format(sw, NULL, 0);
	char *t = malloc(l + 1);

	if (t != NULL)
		hb_sweep_spec_format(sw, t, l + 1);
	*len = l;
	return t;
}

/*
 * 1 for the files a sweep folder may hold before its sweep.preset exists:
 * journals, and the atomic writer's temporary files of sweep.preset (those
 * of a process that is gone are removed when sweep.preset is written).
 */
static int
ours(const char *name)
{
	size_t l = strlen(name);

	return strcmp(name, ".") == 0 || strcmp(name, "..") == 0 ||
	       hb_atomic_is_temp(name, SWEEP_SPEC_NAME, NULL) ||
	       (l > 8 && strcmp(name + l - 8, ".journal") == 0);
}

int
hb_sweep_prepare_dir(const struct hb_sweep *sw, const char *dir, char *msg, size_t n)
{
	return hb_sweep_prepare_dir_with(sw, dir, NULL, msg, n);
}

int
hb_sweep_prepare_dir_with(const struct hb_sweep *sw, const char *dir, const char *provenance,
                          char *msg, size_t n)
{
	char path[4096];
	struct stat st;
	size_t len, have_len;
	char *want, *have;
	int rc;

	if (dir == NULL || dir[0] == '\0')
		return hb_status_set(msg, n, HB_EINVAL, "--out: empty folder name; expected a "
		                  "folder for runs.csv and collisions.csv");
	if (mkdir(dir, 0777) != 0 && errno != EEXIST)
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: cannot create the folder: %s",
		                  dir, strerror(errno));
	if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: not a folder; expected a folder "
		                  "(created if missing)", dir);
	if (access(dir, W_OK) != 0)
		return hb_status_set(msg, n, HB_EINVAL, "--out %s: cannot write there: %s", dir,
		                  strerror(errno));
	want = spec_text(sw, &len);
	if (want == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	snprintf(path, sizeof path, "%s/" SWEEP_SPEC_NAME, dir);
	have = sweep_slurp(path, &have_len, msg, n);
	if (have != NULL) {
		have_len = strip_provenance(have, have_len);
		rc = have_len == len && memcmp(have, want, len) == 0 ? HB_OK
		   : hb_status_set(msg, n, HB_EINVAL, "--out %s: the folder holds a different "
		                "sweep (%s differs from this one's); expected a new folder, "
		                "or this sweep's own folder to resume it", dir, path);
		free(have);
		free(want);
		return rc;
	}
	if (errno != ENOENT) {
		free(want);
		return HB_EIO;   /* sweep_slurp said why */
	}
	{
		DIR *d = opendir(dir);
		struct dirent *e;

		if (d == NULL) {
			free(want);
			return hb_status_set(msg, n, HB_EIO, "%s: %s", dir, strerror(errno));
		}
		while ((e = readdir(d)) != NULL)
			if (!ours(e->d_name)) {
				hb_status_set(msg, n, HB_EINVAL, "--out %s: the folder is not empty "
				    "and holds no sweep (found %s); expected a new or empty folder",
				    dir, e->d_name);
				closedir(d);
				free(want);
				return HB_EINVAL;
			}
		closedir(d);
	}
	if (provenance != NULL && provenance[0] != '\0') {
		/* The spec, then the line saying which command wrote it. */
		size_t pl = strlen(provenance);
		char *nb = realloc(want, len + pl + 2);

		if (nb == NULL) {
			free(want);
			return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		}
		want = nb;
		memcpy(want + len, provenance, pl);
		want[len + pl] = '\n';
		len += pl + 1;
	}
	rc = hb_atomic_write_file(path, want, len, msg, n);
	free(want);
	return rc;
}

/* ------------------------------------------------------------------ */
/* Journal                                                             */

/* "c,ID," or "r,ID,": kind and id; -1 if the line is not a journal line. */
static int
journal_line(const char *line, size_t len, long *id)
{
	char *end;

	if (len < 4 || (line[0] != 'c' && line[0] != 'r') || line[1] != ',')
		return -1;
	errno = 0;
	*id = strtol(line + 2, &end, 10);
	if (end == line + 2 || *end != ',' || errno != 0 || *id < 0)
		return -1;
	return line[0];
}

/* See sweep_impl.h. */
int
sweep_journal_scan(const char *path, long npoints, int trunc,
             int (*seen)(void *, long, off_t, size_t), void *ctx, char *msg, size_t n)
{
	FILE *f = fopen(path, "r");
	char *line = NULL;
	size_t cap = 0;
	ssize_t got;
	off_t pos = 0, block = 0;
	long id, block_id = -1, lineno = 0;
	int kind, rc = HB_OK;

	if (f == NULL)
		return errno == ENOENT ? HB_OK : hb_status_set(msg, n, HB_EIO, "%s: %s", path,
		                                             strerror(errno));
	while ((got = getline(&line, &cap, f)) > 0) {
		lineno++;
		if (line[got - 1] != '\n')
			break;  /* a torn last line */
		kind = journal_line(line, (size_t)got, &id);
		if (kind < 0 || id >= npoints || (block_id >= 0 && id != block_id)) {
			rc = hb_status_set(msg, n, HB_EINVAL, "%s:%ld: not a line of this sweep's "
			                "journal; remove the file to compute its points again",
			                path, lineno);
			break;
		}
		pos += got;
		if (kind == 'r') {
			if ((rc = seen(ctx, id, block, (size_t)(pos - block))) != HB_OK)
				break;
			block = pos;
			block_id = -1;
		} else {
			block_id = id;
		}
	}
	free(line);
	if (ferror(f) && rc == HB_OK)
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	fclose(f);
	if (rc == HB_OK && trunc && truncate(path, block) != 0)
		rc = hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	return rc;
}

static void
journal_name(char *buf, size_t n, const char *dir, long k, long nshards)
{
	if (nshards <= 1)
		snprintf(buf, n, "%s/points.journal", dir);
	else
		snprintf(buf, n, "%s/shard-%ld-of-%ld.journal", dir, k, nshards);
}

struct doneset {
	unsigned char *bits;
	long count, failed;
};

/*
 * An exclusive lock on the journal open as fd (flock: a second process on
 * the same shard, here or on another node of a shared file system, is
 * refused instead of appending beside it).  A file system without locks is
 * taken as it is.  fd < 0: the open's errno.
 */
static int
journal_lock(int fd, const char *path, char *msg, size_t n)
{
	if (fd < 0)
		return hb_status_set(msg, n, HB_EIO, "%s: %s", path, strerror(errno));
	if (flock(fd, LOCK_EX | LOCK_NB) == 0 || errno != EWOULDBLOCK)
		return HB_OK;
	return hb_status_set(msg, n, HB_EIO, "%s: another process is computing these points "
	                     "(the journal is locked); expected one run of a shard at a time",
	                     path);
}

static int
mark_done(void *ctx, long id, off_t off, size_t len)
{
	struct doneset *d = ctx;

	(void)off;
	(void)len;
	if (!(d->bits[id / 8] & (1u << (id % 8)))) {
		d->bits[id / 8] |= (unsigned char)(1u << (id % 8));
		d->count++;
	}
	return HB_OK;
}

/* ------------------------------------------------------------------ */
/* Worker threads                                                      */

struct result {
	struct result *next;
	long id;
	char *blk;
	int failed, rc;
	double cpu;
	char msg[256];
};

struct pool {
	const struct hb_sweep *sw;
	pthread_mutex_t mu;
	pthread_cond_t cv;
	const unsigned char *done;  /* the journal's points: one bit each */
	long npending;              /* points of the shard to compute */
	long next, step, np;        /* the next id to look at, the shard count, the points */
	int stop;
	struct result *head, *tail;
};

static void *
worker(void *arg)
{
	struct pool *p = arg;

	for (;;) {
		struct result *r;
		long id;
		double c0;

		pthread_mutex_lock(&p->mu);
		while (p->next < p->np && (p->done[p->next / 8] & (1u << (p->next % 8))))
			p->next += p->step;   /* in the journal already */
		if (p->stop || p->next >= p->np) {
			pthread_mutex_unlock(&p->mu);
			return NULL;
		}
		id = p->next;
		p->next += p->step;
		pthread_mutex_unlock(&p->mu);

		r = calloc(1, sizeof *r);
		c0 = clock_seconds(CLOCK_THREAD_CPUTIME_ID);
		if (r != NULL) {
			r->id = id;
			r->rc = hb_sweep_point_block(p->sw, id, &r->blk, &r->failed, r->msg,
			                          sizeof r->msg);
			r->cpu = clock_seconds(CLOCK_THREAD_CPUTIME_ID) - c0;
		}
		pthread_mutex_lock(&p->mu);
		if (r == NULL) {
			p->stop = 2;  /* out of memory: the caller says so */
		} else {
			if (p->tail)
				p->tail->next = r;
			else
				p->head = r;
			p->tail = r;
		}
		pthread_mutex_unlock(&p->mu);
		/*
		 * After the unlock: signalled under the mutex, the woken writer
		 * would block at once on the mutex this thread still holds (half
		 * of its sleeps, measured with perf sched).
		 */
		pthread_cond_signal(&p->cv);
	}
}

int
hb_sweep_run(const struct hb_sweep *sw, const struct hb_sweep_options *o, char *msg, size_t n)
{
	long np = hb_sweep_npoints(sw), k = o->shard_k, ns = o->shard_n < 1 ? 1 : o->shard_n;
	struct hb_sweep_progress pr;
	struct doneset ds = { 0 };
	struct pool p;
	pthread_t *th = NULL;
	long got = 0, nth = 0;
	char jpath[4200];
	int fd = -1, rc, cancelled = 0;
	double t0 = clock_seconds(CLOCK_MONOTONIC);

	memset(&pr, 0, sizeof pr);
	memset(&p, 0, sizeof p);
	if (np == 0)
		return hb_status_set(msg, n, HB_EINVAL, "nothing to vary; expected at least one "
		                  "--vary KEY=SPEC");
	if (k < 0 || k >= ns)
		return hb_status_set(msg, n, HB_EINVAL, "--shard %ld/%ld: accepted: K/N with "
		                  "0 <= K < N", k, ns);
	if ((rc = hb_sweep_prepare_dir_with(sw, o->dir, o->provenance, msg, n)) != HB_OK)
		return rc;
	journal_name(jpath, sizeof jpath, o->dir, k, ns);
	if (ns == 1 && access(jpath, F_OK) != 0 && errno == ENOENT) {
		char r[4200], c[4200];

		/* Merged and its journal removed: the sweep is complete. */
		snprintf(r, sizeof r, "%s/runs.csv", o->dir);
		snprintf(c, sizeof c, "%s/collisions.csv", o->dir);
		if (access(r, F_OK) == 0 && access(c, F_OK) == 0) {
			pr.total = pr.done = pr.resumed = np;
			if (o->progress)
				o->progress(o->ctx, &pr);
			return HB_OK;
		}
	}
	ds.bits = calloc((size_t)np / 8 + 1, 1);
	if (ds.bits == NULL)
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	/* One process a journal: locked before its torn end is cut off. */
	fd = open(jpath, O_WRONLY | O_APPEND | O_CLOEXEC);
	if (fd >= 0 && (rc = journal_lock(fd, jpath, msg, n)) != HB_OK)
		goto out;
	if ((rc = sweep_journal_scan(jpath, np, 1, mark_done, &ds, msg, n)) != HB_OK)
		goto out;
	/* The shard's points that the journal does not hold. */
	for (long id = k; id < np; id += ns)
		pr.total++;
	for (long id = k; id < np; id += ns)
		p.npending += !(ds.bits[id / 8] & (1u << (id % 8)));
	pr.resumed = pr.done = pr.total - p.npending;
	if (o->progress)
		o->progress(o->ctx, &pr);

	if (p.npending > 0) {
		if (fd < 0 && ((fd = open(jpath, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644)) < 0 ||
		               (rc = journal_lock(fd, jpath, msg, n)) != HB_OK)) {
			if (fd < 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
			goto out;
		}
		p.sw = sw;
		p.done = ds.bits;
		p.next = k;
		p.step = ns;
		p.np = np;
		pthread_mutex_init(&p.mu, NULL);
		pthread_cond_init(&p.cv, NULL);
		nth = o->jobs < 1 ? 1 : o->jobs;
		if (nth > p.npending)
			nth = p.npending;
		th = calloc((size_t)nth, sizeof *th);
		if (th == NULL) {
			rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			goto threads_done;
		}
		for (long i = 0; i < nth; i++)
			if (pthread_create(&th[i], NULL, worker, &p) != 0) {
				nth = i;
				if (nth == 0) {
					rc = hb_status_set(msg, n, HB_ENOMEM, "cannot start a thread");
					goto threads_done;
				}
				break;
			}
		pthread_mutex_lock(&p.mu);
		while (got < p.npending && rc == HB_OK) {
			struct result *r;

			while (p.head == NULL && p.stop == 0 && !cancelled) {
				struct timespec until;

				if (o->cancel != NULL && *o->cancel) {
					cancelled = 1;
					break;
				}
				clock_gettime(CLOCK_REALTIME, &until);
				until.tv_nsec += 100000000L;   /* look at *o->cancel every 0.1 s */
				if (until.tv_nsec >= 1000000000L) {
					until.tv_sec++;
					until.tv_nsec -= 1000000000L;
				}
				pthread_cond_timedwait(&p.cv, &p.mu, &until);
			}
			if (cancelled || (o->cancel != NULL && *o->cancel)) {
				cancelled = 1;
				break;
			}
			if (p.head == NULL) {
				rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
				break;
			}
			r = p.head;
			p.head = r->next;
			if (p.head == NULL)
				p.tail = NULL;
			pthread_mutex_unlock(&p.mu);
			if (r->rc != HB_OK)
				rc = hb_status_set(msg, n, r->rc, "%s", r->msg);
			else if (write_all(fd, r->blk, strlen(r->blk)) != 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
			else {
				got++;
				pr.done++;
				pr.failed += r->failed;
				pr.point_cpu += r->cpu;
				pr.elapsed = clock_seconds(CLOCK_MONOTONIC) - t0;
				if (o->progress)
					o->progress(o->ctx, &pr);
			}
			free(r->blk);
			free(r);
			pthread_mutex_lock(&p.mu);
		}
		p.stop = p.stop ? p.stop : rc != HB_OK || cancelled;
		pthread_mutex_unlock(&p.mu);
threads_done:
		for (long i = 0; i < nth; i++)
			pthread_join(th[i], NULL);
		while (p.head) {
			struct result *r = p.head;

			/* Stopped: the points that were finishing are kept too. */
			if (cancelled && rc == HB_OK && r->rc == HB_OK) {
				if (write_all(fd, r->blk, strlen(r->blk)) != 0)
					rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
				else {
					pr.done++;
					pr.failed += r->failed;
				}
			}
			p.head = r->next;
			free(r->blk);
			free(r);
		}
		if (cancelled && rc == HB_OK)
			rc = hb_status_set(msg, n, HB_EDONE, "stopped with %ld of %ld points done; "
			                "the same command resumes", pr.done, pr.total);
		free(th);
		pthread_cond_destroy(&p.cv);
		pthread_mutex_destroy(&p.mu);
		if (close(fd) != 0 && rc == HB_OK)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		fd = -1;
		if (rc != HB_OK)
			goto out;
	}
	if (fd >= 0) {
		close(fd);   /* nothing was appended */
		fd = -1;
	}
	if (ns == 1) {
		if ((rc = sweep_merge_into(sw, o->dir, 0, msg, n)) == HB_OK && unlink(jpath) != 0 &&
		    errno != ENOENT)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
	}
out:
	if (fd >= 0)
		close(fd);
	free(ds.bits);
	return rc;
}
