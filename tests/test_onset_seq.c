/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_onset_seq.c - the bouncing-sequence model of onset_seq.c: the
 * longest run of clicks that get quieter and closer is kept; a blip before
 * the first impact, a knock between two, clicks after the last and clicks
 * under the noise are dropped, each with its reason; a take with too few
 * impacts, or with even intervals, is refused.
 */
#include <criterion/criterion.h>
#include <string.h>

#include "hybounce/onset.h"
#include "onset_seq.h"

/* n impacts from t0: first interval T, restitution e, peaks falling by f. */
static size_t
bounce(struct onset_cand *c, size_t n, double t0, double T, double e, double f)
{
	double t = t0, p = 0.9;

	for (size_t i = 0; i < n; i++) {
		memset(&c[i], 0, sizeof c[i]);
		c[i].t = t;
		c[i].peak = p;
		t += T;
		T *= e;
		p *= f;
	}
	return n;
}

/* Inserts a click at t with peak p, keeping c ascending in t. */
static size_t
insert(struct onset_cand *c, size_t n, double t, double p)
{
	size_t k = 0;

	while (k < n && c[k].t < t)
		k++;
	memmove(c + k + 1, c + k, (n - k) * sizeof *c);
	memset(&c[k], 0, sizeof c[k]);
	c[k].t = t;
	c[k].peak = p;
	return n + 1;
}

Test(onset_seq, a_clean_sequence_is_kept_whole)
{
	struct onset_cand c[16];
	size_t n = bounce(c, 12, 0.2, 0.076, 0.75, 0.7);
	char why[256];

	cr_assert_eq(onset_sequence(c, n, 1e-3, 5e-5, why, sizeof why), 12, "%s", why);
	for (size_t i = 0; i < n; i++)
		cr_assert(c[i].keep);
}

Test(onset_seq, blip_knock_and_after_are_dropped_with_reasons)
{
	struct onset_cand c[20];
	size_t n = bounce(c, 10, 0.2, 0.076, 0.75, 0.75);
	char why[256];

	n = insert(c, n, 0.197, 0.01);   /* a blip before the first impact */
	n = insert(c, n, 0.300, 0.55);   /* a knock between impacts 1 and 2 */
	n = insert(c, n, 0.700, 0.55);   /* a knock long after the last */
	n = insert(c, n, 0.650, 0.0005); /* under the noise */
	cr_assert_eq(onset_sequence(c, n, 1e-3, 5e-5, why, sizeof why), 10, "%s", why);
	cr_assert(!c[0].keep);
	cr_assert(strstr(c[0].why, "before the first impact") != NULL, "%s", c[0].why);
	for (size_t i = 0; i < n; i++) {
		if (c[i].t == 0.300)
			cr_assert(!c[i].keep && strstr(c[i].why, "between two impacts"), "%s", c[i].why);
		if (c[i].t == 0.700)
			cr_assert(!c[i].keep && strstr(c[i].why, "after the last impact"), "%s", c[i].why);
		if (c[i].t == 0.650)
			cr_assert(!c[i].keep && strstr(c[i].why, "no louder than the noise"), "%s",
			          c[i].why);
	}
}

Test(onset_seq, too_few_or_even_is_refused)
{
	struct onset_cand c[16];
	size_t n = bounce(c, 3, 0.2, 0.076, 0.75, 0.7);
	char why[256];

	cr_assert_eq(onset_sequence(c, n, 1e-3, 5e-5, why, sizeof why), 0);
	cr_assert(strstr(why, "at least 4 impacts") != NULL, "%s", why);

	n = bounce(c, 8, 0.2, 0.25, 1.0, 1.0);
	cr_assert_eq(onset_sequence(c, n, 1e-3, 5e-5, why, sizeof why), 0);
	cr_assert(strstr(why, "even intervals") != NULL, "%s", why);

	cr_assert_eq(onset_sequence(c, 0, 1e-3, 5e-5, why, sizeof why), 0);
	cr_assert(strstr(why, "at least 4 impacts") != NULL, "%s", why);
}

/* Two clicks 11 ms apart are both kept: the model needs no window. */
Test(onset_seq, close_clicks_are_both_kept)
{
	struct onset_cand c[40];
	size_t n = bounce(c, 30, 0.2, 0.076, 0.85, 0.92), k = 0;
	char why[256];

	while (k + 1 < n && c[k + 1].t - c[k].t > 0.011)
		k++;
	cr_assert_lt(c[k + 1].t - c[k].t, 0.0111);
	cr_assert_eq(onset_sequence(c, n, 1e-3, 5e-5, why, sizeof why), 30, "%s", why);
	cr_assert(c[k].keep && c[k + 1].keep);
}
