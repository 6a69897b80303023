/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_run.c - running a sweep into a folder: the journal that makes it
 * resumable, the shard's points not yet computed, and the worker threads
 * (see sweep.h); the folder and its journals' primitives are in
 * sweep_journal.c, the merge in sweep_merge.c.
 *
 * Journal.  Each shard appends to its own journal (points.journal for a
 * one-machine sweep, shard-K-of-N.journal otherwise) one block per point,
 * a grid's in id order (sweep_pool.c): its collision rows "c,ID,...", then
 * its runs row "r,ID,...", the whole block in one write(2) from the
 * calling thread.  A block counts once its runs row is complete (ends in a
 * newline); a SIGKILL can leave at most one partial block at the end, which
 * the next start cuts off before it appends.  Nothing is cached in memory
 * but one bit per point (the workers take the next id not in the journal
 * from those bits), and the merge reads sorted journals side by side (an
 * index of 8 bytes a point only for journals out of order), so memory
 * stays flat in the number of points computed.
 *
 * Each point's scene is validated once, by its run (hb_sim_new); a refused
 * point stops the sweep (HB_EINVAL) and what the call began is removed
 * (sweep_refused_undo).
 *
 * The worker threads are in sweep_pool.c; a refined sweep (--refine) in
 * sweep_refine_run.c.
 */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
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

struct doneset {
	unsigned char *bits;
	long count, failed;
};

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

int
hb_sweep_run(const struct hb_sweep *sw, const struct hb_sweep_options *o, char *msg, size_t n)
{
	long np = hb_sweep_npoints(sw), k = o->shard_k, ns = o->shard_n < 1 ? 1 : o->shard_n;
	struct hb_sweep_progress pr;
	struct doneset ds = { 0 };
	long npending = 0;
	char jpath[4200];
	int fd = -1, rc, made = 0, ordered = 0;
	double t0 = clock_seconds(CLOCK_MONOTONIC);

	memset(&pr, 0, sizeof pr);
	if (np == 0)
		return hb_status_set(msg, n, HB_EINVAL, "nothing to vary; expected at least one "
		                  "--vary KEY=SPEC");
	if (k < 0 || k >= ns)
		return hb_status_set(msg, n, HB_EINVAL, "--shard %ld/%ld: accepted: K/N with "
		                  "0 <= K < N", k, ns);
	if (sw->rf.on) {
		if (ns > 1)
			return hb_status_set(msg, n, HB_EINVAL, "--shard: a refined sweep (--refine) "
			                     "runs on one machine, its rounds one after another; "
			                     "accepted: --refine without --shard");
		return sweep_refine_run(sw, o, msg, n);
	}
	if ((rc = sweep_prepare_dir(sw, o->dir, o->provenance, &made, msg, n)) != HB_OK)
		return rc;
	sweep_journal_name(jpath, sizeof jpath, o->dir, k, ns);
	if (ns == 1 && access(jpath, F_OK) != 0 && errno == ENOENT) {
		char r[4200], c[4200];

		/* Merged and its journal removed: the sweep is complete. */
		snprintf(r, sizeof r, "%s/runs.csv", o->dir);
		snprintf(c, sizeof c, "%s/collisions.csv", o->dir);
		if (o->sink != NULL) {
			int csv = access(r, F_OK) == 0 && access(c, F_OK) == 0;

			snprintf(r, sizeof r, "%s/%s", o->dir, o->sink->name);
			if (access(r, F_OK) != 0 && csv)
				return hb_status_set(msg, n, HB_EINVAL, "--out %s: the folder holds this "
				                     "sweep complete as runs.csv and collisions.csv, not "
				                     "%s; expected a new folder for it", o->dir,
				                     o->sink->name);
			snprintf(c, sizeof c, "%s", r);
		}
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
	if (fd >= 0 && (rc = sweep_journal_lock(fd, jpath, msg, n)) != HB_OK)
		goto out;
	if ((rc = sweep_journal_scan(jpath, np, 1, mark_done, &ds, msg, n)) != HB_OK)
		goto out;
	/* The shard's points that the journal does not hold. */
	for (long id = k; id < np; id += ns)
		pr.total++;
	for (long id = k; id < np; id += ns)
		npending += !(ds.bits[id / 8] & (1u << (id % 8)));
	pr.resumed = pr.done = pr.total - npending;
	if (o->progress)
		o->progress(o->ctx, &pr);

	if (npending > 0) {
		if (fd < 0 && ((fd = open(jpath, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644)) < 0 ||
		               (rc = sweep_journal_lock(fd, jpath, msg, n)) != HB_OK)) {
			if (fd < 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
			goto out;
		}
		if (ds.count == 0)
			made |= SWEEP_MADE_JOURNAL;   /* no point before: this call's */
		rc = sweep_compute(sw, o, fd, jpath, NULL, 0, ds.bits, k, ns, npending, &pr, t0,
		                   NULL, NULL, &ordered, msg, n);
		if (close(fd) != 0 && rc == HB_OK)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		fd = -1;
		/*
		 * A refused point (bad input): a sweep begun by this call leaves
		 * nothing.  A shard leaves what it made: the others may be running
		 * in the folder (--emit checks every point before it writes a job).
		 */
		if (rc == HB_EINVAL && ns == 1)
			sweep_refused_undo(o->dir, made, jpath);
		if (rc != HB_OK)
			goto out;
	}
	if (fd >= 0) {
		close(fd);   /* nothing was appended */
		fd = -1;
	}
	if (ns == 1) {
		/* every point written by this call, in id order: the merge need not check */
		int whole = ds.count == 0 && npending == np && ordered;

		if ((rc = sweep_merge_into(sw, o->dir, 0, whole, o->sink, o->sink_ctx, msg, n)) == HB_OK &&
		    unlink(jpath) != 0 &&
		    errno != ENOENT)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
	}
out:
	if (fd >= 0)
		close(fd);
	free(ds.bits);
	return rc;
}
