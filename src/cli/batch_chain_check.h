/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_chain_check.h - the physics lines of a chain's batch report.
 */
#ifndef HYBOUNCE_CLI_BATCH_CHAIN_CHECK_H
#define HYBOUNCE_CLI_BATCH_CHAIN_CHECK_H

#include <stdio.h>

#include "hybounce/sim.h"

/*
 * Checks the chain run s (hb_check_chain) and writes its lines to out: a
 * failure always (a warning, or FAILED under check, also on stderr), the
 * passes and the model limits passed under check.  Returns 1 when check
 * is set and a check failed (the batch exits 1), 0 otherwise.
 */
int batch_chain_check(FILE *out, const struct hb_sim *s, int check);

#endif
