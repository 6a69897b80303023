/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_units.c - values with units (src/core/units.c): parsing with SI
 * prefixes, products, quotients and fractional powers; the messages of a
 * wrong unit, an unknown unit and a non-number; the unit names printed for
 * a dimension (and that they parse back); formatting with prefixes; axis
 * scales.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <criterion/criterion.h>

#include "hybounce/status.h"
#include "hybounce/units.h"
#include "testutil.h"

static void
dim_is(struct hb_unit_dim d, double kg, double m, double s)
{
	cr_assert(fabs(d.kg - kg) < 1e-12 && fabs(d.m - m) < 1e-12 && fabs(d.s - s) < 1e-12,
	    "dimension kg^%g m^%g s^%g, expected kg^%g m^%g s^%g", d.kg, d.m, d.s, kg, m, s);
}

/* Parses text against dimension d and checks the SI value to 1e-15 relative. */
static void
parses(const char *text, struct hb_unit_dim d, double want)
{
	double v = -12345;
	char msg[256] = "";
	int st = hb_units_parse(text, d, &v, msg, sizeof msg);

	cr_assert_eq(st, HB_OK, "'%s' failed: %s", text, msg);
	if (isinf(want))
		cr_assert(v == want, "'%s' gave %g, expected %g", text, v, want);
	else
		cr_assert(fabs(v - want) <= 1e-15 * fabs(want), "'%s' gave %.17g, expected %.17g",
		    text, v, want);
}

static void
fails(const char *text, struct hb_unit_dim d, const char *part)
{
	double v = 777;
	char msg[256] = "";
	int st = hb_units_parse(text, d, &v, msg, sizeof msg);

	cr_assert_eq(st, HB_EINVAL, "'%s' was accepted", text);
	cr_assert(strstr(msg, part) != NULL, "message for '%s' is \"%s\", lacks \"%s\"", text, msg,
	    part);
	cr_assert_eq(v, 777, "value changed on error");
}

static const struct hb_unit_dim K_HERTZ = { 1, -0.5, -2, 0, 0 };    /* N m^-3/2 */
static const struct hb_unit_dim C_SHC = { 1, -1.5, -1, 0, 0 };      /* N s m^-5/2 */
static const struct hb_unit_dim C_MAXWELL = { 1, 0, -1, 0, 0 };     /* N s/m */
static const struct hb_unit_dim PER_M2 = { 0, -2, 0, 0, 0 };

Test(units, parse_simple_and_prefixed)
{
	parses("20 mm", hb_unit_length, 0.020);
	parses("20mm", hb_unit_length, 0.020);
	parses("  1.5e-3  ", hb_unit_length, 1.5e-3);
	parses("40 um", hb_unit_length, 40e-6);
	parses("40 \xc2\xb5m", hb_unit_length, 40e-6);   /* micro sign */
	parses("40 \xce\xbcm", hb_unit_length, 40e-6);   /* Greek mu */
	parses("2.385 km", hb_unit_length, 2385);
	parses("3 nm", hb_unit_length, 3e-9);
	parses("7 cm", hb_unit_length, 0.07);
	parses("200 GPa", hb_unit_pressure, 200e9);
	parses("0.50 GPa", hb_unit_pressure, 0.5e9);
	parses("3 MPa", hb_unit_pressure, 3e6);
	parses("2 PPa", hb_unit_pressure, 2e15);
	parses("4 mPa", hb_unit_pressure, 4e-3);
	parses("1 Pa", hb_unit_pressure, 1);
	parses("0.2 s", hb_unit_time, 0.2);
	parses("3 ms", hb_unit_time, 3e-3);
	parses("261.4 g", hb_unit_mass, 0.2614);
	parses("1 kg", hb_unit_mass, 1);
	parses("0.5759 N", hb_unit_force, 0.5759);
	parses("2 kN", hb_unit_force, 2000);
	parses("3 J", hb_unit_energy, 3);
	parses("5 mJ", hb_unit_energy, 5e-3);
	parses("120 mm/s", hb_unit_velocity, 0.12);
	parses("-0.5 m/s", hb_unit_velocity, -0.5);
	parses("9.81 m/s^2", hb_unit_accel, 9.81);
	parses("7800 kg/m^3", hb_unit_density, 7800);
	parses("7.8 g/cm^3", hb_unit_density, 7800);
	parses("2 N s", hb_unit_impulse, 2);
	parses("2 N*s", hb_unit_impulse, 2);
	parses("1 kg m/s^2", hb_unit_force, 1);
	parses("1 kg*m*s^-2", hb_unit_force, 1);
}

