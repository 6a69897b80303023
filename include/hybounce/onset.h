/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset.h - impact times from a sound recording of a bouncing sequence.
 *
 * aubio's onset detector (libaubio, method "hfc" by default, a hop of
 * 64 samples) finds the candidate clicks; each is then refined within its
 * own neighbourhood (never past half the interval to the candidates on
 * either side): placed on the sample where the click's amplitude first
 * reaches `level` of its peak (and rises clearly above the noise and the
 * ringing of the click before), so that the time depends neither on
 * aubio's hop and delay nor on that ringing.  The first sample of the file
 * is t = 0.
 *
 * The candidates are then checked against what a bouncing sequence is:
 * impacts rise above the noise, get quieter and closer, each ratio of
 * consecutive intervals is a restitution in (0, 1) up to timing noise, and
 * a peak far below the impact after it is not an impact, and the last
 * interval is clearly shorter than the first.  The longest
 * consistent run is kept; every other candidate is listed in drop[] with
 * the reason.  A recording with no consistent run of MIN_IMPACTS is
 * refused (HB_EINVAL, the reason in the message).
 */
#ifndef HB_ONSET_H
#define HB_ONSET_H

#include <stddef.h>
#include "export.h"

HB_BEGIN_DECLS

struct hb_onset_options {
	const char *method;  /* aubio onset method; NULL: "hfc" */
	double threshold;    /* aubio peak-picking threshold; 0: 0.3 */
	double min_interval; /* shortest interval between two onsets, s; 0: 2 ms */
	double level;        /* fraction of the click's peak that marks its start; 0: 0.3 */
};

/* The fewest impacts a recording must give (three intervals, two ratios). */
#define HB_ONSET_MIN_IMPACTS 4

/* A candidate click that is not taken as an impact, and why. */
struct hb_onset_drop {
	double t;            /* s */
	double peak;         /* peak |amplitude|, full scale 1 */
	char why[128];
};

struct hb_onset_result {
	double *t;           /* onset times, s, ascending (malloc'd) */
	double *peak;        /* peak |amplitude| of each click, full scale 1 */
	size_t n;
	double samplerate;   /* Hz */
	double duration;     /* s */
	double noise;        /* rms of the quietest 10 ms of sound (digital silence aside) */
	struct hb_onset_drop *drop; /* candidates not kept, in time order (malloc'd) */
	size_t ndrop;
	size_t ncand;        /* candidates aubio reported */
	float *env;          /* the envelope, for showing: peak |amplitude| per env_dt (malloc'd) */
	size_t nenv;
	double env_dt;       /* s (0.5 ms, a whole number of samples) */
};

/*
 * Reads the recording at path (any format aubio reads: WAV always) and
 * detects the onsets.  Returns 0, or HB_EIO / HB_EINVAL / HB_ENOMEM with
 * a message naming the file; on HB_EINVAL for a recording that is no
 * consistent bouncing sequence, r still holds the candidates kept (t, peak)
 * and dropped (drop), for showing.  hb_onset_result_free(r) in every case.  Not
 * for concurrent calls: aubio's log hook, captured meanwhile, is global.
 */
int
hb_onset_detect(const char *path, const struct hb_onset_options *o, struct hb_onset_result *r,
             char *msg, size_t n);

void
hb_onset_result_free(struct hb_onset_result *r);

/*
 * The sound format of a file from its first n bytes (16 or more; 40 tell
 * an Ogg stream's codec): "WAV", "Wave64", "FLAC", "Ogg Vorbis", "Ogg
 * Opus", "Ogg FLAC", "Ogg", "MP4/M4A", "AIFF", "CAF", "MP3", "MP3 (ID3)",
 * "AAC (ADTS)"; or NULL when they are no sound header (text, say).  A
 * recording is recognised by its content, not its name.
 */
const char *
hb_audio_format(const void *head, size_t n);

HB_END_DECLS

#endif
