/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_onsets.c - `hybounce fit` on a recording: which files are recordings
 * (by content), the onsets shown before the fit with the clicks dropped,
 * and the t_e CSV of --onsets-out.  See fit_cmd.h.
 */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "hybounce/onset.h"
#include "fit_cmd.h"
#include "report.h"
#include "signals.h"

/* Shows the onsets found in a recording and the restitution they imply. */
void
fit_print_onsets(const char *path, const struct hb_onset_result *on)
{
	printf("onsets      %zu in %s (%.0f Hz, %.3f s, noise rms %.2g of full scale)\n",
	    on->n, path, on->samplerate, on->duration, on->noise);
	printf("   i      t [s]    interval [ms]   e ~ ratio of intervals   peak\n");
	for (size_t i = 0; i < on->n; i++) {
		printf("%4zu %10.6f", i, on->t[i]);
		if (i > 0)
			printf(" %16.3f", 1e3 * (on->t[i] - on->t[i - 1]));
		else
			printf(" %16s", "-");
		if (i > 1)
			printf(" %24.4f", (on->t[i] - on->t[i - 1]) / (on->t[i - 1] - on->t[i - 2]));
		else
			printf(" %24s", "-");
		printf(" %6.3f\n", on->peak[i]);
	}
	printf("            (e of collision i-1 ~ interval i / interval i-1, neglecting the "
	       "contact's duration)\n");
	if (on->ndrop > 0)
		printf("dropped     %zu of %zu clicks found, not impacts of the sequence:\n",
		       on->ndrop, on->ndrop + on->n);
	for (size_t i = 0; i < on->ndrop; i++)
		printf("     %10.6f  peak %6.3f  %s\n", on->drop[i].t, on->drop[i].peak,
		       on->drop[i].why);
}

/*
 * The onsets as the t_e CSV that --data reads, for correcting by hand: the
 * impacts kept, and the clicks dropped as comments with the reason, in
 * time order (uncommenting one makes it an impact).
 */
void
fit_fill_onsets(FILE *f, const void *ctx)
{
	const struct hb_onset_result *on = ctx;
	const char *prov = cli_provenance();
	size_t i = 0, k = 0;

	if (prov[0] == ';')     /* the preset comment, as a CSV comment */
		fprintf(f, "#%s\n", prov + 1);
	fprintf(f, "t_e\n");
	while (i < on->n || k < on->ndrop) {
		if (k < on->ndrop && (i == on->n || on->drop[k].t < on->t[i])) {
			fprintf(f, "#%.9f  (dropped: %s)\n", on->drop[k].t, on->drop[k].why);
			k++;
		} else {
			fprintf(f, "%.9f\n", on->t[i++]);
		}
	}
}