Test(units, parse_compound_and_fractional_powers)
{
	parses("4.4e3 N s/m", C_MAXWELL, 4.4e3);
	parses("4.4e3 kg/s", C_MAXWELL, 4.4e3);
	parses("2.5e7 N s m^-5/2", C_SHC, 2.5e7);
	parses("2.138e8 N m^-3/2", K_HERTZ, 2.138e8);
	parses("2.138e8 N/m^3/2", K_HERTZ, 2.138e8);
	parses("2.138e8 N m^-1.5", K_HERTZ, 2.138e8);
	parses("5e7 m^-2", PER_M2, 5e7);
}

Test(units, parse_fraction_exponent_value)
{
	/* (1 mm)^-3/2 = 1e4.5 m^-3/2 */
	parses("1 mm^-3/2", (struct hb_unit_dim){ 0, -1.5, 0, 0, 0 }, pow(1e-3, -1.5));
	parses("1 Hz", (struct hb_unit_dim){ 0, 0, -1, 0, 0 }, 1);
	parses("1 s^-1", (struct hb_unit_dim){ 0, 0, -1, 0, 0 }, 1);
	parses("2 kHz", (struct hb_unit_dim){ 0, 0, -1, 0, 0 }, 2000);
	parses("1 W", (struct hb_unit_dim){ 1, 2, -3, 0, 0 }, 1);
}

Test(units, parse_infinity_and_bare_numbers)
{
	parses("inf", hb_unit_length, INFINITY);
	parses("infinity", hb_unit_mass, INFINITY);
	parses("inf m", hb_unit_length, INFINITY);
	parses("-inf N", hb_unit_force, -INFINITY);
	parses("0.35", hb_unit_none, 0.35);
	/* A bare number is SI whatever the dimension. */
	parses("0.02", hb_unit_length, 0.02);
	parses("2e11", hb_unit_pressure, 2e11);
}

Test(units, parse_errors)
{
	fails("abc", hb_unit_length, "'abc' is not a number");
	fails("", hb_unit_length, "empty");
	fails("nan", hb_unit_none, "not a number");
	fails("0x10", hb_unit_none, "not a number");
	fails("1.2.3 m", hb_unit_length, "not a number");
	fails("20 furlong", hb_unit_length, "unknown unit 'furlong'");
	fails("20 m/furlong", hb_unit_velocity, "unknown unit 'furlong'");
	fails("20 mm/s", hb_unit_none, "'20 mm/s' has unit m/s");
	fails("20 mm/s", hb_unit_none, "dimensionless");
	fails("20 mm", hb_unit_pressure, "a pressure");
	fails("20 mm", hb_unit_pressure, "has unit m");
	fails("1 GPa", K_HERTZ, "N m^-3/2");
	fails("3 m^", hb_unit_length, "exponent");
	fails("3 m/s/s", hb_unit_accel, "'/'");
	fails("3 mm2", hb_unit_length, "unknown unit 'mm2'");
}

Test(units, resolve)
{
	struct hb_unit_dim k = { 1, 1, -2, -1, 0 }, beta = { 0, 0, 0, 0, -1 };
	struct hb_unit_dim c = { 1, 0, -1, -1, 0 };

	dim_is(hb_units_resolve(k, 1.5, 2), 1, -0.5, -2);
	dim_is(hb_units_resolve(beta, 1.5, 2), 0, -2, 0);
	dim_is(hb_units_resolve(c, 1.5, 2), 1, -1.5, -1);
	cr_assert_eq(hb_units_resolve(k, 1.5, 2).mp, 0);
}

