/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_refine.c - the summary line of a refined sweep (--refine): what it
 * found and what it cost against the uniform grid of the same resolution.
 */
#include <stdio.h>

#include "hybounce/sweep.h"
#include "sweep_cli.h"

void
sweep_refine_summary(FILE *f, const struct hb_sweep *sw, const struct hb_sweep_refine_stats *s)
{
	fprintf(f, "sweep: refined: %ld boundar%s located to %.2g of %s (%d bisection%s) in "
	        "%ld runs, %ld of the grid and %ld added; the uniform grid of that resolution "
	        "is %ld runs (%.1f%%)\n", s->boundaries, s->boundaries == 1 ? "y" : "ies",
	        s->resolution, hb_sweep_naxes(sw) > 1 ? "each axis" : "the axis", s->levels,
	        s->levels == 1 ? "" : "s", s->runs, s->grid, s->runs - s->grid, s->uniform,
	        s->uniform > 0 ? 100.0 * (double)s->runs / (double)s->uniform : 0.0);
}
