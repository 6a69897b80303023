/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz_fitdata.c - the data files of `hybounce fit` (hb_fit_data_read): any
 * input is read or refused with a message, never a crash, a leak or a
 * read out of bounds; what is read keeps the invariant of fit_data.c (n >=
 * 1 rows, values finite or NAN for a missed one, sd > 0 of every value
 * given, each trial's times increasing, every drop's h_0 > 0).
 */
#include <math.h>
#include <stdio.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fuzz.h"

int
LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct hb_fit_data d;
	char msg[512];
	FILE *f = fmemopen((void *)data, size ? size : 1, "r");

	if (f == NULL)
		return 0;
	if (size == 0) {
		fclose(f);
		return 0;
	}
	if (hb_fit_data_read(f, "fuzz.csv", &d, msg, sizeof msg) == HB_OK) {
		if (d.n == 0 || hb_fit_npoints(&d) == 0)
			abort();
		for (int k = 0; k < HB_FIT_OBS_COUNT; k++)
			for (size_t i = 0; i < d.n; i++) {
				/* a value is finite, or NAN for a missed one */
				if (d.col[k] != NULL && isinf(d.col[k][i]))
					abort();
				if (d.sd[k] != NULL && !isnan(d.col[k][i]) && !(d.sd[k][i] > 0))
					abort();
			}
		if (d.kind != HB_FIT_DROPS && (d.ntrials == 0 || d.trial_row[0] != 0
		                               || d.trial_row[d.ntrials] != d.n))
			abort();
		for (size_t t = 0; d.kind == HB_FIT_SEQUENCE && t < d.ntrials; t++) {
			double prev = NAN;

			for (size_t i = d.trial_row[t]; i < d.trial_row[t + 1]; i++) {
				double v = d.col[HB_FIT_OBS_TE][i];

				if (!isnan(v) && !isnan(prev) && !(v > prev))
					abort();
				if (!isnan(v))
					prev = v;
			}
		}
		for (size_t t = 0; d.kind == HB_FIT_HEIGHTS && t < d.ntrials; t++)
			if (!(d.col[HB_FIT_OBS_H][d.trial_row[t]] > 0))
				abort();
		hb_fit_data_free(&d);
	} else if (msg[0] == '\0') {
		abort(); /* a refusal always says why */
	}
	fclose(f);
	return 0;
}
