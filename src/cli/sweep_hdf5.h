/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_hdf5.h - `hybounce sweep --format hdf5`: a sink (sweep.h:
 * hb_sweep_sink) that writes the merged runs and collisions as DIR/sweep.h5
 * (sweep_hdf5.c says what the file holds).
 *
 *     struct sweep_hdf5 *h = sweep_hdf5_new(dir, msg, sizeof msg);
 *     o.sink = &sweep_hdf5_sink; o.sink_ctx = h;
 *     hb_sweep_run(sw, &o, msg, sizeof msg);
 *     sweep_hdf5_free(h);
 */
#ifndef HYBOUNCE_CLI_SWEEP_HDF5_H
#define HYBOUNCE_CLI_SWEEP_HDF5_H

#include <stddef.h>

#include "hybounce/sweep.h"

#define SWEEP_HDF5_NAME "sweep.h5"

extern const struct hb_sweep_sink sweep_hdf5_sink;

struct sweep_hdf5;

/* HB_OK when libhdf5 can be loaded, else HB_EINVAL saying why. */
int
sweep_hdf5_available(char *msg, size_t n);

/* The sink's context for the folder dir; NULL with msg (no libhdf5, no memory). */
struct sweep_hdf5 *
sweep_hdf5_new(const char *dir, char *msg, size_t n);

void
sweep_hdf5_free(struct sweep_hdf5 *h);

#endif