static void
dim_str_is(struct hb_unit_dim d, const char *want)
{
	char buf[64];

	cr_assert_str_eq(hb_units_dim_str(d, buf, sizeof buf), want);
}

Test(units, dim_str)
{
	dim_str_is(hb_unit_none, "");
	dim_str_is(hb_unit_length, "m");
	dim_str_is(hb_unit_time, "s");
	dim_str_is(hb_unit_mass, "kg");
	dim_str_is(hb_unit_velocity, "m/s");
	dim_str_is(hb_unit_accel, "m/s^2");
	dim_str_is(hb_unit_force, "N");
	dim_str_is(hb_unit_pressure, "Pa");
	dim_str_is(hb_unit_density, "kg/m^3");
	dim_str_is(hb_unit_energy, "J");
	dim_str_is(hb_unit_impulse, "N s");
	dim_str_is(K_HERTZ, "N m^-3/2");
	dim_str_is(C_SHC, "N s m^-5/2");
	dim_str_is(C_MAXWELL, "N s/m");
	dim_str_is((struct hb_unit_dim){ 1, 0, -2, 0, 0 }, "N/m");
	dim_str_is(PER_M2, "m^-2");
}

Test(units, dim_str_parses_back)
{
	const struct hb_unit_dim ds[] = {
		hb_unit_none, hb_unit_length, hb_unit_time, hb_unit_mass, hb_unit_velocity, hb_unit_accel, hb_unit_force,
		hb_unit_pressure, hb_unit_density, hb_unit_energy, hb_unit_impulse, K_HERTZ, C_SHC, C_MAXWELL,
		PER_M2, { 1, -2.7, -2, 0, 0 }, { 0, -3.1, 0, 0, 0 }, { 1, 0, -2, 0, 0 },
		{ 2, 1, -1, 0, 0 }, { 0, 0, -1, 0, 0 }, { 1, 2, -3, 0, 0 },
	};

	for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++) {
		char u[64], text[96], msg[256] = "";
		double v = 0;
		hb_units_dim_str(ds[i], u, sizeof u);
		snprintf(text, sizeof text, "2.385 %s", u);
		cr_assert_eq(hb_units_parse(text, ds[i], &v, msg, sizeof msg), HB_OK,
		    "'%s' does not parse back: %s", text, msg);
		/* SI unit names carry a factor of exactly 1. */
		cr_assert_eq(v, 2.385, "'%s' gave %.17g", text, v);
	}
}

static void
format_is(double v, struct hb_unit_dim d, int sig, const char *want)
{
	char buf[64];

	cr_assert_str_eq(hb_units_format(v, d, sig, buf, sizeof buf), want);
}

Test(units, format)
{
	format_is(0.02, hb_unit_length, 4, "20 mm");
	format_is(40e-6, hb_unit_length, 4, "40 um");
	format_is(3.312e-6, hb_unit_length, 4, "3.312 um");
	format_is(1.5, hb_unit_length, 4, "1.5 m");
	format_is(0.99996, hb_unit_length, 4, "1 m");      /* rounding carries to the next prefix */
	format_is(200e9, hb_unit_pressure, 4, "200 GPa");
	format_is(1.134e9, hb_unit_pressure, 4, "1.134 GPa");
	format_is(0.2614, hb_unit_mass, 4, "261.4 g");
	format_is(2.5, hb_unit_mass, 4, "2.5 kg");
	format_is(0.5759, hb_unit_force, 4, "575.9 mN");
	format_is(0.2, hb_unit_time, 4, "200 ms");
	format_is(0.12, hb_unit_velocity, 4, "120 mm/s");
	format_is(-0.5, hb_unit_velocity, 4, "-500 mm/s");
	format_is(2.5, hb_unit_velocity, 4, "2.5 m/s");
	format_is(0, hb_unit_length, 4, "0 m");
	format_is(-0.0, hb_unit_force, 4, "0 N");           /* no "-0 N" */
	format_is(-0.0, hb_unit_none, 4, "0");
	format_is(INFINITY, hb_unit_length, 4, "inf m");
	format_is(INFINITY, hb_unit_mass, 4, "inf kg");
	format_is(0.35, hb_unit_none, 4, "0.35");
	format_is(2.138e8, K_HERTZ, 4, "2.138e+08 N m^-3/2");
	format_is(4400, C_MAXWELL, 4, "4400 N s/m");
	format_is(9.81, hb_unit_accel, 4, "9.81 m/s^2");
}

