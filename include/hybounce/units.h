/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * units.h - values with SI-prefixed units, in and out.
 *
 * Input: "20 mm", "200 GPa", "7800 kg/m^3", "4.4e3 N s/m",
 * "2.5e7 N s m^-5/2", "9.81 m/s^2", "40 um" (also "µm"), "1.5e-3".
 * A bare number is taken as SI.  Units: m, g, s, N, Pa, J, W, Hz, with the
 * prefixes y z a f p n u µ m c d k M G T P; products by space or '*',
 * quotients by '/', powers by '^' with an integer or fraction exponent
 * (m^-5/2, m^3).  Everything right of the first '/' is in the denominator,
 * as in "N s/m" or "kg/m^3".
 *
 * Output: hb_units_format() picks the SI prefix that puts the mantissa in
 * [1, 1000) for the expected dimension's base unit.
 */
#ifndef HB_UNITS_H
#define HB_UNITS_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>

/*
 * Physical dimension of a quantity as exponents of kg, m and s.  The metre
 * exponent may depend on a contact law's exponents p and n:
 *     m exponent = m + mp * p + mn * n
 * (e.g. k of a Hertz-type term, N m^-p: kg = 1, m = 1, mp = -1, s = -2).
 */
struct hb_unit_dim {
	double kg, m, s;
	double mp, mn;
};

/*
 * An admissible range: lo .. hi, each bound excluded when its *_open is 1
 * ([0, inf] admits inf, [0, inf) does not); whole = 1 for whole numbers.
 */
struct hb_unit_range {
	double lo, hi;
	int lo_open, hi_open;
	int whole;
};

/* Dimensions used by scenes (p and n terms zero). */
extern const struct hb_unit_dim hb_unit_none;     /* dimensionless */
extern const struct hb_unit_dim hb_unit_length;   /* m */
extern const struct hb_unit_dim hb_unit_time;     /* s */
extern const struct hb_unit_dim hb_unit_mass;     /* kg */
extern const struct hb_unit_dim hb_unit_velocity; /* m/s */
extern const struct hb_unit_dim hb_unit_accel;    /* m/s^2 */
extern const struct hb_unit_dim hb_unit_force;    /* N */
extern const struct hb_unit_dim hb_unit_pressure; /* Pa */
extern const struct hb_unit_dim hb_unit_density;  /* kg/m^3 */
extern const struct hb_unit_dim hb_unit_energy;   /* J */
extern const struct hb_unit_dim hb_unit_impulse;  /* N s */

/*
 * Resolves a dimension that depends on p and n into plain exponents.
 */
struct hb_unit_dim
hb_units_resolve(struct hb_unit_dim d, double p, double n);

/*
 * Parses "NUMBER [UNIT]" into an SI value, checking the unit against the
 * expected dimension (already resolved).  Returns 0, or HB_EINVAL with a
 * message in msg such as "unit 'mm' is a length; expected a pressure
 * (e.g. GPa)" or "'abc' is not a number".
 */
int
hb_units_parse(const char *text, struct hb_unit_dim expect, double *value,
            char *msg, size_t n);

/*
 * Writes the unit of a dimension in plain ASCII ("N s m^-5/2", "kg/m^3",
 * "m/s", "Pa", "" for dimensionless) into buf.  Returns buf.
 */
char *
hb_units_dim_str(struct hb_unit_dim d, char *buf, size_t n);

/*
 * Formats an SI value with `sig` significant digits and the SI prefix that
 * suits it, e.g. 0.02 m -> "20 mm", 2.138e8 N m^-3/2 -> "2.138e+08 N m^-3/2"
 * (compound units get no prefix and an exponent instead).  Returns buf.
 */
char *
hb_units_format(double value, struct hb_unit_dim d, int sig, char *buf, size_t n);

/*
 * The shortest hb_units_format() text (6 digits or more) that hb_units_parse() reads back to the
 * same double ("20 mm", "0.35"), else "%.17g UNIT": for text a user edits.
 * Output is ASCII: micro is written "u".  Returns buf.
 */
char *
hb_units_format_exact(double value, struct hb_unit_dim d, char *buf, size_t n);

/*
 * Picks, for a quantity of plain base unit `base` ("m", "N", "s", "J"),
 * the prefix that suits a typical magnitude, for axis labels: writes the
 * label (e.g. "mm") into label and returns the scale (e.g. 1e-3), so that
 * the axis shows value / scale.  A compound base ("m/s", "N s") takes the
 * prefix on its first factor ("mm/s").
 */
double
hb_units_axis(double magnitude, const char *base, char *label, size_t n);

/* 1 if v lies in r (NaN never does; whole numbers must be integers). */
int
hb_units_in_range(double v, const struct hb_unit_range *r);

/*
 * The one way a range is written: "(0, 1)", "[0, inf) m", "whole numbers
 * >= 2", "any finite value"; the unit of dim (already resolved) follows an
 * interval when dim is not NULL and not dimensionless.  Returns buf.
 */
char *
hb_units_range_str(const struct hb_unit_range *r, const struct hb_unit_dim *dim, char *buf, size_t n);
HB_END_DECLS

#endif
