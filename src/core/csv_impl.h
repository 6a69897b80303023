/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * csv_impl.h - the CSV field and number writers that csv.c's collision
 * tables and sweep.c's runs table share (private to the engine).
 */
#ifndef HYBOUNCE_CSV_IMPL_H
#define HYBOUNCE_CSV_IMPL_H

#include <stdio.h>

/* Writes the field s, quoted as RFC 4180 asks when it holds a comma, a
 * quote or a line break (a quote inside is doubled); no separator. */
void
csv_put_field(FILE *f, const char *s);

/* Writes a separator, then v as %.17g (a negative zero as 0); NaN (unknown)
 * as an empty field. */
void
csv_put_num(FILE *f, double v);

#endif
