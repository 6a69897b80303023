/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_progress.c - the progress of "hybounce sweep" on stderr
 * (sweep_cmd.h): on a terminal a bar redrawn in place, else a line every
 * --progress PCT of the points; the points found done when a sweep resumes.
 */
#include <stdio.h>
#include <time.h>

#include "hybounce/sweep.h"

#include "sweep_cmd.h"
#include "clock.h"

static void
fmt_eta(double s, char *buf, size_t n)
{
	long t = (long)(s + 0.5);

	if (s != s || s < 0 || s > 1e8)
		snprintf(buf, n, "--:--");
	else if (t >= 3600)
		snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
	else
		snprintf(buf, n, "%ld:%02ld", t / 60, t % 60);
}

void
sweep_on_progress(void *ctx, const struct hb_sweep_progress *p)
{
	struct sweep_progress *g = ctx;
	long computed = p->done - p->resumed;
	double frac = p->total ? (double)p->done / (double)p->total : 1;
	double rate = p->elapsed > 0 ? (double)computed / p->elapsed : 0;
	double eta = rate > 0 ? (double)(p->total - p->done) / rate : -1;
	char e[32];

	if (computed == 0) {
		g->resumed = p->resumed;
		g->total = p->total;
	}
	if (g->quiet)
		return;
	if (computed == 0) {
		if (p->resumed > 0)
			fprintf(stderr, "sweep: resuming: %ld of %ld points already done\n",
			        p->resumed, p->total);
		return;
	}
	fmt_eta(eta, e, sizeof e);
	if (g->tty) {
		double now = clock_seconds(CLOCK_MONOTONIC);
		int w = 30, fill = (int)(frac * w);

		if (p->done < p->total && now - g->last_draw < 0.1)
			return;
		g->last_draw = now;
		fprintf(stderr, "\r[%.*s%*s] %ld/%ld %3.0f%%  %.1f points/s  ETA %s  failed %ld\033[K",
		        fill, "##############################", w - fill, "", p->done,
		        p->total, 100 * frac, rate, e, p->failed);
		if (p->done == p->total)
			fputc('\n', stderr);
		return;
	}
	if (frac + 1e-12 < g->next && p->done < p->total)
		return;
	while (g->next <= frac + 1e-12)
		g->next += g->step;
	fprintf(stderr, "sweep: %ld/%ld points (%.0f%%), %.1f points/s, ETA %s, %ld failed\n",
	        p->done, p->total, 100 * frac, rate, e, p->failed);
}
