/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units.c - values with SI-prefixed units, in and out (see units.h).
 *
 * A unit is a product of factors SYMBOL[^EXPONENT], separated by spaces or
 * '*'; everything right of the first '/' that is not part of an exponent
 * is in the denominator.  A factor is a symbol (m g s N Pa J W Hz), or a
 * prefix followed by a symbol; a token that is itself a symbol is that
 * symbol (longest match: "m" is the metre, "mm" the millimetre, "Pa" the
 * pascal, "PPa" the petapascal).  Exponents are integers, decimals or
 * fractions ("m^-5/2"): after '^', a '/' followed by a digit continues the
 * exponent.
 *
 * Dimensions are exponents of kg, m and s; two dimensions are equal when
 * every exponent agrees within 1e-9.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/status.h"
#include "hybounce/units.h"
#include "cnum.h"

const struct hb_unit_dim hb_unit_none = { 0, 0, 0, 0, 0 };
const struct hb_unit_dim hb_unit_length = { 0, 1, 0, 0, 0 };
const struct hb_unit_dim hb_unit_time = { 0, 0, 1, 0, 0 };
const struct hb_unit_dim hb_unit_mass = { 1, 0, 0, 0, 0 };
const struct hb_unit_dim hb_unit_velocity = { 0, 1, -1, 0, 0 };
const struct hb_unit_dim hb_unit_accel = { 0, 1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_force = { 1, 1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_pressure = { 1, -1, -2, 0, 0 };
const struct hb_unit_dim hb_unit_density = { 1, -3, 0, 0, 0 };
const struct hb_unit_dim hb_unit_energy = { 1, 2, -2, 0, 0 };
const struct hb_unit_dim hb_unit_impulse = { 1, 1, -1, 0, 0 };

#define UNITS_TOL 1e-9

struct symbol {
	const char *name;
	double factor; /* SI value of one unit */
	double kg, m, s;
};

static const struct symbol symbols[] = {
	{ "m", 1, 0, 1, 0 },
	{ "g", 1e-3, 1, 0, 0 },
	{ "s", 1, 0, 0, 1 },
	{ "N", 1, 1, 1, -2 },
	{ "Pa", 1, 1, -1, -2 },
	{ "J", 1, 1, 2, -2 },
	{ "W", 1, 1, 2, -3 },
	{ "Hz", 1, 0, 0, -1 },
};
#define NSYMBOLS (sizeof symbols / sizeof symbols[0])

struct prefix {
	const char *name;
	double factor;
};

static const struct prefix prefixes[] = {
	{ "y", 1e-24 }, { "z", 1e-21 }, { "a", 1e-18 }, { "f", 1e-15 },
	{ "p", 1e-12 }, { "n", 1e-9 }, { "u", 1e-6 },
	{ "\xc2\xb5", 1e-6 }, /* U+00B5 MICRO SIGN */
	{ "\xce\xbc", 1e-6 }, /* U+03BC GREEK SMALL LETTER MU */
	{ "m", 1e-3 }, { "c", 1e-2 }, { "d", 1e-1 },
	{ "k", 1e3 }, { "M", 1e6 }, { "G", 1e9 }, { "T", 1e12 }, { "P", 1e15 },
};
#define NPREFIXES (sizeof prefixes / sizeof prefixes[0])

/* Prefixes used for output, mantissa in [1, 1000). */
static const struct prefix out_prefixes[] = {
	{ "f", 1e-15 }, { "p", 1e-12 }, { "n", 1e-9 }, { "u", 1e-6 },
	{ "m", 1e-3 }, { "", 1 }, { "k", 1e3 }, { "M", 1e6 }, { "G", 1e9 },
	{ "T", 1e12 },
};
#define NOUT (sizeof out_prefixes / sizeof out_prefixes[0])

struct hb_unit_dim
hb_units_resolve(struct hb_unit_dim d, double p, double n)
{
	struct hb_unit_dim r = d;

	r.m = d.m + d.mp * p + d.mn * n;
	r.mp = 0;
	r.mn = 0;
	return r;
}

/* Exponents agree within 1e-9, relative for large ones (m^-1e17 and m^(1 - 1e17)). */
static int
exp_eq(double a, double b)
{
	return fabs(a - b) < UNITS_TOL * fmax(1.0, fmax(fabs(a), fabs(b)));
}

static int
dim_eq(struct hb_unit_dim a, struct hb_unit_dim b)
{
	return exp_eq(a.kg, b.kg) && exp_eq(a.m, b.m) && exp_eq(a.s, b.s);
}

static const struct symbol *
symbol_find(const char *tok, size_t len)
{
	for (size_t i = 0; i < NSYMBOLS; i++)
		if (strlen(symbols[i].name) == len && strncmp(symbols[i].name, tok, len) == 0)
			return &symbols[i];
	return NULL;
}

/*
 * Resolves a token without exponent ("mm", "GPa", "kg") into its SI factor
 * and dimension.  Returns 0 or -1 if unknown.
 */
static int
token_resolve(const char *tok, size_t len, double *factor, struct hb_unit_dim *d)
{
	const struct symbol *sym = symbol_find(tok, len);
	double pf = 1;

	if (sym == NULL) {
		for (size_t i = 0; i < NPREFIXES && sym == NULL; i++) {
			size_t pl = strlen(prefixes[i].name);
			if (pl < len && strncmp(tok, prefixes[i].name, pl) == 0) {
				sym = symbol_find(tok + pl, len - pl);
				pf = prefixes[i].factor;
			}
		}
	}
	if (sym == NULL)
		return -1;
	*factor = pf * sym->factor;
	d->kg = sym->kg;
	d->m = sym->m;
	d->s = sym->s;
	d->mp = d->mn = 0;
	return 0;
}

/* Parses an exponent at *pp ("-5/2", "3", "0.5").  Returns 0 or -1. */
static int
exponent_parse(const char **pp, double *e)
{
	const char *p = *pp;
	char *end;
	double num, den = 1;

	if (!(cnum_isdigit((unsigned char)*p) || ((*p == '-' || *p == '+') &&
	    (cnum_isdigit((unsigned char)p[1]) || p[1] == '.')) || *p == '.'))
		return -1;
	num = cnum_strtod(p, &end);
	if (end == p)
		return -1;
	p = end;
	if (*p == '/' && cnum_isdigit((unsigned char)p[1])) {
		den = cnum_strtod(p + 1, &end);
		if (den == 0)
			return -1;
		p = end;
	}
	*e = num / den;
	*pp = p;
	return 0;
}

/*
 * Parses a unit string into an SI factor and a dimension.  On error writes
 * a message and returns HB_EINVAL.
 */
static int
unit_parse(const char *text, double *factor, struct hb_unit_dim *dim, char *msg, size_t n)
{
	const char *p = text;
	int denom = 0;
	double f = 1;
	struct hb_unit_dim d = { 0, 0, 0, 0, 0 };

	for (;;) {
		const char *tok;
		size_t len;
		double tf, e = 1, sign;
		struct hb_unit_dim td;

		while (*p == ' ' || *p == '\t' || *p == '*' || *p == '/') {
			if (*p == '/') {
				if (denom)
					return hb_status_set(msg, n, HB_EINVAL,
					    "unit '%s' has more than one '/'", text);
				denom = 1;
			}
			p++;
		}
		if (*p == '\0')
			break;
		tok = p;
		while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '*' && *p != '/' &&
		    *p != '^')
			p++;
		len = (size_t)(p - tok);
		if (len == 0 || token_resolve(tok, len, &tf, &td) != 0) {
			while (*p != '\0' && *p != ' ' && *p != '\t' && *p != '*' && *p != '/')
				p++;
			return hb_status_set(msg, n, HB_EINVAL,
			    "unknown unit '%.*s'; known units: m, g, s, N, Pa, J, W, Hz "
			    "with SI prefixes (e.g. mm, kg, GPa)", (int)(p - tok), tok);
		}
		if (*p == '^') {
			p++;
			if (exponent_parse(&p, &e) != 0)
				return hb_status_set(msg, n, HB_EINVAL,
				    "bad exponent in unit '%s' (expected e.g. m^3, m^-5/2)", text);
		}
		sign = denom ? -1 : 1;
		f *= pow(tf, sign * e);
		d.kg += sign * e * td.kg;
		d.m += sign * e * td.m;
		d.s += sign * e * td.s;
		if (*p != '\0' && *p != ' ' && *p != '\t' && *p != '*' && *p != '/')
			return hb_status_set(msg, n, HB_EINVAL, "malformed unit '%s'", text);
	}
	*factor = f;
	*dim = d;
	return HB_OK;
}

/* A name for a dimension in messages: "a length", "a value in N s m^-5/2". */
static void
dim_describe(struct hb_unit_dim d, char *buf, size_t n)
{
	static const struct {
		const struct hb_unit_dim *d;
		const char *name, *eg;
	} names[] = {
		{ &hb_unit_none, "a dimensionless value", "0.35" },
		{ &hb_unit_length, "a length", "mm" },
		{ &hb_unit_time, "a time", "ms" },
		{ &hb_unit_mass, "a mass", "kg" },
		{ &hb_unit_velocity, "a velocity", "m/s" },
		{ &hb_unit_accel, "an acceleration", "m/s^2" },
		{ &hb_unit_force, "a force", "N" },
		{ &hb_unit_pressure, "a pressure", "GPa" },
		{ &hb_unit_density, "a density", "kg/m^3" },
		{ &hb_unit_energy, "an energy", "J" },
		{ &hb_unit_impulse, "an impulse", "N s" },
	};
	char u[64];

	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
		if (dim_eq(d, *names[i].d)) {
			if (i == 0)
				snprintf(buf, n, "%s", names[i].name);
			else
				snprintf(buf, n, "%s (e.g. %s)", names[i].name, names[i].eg);
			return;
		}
	}
	snprintf(buf, n, "a value in %s", hb_units_dim_str(d, u, sizeof u));
}