/* Values past the largest prefix: the SI unit with an exponent, never inf. */
Test(units, format_extreme)
{
	char buf[64];
	double v;

	format_is(1e308, hb_unit_mass, 4, "1e+308 kg");
	format_is(-1e308, hb_unit_mass, 4, "-1e+308 kg");
	format_is(DBL_MAX, hb_unit_mass, 4, "1.798e+308 kg");
	format_is(1e308, hb_unit_length, 4, "1e+308 m");
	format_is(1e308, hb_unit_pressure, 4, "1e+308 Pa");
	format_is(1e308, hb_unit_velocity, 4, "1e+308 m/s");
	format_is(2.5e3, hb_unit_mass, 4, "2.5 Mg");       /* within the prefixes: unchanged */
	format_is(2.5e6, hb_unit_mass, 4, "2.5e+06 kg");
	format_is(4e-300, hb_unit_mass, 4, "4e-282 fg");
	cr_assert_str_eq(hb_units_format_exact(1e308, hb_unit_mass, buf, sizeof buf), "1e+308 kg");
	cr_assert_eq(hb_units_parse(buf, hb_unit_mass, &v, NULL, 0), HB_OK);
	cr_assert_eq(v, 1e308);
	hb_units_format_exact(DBL_MAX, hb_unit_mass, buf, sizeof buf);
	cr_assert_eq(hb_units_parse(buf, hb_unit_mass, &v, NULL, 0), HB_OK, "%s", buf);
	cr_assert_eq(v, DBL_MAX, "%s", buf);
}

Test(units, axis)
{
	char label[16];
	double s;

	s = hb_units_axis(0.02, "m", label, sizeof label);
	cr_assert_eq(s, 1e-3);
	cr_assert_str_eq(label, "mm");
	s = hb_units_axis(3.3e-6, "m", label, sizeof label);
	cr_assert_eq(s, 1e-6);
	cr_assert_str_eq(label, "um");
	s = hb_units_axis(2.5e5, "N", label, sizeof label);
	cr_assert_eq(s, 1e3);
	cr_assert_str_eq(label, "kN");
	s = hb_units_axis(5, "s", label, sizeof label);
	cr_assert_eq(s, 1);
	cr_assert_str_eq(label, "s");
	s = hb_units_axis(0, "J", label, sizeof label);
	cr_assert_eq(s, 1);
	cr_assert_str_eq(label, "J");
	s = hb_units_axis(0.2614, "kg", label, sizeof label);
	assert_abs(s, 1e-3, 1e-18);
	cr_assert_str_eq(label, "g");
}

Test(units, format_exact_reads_back)
{
	static const double v[] = { 0.02, 0.3, 1.0 / 3.0, 2.13777e8, 7800, 1e-300, 123456789.123,
		-0.1e-3, 4.4e3, 0 };
	const struct hb_unit_dim *dims[] = { &hb_unit_length, &hb_unit_none, &hb_unit_pressure, &hb_unit_density,
		&hb_unit_velocity, &hb_unit_mass };
	char buf[64], msg[128];

	for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
		for (size_t d = 0; d < sizeof dims / sizeof dims[0]; d++) {
			double back;
			hb_units_format_exact(v[i], *dims[d], buf, sizeof buf);
			cr_assert_eq(hb_units_parse(buf, *dims[d], &back, msg, sizeof msg), 0, "%s: %s",
			    buf, msg);
			cr_assert(back == v[i], "'%s' reads back as %.17g, not %.17g", buf, back, v[i]);
		}
	hb_units_format_exact(0.02, hb_unit_length, buf, sizeof buf);
	cr_assert_str_eq(buf, "20 mm");
}

