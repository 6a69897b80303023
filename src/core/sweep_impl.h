/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_impl.h - what the sweep's files share inside the engine.
 */
#ifndef HYBOUNCE_SWEEP_IMPL_H
#define HYBOUNCE_SWEEP_IMPL_H

#include <stddef.h>
#include "hybounce/sim.h"

struct hb_sweep;

/*
 * hb_sim_new() for a worker thread of sweep sw: serialised with the sweep's
 * other threads, because hb_sim_new() switches GSL's process-wide error
 * handler off (one global written by every call).
 */
struct hb_sim *
sweep_sim_new(const struct hb_sweep *sw, const struct hb_scene *sc, char *msg, size_t n);

#endif
