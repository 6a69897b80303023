/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * batch_text.c - how the batch report writes (batch_report.h): a value
 * with its unit, and a paragraph wrapped at 79 columns.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/units.h"

#include "batch_report.h"

/* A value with its unit, 6 significant digits, into buf. */
const char *
batch_fmt(double v, struct hb_unit_dim d, char *buf, size_t n)
{
	if (isinf(v))
		snprintf(buf, n, "%s", v > 0 ? "inf" : "-inf");
	else if (isnan(v))
		snprintf(buf, n, "-");
	else
		hb_units_format(v, d, 6, buf, n);
	return buf;
}

/*
 * Prints text word-wrapped to 79 columns, every line starting with indent
 * (the first line too).
 */
void
batch_print_wrapped(FILE *out, const char *indent, const char *text)
{
	const int width = 79 - (int)strlen(indent);
	const char *p = text;

	while (*p != '\0') {
		int len = (int)strlen(p), cut = len;

		if (len > width) {
			cut = width;
			while (cut > 0 && p[cut] != ' ')
				cut--;
			if (cut == 0) /* one long word */
				for (cut = width; p[cut] != '\0' && p[cut] != ' '; cut++)
					;
		}
		fprintf(out, "%s%.*s\n", indent, cut, p);
		p += cut;
		while (*p == ' ')
			p++;
	}
}
