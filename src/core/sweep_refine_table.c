/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_refine_table.c - the points of a refined sweep (sweep_refine_run.c):
 * a hash table by id (open addressing) of the points computed or asked
 * for, each with its observable, its class, the round that asked for it
 * and where its block lies in the journal; and the round's list of points
 * to compute.  About 48 bytes a point, never the points' text.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/status.h"
#include "sweep_impl.h"
#include "sweep_refine_table.h"

static size_t
slot(const struct refine_state *r, long id)
{
	return (size_t)(((uint64_t)id * 0x9E3779B97F4A7C15ull) >> 17) & (r->cap - 1);
}

struct refine_node *
sweep_refine_node_get(const struct refine_state *r, long id)
{
	if (r->cap == 0)
		return NULL;
	for (size_t i = slot(r, id);; i = (i + 1) & (r->cap - 1)) {
		if (r->t[i].id == id)
			return &r->t[i];
		if (r->t[i].id < 0)
			return NULL;
	}
}

/* A new node for id (not there yet); NULL: no memory.  Pointers held before are stale. */
static struct refine_node *
node_add(struct refine_state *r, long id)
{
	size_t i;

	if (2 * (r->count + 1) > r->cap) {
		size_t oc = r->cap, nc = oc ? 2 * oc : 1024;
		struct refine_node *ot = r->t, *nt = malloc(nc * sizeof *nt);

		if (nt == NULL)
			return NULL;
		for (size_t k = 0; k < nc; k++)
			nt[k].id = -1;
		r->t = nt;
		r->cap = nc;
		for (size_t k = 0; k < oc; k++)
			if (ot[k].id >= 0) {
				for (i = slot(r, ot[k].id); nt[i].id >= 0; i = (i + 1) & (nc - 1))
					;
				nt[i] = ot[k];
			}
		free(ot);
	}
	for (i = slot(r, id); r->t[i].id >= 0; i = (i + 1) & (r->cap - 1))
		;
	memset(&r->t[i], 0, sizeof r->t[i]);
	r->t[i].id = id;
	r->t[i].level = -1;
	r->count++;
	return &r->t[i];
}

int
sweep_refine_note(struct refine_state *r, long id, const char *blk, size_t len, int64_t off)
{
	struct refine_node *x = sweep_refine_node_get(r, id);
	double v;
	int failed;

	if (x != NULL && x->have)
		return HB_OK;   /* the first copy wins */
	if (sweep_block_observable(r->sw, blk, len, r->sw->rf.obs, &v, &failed) != HB_OK)
		return HB_EINVAL;
	if (x == NULL && (x = node_add(r, id)) == NULL)
		return HB_ENOMEM;
	x->v = v;
	x->cls = sweep_refine_class(&r->sw->rf, v, failed);
	x->off = off;
	x->len = (uint32_t)len;
	x->have = 1;
	return HB_OK;
}

int
sweep_refine_request(struct refine_state *r, long id, int level)
{
	struct refine_node *x = sweep_refine_node_get(r, id);

	if (x != NULL) {
		if (x->level < 0)
			x->level = (signed char)level;
		return HB_OK;
	}
	if ((x = node_add(r, id)) == NULL)
		return HB_ENOMEM;
	x->level = (signed char)level;
	if (r->npending == r->pending_cap) {
		long nc = r->pending_cap ? 2 * r->pending_cap : 256;
		long *nt = realloc(r->pending, (size_t)nc * sizeof *nt);

		if (nt == NULL)
			return HB_ENOMEM;
		r->pending = nt;
		r->pending_cap = nc;
	}
	r->pending[r->npending++] = id;
	return HB_OK;
}
