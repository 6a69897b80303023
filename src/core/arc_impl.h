/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * arc_impl.h - the arc's constructor and mutators, private to the engine
 * (the front ends read the arc through include/hybounce/arc.h only).
 */
#ifndef HYBOUNCE_ARC_IMPL_H
#define HYBOUNCE_ARC_IMPL_H

#include "hybounce/arc.h"

/* An empty arc that thins beyond max_samples samples.  NULL on no memory. */
struct hb_arc *arc_new(size_t max_samples);
void arc_free(struct hb_arc *a);

/* Appends a sample (hybrid-time order is the caller's duty).  Returns 0 or HB_ENOMEM. */
int arc_push(struct hb_arc *a, const struct hb_arc_sample *s);

/* Appends a jump record.  Returns 0 or HB_ENOMEM. */
int arc_push_jump(struct hb_arc *a, const struct hb_arc_jump *jr);

/* Keeps samples [0, keep) and the jumps whose post-jump sample is kept. */
void arc_truncate(struct hb_arc *a, size_t keep);

/* Empty again, as arc_new(max_samples) makes it, its buffers kept. */
void arc_clear(struct hb_arc *a, size_t max_samples);

/* Changes the memory bound (thins at once if needed). */
void arc_set_max(struct hb_arc *a, size_t max_samples);

#endif
