/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_life.h - a simulator's life beyond sim.h, for the engine's own
 * callers (sim_life.c).
 */
#ifndef HYBOUNCE_SIM_LIFE_H
#define HYBOUNCE_SIM_LIFE_H

#include <stddef.h>

#include "hybounce/scene.h"
#include "hybounce/sim.h"

/*
 * hb_sim_free(s) then hb_sim_new(sc, msg, n), the same simulator in every
 * way, but s's own block, its arc's buffers and its root finder kept for
 * the new one (a sweep's worker runs point after point on one simulator:
 * no allocator round trip of ~21 KB, of the arc's block and of the
 * solver).  s: a simulator hb_sim_new made (or this function).  On
 * failure s is freed and NULL returned, with msg as hb_sim_new gives it.
 */
struct hb_sim *
hbs_sim_renew(struct hb_sim *s, const struct hb_scene *sc, char *msg, size_t n);

#endif
