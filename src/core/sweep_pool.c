/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_pool.c - the worker threads of a sweep (sweep_impl.h:
 * sweep_compute).
 *
 * Workers take the next id under a mutex, run the point on their own scene
 * and sim (hb_sweep_point_block), and queue the block (the queue is
 * unbounded: a worker never waits for the writer); the calling thread
 * writes blocks to the journal and reports progress.  The mutex is held for
 * a few instructions per point and the writer is signalled after it is
 * released.  The results do not depend on the number of threads or the
 * order of completion: each point's bytes come from its own run alone, and
 * the files are sorted by id.
 */
#include <errno.h>
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
	const long *ids;            /* or the points to compute, nids of them */
	long nids;
	long next, step, np;        /* the next id (index of ids) to look at, the shard count, the points */
	int stop;
	struct result *head, *tail;
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

static void *
worker(void *arg)
{
	struct pool *p = arg;
	struct sweep_wbuf wb = { 0 };   /* this worker's buffers, reused point after point */

	for (;;) {
		struct result *r;
		long id;
		double c0;

		pthread_mutex_lock(&p->mu);
		if (p->stop || (id = pool_take(p)) < 0) {
			pthread_mutex_unlock(&p->mu);
			sweep_wbuf_free(&wb);
			return NULL;
		}
		pthread_mutex_unlock(&p->mu);

		r = malloc(sizeof *r);   /* not calloc: msg is 256 bytes to clear */
		c0 = clock_seconds(CLOCK_THREAD_CPUTIME_ID);
		if (r != NULL) {
			r->next = NULL;
			r->msg[0] = '\0';
			r->id = id;
			r->rc = sweep_point_block_buf(p->sw, id, &wb, &r->blk, &r->failed, r->msg,
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

/* See sweep_impl.h. */
int
sweep_compute(const struct hb_sweep *sw, const struct hb_sweep_options *o, int fd,
              const char *jpath, const long *ids, long nids, const unsigned char *done,
              long first, long step, long npending, struct hb_sweep_progress *pr, double t0,
              int (*got_block)(void *, long, const char *, size_t), void *ctx, char *msg,
              size_t n)
{
	struct pool p;
	pthread_t *th = NULL;
	long got = 0, nth = 0;
	int rc = HB_OK, cancelled = 0;

	memset(&p, 0, sizeof p);
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
	pthread_mutex_init(&p.mu, NULL);
	pthread_cond_init(&p.cv, NULL);
	nth = o->jobs < 1 ? 1 : o->jobs;
	if (nth > npending)
		nth = npending;
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
	while (got < npending && rc == HB_OK) {
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
		else if (sweep_write_all(fd, r->blk, strlen(r->blk)) != 0)
			rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
		else if (got_block != NULL &&
		         (rc = got_block(ctx, r->id, r->blk, strlen(r->blk))) != HB_OK)
			rc = hb_status_set(msg, n, rc, "%s: point %ld: no runs row", jpath, r->id);
		else {
			got++;
			pr->done++;
			pr->failed += r->failed;
			pr->point_cpu += r->cpu;
			pr->elapsed = clock_seconds(CLOCK_MONOTONIC) - t0;
			if (o->progress)
				o->progress(o->ctx, pr);
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
			if (sweep_write_all(fd, r->blk, strlen(r->blk)) != 0)
				rc = hb_status_set(msg, n, HB_EIO, "%s: %s", jpath, strerror(errno));
			else {
				pr->done++;
				pr->failed += r->failed;
			}
		}
		p.head = r->next;
		free(r->blk);
		free(r);
	}
	if (cancelled && rc == HB_OK)
		rc = hb_status_set(msg, n, HB_EDONE, "stopped with %ld of %ld points done; "
		                "the same command resumes", pr->done, pr->total);
	free(th);
	pthread_cond_destroy(&p.cv);
	pthread_mutex_destroy(&p.mu);
	return rc;
}

