/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_pool.c - the worker threads of a sweep (sweep_impl.h:
 * sweep_compute).
 *
 * Workers take the next id under a mutex, run the point on their own scene
 * and sim (sweep_point_block_buf), and queue the block (the queue is
 * unbounded: a worker never waits for the writer); the calling thread
 * writes blocks to the journal, reports progress and hands the result, its
 * block's buffer with it, back to the workers (the spare list), so that a
 * point in steady state allocates nothing of the sweep's own.  The mutex is held for
 * a few instructions per point; the writer is signalled after it is
 * released, once a batch of WAKE_BATCH results is queued (or a point
 * failed, or a worker ends), and looks by itself every 0.1 s.  The results do not depend on the number of threads or the
 * order of completion: each point's bytes come from its own run alone, and
 * the files are sorted by id.  The writer writes a grid's blocks in id
 * order (a block waits while a point before it is still being computed),
 * so a journal written in one go is sorted and its merge needs no index
 * (sweep_merge.c).  With one job (--jobs 1, or a single point) there are no
 * threads: the calling thread computes each point and writes it, with one
 * result reused point after point (no mutex, no wake-ups, no queue).
 */
#include <errno.h>
#include <limits.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "hybounce/status.h"
#include "hybounce/sweep.h"
#include "clock.h"
#include "sweep_impl.h"

struct result {
	struct result *next;
	long id;
	struct sweep_block b;   /* its buffer reused by the next point that takes this result */
	int rc;
	char msg[256];
};

struct pool {
	const struct hb_sweep *sw;
	pthread_mutex_t mu;
	pthread_cond_t cv;
	const unsigned char *done;  /* the journal's points: one bit each */
	const long *ids;            /* or the points to compute, nids of them */
	long nids;
	long next, step, np;        /* the next id (index of ids) to look at, the shard count, the points */
	int stop;
	struct result *head, *tail;
	long queued;                /* results from head to tail */
	struct result *spare;       /* written results, their buffers kept for the next points */
	long *busy;                 /* each worker's point, LONG_MAX: none */
};

struct worker_arg {
	struct pool *p;
	long w;
};

/* The next point to compute, or -1 (under p->mu). */
static long
pool_take(struct pool *p)
{
	long id;

	if (p->ids != NULL) {
		if (p->next >= p->nids)
			return -1;
		return p->ids[p->next++];
	}
	while (p->next < p->np && (p->done[p->next / 8] & (1u << (p->next % 8))))
		p->next += p->step;   /* in the journal already */
	if (p->next >= p->np)
		return -1;
	id = p->next;
	p->next += p->step;
	return id;
}

/* Results a worker queues before it wakes the writer (see worker). */
enum { WAKE_BATCH = 16 };

static void *
worker(void *arg)
{
	struct pool *p = ((struct worker_arg *)arg)->p;
	long w = ((struct worker_arg *)arg)->w;
	struct sweep_wbuf wb = { 0 };   /* this worker's buffers, reused point after point */

	for (;;) {
		struct result *r;
		long id;
		int wake;

		pthread_mutex_lock(&p->mu);
		if (p->stop || (id = pool_take(p)) < 0) {
			pthread_mutex_unlock(&p->mu);
			pthread_cond_signal(&p->cv);   /* the last results: written now */
			sweep_wbuf_free(&wb);
			return NULL;
		}
		p->busy[w] = id;
		if ((r = p->spare) != NULL)
			p->spare = r->next;
		pthread_mutex_unlock(&p->mu);

		if (r == NULL && (r = malloc(sizeof *r)) != NULL) {
			/* not calloc: msg is 256 bytes to clear */
			r->b.p = NULL;
			r->b.cap = 0;
		}
		if (r != NULL) {
			r->next = NULL;
			r->msg[0] = '\0';
			r->id = id;
			r->rc = sweep_point_block_buf(p->sw, id, &wb, &r->b, r->msg, sizeof r->msg);
		}
		pthread_mutex_lock(&p->mu);
		p->busy[w] = LONG_MAX;
		if (r == NULL) {
			p->stop = 2;  /* out of memory: the caller says so */
			wake = 1;
		} else {
			if (p->tail)
				p->tail->next = r;
			else
				p->head = r;
			p->tail = r;
			wake = ++p->queued >= WAKE_BATCH || r->rc != HB_OK;
		}
		pthread_mutex_unlock(&p->mu);
		/*
		 * After the unlock: signalled under the mutex, the woken writer
		 * would block at once on the mutex this thread still holds (half
		 * of its sleeps, measured with perf sched).  Woken for a batch of
		 * results, not for each: a wake-up and the writer's sleep cost as
		 * much CPU as a cheap point; the writer also looks every 0.1 s.
		 */
		if (wake)
			pthread_cond_signal(&p->cv);
	}
}