int
hb_units_parse(const char *text, struct hb_unit_dim expect, double *value, char *msg, size_t n)
{
	const char *p = text;
	char *end;
	double v, factor = 1;
	struct hb_unit_dim d = { 0, 0, 0, 0, 0 };
	int st;

	while (cnum_isspace((unsigned char)*p))
		p++;
	if (*p == '\0')
		return hb_status_set(msg, n, HB_EINVAL, "empty value");
	v = cnum_strtod(p, &end);
	/* strtod also reads "nan" and hexadecimal; refuse those. */
	if (end == p || isnan(v) || memchr(p, 'x', (size_t)(end - p)) != NULL ||
	    memchr(p, 'X', (size_t)(end - p)) != NULL)
		return hb_status_set(msg, n, HB_EINVAL, "'%s' is not a number", text);
	p = end;
	while (cnum_isspace((unsigned char)*p))
		p++;
	if (*p == '\0') {
		/* A bare number is taken as SI, whatever the expected dimension. */
		*value = v;
		return HB_OK;
	}
	{
		char ubuf[128];
		size_t len = strlen(p);

		while (len > 0 && cnum_isspace((unsigned char)p[len - 1]))
			len--;
		if (len >= sizeof ubuf)
			return hb_status_set(msg, n, HB_EINVAL, "unit of '%s' too long", text);
		memcpy(ubuf, p, len);
		ubuf[len] = '\0';
		if (!cnum_isalpha((unsigned char)ubuf[0]) && (unsigned char)ubuf[0] < 0x80)
			return hb_status_set(msg, n, HB_EINVAL, "'%s' is not a number", text);
		st = unit_parse(ubuf, &factor, &d, msg, n);
		if (st != HB_OK)
			return st;
	}
	if (!dim_eq(d, expect)) {
		char have[64], want[96];

		hb_units_dim_str(d, have, sizeof have);
		dim_describe(expect, want, sizeof want);
		if (have[0] == '\0')
			return hb_status_set(msg, n, HB_EINVAL,
			    "'%s' has no dimension but %s is expected", text, want);
		return hb_status_set(msg, n, HB_EINVAL, "'%s' has unit %s but %s is expected",
		    text, have, want);
	}
	*value = v * factor;
	return HB_OK;
}

