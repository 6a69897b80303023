/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units_impl.h - what units.c (parsing), units_dim.c (dimensions) and
 * units_format.c (writing values) share, private to the engine.
 */
#ifndef HYBOUNCE_UNITS_IMPL_H
#define HYBOUNCE_UNITS_IMPL_H

#include "hybounce/units.h"

#define UNITS_TOL 1e-9

/* An SI prefix and its factor ("k", 1e3). */
struct unit_prefix {
	const char *name;
	double factor;
};

/* 1 when every exponent (kg, m, s) of a and b agrees within UNITS_TOL,
 * relative for large ones. */
int
units_dim_eq(struct hb_unit_dim a, struct hb_unit_dim b);

#endif
