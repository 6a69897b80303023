/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * csv_impl.h - the CSV field and number writers that csv.c's collision
 * tables and sweep.c's runs table share, and the path of the scene written
 * beside an export (private to the engine; the front ends' --bodies uses it).
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

/* PATH with the extension of its last component replaced by ".preset", into
 * out (n bytes): the scene written beside an export.  0, or -1 if too long. */
int
csv_scene_path(const char *path, char *out, size_t n);

#endif