Test(units, range_str)
{
	struct hb_unit_range r = { 0, HUGE_VAL, 1, 1, 0 }, w = { 2, 2147483647.0, 0, 0, 1 };
	struct hb_unit_range any = { -HUGE_VAL, HUGE_VAL, 1, 1, 0 }, inf = { 0, HUGE_VAL, 1, 0, 0 };
	char buf[64];

	cr_assert_str_eq(hb_units_range_str(&r, &hb_unit_time, buf, sizeof buf), "(0, inf) s");
	cr_assert_str_eq(hb_units_range_str(&r, NULL, buf, sizeof buf), "(0, inf)");
	cr_assert_str_eq(hb_units_range_str(&inf, &hb_unit_length, buf, sizeof buf), "(0, inf] m");
	cr_assert_str_eq(hb_units_range_str(&w, NULL, buf, sizeof buf), "whole numbers >= 2");
	cr_assert_str_eq(hb_units_range_str(&any, &hb_unit_force, buf, sizeof buf), "any finite value");
	cr_assert(hb_units_in_range(HUGE_VAL, &inf));
	cr_assert(!hb_units_in_range(HUGE_VAL, &r));
	cr_assert(!hb_units_in_range(NAN, &any));
	cr_assert(!hb_units_in_range(2.5, &w));
	cr_assert(hb_units_in_range(3, &w));
}

/* An exponent far beyond INT_MAX is written with its digits (no cast to int). */
Test(units, huge_exponent_is_written)
{
	struct hb_unit_dim d = { 0, -4e97, 0, 0, 0 };
	char buf[64], want[64];

	hb_units_dim_str(d, buf, sizeof buf);
	snprintf(want, sizeof want, "m^%.17g", -4e97);
	cr_assert_str_eq(buf, want);
}

/* Issue 10 item 4: an exponent beyond int was cast to int (undefined). */
Test(units, absurd_exponents)
{
	char msg[256], buf[64];
	double v;
	struct hb_unit_dim huge = { 0, 3e9, 0, 0, 0 }, big = { 0, -4e97, 0, 0, 0 };

	cr_assert_eq(hb_units_parse("1 m^-4e97", hb_unit_length, &v, msg, sizeof msg), HB_EINVAL);
	cr_assert(strstr(msg, "m^-4.0000000000000003e+97") != NULL, "%s", msg);
	cr_assert(strstr(msg, "a length (e.g. mm) is expected") != NULL, "%s", msg);
	cr_assert_eq(hb_units_parse("1 m^1e400", hb_unit_length, &v, msg, sizeof msg), HB_EINVAL);
	cr_assert_eq(hb_units_parse("1 m^2e15", hb_unit_length, &v, msg, sizeof msg), HB_EINVAL);
	cr_assert_eq(hb_units_parse("1 m^3000000000/3000000000", hb_unit_length, &v, msg, sizeof msg),
	             HB_OK);
	cr_assert_eq(v, 1.0);
	/* what hb_units_dim_str writes for law.n = 3e9 reads back */
	cr_assert_eq(hb_units_parse("2 m^3000000000", huge, &v, msg, sizeof msg), HB_OK, "%s", msg);
	cr_assert_eq(v, 2.0);
	/* dimensions derived from law.n = 3e9 print without a cast */
	cr_assert_str_eq(hb_units_dim_str(huge, buf, sizeof buf), "m^3000000000");
	hb_units_dim_str(big, buf, sizeof buf);
	cr_assert(strstr(buf, "e+97") != NULL, "%s", buf);
}
