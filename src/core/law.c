/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * law.c - the registry of contact laws and helpers over their parameter
 * tables (see law.h).  The callbacks several laws share are in
 * law_common.c.
 *
 * Each law lives in its own file (law_shccl.c, law_bwshccl.c, law_bwmcl.c,
 * law_hertz.c, law_linear.c) and ends in one `const struct hb_law_type`.  This
 * file lists them; adding a law means adding one file and one line to
 * `laws` below.  The order of `laws` is the order of pickers and help text.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/law.h"
#include "hybounce/status.h"
#include "hybounce/units.h"
#include "cnum.h"

static const struct hb_law_type *const laws[] = {
	&hb_law_shccl,
	&hb_law_bwshccl,
	&hb_law_bwmcl,
	&hb_law_hertz,
	&hb_law_linear,
	NULL,
};

/* ASCII case-insensitive equality; names are plain ASCII keys. */
static int
law_name_eq(const char *a, const char *b)
{
	while (*a != '\0' && *b != '\0') {
		if (cnum_tolower((unsigned char)*a) != cnum_tolower((unsigned char)*b))
			return 0;
		a++;
		b++;
	}
	return *a == *b;
}

/*
 * Returns the registered laws as a NULL-terminated array in a fixed order.
 * The array and the laws are static: never freed by the caller.
 */
const struct hb_law_type *const *
hb_law_list(void)
{
	return laws;
}

/*
 * Returns the law whose name equals `name` ignoring ASCII case ("BWMCL" and
 * "bwmcl" are the same law), or NULL when there is none or name is NULL.
 */
const struct hb_law_type *
hb_law_find(const char *name)
{
	if (name == NULL)
		return NULL;
	for (int i = 0; laws[i] != NULL; i++)
		if (law_name_eq(laws[i]->name, name))
			return laws[i];
	return NULL;
}

/*
 * Returns the index of the parameter called `name` in the law's table, or
 * -1.  An exact match is preferred; otherwise case is ignored (the names of
 * one law never differ by case alone).
 */
int
hb_law_param_index(const struct hb_law_type *law, const char *name)
{
	if (law == NULL || name == NULL)
		return -1;
	for (int i = 0; i < law->n_params; i++)
		if (strcmp(law->params[i].name, name) == 0)
			return i;
	for (int i = 0; i < law->n_params; i++)
		if (law_name_eq(law->params[i].name, name))
			return i;
	return -1;
}

/* Fills par[0 .. n_params-1] with the law's default values. */
void
hb_law_defaults(const struct hb_law_type *law, double *par)
{
	for (int i = 0; i < law->n_params; i++)
		par[i] = law->params[i].def;
}

/* The range of a parameter; an infinite bound is never admitted. */
struct hb_unit_range
hb_law_param_range(const struct hb_law_param *pp)
{
	struct hb_unit_range r = { pp->lo, pp->hi, pp->lo_open || isinf(pp->lo),
		pp->hi_open || isinf(pp->hi), 0 };

	return r;
}

/*
 * Checks `value` against the range of parameter `pp`.  Infinite and NaN
 * values are always rejected.  Returns 0, or HB_EINVAL with a message such
 * as "alpha = 1.2 is out of range; accepted: (0, 1)" in msg (size n).
 */
int
hb_law_param_check(const struct hb_law_param *pp, double value, char *msg, size_t n)
{
	struct hb_unit_range r = hb_law_param_range(pp);
	char rs[80];

	if (isfinite(value) && hb_units_in_range(value, &r))
		return HB_OK;
	return hb_status_set(msg, n, HB_EINVAL, "%s = %g is out of range; accepted: %s", pp->name,
	    value, hb_units_range_str(&r, NULL, rs, sizeof rs));
}

/* The value of the first parameter carrying `flag`, or 1 when none does. */
static double
law_flagged(const struct hb_law_type *law, const double *par, int flag)
{
	for (int i = 0; i < law->n_params; i++)
		if (law->params[i].flags & flag)
			return par[i];
	return 1.0;
}

/* The exponent p of this parameter set (1 if the law has none). */
double
hb_law_exponent_p(const struct hb_law_type *law, const double *par)
{
	return law_flagged(law, par, HB_LAW_PARAM_EXPONENT_P);
}

/* The exponent n of this parameter set (1 if the law has none). */
double
hb_law_exponent_n(const struct hb_law_type *law, const double *par)
{
	return law_flagged(law, par, HB_LAW_PARAM_EXPONENT_N);
}