/* Adds r to the list at *l, kept by increasing id. */
static void
held_add(struct result **l, struct result *r)
{
	while (*l != NULL && (*l)->id < r->id)
		l = &(*l)->next;
	r->next = *l;
	*l = r;
}

/*
 * Blocks held at most: past this (a worker stalled on one point while the
 * others finish thousands), the first is written out of order, memory
 * stays bounded (a few MB) and the merge takes its index.  256 was passed
 * at a load average of 13 on 2 cores (a worker descheduled for long).
 */
enum { HELD_MAX = 4096 };

/* Whether held's first block can be written (under p->mu): a list of ids
 * at once, a grid's when no worker computes a point before it. */
static int
writable(const struct pool *p, const struct result *held, long nheld, long nth)
{
	if (held == NULL)
		return 0;
	if (p->ids != NULL || nheld >= HELD_MAX)
		return 1;
	for (long i = 0; i < nth; i++)
		if (p->busy[i] < held->id)
			return 0;
	return 1;
}

/* Where finished points go: the journal, got_block, the progress. */
struct writer {
	const struct hb_sweep_options *o;
	int fd;
	const char *jpath;
	struct hb_sweep_progress *pr;
	double t0;
	int (*got_block)(void *, long, const char *, size_t);
	void *ctx;
	int *ordered;
	long last;                  /* the id written last, -1: none */
	char *msg;
	size_t n;
};

/* Writes finished point r (its block, or its error) where w says. */
static int
emit(const struct result *r, struct writer *w)
{
	int rc;

	if (r->rc != HB_OK)
		return hb_status_set(w->msg, w->n, r->rc, "%s", r->msg);
	if (sweep_write_all(w->fd, r->b.p, r->b.len) != 0)
		return hb_status_set(w->msg, w->n, HB_EIO, "%s: %s", w->jpath, strerror(errno));
	if (w->got_block != NULL && (rc = w->got_block(w->ctx, r->id, r->b.p, r->b.len)) != HB_OK)
		return hb_status_set(w->msg, w->n, rc, "%s: point %ld: no runs row", w->jpath, r->id);
	if (r->id < w->last && w->ordered != NULL)
		*w->ordered = 0;
	w->last = r->id;
	w->pr->done++;
	w->pr->failed += r->b.failed;
	w->pr->point_cpu += r->b.cpu;
	w->pr->elapsed = clock_seconds(CLOCK_MONOTONIC) - w->t0;
	if (w->o->progress)
		w->o->progress(w->o->ctx, w->pr);
	return HB_OK;
}

/*
 * One job: the points computed and written by the calling thread, in the
 * order taken (so a grid's journal is sorted), one result and one worker's
 * buffers reused; *o->cancel looked at between points.
 */
static int
compute_inline(struct pool *p, struct writer *w, long npending)
{
	struct sweep_wbuf wb = { 0 };
	struct result r;
	long got = 0, id;
	int rc = HB_OK, cancelled = 0;

	r.b.p = NULL;
	r.b.cap = 0;
	while (got < npending && (id = pool_take(p)) >= 0) {
		if (w->o->cancel != NULL && *w->o->cancel) {
			cancelled = 1;
			break;
		}
		r.msg[0] = '\0';
		r.id = id;
		r.rc = sweep_point_block_buf(p->sw, id, &wb, &r.b, r.msg, sizeof r.msg);
		if ((rc = emit(&r, w)) != HB_OK)
			break;
		got++;
	}
	sweep_wbuf_free(&wb);
	free(r.b.p);
	if (cancelled)
		rc = hb_status_set(w->msg, w->n, HB_EDONE, "stopped with %ld of %ld points done; "
		                   "the same command resumes", w->pr->done, w->pr->total);
	return rc;
}

