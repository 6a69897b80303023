/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_bodies.h - --bodies FILE of batch mode: each body's final state as
 * CSV (mass, position, velocity, kinetic energy), written by the output
 * policy (outputs.h) with the provenance line.
 */
#ifndef HYBOUNCE_CLI_BATCH_BODIES_H
#define HYBOUNCE_CLI_BATCH_BODIES_H

#include <stddef.h>

#include "hybounce/outputs.h"
#include "hybounce/sim.h"

/*
 * Checks path as an output of the command in pol, beside the CSVs of
 * --trace and --collisions (files, or NULL) and the scene saved beside the
 * first of them, before anything runs.  0, or -1 with msg.
 */
int
batch_bodies_check(struct hb_outputs *pol, const char *path, const char *trace, const char *coll,
                   char *msg, size_t n);

/*
 * Writes the CSV of s's bodies to path (checked by batch_bodies_check, the
 * last output added to pol), atomically, and says "wrote PATH".  0, or -1
 * with msg.
 */
int
batch_bodies_write(const struct hb_outputs *pol, const char *path, const struct hb_sim *s,
                   char *msg, size_t n);

#endif
