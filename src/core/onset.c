/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset.c - impact times from a recording (see onset.h): aubio's onset
 * detector finds the clicks, then each is placed on the first sample where
 * its amplitude reaches `level` of its peak.
 *
 * aubio reports an onset to within a hop or two (its detection function is
 * computed per hop and its time is corrected by a fixed delay); a click
 * from an impact rises within a few samples, so the threshold crossing
 * near aubio's time is the impact to about one sample (23 us at 44.1 kHz).
 * The crossing is looked for at most RISE before the peak, since the
 * previous click may still ring at the start of the search window.
 * aubio's own log output is captured into the message instead of going to
 * stderr (the engine never prints).  libaubio is loaded on first use
 * (onset_aubio.c), so that runs which read no recording do not pay for it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/onset.h"
#include "hybounce/status.h"
#include "onset_aubio.h"

enum { HOP = 64, WIN = 512 };
#define RISE 0.002 /* longest rise of a click from its start to its peak, s */

void
hb_onset_result_free(struct hb_onset_result *r)
{
	if (r == NULL)
		return;
	free(r->t);
	free(r->peak);
	memset(r, 0, sizeof *r);
}

/* aubio's error log, kept for the message. */
static void
log_to_buf(sint_t level, const char_t *message, void *data)
{
	char *buf = data;
	size_t len = strlen(buf);

	(void)level;
	snprintf(buf + len, 256 - len, "%s", message);
	len = strlen(buf);
	while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == ' '))
		buf[--len] = '\0';
}

/* Reads every sample (downmixed to mono by aubio) into *x. */
static int
read_all(const struct aubio_api *A, const char *path, float **x, size_t *nx, double *sr,
         char *alog, char *msg, size_t n)
{
	aubio_source_t *src = A->new_aubio_source(path, 0, HOP);
	fvec_t *buf;
	size_t cap = 0;
	uint_t got = 0;

	*x = NULL;
	*nx = 0;
	if (src == NULL)
		return hb_status_set(msg, n, HB_EIO, "%s: cannot be read as a recording%s%s; "
		    "accepted: a WAV file (or another format libaubio reads)", path,
		    alog[0] ? ": " : "", alog);
	*sr = A->aubio_source_get_samplerate(src);
	if ((buf = A->new_fvec(HOP)) == NULL) {
		A->del_aubio_source(src);
		return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	}
	do {
		A->aubio_source_do(src, buf, &got);
		if (*nx + got > cap) {
			size_t nc = cap ? 2 * cap : 1 << 16;
			float *t = realloc(*x, nc * sizeof *t);

			if (t == NULL) {
				A->del_fvec(buf);
				A->del_aubio_source(src);
				return hb_status_set(msg, n, HB_ENOMEM, "out of memory");
			}
			*x = t;
			cap = nc;
		}
		for (uint_t i = 0; i < got; i++)
			(*x)[(*nx)++] = (float)A->fvec_get_sample(buf, i);
	} while (got == HOP);
	A->del_fvec(buf);
	A->del_aubio_source(src);
	return HB_OK;
}

/* rms of the quietest 10 ms block: the noise floor. */
static double
noise_floor(const float *x, size_t nx, double sr)
{
	size_t blk = (size_t)(0.010 * sr), best = 0;
	double min = HUGE_VAL;

	if (blk < 1 || blk > nx)
		blk = nx;
	for (size_t s = 0; s + blk <= nx && blk > 0; s += blk) {
		double acc = 0;

		for (size_t i = s; i < s + blk; i++)
			acc += (double)x[i] * x[i];
		if (acc < min) {
			min = acc;
			best = blk;
		}
	}
	return best ? sqrt(min / (double)best) : 0;
}

