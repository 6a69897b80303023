/*
 * law.c - the registry of contact laws, helpers over their parameter
 * tables (see law.h) and the callbacks several laws share (law_common.h).
 *
 * Each law lives in its own file (law_shccl.c, law_bwshccl.c, law_bwmcl.c,
 * law_hertz.c, law_linear.c) and ends in one `const struct law_type`.  This
 * file lists them; adding a law means adding one file and one line to
 * `laws` below.  The order of `laws` is the order of pickers and help text.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/law.h"
#include "hybounce/status.h"

#include "law_common.h"

static const struct law_type *const laws[] = {
	&law_shccl,
	&law_bwshccl,
	&law_bwmcl,
	&law_hertz,
	&law_linear,
	NULL,
};

/* ASCII case-insensitive equality; names are plain ASCII keys. */
static int
law_name_eq(const char *a, const char *b)
{
	while (*a != '\0' && *b != '\0') {
		if (tolower((unsigned char)*a) != tolower((unsigned char)*b))
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
const struct law_type *const *
law_list(void)
{
	return laws;
}

/*
 * Returns the law whose name equals `name` ignoring ASCII case ("BWMCL" and
 * "bwmcl" are the same law), or NULL when there is none or name is NULL.
 */
const struct law_type *
law_find(const char *name)
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
law_param_index(const struct law_type *law, const char *name)
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
law_defaults(const struct law_type *law, double *par)
{
	for (int i = 0; i < law->n_params; i++)
		par[i] = law->params[i].def;
}

/* Writes one bound of a range, "inf"/"-inf" for none. */
static void
law_bound_str(double b, char *buf, size_t n)
{
	if (isinf(b))
		snprintf(buf, n, "%sinf", b < 0 ? "-" : "");
	else
		snprintf(buf, n, "%g", b);
}

/*
 * Checks `value` against the range of parameter `pp`.  Infinite and NaN
 * values are always rejected.  Returns 0, or HB_EINVAL with a message such
 * as "alpha = 1.2 is out of range; accepted: (0, 1)" in msg (size n).
 */
int
law_param_check(const struct law_param *pp, double value, char *msg, size_t n)
{
	char lo[32], hi[32];
	int ok;

	ok = isfinite(value);
	if (ok && !isinf(pp->lo))
		ok = pp->lo_open ? value > pp->lo : value >= pp->lo;
	if (ok && !isinf(pp->hi))
		ok = pp->hi_open ? value < pp->hi : value <= pp->hi;
	if (ok)
		return HB_OK;
	law_bound_str(pp->lo, lo, sizeof lo);
	law_bound_str(pp->hi, hi, sizeof hi);
	return status_set(msg, n, HB_EINVAL,
	    "%s = %g is out of range; accepted: %c%s, %s%c", pp->name, value,
	    pp->lo_open || isinf(pp->lo) ? '(' : '[', lo, hi,
	    pp->hi_open || isinf(pp->hi) ? ')' : ']');
}

/* The value of the first parameter carrying `flag`, or 1 when none does. */
static double
law_flagged(const struct law_type *law, const double *par, int flag)
{
	for (int i = 0; i < law->n_params; i++)
		if (law->params[i].flags & flag)
			return par[i];
	return 1.0;
}

/* The exponent p of this parameter set (1 if the law has none). */
double
law_exponent_p(const struct law_type *law, const double *par)
{
	return law_flagged(law, par, LAW_PARAM_EXPONENT_P);
}

/* The exponent n of this parameter set (1 if the law has none). */
double
law_exponent_n(const struct law_type *law, const double *par)
{
	return law_flagged(law, par, LAW_PARAM_EXPONENT_N);
}

/*
 * Switching function of a law whose only kink is at x_c = 0 (the clamp of
 * rule R1 with ext = 0, and |x_c|^p): g[0] = x_c.
 */
void
law_kinks_xc(const double *par, int ext, double xc, const double *z, double v,
             double *g)
{
	(void)par;
	(void)ext;
	(void)z;
	(void)v;
	g[0] = xc;
}

/* k = k_H, for a law whose elastic term is the Hertzian relation itself. */
double
law_k_hertz_identity(const double *par, double kH)
{
	(void)par;
	return kH;
}

/*
 * Checks a Bouc-Wen parameter set (layout LAW_BW_*): eqs. bwshc_psi and
 * bwm_psi1 require gamma in [-beta, beta].  Returns 0, or HB_EINVAL with
 * the accepted range in msg (size n).
 */
int
law_bw_check(const double *par, char *msg, size_t n)
{
	double beta = par[LAW_BW_BETA], gamma = par[LAW_BW_GAMMA];

	if (gamma >= -beta && gamma <= beta)
		return HB_OK;
	return status_set(msg, n, HB_EINVAL,
	    "gamma = %g must lie in [-beta, beta] = [%g, %g]", gamma, -beta, beta);
}

/*
 * Eq. k_hertz for a Bouc-Wen law (layout LAW_BW_*): the k whose two
 * branches together match the Hertz coefficient kH,
 * k = k_H / (alpha + (1 - alpha) A^p).
 */
double
law_bw_k_hertz(const double *par, double kH)
{
	double alpha = par[LAW_BW_ALPHA];

	return kH / (alpha + (1.0 - alpha) * apow(par[LAW_BW_A], par[LAW_BW_P]));
}
