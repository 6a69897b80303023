/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units.c - values with SI-prefixed units read from text (see units.h).
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
 * Dimensions are exponents of kg, m and s (units_dim.c); values are
 * written back with prefixes by units_format.c.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/status.h"
#include "hybounce/units.h"
#include "cnum.h"
#include "units_impl.h"

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

static const struct unit_prefix prefixes[] = {
	{ "y", 1e-24 }, { "z", 1e-21 }, { "a", 1e-18 }, { "f", 1e-15 },
	{ "p", 1e-12 }, { "n", 1e-9 }, { "u", 1e-6 },
	{ "\xc2\xb5", 1e-6 }, /* U+00B5 MICRO SIGN */
	{ "\xce\xbc", 1e-6 }, /* U+03BC GREEK SMALL LETTER MU */
	{ "m", 1e-3 }, { "c", 1e-2 }, { "d", 1e-1 },
	{ "k", 1e3 }, { "M", 1e6 }, { "G", 1e9 }, { "T", 1e12 }, { "P", 1e15 },
};
#define NPREFIXES (sizeof prefixes / sizeof prefixes[0])
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
		if (units_dim_eq(d, *names[i].d)) {
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
	if (!units_dim_eq(d, expect)) {
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
