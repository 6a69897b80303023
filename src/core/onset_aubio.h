/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset_aubio.h - libaubio, loaded when a recording is first read.
 *
 * Linking libaubio pulls in about 140 shared libraries (its sound-file
 * readers: FFmpeg, codecs, image and font libraries) whose relocation took
 * about 20 ms at every start of the program, for a feature only `fit
 * --data FILE.wav` uses.  So the engine opens it with dlopen(3) the first
 * time a recording is read, and reaches it through the table below, typed
 * from aubio's own header.  Private to onset.c.
 */
#ifndef HYBOUNCE_ONSET_AUBIO_H
#define HYBOUNCE_ONSET_AUBIO_H

#include <stddef.h>

#include <aubio/aubio.h>

struct aubio_api {
	__typeof__(&new_aubio_source) new_aubio_source;
	__typeof__(&del_aubio_source) del_aubio_source;
	__typeof__(&aubio_source_do) aubio_source_do;
	__typeof__(&aubio_source_get_samplerate) aubio_source_get_samplerate;
	__typeof__(&new_fvec) new_fvec;
	__typeof__(&del_fvec) del_fvec;
	__typeof__(&fvec_get_sample) fvec_get_sample;
	__typeof__(&fvec_set_sample) fvec_set_sample;
	__typeof__(&new_aubio_onset) new_aubio_onset;
	__typeof__(&del_aubio_onset) del_aubio_onset;
	__typeof__(&aubio_onset_do) aubio_onset_do;
	__typeof__(&aubio_onset_get_last) aubio_onset_get_last;
	__typeof__(&aubio_onset_set_threshold) aubio_onset_set_threshold;
	__typeof__(&aubio_onset_set_minioi_s) aubio_onset_set_minioi_s;
	__typeof__(&aubio_log_set_level_function) aubio_log_set_level_function;
	__typeof__(&aubio_log_reset) aubio_log_reset;
};

/*
 * The functions of libaubio, loaded once per process (thread-safe), or
 * NULL with a message naming the library and the package that provides it.
 */
const struct aubio_api *
aubio_api(char *msg, size_t n);

#endif
