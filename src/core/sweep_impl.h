/*
 * sweep_impl.h - what the sweep's files share inside the engine.
 */
#ifndef HYBOUNCE_SWEEP_IMPL_H
#define HYBOUNCE_SWEEP_IMPL_H

#include <stddef.h>
#include "hybounce/sim.h"

struct sweep;

/*
 * sim_new() for a worker thread of sweep sw: serialised with the sweep's
 * other threads, because sim_new() switches GSL's process-wide error
 * handler off (one global written by every call).
 */
struct sim *
sweep_sim_new(const struct sweep *sw, const struct scene *sc, char *msg, size_t n);

#endif
