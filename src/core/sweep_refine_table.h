/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_refine_table.h - the points of a refined sweep (sweep_refine_table.c),
 * private to the engine: the state of sweep_refine_run.c.
 */
#ifndef HYBOUNCE_SWEEP_REFINE_TABLE_H
#define HYBOUNCE_SWEEP_REFINE_TABLE_H

#include <stddef.h>
#include <stdint.h>

#include "sweep_impl.h"

struct refine_node {
	long id;            /* -1: an empty slot */
	double v;           /* the observable */
	long cls;           /* its class (sweep_refine_class) */
	int64_t off;        /* the block in the journal */
	uint32_t len;
	signed char level;  /* the round that asked for it; -1: not (yet) asked */
	unsigned char have; /* computed: v and cls known */
};

struct refine_state {
	const struct hb_sweep *sw;
	struct refine_node *t;     /* open addressing, cap a power of 2 */
	size_t cap, count;
	long *pending;         /* the round's points to compute */
	long npending, pending_cap;
	int64_t jsize;      /* the journal's length */
	int rfd;            /* the journal, to read blocks */
	char *buf;
	size_t buf_cap;
	int err;            /* what stopped the journal's scan */
};

/* The node of point id; NULL when the table has none. */
struct refine_node *
sweep_refine_node_get(const struct refine_state *r, long id);

/* A point's block has been journaled at r->jsize (or read from the journal at off). */
int
sweep_refine_note(struct refine_state *r, long id, const char *blk, size_t len, int64_t off);

/* Round `level` needs point id: to compute unless the journal has it. */
int
sweep_refine_request(struct refine_state *r, long id, int level);

#endif