/*
 * Writes an exponent: "2", "-5/2", or all the digits that read back to the
 * same double ("1.23456789", "3000000000"), so that a unit written for a
 * law's exponent parses back to the same dimension.  "%.0f", never a cast
 * to int: an exponent may be far beyond INT_MAX.
 */
static void
exp_str(double e, char *buf, size_t n)
{
	double r2 = round(2 * e);

	if (fabs(e - round(e)) < UNITS_TOL && fabs(e) < 1e15)
		cnum_snprintf(buf, n, "%.0f", round(e) == 0 ? 0.0 : round(e));
	else if (fabs(2 * e - r2) < UNITS_TOL && fabs(e) < 1e15)
		cnum_snprintf(buf, n, "%.0f/2", r2);
	else
		cnum_snprintf(buf, n, "%.17g", e);
}

static void
append(char *buf, size_t n, const char *s)
{
	size_t l = strlen(buf);

	if (l + 1 < n)
		snprintf(buf + l, n - l, "%s", s);
}

/* Appends " SYM^E" (or "SYM" when e == 1) to buf. */
static void
append_factor(char *buf, size_t n, const char *sym, double e)
{
	char es[32];

	if (buf[0] != '\0' && buf[strlen(buf) - 1] != '/')
		append(buf, n, " ");
	append(buf, n, sym);
	if (fabs(e - 1) >= UNITS_TOL) {
		exp_str(e, es, sizeof es);
		append(buf, n, "^");
		append(buf, n, es);
	}
}

