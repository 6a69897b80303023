/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_impl.h - what the sweep's files share inside the engine.
 */
#ifndef HYBOUNCE_SWEEP_IMPL_H
#define HYBOUNCE_SWEEP_IMPL_H

#include <stddef.h>
#include <sys/types.h>
#include "hybounce/scene.h"
#include "hybounce/sim.h"

struct hb_sweep;

#define SWEEP_SPEC_NAME "sweep.preset"

/* The whole of a file into a malloc'd string (*len bytes), read once and
 * bounded (input.h).  NULL with msg on failure; errno ENOENT when absent. */
char *
sweep_slurp(const char *path, size_t *len, char *msg, size_t n);

/*
 * Reads a journal: calls seen(ctx, id, off, len) for each complete block
 * and cuts a partial block off the end when trunc is set.  Returns HB_OK
 * (also for a journal that is not there), HB_EIO, or HB_EINVAL for a
 * damaged journal.
 */
int
sweep_journal_scan(const char *path, long npoints, int trunc,
                   int (*seen)(void *, long, off_t, size_t), void *ctx, char *msg, size_t n);

/* The base scene of a sweep (the preset and --set, before any axis). */
const struct hb_scene *
sweep_base(const struct hb_sweep *sw);

/*
 * hb_sweep_merge_shards for a sweep in hand, which DIR/sweep.preset holds
 * (hb_sweep_prepare_dir checked it): its values are not made again.
 */
int
sweep_merge_into(const struct hb_sweep *sw, const char *dir, long nshards, char *msg, size_t n);

#endif
