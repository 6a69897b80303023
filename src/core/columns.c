/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * columns.c - the table of collision columns (see columns.h), and its
 * reference text for the man page and the README.
 */
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/columns.h"

#include "docs.h"
#include "textbuf.h"

#define V(f) 0, offsetof(struct hb_collision, f)
#define BOTH (HB_COLUMN_BATCH | HB_COLUMN_EXPLORER)

const struct hb_collision_column hb_collision_columns[] = {
	{ "i", "i", "", "index, from 0", 1, 0, BOTH },
	{ "t_e", "t_e", "s", "commencement", V(te), BOTH },
	{ "t_s", "t_s", "s", "separation", V(ts), HB_COLUMN_BATCH },
	{ "t_d", "t_d", "s", "duration t_s - t_e", V(td), BOTH },
	{ "t_f", "t_f", "s", "the flight that follows (empty until known)", V(tf), HB_COLUMN_BATCH },
	{ "v_i", "v_i", "m/s", "approach velocity (negative)", V(vi), BOTH },
	{ "e", "e", "", "coefficient of restitution -v(t_s) / v_i", V(e), BOTH },
	{ "x_c_max", "x_c^max", "m", "greatest indentation", V(xcmax), BOTH },
	{ "F_c_max", "F_c^max", "N", "greatest contact force", V(Fcmax), BOTH },
	{ "x_c_r", "x_c^r", "m", "residual indentation |x_c(t_s)|", V(xcr), BOTH },
	{ "W", "W", "J", "work -int F_c v dt", V(W), HB_COLUMN_BATCH },
	{ "J_Fc", "J_Fc", "N s", "impulse of the contact force", V(JFc), 0 },
	{ "J_Fe", "J_Fe", "N s", "impulse of the applied force", V(JFe), 0 },
	{ "Lambda", "Lambda", "", "J_Fe / J_Fc", V(Lambda), BOTH },
};
const int hb_collision_ncolumns = (int)(sizeof hb_collision_columns / sizeof hb_collision_columns[0]);

const struct hb_collision_column *
hb_collision_column_find(const char *name)
{
	for (int i = 0; i < hb_collision_ncolumns; i++)
		if (strcmp(hb_collision_columns[i].name, name) == 0 ||
		    strcmp(hb_collision_columns[i].label, name) == 0)
			return &hb_collision_columns[i];
	return NULL;
}

double
hb_collision_value(const struct hb_collision *c, const struct hb_collision_column *col)
{
	if (col->index)
		return (double)c->i;
	return *(const double *)((const char *)c + col->off);
}

size_t
collision_columns_mdoc(char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };

	if (buf != NULL && n > 0)
		buf[0] = '\0';
	textbuf_printf(&o, ".Bl -tag -width \"F_c_max\" -compact\n");
	for (int i = 0; i < hb_collision_ncolumns; i++) {
		const struct hb_collision_column *c = &hb_collision_columns[i];
		textbuf_printf(&o, ".It Li %s\n%s%s%s\n", c->name, c->meaning, c->unit[0] ? ", " : "",
		    c->unit);
	}
	textbuf_printf(&o, ".El\n");
	return o.len;
}

size_t
collision_columns_markdown(char *buf, size_t n)
{
	struct textbuf o = { buf, n, 0 };

	if (buf != NULL && n > 0)
		buf[0] = '\0';
	textbuf_printf(&o, "| column | meaning | unit |\n|---|---|---|\n");
	for (int i = 0; i < hb_collision_ncolumns; i++) {
		const struct hb_collision_column *c = &hb_collision_columns[i];
		textbuf_printf(&o, "| `%s` | ", c->name);
		for (const char *m = c->meaning; *m; m++) /* a '|' would end the cell */
			textbuf_printf(&o, "%s%c", *m == '|' ? "\\" : "", *m);
		textbuf_printf(&o, " | %s |\n", c->unit[0] ? c->unit : "–");
	}
	return o.len;
}