static int
is_zero(double e)
{
	return fabs(e) < UNITS_TOL;
}

static int
is_int(double e)
{
	return fabs(e - round(e)) < UNITS_TOL;
}

char *
hb_units_dim_str(struct hb_unit_dim d, char *buf, size_t n)
{
	static const struct {
		const char *name;
		double kg, m, s;
	} named[] = {
		{ "N", 1, 1, -2 }, { "Pa", 1, -1, -2 }, { "J", 1, 2, -2 }, { "W", 1, 2, -3 },
	};
	const char *sym[3];
	double e[3];
	int nf = 3, useN = 0;

	if (n == 0)
		return buf;
	buf[0] = '\0';
	d = hb_units_resolve(d, 0, 0);
	for (size_t i = 0; i < sizeof named / sizeof named[0]; i++) {
		struct hb_unit_dim nd = { named[i].kg, named[i].m, named[i].s, 0, 0 };
		if (dim_eq(d, nd)) {
			append(buf, n, named[i].name);
			return buf;
		}
	}
	/* N when the dimension holds kg m s^-2 and the rest reads well. */
	if (fabs(d.kg - 1) < UNITS_TOL && (fabs(d.s + 2) < UNITS_TOL || fabs(d.s + 1) < UNITS_TOL))
		useN = 1;
	if (useN) {
		sym[0] = "N", e[0] = 1;
		sym[1] = "s", e[1] = d.s + 2;
		sym[2] = "m", e[2] = d.m - 1;
	} else {
		sym[0] = "kg", e[0] = d.kg;
		sym[1] = "m", e[1] = d.m;
		sym[2] = "s", e[2] = d.s;
	}
	/*
	 * Positive exponents first; negative integer exponents after one '/'
	 * when there is a numerator and every negative exponent is an
	 * integer; otherwise negative exponents inline ("N s m^-5/2").
	 */
	int npos = 0, nneg = 0, negint = 1;
	for (int i = 0; i < nf; i++) {
		if (is_zero(e[i]))
			continue;
		if (e[i] > 0)
			npos++;
		else {
			nneg++;
			if (!is_int(e[i]))
				negint = 0;
		}
	}
	for (int i = 0; i < nf; i++)
		if (!is_zero(e[i]) && e[i] > 0)
			append_factor(buf, n, sym[i], e[i]);
	if (nneg == 0)
		return buf;
	if (npos > 0 && negint) {
		append(buf, n, "/");
		for (int i = 0; i < nf; i++)
			if (!is_zero(e[i]) && e[i] < 0)
				append_factor(buf, n, sym[i], -e[i]);
	} else {
		for (int i = 0; i < nf; i++)
			if (!is_zero(e[i]) && e[i] < 0)
				append_factor(buf, n, sym[i], e[i]);
	}
	return buf;
}

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
	if (dim_eq(d, hb_unit_none)) {
		cnum_snprintf(buf, n, "%.*g", sig, value);
		return buf;
	}
	for (size_t i = 0; i < sizeof simple / sizeof simple[0]; i++) {
		if (!dim_eq(d, *simple[i].d))
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
