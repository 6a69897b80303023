/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_load.c - the one loader of measured data, for every front end (fit,
 * the explorer's --data and D prompt, a host program): a CSV file
 * (fit_data.c), or a recording whose onsets (onset.c) give the impact
 * times of one bouncing sequence.  A recording is told by its content (its
 * first bytes: hb_audio_format), never by its name; it is read by name
 * (aubio opens it), so it must be a regular file.  See fit.h.
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
#define ACCEPTED "a CSV file of measurements or a recording (WAV, FLAC, Ogg, MP3, M4A/AAC, AIFF)"
#define AUDIO_ACCEPTED "WAV, FLAC, Ogg Vorbis or Opus, MP3, M4A/AAC, AIFF (recognised by content), " \
                       "or a CSV file"

/* 1 if path is named as a recording is (.wav, .flac, ...): for the message only. */
static int
audio_name(const char *path)
{
	static const char *const ext[] = { ".wav", ".flac", ".ogg", ".oga", ".mp3", ".m4a",
	                                   ".aac", ".aif", ".aiff", ".opus", ".w64", ".caf" };
	const char *dot = strrchr(path, '.');

	for (size_t i = 0; dot != NULL && i < sizeof ext / sizeof ext[0]; i++)
		if (strcasecmp(dot, ext[i]) == 0)
			return 1;
	return 0;
}

/* The recording format of a regular file at path, by its first bytes; NULL if none. */
static const char *
audio_format_of(const char *path)
{
	unsigned char head[64];
	struct stat sb;
	size_t got;
	FILE *f;

	if (stat(path, &sb) != 0 || !S_ISREG(sb.st_mode) || (f = fopen(path, "rb")) == NULL)
		return NULL;
	got = fread(head, 1, sizeof head, f);
	fclose(f);
	return hb_audio_format(head, got);
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
		                     "a regular file (not a pipe, a device or a folder)", path);
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
	if (audio_format_of(path) == NULL) {
		struct stat sb;

		if (audio_name(path) && stat(path, &sb) == 0 && S_ISREG(sb.st_mode))
			return hb_status_set(msg, n, HB_EINVAL, "%s: cannot be read as a recording: its "
			                     "first bytes are no sound header; accepted: %s", path,
			                     AUDIO_ACCEPTED);
		/* Read once, bounded: a pipe or a FIFO works, /dev/zero is refused. */
		if ((st = hb_input_read(path, HB_INPUT_DATA_MAX, &text, &len, msg, n)) != HB_OK) {
			size_t l = strlen(msg);

			/* the system's reason (a loop of links ...), then what is accepted */
			if (strstr(msg, "accepted") == NULL && strstr(msg, "expected") == NULL && l < n)
				snprintf(msg + l, n - l, "; accepted: %s", ACCEPTED);
			return st;
		}
		if (hb_audio_format(text, len) != NULL || (len >= 4 && memcmp(text, "RIFF", 4) == 0)) {
			const char *f = hb_audio_format(text, len);

			st = hb_status_set(msg, n, HB_EINVAL, "%s: a recording (%s) is read by name; "
			                   "accepted: a regular file (not a pipe or a device)", path,
			                   f != NULL ? f : "RIFF");
			free(text);
			return st;
		}
		st = hb_fit_data_parse(text, len, path, d, msg, n);
		free(text);
		return st;
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