int
hb_onset_detect(const char *path, const struct hb_onset_options *o, struct hb_onset_result *r,
             char *msg, size_t n)
{
	const char *method = o != NULL && o->method != NULL ? o->method : "hfc";
	double thr = o != NULL && o->threshold > 0 ? o->threshold : 0.3;
	double mioi = o != NULL && o->min_interval > 0 ? o->min_interval : 0.002;
	double level = o != NULL && o->level > 0 ? o->level : 0.3;
	char alog[256] = "";
	float *x = NULL;
	size_t nx = 0, cap = 0;
	const struct aubio_api *A;
	aubio_onset_t *od = NULL;
	fvec_t *in = NULL, *out = NULL;
	long prev = -1;
	int st;

	memset(r, 0, sizeof *r);
	if (!(level < 1))
		return hb_status_set(msg, n, HB_EINVAL, "onset level %g; accepted: a fraction of "
		    "the peak in (0, 1)", level);
	if ((A = aubio_api(msg, n)) == NULL)
		return HB_EIO;
	A->aubio_log_set_level_function(AUBIO_LOG_ERR, log_to_buf, alog);
	A->aubio_log_set_level_function(AUBIO_LOG_WRN, log_to_buf, alog);
	if ((st = read_all(A, path, &x, &nx, &r->samplerate, alog, msg, n)) != HB_OK)
		goto out;
	r->duration = (double)nx / r->samplerate;
	r->noise = noise_floor(x, nx, r->samplerate);
	od = A->new_aubio_onset(method, WIN, HOP, (uint_t)r->samplerate);
	if (od == NULL) {
		st = hb_status_set(msg, n, HB_EINVAL, "onset method '%s'%s%s; accepted: default, "
		    "energy, hfc, complex, phase, wphase, specdiff, kl, mkl, specflux", method,
		    alog[0] ? ": " : "", alog);
		goto out;
	}
	A->aubio_onset_set_threshold(od, (smpl_t)thr);
	A->aubio_onset_set_minioi_s(od, (smpl_t)mioi);
	in = A->new_fvec(HOP);
	out = A->new_fvec(1);
	if (in == NULL || out == NULL) {
		st = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
		goto out;
	}
	for (size_t s = 0; s < nx; s += HOP) {
		long rough, w = (long)(0.010 * r->samplerate), lo, hi, pk, on;
		float P = 0;

		for (uint_t i = 0; i < HOP; i++)
			A->fvec_set_sample(in, s + i < nx ? x[s + i] : 0, i);
		A->aubio_onset_do(od, in, out);
		if (A->fvec_get_sample(out, 0) == 0)
			continue; /* no onset in this hop */
		rough = (long)A->aubio_onset_get_last(od);
		/* the click: its peak near aubio's time, its start before the peak */
		lo = rough - w > 0 ? rough - w : 0;
		if (prev >= 0 && lo < prev + (long)(mioi * r->samplerate))
			lo = prev + (long)(mioi * r->samplerate);
		hi = rough + w < (long)nx ? rough + w : (long)nx;
		if (lo >= hi)
			continue;
		pk = lo;
		for (long i = lo; i < hi; i++)
			if (fabsf(x[i]) > P) {
				P = fabsf(x[i]);
				pk = i;
			}
		if (!(P > 4 * r->noise))
			continue; /* no click rises above the noise here */
		/*
		 * The start: the first sample reaching level x peak, at most
		 * RISE before the peak, so that the ringing of the click before
		 * (still loud a few ms later) is not taken for this one's start.
		 */
		on = pk - (long)(RISE * r->samplerate) > lo ? pk - (long)(RISE * r->samplerate) : lo;
		for (; on < pk && fabsf(x[on]) < fmaxf(level * P, (float)(4 * r->noise)); on++)
			;
		if (prev >= 0 && on < prev + (long)(mioi * r->samplerate))
			continue; /* the same click found twice */
		if (r->n == cap) {
			size_t nc = cap ? 2 * cap : 64;
			double *t = realloc(r->t, nc * sizeof *t), *p;

			if (t != NULL)
				r->t = t;
			p = realloc(r->peak, nc * sizeof *p);
			if (p != NULL)
				r->peak = p;
			if (t == NULL || p == NULL) {
				st = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
				goto out;
			}
			cap = nc;
		}
		r->t[r->n] = (double)on / r->samplerate;
		r->peak[r->n] = P;
		r->n++;
		prev = on;
	}
	if (r->n == 0)
		st = hb_status_set(msg, n, HB_EINVAL, "%s: no onsets found in %.3g s of sound "
		    "(noise rms %.2g of full scale); accepted: a recording of clicks above the "
		    "noise (a lower --onset-threshold finds fainter ones)", path, r->duration,
		    r->noise);
out:
	if (od != NULL)
		A->del_aubio_onset(od);
	if (in != NULL)
		A->del_fvec(in);
	if (out != NULL)
		A->del_fvec(out);
	free(x);
	A->aubio_log_reset();
	return st;
}
