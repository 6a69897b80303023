/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * clock.h - seconds on a POSIX clock, as a double: CLOCK_MONOTONIC for
 * elapsed (wall) time, CLOCK_PROCESS_CPUTIME_ID or CLOCK_THREAD_CPUTIME_ID
 * for CPU time.  0 when the clock cannot be read.  Header only (private to
 * the engine and its front ends: sim.c, sweeps, batch progress, scripts).
 */
#ifndef HYBOUNCE_CLOCK_H
#define HYBOUNCE_CLOCK_H

#include <time.h>

static inline double
clock_seconds(clockid_t clock)
{
	struct timespec ts;

	if (clock_gettime(clock, &ts) != 0)
		return 0.0;
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

#endif
