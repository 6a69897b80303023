/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset_aubio.c - libaubio through dlopen(3) (see onset_aubio.h).
 *
 * The library's name is its soname, read by the Makefile from the libaubio
 * that pkg-config finds (AUBIO_SONAME; libaubio.so.5 on Debian 12), so the
 * program loads the ABI it was compiled against.
 */
#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/status.h"
#include "onset_aubio.h"

#ifndef AUBIO_SONAME
#define AUBIO_SONAME "libaubio.so.5"
#endif

/*
 * Process-wide, written once under aubio_once and only read after: the
 * library is the same for every thread (the re-entrancy checks of
 * tests/cli/sweep_reentrant.sh and install.sh list these four).
 */
static pthread_once_t aubio_once = PTHREAD_ONCE_INIT;
static struct aubio_api aubio_tab; /* the functions */
static int aubio_loaded;           /* 1: aubio_tab is complete */
static char aubio_why[256];        /* the reason it is not, when not */

/* dlsym's void * to a function pointer, through memcpy (ISO C has no cast). */
#define LOAD(h, name)                                                        \
	do {                                                                 \
		void *p_ = dlsym(h, #name);                                  \
		if (p_ == NULL) {                                            \
			snprintf(aubio_why, sizeof aubio_why, "%s has no %s", AUBIO_SONAME, #name); \
			return;                                              \
		}                                                            \
		memcpy(&aubio_tab.name, &p_, sizeof p_);                           \
	} while (0)

static void
load(void)
{
	void *h = dlopen(AUBIO_SONAME, RTLD_NOW | RTLD_LOCAL);

	if (h == NULL) {
		const char *e = dlerror();
		snprintf(aubio_why, sizeof aubio_why, "%s", e != NULL ? e : AUBIO_SONAME ": cannot be loaded");
		return;
	}
	LOAD(h, new_aubio_source);
	LOAD(h, del_aubio_source);
	LOAD(h, aubio_source_do);
	LOAD(h, aubio_source_get_samplerate);
	LOAD(h, new_fvec);
	LOAD(h, del_fvec);
	LOAD(h, fvec_get_sample);
	LOAD(h, fvec_set_sample);
	LOAD(h, new_aubio_onset);
	LOAD(h, del_aubio_onset);
	LOAD(h, aubio_onset_do);
	LOAD(h, aubio_onset_get_last);
	LOAD(h, aubio_onset_set_threshold);
	LOAD(h, aubio_onset_set_minioi_s);
	LOAD(h, aubio_log_set_level_function);
	LOAD(h, aubio_log_reset);
	/*
	 * aubio reads through FFmpeg (libavformat), whose log goes to stderr
	 * ("[vorbis @ 0x...] Could not update timestamps ..."): the engine
	 * never prints, so it is silenced (AV_LOG_QUIET) where aubio links it.
	 */
	{
		void *p = dlsym(h, "av_log_set_level");
		void (*set_level)(int);

		if (p != NULL) {
			memcpy(&set_level, &p, sizeof p);
			set_level(-8);
		}
	}
	aubio_loaded = 1; /* the handle stays open for the life of the process */
}

const struct aubio_api *
aubio_api(char *msg, size_t n)
{
	pthread_once(&aubio_once, load);
	if (aubio_loaded)
		return &aubio_tab;
	hb_status_set(msg, n, HB_EIO, "reading a recording needs libaubio (%s), which cannot be "
	    "loaded: %s; expected the Debian package libaubio5 (make deps installs it)",
	    AUBIO_SONAME, aubio_why);
	return NULL;
}
