/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset.c - impact times from a recording (see onset.h): aubio's onset
 * detector finds the candidate clicks, each is placed on the first sample
 * where its amplitude reaches `level` of its peak, searched for within its
 * own neighbourhood, and the candidates that form a bouncing sequence are
 * kept (onset_seq.c).
 *
 * aubio reports an onset to within a hop or two (its detection function is
 * computed per hop and its time is corrected by a fixed delay); a click
 * from an impact rises within a few samples, so the threshold crossing
 * near aubio's time is the impact to about one sample (23 us at 44.1 kHz).
 * The neighbourhood of a candidate ends half-way to aubio's times of the
 * candidates on either side (and 10 ms away at most), so that two clicks a
 * few ms apart are each found in their own; the start is the earliest
 * sample reaching the threshold in the stretch of sound that ends at the
 * peak (a gap of QUIET below the threshold ends it), at most RISE before
 * the peak; where the click before still rings above the threshold, the
 * start is where the amplitude jumps most.
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
#include "onset_seq.h"

enum { HOP = 64, WIN = 512 };
#define ENV_DT 0.0005 /* the envelope's block, s */
#define RISE 0.002   /* longest rise of a click from its start to its peak, s */
#define QUIET 0.0005 /* a gap this long below the threshold ends a click's sound, s */
#define REACH 0.010  /* farthest a click lies from aubio's time for it, s */
#define GATE 5.0     /* an impact rises GATE x (14 dB) above the noise rms */
#define MAX_CAND 400  /* candidates weighed for the sequence (O(n^3) time, O(n^2) memory) */

