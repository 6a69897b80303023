/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset.h - impact times from a sound recording of a bouncing sequence.
 *
 * aubio's onset detector (libaubio, method "hfc" by default, a hop of
 * 64 samples) finds each click; each onset is then placed on the sample
 * where the click's amplitude first reaches `level` of its peak (and rises
 * clearly above the noise), looked for within 2 ms before the peak, so that
 * the time depends neither on aubio's hop and delay nor on the ringing of
 * the click before.  The first sample of the file is t = 0.
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

struct hb_onset_result {
	double *t;           /* onset times, s, ascending (malloc'd) */
	double *peak;        /* peak |amplitude| of each click, full scale 1 */
	size_t n;
	double samplerate;   /* Hz */
	double duration;     /* s */
	double noise;        /* rms of the quietest 10 ms of the file */
};

/*
 * Reads the recording at path (any format aubio reads: WAV always) and
 * detects the onsets.  Returns 0, or HB_EIO / HB_EINVAL / HB_ENOMEM with
 * a message naming the file.  hb_onset_result_free(r) in every case.  Not
 * for concurrent calls: aubio's log hook, captured meanwhile, is global.
 */
int
hb_onset_detect(const char *path, const struct hb_onset_options *o, struct hb_onset_result *r,
             char *msg, size_t n);

void
hb_onset_result_free(struct hb_onset_result *r);

HB_END_DECLS

#endif
