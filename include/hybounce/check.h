/*
 * check.h - the paper's checks of a computed solution (section Simulation).
 *
 *  - check_solution_pair: the hybrid time domain is ordered; every sample
 *    lies in the flow set C except the last before a jump, which lies in the
 *    jump set D; each post-jump state is g of the pre-jump state, exactly.
 *  - check_euler: forward Euler, started from a flow interval's initial
 *    state, converges to its final state; returns the estimated order.
 */
#ifndef HYBOUNCE_CHECK_H
#define HYBOUNCE_CHECK_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "scene.h"
#include "arc.h"

/* 1 if the state of sample a lies in C (resp. D), by the paper's sets. */
int check_in_C(const struct scene *sc, const struct arc_sample *a);
int check_in_D(const struct scene *sc, const struct arc_sample *a);

/* Returns 0, or HB_EINVAL with the first violation (sample, t, j) in msg. */
int
check_solution_pair(const struct scene *sc, const struct arc *a, char *msg, size_t n);

/*
 * Forward Euler on interval k of the arc with N, 2N, 4N, ... steps; fills
 * *order with the estimated order of convergence to the interval's final
 * state (in the scaled norm).  Returns 0 or HB_EINVAL (msg) if the interval
 * is too short to say.
 */
int
check_euler(const struct scene *sc, const struct arc *a, size_t k, double *order,
            char *msg, size_t n);

HB_END_DECLS

#endif
