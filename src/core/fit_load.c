/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_load.c - the one loader of measured data, for every front end (fit,
 * the explorer's --data and D prompt, a host program): a CSV file
 * (fit_data.c), or a recording whose onsets (onset.c) give the impact
 * times of one bouncing sequence.  A recording is told by its name (.wav)
 * or by a RIFF header; it is read by name (aubio opens it), so it must be
 * a regular file.  See fit.h.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

#include "hybounce/fit.h"
#include "hybounce/input.h"
#include "hybounce/onset.h"
#include "hybounce/status.h"

/* What --data accepts, for a refusal that does not say it already. */
#define ACCEPTED "a CSV file of measurements or a .wav recording"

/* 1 if path names a recording by its extension (.wav). */
static int
wav_name(const char *path)
{
	size_t l = strlen(path);

	return l > 4 && strcasecmp(path + l - 4, ".wav") == 0;
}

static int
from_recording(const char *path, const struct hb_onset_options *oo, struct hb_fit_data *d,
               struct hb_onset_result *on, char *msg, size_t n)
{
	struct stat sb;
	int st;

	if (stat(path, &sb) != 0)
		return hb_status_set(msg, n, HB_EIO, "%s: %s; accepted: %s", path, strerror(errno),
		                     ACCEPTED);
	if (!S_ISREG(sb.st_mode))
		return hb_status_set(msg, n, HB_EINVAL, "%s: a recording is read by name; accepted: "
		                     "a .wav file (not a pipe, a device or a folder)", path);
	if ((st = hb_onset_detect(path, oo, on, msg, n)) != HB_OK)
		return st;
	return hb_fit_data_from_times(on->t, NULL, on->n, path, d, msg, n);
}

int
hb_fit_data_open(const char *path, const struct hb_onset_options *oo, struct hb_fit_data *d,
                 struct hb_onset_result *on, char *msg, size_t n)
{
	struct hb_onset_result local;
	char *text = NULL;
	size_t len = 0;
	int st;

	memset(d, 0, sizeof *d);
	if (on == NULL)
		on = &local;
	memset(on, 0, sizeof *on);
	if (!wav_name(path)) {
		/* Read once, bounded: a pipe or a FIFO works, /dev/zero is refused. */
		if ((st = hb_input_read(path, HB_INPUT_DATA_MAX, &text, &len, msg, n)) != HB_OK) {
			size_t l = strlen(msg);

			/* the system's reason (a loop of links ...), then what is accepted */
			if (strstr(msg, "accepted") == NULL && strstr(msg, "expected") == NULL && l < n)
				snprintf(msg + l, n - l, "; accepted: %s", ACCEPTED);
			return st;
		}
		if (len < 4 || memcmp(text, "RIFF", 4) != 0) {
			st = hb_fit_data_parse(text, len, path, d, msg, n);
			free(text);
			return st;
		}
		free(text);
	}
	st = from_recording(path, oo, d, on, msg, n);
	if (on == &local)
		hb_onset_result_free(&local);
	return st;
}

int
hb_fit_data_load(const char *path, struct hb_fit_data *d, char *msg, size_t n)
{
	return hb_fit_data_open(path, NULL, d, NULL, msg, n);
}
