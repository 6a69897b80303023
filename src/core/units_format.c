/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units_format.c - values written with SI-prefixed units (see units.h):
 * hb_units_format ("3.2 mm", "210 GPa"), the shortest text that reads back
 * to the same double, axis labels, and ranges in messages.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/units.h"
#include "cnum.h"
#include "units_impl.h"

/* Prefixes used for output, mantissa in [1, 1000). */
static const struct unit_prefix out_prefixes[] = {
	{ "f", 1e-15 }, { "p", 1e-12 }, { "n", 1e-9 }, { "u", 1e-6 },
	{ "m", 1e-3 }, { "", 1 }, { "k", 1e3 }, { "M", 1e6 }, { "G", 1e9 },
	{ "T", 1e12 },
};
#define NOUT (sizeof out_prefixes / sizeof out_prefixes[0])

/*
 * Formats v / scale with sig significant digits; returns the rounded
 * mantissa's magnitude so the caller can move to the next prefix.
 */
static double
mantissa(double v, int sig, char *buf, size_t n)
{
	cnum_snprintf(buf, n, "%.*g", sig, v);
	return fabs(cnum_strtod(buf, NULL));
}

/*
 * Formats with a prefix on `base` (e.g. "m", "g"), then `tail` ("/s").
 * The scale is one product (base times prefix), so no intermediate
 * quotient overflows (1e308 kg is not 1e311 g).  A value past the largest
 * prefix is written in the SI unit (m, kg, Pa) with an exponent: 1e+308 kg,
 * not 1e+302 Mg.
 */
static char *
format_prefixed(double value, double base_factor, const char *base, const char *tail,
                int lo, int hi, int sig, char *buf, size_t n)
{
	char mbuf[64];
	double a = fabs(value);
	int k = 5; /* index of "" in out_prefixes */

	if (a != 0 && isfinite(a)) {
		for (k = lo; k < hi; k++)
			if (a < out_prefixes[k + 1].factor * base_factor)
				break;
		if (mantissa(value / (out_prefixes[k].factor * base_factor), sig, mbuf,
		        sizeof mbuf) >= 1000) {
			if (k < hi)
				k++;
			if (mantissa(value / (out_prefixes[k].factor * base_factor), sig, mbuf,
			        sizeof mbuf) >= 1000) /* past the largest prefix: the SI unit */
				for (k = 0; k < (int)NOUT - 1; k++)
					if (fabs(out_prefixes[k].factor * base_factor - 1) < 1e-9)
						break;
		}
	}
	mantissa(value / (out_prefixes[k].factor * base_factor), sig, mbuf, sizeof mbuf);
	snprintf(buf, n, "%s %s%s%s", mbuf, out_prefixes[k].name, base, tail);
	return buf;
}

char *
hb_units_format(double value, struct hb_unit_dim d, int sig, char *buf, size_t n)
{
	static const struct {
		const struct hb_unit_dim *d;
		const char *base, *tail;
		double factor;
		int lo, hi; /* range of out_prefixes indices */
	} simple[] = {
		{ &hb_unit_length, "m", "", 1, 0, 6 },
		{ &hb_unit_time, "s", "", 1, 0, 5 },
		{ &hb_unit_mass, "g", "", 1e-3, 0, 7 },
		{ &hb_unit_force, "N", "", 1, 0, 7 },
		{ &hb_unit_pressure, "Pa", "", 1, 0, 9 },
		{ &hb_unit_energy, "J", "", 1, 0, 7 },
		{ &hb_unit_velocity, "m", "/s", 1, 3, 5 },
	};
	char u[64];

	if (n == 0)
		return buf;
	if (sig < 1)
		sig = 1;
	if (sig > 17)
		sig = 17;
	if (value == 0)
		value = 0; /* -0 is shown as 0: its sign carries nothing */
	d = hb_units_resolve(d, 0, 0);
	if (units_dim_eq(d, hb_unit_none)) {
		cnum_snprintf(buf, n, "%.*g", sig, value);
		return buf;
	}
	for (size_t i = 0; i < sizeof simple / sizeof simple[0]; i++) {
		if (!units_dim_eq(d, *simple[i].d))
			continue;
		if (!isfinite(value)) {
			cnum_snprintf(buf, n, "%g %s%s%s", value, simple[i].factor == 1 ? "" : "k",
			    simple[i].base, simple[i].tail);
			return buf;
		}
		return format_prefixed(value, simple[i].factor, simple[i].base, simple[i].tail,
		    simple[i].lo, simple[i].hi, sig, buf, n);
	}
	hb_units_dim_str(d, u, sizeof u);
	cnum_snprintf(buf, n, "%.*g %s", sig, value, u);
	return buf;
}