void
hb_onset_result_free(struct hb_onset_result *r)
{
	if (r == NULL)
		return;
	free(r->t);
	free(r->peak);
	free(r->drop);
	free(r->env);
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

/*
 * The noise: the rms of the quietest 10 ms block of sound.  Blocks of
 * digital silence (padding before or after the take, mostly exact zeros)
 * are no noise floor: counting them would let any blip pass as a click.
 */
static double
noise_floor(const float *x, size_t nx, double sr)
{
	size_t blk = (size_t)(0.010 * sr);
	double min = HUGE_VAL, all = HUGE_VAL;

	if (blk < 1 || blk > nx)
		blk = nx;
	for (size_t s = 0; blk > 0 && s + blk <= nx; s += blk) {
		double acc = 0;
		size_t nz = 0;

		for (size_t i = s; i < s + blk; i++) {
			acc += (double)x[i] * x[i];
			nz += x[i] != 0;
		}
		acc = sqrt(acc / (double)blk);
		if (acc < all)
			all = acc;
		if (nz * 10 >= blk * 9 && acc < min)
			min = acc;
	}
	if (isfinite(min))
		return min;
	return isfinite(all) ? all : 0;
}

/* The envelope for showing: the peak |amplitude| of each ENV_DT block. */
static int
envelope(const float *x, size_t nx, double sr, struct hb_onset_result *r)
{
	size_t blk = (size_t)lround(ENV_DT * sr), nb;

	if (blk < 1)
		blk = 1;
	nb = (nx + blk - 1) / blk;
	if (nb == 0)
		return 0;
	if ((r->env = calloc(nb, sizeof *r->env)) == NULL)
		return -1;
	for (size_t k = 0; k < nx; k++)
		if (fabsf(x[k]) > r->env[k / blk])
			r->env[k / blk] = fabsf(x[k]);
	r->nenv = nb;
	r->env_dt = (double)blk / sr;
	return 0;
}

static float
amax(const float *x, long a, long b)
{
	float m = 0;

	for (long i = a; i < b; i++)
		if (fabsf(x[i]) > m)
			m = fabsf(x[i]);
	return m;
}

/*
 * One click in x[lo, hi): its peak *P and its start (returned), or -1 when
 * all is silent there.  Its start reaches level of the peak, and the noise
 * floor (the gate) where the peak rises above it.
 */
static long
refine(const float *x, long lo, long hi, double sr, double level, double gate, float *P)
{
	long pk = lo, s0, on, q = (long)(QUIET * sr), h = (long)(0.00025 * sr);
	float thr;

	*P = 0;
	for (long i = lo; i < hi; i++)
		if (fabsf(x[i]) > *P) {
			*P = fabsf(x[i]);
			pk = i;
		}
	if (!(*P > 0))
		return -1;
	thr = fmaxf((float)level * *P, *P > gate ? (float)gate : 0);
	s0 = pk - (long)(RISE * sr) > lo ? pk - (long)(RISE * sr) : lo;
	if (q < 1)
		q = 1;
	if (h < 2)
		h = 2;
	/* Back from the peak while the sound goes on (gaps shorter than QUIET). */
	on = pk;
	for (long i = pk, below = 0; i >= s0; i--) {
		if (fabsf(x[i]) >= thr) {
			on = i;
			below = 0;
		} else if (++below >= q) {
			return on;
		}
	}
	if (on > s0 + q || s0 == 0)
		return on;
	/*
	 * The sound before still rings above the threshold: the start is where
	 * the amplitude jumps most (the next h samples against the h before),
	 * then its first sample reaching level of the louder side.
	 */
	{
		double bestr = 0;
		long bi = pk;

		for (long i = s0 > lo + h ? s0 : lo + h; i + h <= pk + 1 && i + h <= hi; i++) {
			float b = amax(x, i - h, i), a = amax(x, i, i + h);
			double r = a / (b > 0 ? b : 1e-30f);

			if (r > bestr) {
				bestr = r;
				bi = i;
			}
		}
		{
			float a = amax(x, bi, bi + h < hi ? bi + h : hi), t = fmaxf((float)level * a,
			    amax(x, bi - h > lo ? bi - h : lo, bi));

			for (on = bi; on < pk && fabsf(x[on]) <= t; on++)
				;
		}
	}
	return on;
}

/*
 * Clicks aubio's detector misses: late impacts, quieter and closer, whose
 * rise its adaptive threshold (tuned by the loud first ones) does not see.
 * A click is where the amplitude over a block of JUMP_BLK jumps JUMP times
 * above every one of the JUMP_BACK blocks before and above the gate.  Adds
 * their times to *rough (ascending) where no aubio time lies within mioi,
 * and replaces an aubio time that does by this one (exact to a block).
 */
#define JUMP 1.5
#define JUMP_BLK 0.00025
#define JUMP_BACK 4

static int
add_jumps(const float *x, size_t nx, double sr, double gate, double mioi, long **rough,
          size_t *nr, size_t *rcap)
{
	long b = (long)(JUMP_BLK * sr), nb, last = -1000000000L;
	float *m;
	long *j = NULL;
	size_t nj = 0, jc = 0;

	if (b < 1)
		b = 1;
	nb = (long)nx / b;
	if (nb < JUMP_BACK + 1)
		return 0;
	if ((m = malloc((size_t)nb * sizeof *m)) == NULL)
		return -1;
	for (long k = 0; k < nb; k++)
		m[k] = amax(x, k * b, (k + 1) * b);
	for (long k = JUMP_BACK; k < nb; k++) {
		float before = 0;

		for (long q = k - JUMP_BACK; q < k; q++)
			before = fmaxf(before, m[q]);
		if (!(m[k] > gate && m[k] > JUMP * before) ||
		    (double)(k * b - last) / sr < mioi)
			continue;
		if (nj == jc) {
			size_t nc = jc ? 2 * jc : 64;
			long *g = realloc(j, nc * sizeof *g);

			if (g == NULL) {
				free(j);
				free(m);
				return -1;
			}
			j = g;
			jc = nc;
		}
		j[nj++] = last = k * b;
	}
	free(m);
	/* merge */
	if (nj > 0) {
		size_t tot = *nr + nj, a = 0, q = 0, o = 0;
		long *mg = malloc(tot * sizeof *mg);
		long w = (long)(mioi * sr);

		if (mg == NULL) {
			free(j);
			return -1;
		}
		while (a < *nr || q < nj) {
			if (q < nj && (a == *nr || j[q] <= (*rough)[a])) {
				mg[o++] = j[q++];
				while (a < *nr && (*rough)[a] - mg[o - 1] < w)
					a++; /* aubio's time of the same click */
			} else {
				if (q < nj && j[q] - (*rough)[a] < w) {
					a++;
					continue;
				}
				mg[o++] = (*rough)[a++];
			}
		}
		free(*rough);
		*rough = mg;
		*nr = o;
		*rcap = tot;
	}
	free(j);
	return 0;
}

/* Appends to r's arrays (t, peak), growing them. */
static int
push(struct hb_onset_result *r, size_t *cap, double t, double peak)
{
	if (r->n == *cap) {
		size_t nc = *cap ? 2 * *cap : 64;
		double *a = realloc(r->t, nc * sizeof *a), *b;

		if (a == NULL)
			return -1;
		r->t = a;
		if ((b = realloc(r->peak, nc * sizeof *b)) == NULL)
			return -1;
		r->peak = b;
		*cap = nc;
	}
	r->t[r->n] = t;
	r->peak[r->n] = peak;
	r->n++;
	return 0;
}

int
hb_onset_detect(const char *path, const struct hb_onset_options *o, struct hb_onset_result *r,
             char *msg, size_t n)
{
	const char *method = o != NULL && o->method != NULL ? o->method : "hfc";
	double thr = o != NULL && o->threshold > 0 ? o->threshold : 0.3;
	double mioi = o != NULL && o->min_interval > 0 ? o->min_interval : 0.002;
	double level = o != NULL && o->level > 0 ? o->level : 0.3;
	char alog[256] = "", why[256];
	float *x = NULL, loud = 0;
	size_t nx = 0, cap = 0, nr = 0, rcap = 0, nc = 0, nabove = 0;
	long *rough = NULL;
	struct onset_cand *c = NULL;
	const struct aubio_api *A;
	aubio_onset_t *od = NULL;
	fvec_t *in = NULL, *out = NULL;
	double sr, gate;
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
	sr = r->samplerate;
	r->duration = (double)nx / sr;
	r->noise = noise_floor(x, nx, sr);
	if (envelope(x, nx, sr, r) != 0)
		goto nomem;
	od = A->new_aubio_onset(method, WIN, HOP, (uint_t)sr);
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
	if (in == NULL || out == NULL)
		goto nomem;
	/* aubio's candidates: rough times, a hop or two off. */
	for (size_t s = 0; s < nx; s += HOP) {
		long t;

		for (uint_t i = 0; i < HOP; i++)
			A->fvec_set_sample(in, s + i < nx ? x[s + i] : 0, i);
		A->aubio_onset_do(od, in, out);
		if (A->fvec_get_sample(out, 0) == 0)
			continue;
		t = (long)A->aubio_onset_get_last(od);
		if (t >= (long)nx)
			t = (long)nx - 1;
		if (t < 0 || (nr > 0 && t <= rough[nr - 1]))
			continue;
		if (nr == rcap) {
			size_t ncap = rcap ? 2 * rcap : 64;
			long *g = realloc(rough, ncap * sizeof *g);

			if (g == NULL)
				goto nomem;
			rough = g;
			rcap = ncap;
		}
		rough[nr++] = t;
	}
	r->ncand = nr;
	for (size_t k = 0; k < nx; k++)
		if (fabsf(x[k]) > loud)
			loud = fabsf(x[k]);
	/* Above the noise, and above -60 dB of the loudest sound (a clean take). */
	gate = fmax(GATE * r->noise, 1e-3 * loud);
	if (add_jumps(x, nx, sr, gate, mioi, &rough, &nr, &rcap) != 0)
		goto nomem;
	if ((c = calloc(nr ? nr : 1, sizeof *c)) == NULL)
		goto nomem;
	/* Each candidate in its own neighbourhood. */
	for (size_t k = 0; k < nr; k++) {
		long reach = (long)(REACH * sr), lo, hi, on;
		float P;

		lo = rough[k] - reach > 0 ? rough[k] - reach : 0;
		if (k > 0 && lo < (rough[k - 1] + rough[k] + 1) / 2)
			lo = (rough[k - 1] + rough[k] + 1) / 2;
		hi = rough[k] + reach < (long)nx ? rough[k] + reach : (long)nx;
		if (k + 1 < nr && hi > (rough[k] + rough[k + 1] + 1) / 2)
			hi = (rough[k] + rough[k + 1] + 1) / 2;
		if (lo >= hi)
			continue;
		on = refine(x, lo, hi, sr, level, gate, &P);
		if (on < 0)
			continue;
		/* the same click found twice: keep the louder */
		if (nc > 0 && (double)on / sr - c[nc - 1].t < mioi) {
			if (P > c[nc - 1].peak) {
				c[nc - 1].t = (double)on / sr;
				c[nc - 1].peak = P;
			}
			continue;
		}
		c[nc].t = (double)on / sr;
		c[nc].peak = P;
		nc++;
	}
	for (size_t k = 0; k < nc; k++)
		nabove += c[k].peak >= gate;
	if (nabove > MAX_CAND) {
		st = hb_status_set(msg, n, HB_EINVAL, "%s: %zu clicks above the noise in %.3g s, "
		    "more than the %d weighed: no recording of one bouncing sequence; accepted: a "
		    "take cut to the bounces", path, nabove, r->duration, MAX_CAND);
		goto out;
	}
	why[0] = '\0';
	onset_sequence(c, nc, gate, fmax(2 / sr, 5e-5), why, sizeof why);
	if (strcmp(why, "out of memory") == 0)
		goto nomem;
	if (nc > 0 && (r->drop = calloc(nc, sizeof *r->drop)) == NULL)
		goto nomem;
	for (size_t k = 0; k < nc; k++) {
		if (c[k].keep) {
			if (push(r, &cap, c[k].t, c[k].peak) != 0)
				goto nomem;
		} else {
			r->drop[r->ndrop].t = c[k].t;
			r->drop[r->ndrop].peak = c[k].peak;
			memcpy(r->drop[r->ndrop].why, c[k].why, sizeof c[k].why);
			r->ndrop++;
		}
	}
	if (!(loud > GATE * r->noise))
		st = hb_status_set(msg, n, HB_EINVAL, "%s: nothing in its %.3g s rises above %g x "
		    "the noise (the loudest sample %.2g, the noise rms %.2g of full scale): a silent "
		    "take, or one too noisy to time impacts (record closer to the impact or in a "
		    "quieter place: a lower --onset-threshold only finds more noise); accepted: a "
		    "recording of a bouncing sequence", path, r->duration, GATE, loud, r->noise);
	else if (nr == 0)
		st = hb_status_set(msg, n, HB_EINVAL, "%s: no onsets found in %.3g s of sound "
		    "(noise rms %.2g of full scale): aubio's detector (method %s, threshold %g) "
		    "fired nowhere; lower --onset-threshold (e.g. 0.1), or try --onset-method "
		    "energy", path, r->duration, r->noise, method, thr);
	else if (nabove == 0)
		st = hb_status_set(msg, n, HB_EINVAL, "%s: no click rises above %g x the noise "
		    "(%zu found, the noise rms %.2g of full scale over the quietest 10 ms): the "
		    "take is too noisy to time impacts; record closer to the impact or in a "
		    "quieter place (a lower --onset-threshold only finds more noise); accepted: a "
		    "recording of clicks above the noise", path, GATE,
		    nc, r->noise);
	else if (why[0])
		st = hb_status_set(msg, n, HB_EINVAL, "%s: %s; not fitted (the clicks found are "
		    "listed above: --onsets-out FILE writes them, to correct by hand and fit "
		    "with --data FILE); accepted: a recording of one bouncing sequence", path, why);
out:
	if (od != NULL)
		A->del_aubio_onset(od);
	if (in != NULL)
		A->del_fvec(in);
	if (out != NULL)
		A->del_fvec(out);
	free(x);
	free(rough);
	free(c);
	if (A != NULL)
		A->aubio_log_reset();
	return st;
nomem:
	st = hb_status_set(msg, n, HB_ENOMEM, "out of memory");
	goto out;
}