/* See sweep_impl.h. */
int
sweep_compute(const struct hb_sweep *sw, const struct hb_sweep_options *o, int fd,
              const char *jpath, const long *ids, long nids, const unsigned char *done,
              long first, long step, long npending, struct hb_sweep_progress *pr, double t0,
              int (*got_block)(void *, long, const char *, size_t), void *ctx, int *ordered,
              char *msg, size_t n)
{
	struct pool p;
	struct worker_arg *wa = NULL;
	struct result *held = NULL;   /* finished, not written yet, by id */
	long nheld = 0;
	pthread_t *th = NULL;
	long got = 0, nth = 0;
	int rc = HB_OK, cancelled = 0;
	struct writer w = { o, fd, jpath, pr, t0, got_block, ctx, ordered, -1, msg, n };

	memset(&p, 0, sizeof p);
	if (ordered != NULL)
		*ordered = 1;
	if (ids != NULL)
		npending = nids;
	if (npending <= 0)
		return HB_OK;
	p.sw = sw;
	p.done = done;
	p.ids = ids;
	p.nids = nids;
	p.next = ids != NULL ? 0 : first;
	p.step = step;
	p.np = hb_sweep_npoints(sw);
	nth = o->jobs < 1 ? 1 : o->jobs;
	if (nth > npending)
		nth = npending;
	if (nth == 1)
		return compute_inline(&p, &w, npending);
	pthread_mutex_init(&p.mu, NULL);
	pthread_cond_init(&p.cv, NULL);
	th = calloc((size_t)nth, sizeof *th);
	wa = calloc((size_t)nth, sizeof *wa);
	p.busy = malloc((size_t)nth * sizeof *p.busy);
	if (th == NULL || wa == NULL || p.busy == NULL) {
		rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		nth = 0;
		goto threads_done;
	}
	for (long i = 0; i < nth; i++)
		p.busy[i] = LONG_MAX;
	for (long i = 0; i < nth; i++) {
		wa[i].p = &p;
		wa[i].w = i;
		if (pthread_create(&th[i], NULL, worker, &wa[i]) != 0) {
			nth = i;
			if (nth == 0) {
				rc = hb_status_set(msg, n, HB_ENOMEM, "cannot start a thread");
				goto threads_done;
			}
			break;
		}
	}
	pthread_mutex_lock(&p.mu);
	while (got < npending && rc == HB_OK) {
		struct result *r;

		/* the finished points in held, by id; the first written when no
		 * point before it is being computed (a grid's ids are taken in
		 * order; a list of ids is written as it finishes) */
		while (p.head == NULL && !writable(&p, held, nheld, nth) && p.stop == 0 && !cancelled) {
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
		while (p.head != NULL) {
			r = p.head;
			p.head = r->next;
			held_add(&held, r);
			nheld++;
		}
		p.tail = NULL;
		p.queued = 0;
		if (!writable(&p, held, nheld, nth)) {
			if (p.stop != 0) {
				rc = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
				break;
			}
			continue;
		}
		r = held;
		held = r->next;
		nheld--;
		pthread_mutex_unlock(&p.mu);
		if ((rc = emit(r, &w)) == HB_OK)
			got++;
		pthread_mutex_lock(&p.mu);
		r->next = p.spare;
		p.spare = r;
	}
	p.stop = p.stop ? p.stop : rc != HB_OK || cancelled;
	pthread_mutex_unlock(&p.mu);
threads_done:
	for (long i = 0; i < nth; i++)
		pthread_join(th[i], NULL);
	while (p.head) {
		struct result *r = p.head;

		p.head = r->next;
		held_add(&held, r);
	}
	while (held) {
		struct result *r = held;

		/* Stopped: the points that were finishing are kept too. */
		if (cancelled && rc == HB_OK && r->rc == HB_OK) {
			if (sweep_write_all(fd, r->b.p, r->b.len) != 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
			else {
				pr->done++;
				pr->failed += r->b.failed;
			}
		}
		held = r->next;
		free(r->b.p);
		free(r);
	}
	while (p.spare) {
		struct result *r = p.spare;

		p.spare = r->next;
		free(r->b.p);
		free(r);
	}
	if (cancelled && rc == HB_OK)
		rc = hb_status_set(msg, n, HB_EDONE, "stopped with %ld of %ld points done; "
		                "the same command resumes", pr->done, pr->total);
	free(th);
	free(wa);
	free(p.busy);
	pthread_cond_destroy(&p.cv);
	pthread_mutex_destroy(&p.mu);
	return rc;
}

