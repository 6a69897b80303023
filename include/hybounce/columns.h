/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * columns.h - the table of collision columns: name, unit and meaning of
 * each observable of struct hb_collision (paper eqs. t_d .. Lambda).  The CSV
 * header (--collisions), the batch table, the explorer's table, the man
 * page and the README all come from it.
 */
#ifndef HB_COLUMNS_H
#define HB_COLUMNS_H

#include <stddef.h>

#include "collisions.h"
#include "export.h"
HB_BEGIN_DECLS

enum {
	HB_COLUMN_BATCH = 1,    /* shown in the batch report's table */
	HB_COLUMN_EXPLORER = 2, /* shown in the explorer's table */
};

struct hb_collision_column {
	const char *name;    /* CSV header: "x_c_max" */
	const char *label;   /* tables: "x_c^max" */
	const char *unit;    /* SI unit: "m", "m/s", "N s"; "" for a pure number */
	const char *meaning; /* "greatest indentation" */
	int index;           /* 1: the collision index i (a whole number) */
	size_t off;          /* offset of the double in struct hb_collision */
	int shown;           /* COLUMN_* */
};

/* The columns, in CSV order. */
extern const struct hb_collision_column hb_collision_columns[];
extern const int hb_collision_ncolumns;

/* The column named (CSV name or label), or NULL. */
const struct hb_collision_column *
hb_collision_column_find(const char *name);

/* The value of a column in a collision (i as a double). */
double
hb_collision_value(const struct hb_collision *c, const struct hb_collision_column *col);

HB_END_DECLS

#endif
