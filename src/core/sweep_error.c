/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sweep_error.c - a sweep with error bars (sweep.h: hb_sweep_set_error):
 * the flag and its line in the spec.  The estimate itself is error.c's,
 * called for each point by sweep.c.
 */
#include <string.h>

#include "hybounce/sweep.h"
#include "sweep_impl.h"

void
hb_sweep_set_error(struct hb_sweep *sw, int on)
{
	sw->error = on != 0;
}

int
hb_sweep_error(const struct hb_sweep *sw)
{
	return sw->error;
}

void
hb_sweep_error_from_preset(struct hb_sweep *sw, const char *text)
{
	const size_t tl = strlen(SWEEP_ERROR_LINE);
	const char *p = text;

	while (*p) {
		const char *end = strchr(p, '\n');
		size_t full = end ? (size_t)(end - p) : strlen(p), len = full;

		while (len > tl && (p[len - 1] == ' ' || p[len - 1] == '\t' || p[len - 1] == '\r'))
			len--;
		if (len == tl && strncmp(p, SWEEP_ERROR_LINE, tl) == 0)
			sw->error = 1;
		p = end ? end + 1 : p + full;
	}
}