char *
hb_units_format_exact(double value, struct hb_unit_dim d, char *buf, size_t n)
{
	char u[64];
	double back;

	for (int sig = 6; sig <= 17; sig++) { /* %g of 6 digits and more: no "2e+01" */
		hb_units_format(value, d, sig, buf, n);
		if (hb_units_parse(buf, hb_units_resolve(d, 0, 0), &back, NULL, 0) == 0 &&
		    memcmp(&back, &value, sizeof back) == 0)
			return buf;
	}
	hb_units_dim_str(d, u, sizeof u);
	cnum_snprintf(buf, n, "%.17g%s%s", value, u[0] ? " " : "", u);
	return buf;
}

double
hb_units_axis(double magnitude, const char *base, char *label, size_t n)
{
	double a = fabs(magnitude), f = 1;
	const char *b = base;
	size_t hl = strcspn(base, " /");
	int k = 5;

	/* A compound unit ("m/s", "N s") takes the prefix on its first factor. */
	if (base[hl] != '\0') {
		char head[16];
		double sc;
		if (hl >= sizeof head)
			hl = sizeof head - 1;
		memcpy(head, base, hl);
		head[hl] = '\0';
		sc = hb_units_axis(magnitude, head, label, n);
		if (strlen(label) + strlen(base + hl) < n)
			strcat(label, base + hl);
		return sc;
	}
	/* A base of "kg" is prefixed as grams. */
	if (strcmp(base, "kg") == 0) {
		b = "g";
		f = 1e-3;
		a /= f;
	}
	if (a != 0 && isfinite(a)) {
		for (k = 0; k < (int)NOUT - 1; k++)
			if (a < out_prefixes[k + 1].factor)
				break;
	}
	snprintf(label, n, "%s%s", out_prefixes[k].name, b);
	return out_prefixes[k].factor * f;
}

int
hb_units_in_range(double v, const struct hb_unit_range *r)
{
	if (isnan(v))
		return 0;
	if (r->lo_open ? !(v > r->lo) : !(v >= r->lo))
		return 0;
	if (r->hi_open ? !(v < r->hi) : !(v <= r->hi))
		return 0;
	return !r->whole || v == floor(v);
}

/* One bound: "inf", "-inf" or %g. */
static void
bound_str(double b, char *buf, size_t n)
{
	if (isinf(b))
		snprintf(buf, n, "%sinf", b < 0 ? "-" : "");
	else
		cnum_snprintf(buf, n, "%g", b);
}

char *
hb_units_range_str(const struct hb_unit_range *r, const struct hb_unit_dim *dim, char *buf, size_t n)
{
	char l[32], h[32], u[64] = "";

	if (n == 0)
		return buf;
	bound_str(r->lo, l, sizeof l);
	bound_str(r->hi, h, sizeof h);
	if (r->whole) {
		if (r->hi >= 2147483647.0) /* INT_MAX and beyond: no bound a user meets */
			snprintf(buf, n, "whole numbers >= %s", l);
		else
			snprintf(buf, n, "whole numbers in [%s, %s]", l, h);
		return buf;
	}
	if (isinf(r->lo) && r->lo < 0 && isinf(r->hi) && r->hi > 0 && r->lo_open && r->hi_open) {
		snprintf(buf, n, "any finite value");
		return buf;
	}
	if (dim != NULL)
		hb_units_dim_str(*dim, u, sizeof u);
	snprintf(buf, n, "%c%s, %s%c%s%s", r->lo_open ? '(' : '[', l, h, r->hi_open ? ')' : ']',
	    u[0] ? " " : "", u);
	return buf;
}
