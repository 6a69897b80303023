/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_impl.h - what the sweep's files share inside the engine.
 */
#ifndef HYBOUNCE_SWEEP_IMPL_H
#define HYBOUNCE_SWEEP_IMPL_H

#include <stddef.h>
#include "hybounce/sim.h"

struct hb_sweep;

#endif
