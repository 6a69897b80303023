/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset_seq.c - the longest run of candidate clicks that is a bouncing
 * sequence (see onset_seq.h).
 *
 * A ball's impacts get quieter and closer: the interval after an impact is
 * the interval before times that impact's restitution, a number in (0, 1),
 * and its speed, hence its loudness, falls with them.  A noise blip, a
 * handling knock or the echo of a click breaks that pattern.  The run kept
 * is found by dynamic programming over pairs of consecutive impacts (the
 * ratio test needs three): best[i][k] is the longest run ending with i then
 * k; O(n^3) in the candidates, which are capped by the caller.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hybounce/onset.h"
#include "onset_seq.h"

#define LOUDER 2.0      /* an impact at most this much louder than the one before */
#define FAINTER 0.05    /* ... and at least this fraction of it */
#define RATIO_MIN 0.05  /* the smallest restitution taken for a bounce */
#define RATIO_TOL 0.02  /* a restitution may exceed 1 by this, plus timing noise */
#define SHRINK 0.9      /* the last interval of a run is at most this of the first */
#define FAR 0.2         /* a click below this fraction of its neighbours is none */

/* 1 if the interval ratio (k - i) / (i - j) is a restitution up to noise. */
static int
ratio_ok(const struct onset_cand *c, size_t j, size_t i, size_t k, double dt)
{
	double a = c[i].t - c[j].t, b = c[k].t - c[i].t, r;

	if (!(a > 0 && b > 0))
		return 0;
	r = b / a;
	return r > RATIO_MIN && r < 1 + RATIO_TOL + 3 * dt * (1 / a + 1 / b);
}

static int
loud_ok(const struct onset_cand *c, size_t i, size_t k)
{
	return c[k].peak <= LOUDER * c[i].peak && c[k].peak >= FAINTER * c[i].peak;
}

/* Why candidate x, between kept impacts a and b (either may be none), is not one. */
static void
explain(struct onset_cand *c, size_t x, const size_t *kept, size_t nk, size_t pos, double gate)
{
	char *w = c[x].why;
	size_t ww = sizeof c[x].why;
	long a = pos > 0 ? (long)kept[pos - 1] : -1, b = pos < nk ? (long)kept[pos] : -1;

	if (c[x].peak < gate) {
		snprintf(w, ww, "no louder than the noise (peak %.2g; an impact rises above %.2g)",
		         c[x].peak, gate);
	} else if (a < 0 && b >= 0 && c[x].peak < FAR * c[b].peak) {
		snprintf(w, ww, "before the first impact and far quieter than it (%.2g%% of its peak)",
		         100 * c[x].peak / c[b].peak);
	} else if (a < 0) {
		snprintf(w, ww, "before the first impact, and does not lead into the sequence "
		         "(the intervals would not shrink)");
	} else if (b < 0 && c[x].peak > LOUDER * c[a].peak) {
		snprintf(w, ww, "after the last impact and %.3g times louder than it (a knock?)",
		         c[x].peak / c[a].peak);
	} else if (b < 0 && pos >= 2) {
		double r = (c[x].t - c[a].t) / (c[a].t - c[kept[pos - 2]].t);

		snprintf(w, ww, "after the last impact: the interval would grow by %.3g (a "
		         "restitution is below 1)", r);
	} else if (b < 0) {
		snprintf(w, ww, "after the last impact");
	} else if (c[x].peak < FAR * (c[a].peak < c[b].peak ? c[a].peak : c[b].peak)) {
		snprintf(w, ww, "far below the impacts on either side (%.2g%% of the quieter)",
		         100 * c[x].peak / (c[a].peak < c[b].peak ? c[a].peak : c[b].peak));
	} else if (c[x].peak > LOUDER * c[a].peak) {
		snprintf(w, ww, "%.3g times louder than the impact before (a knock?)",
		         c[x].peak / c[a].peak);
	} else {
		snprintf(w, ww, "between two impacts: it would split the interval %.3f ms into "
		         "%.3f + %.3f, which do not shrink as bounces do", 1e3 * (c[b].t - c[a].t),
		         1e3 * (c[x].t - c[a].t), 1e3 * (c[b].t - c[x].t));
	}
}

size_t
onset_sequence(struct onset_cand *c, size_t n, double gate, double dt, char *why, size_t nwhy)
{
	size_t *idx = malloc((n ? n : 1) * sizeof *idx), m = 0, *kept = NULL, nk = 0;
	int *len = NULL, *from = NULL;  /* m x m: run length ending (i, k); its j */
	double *score = NULL;           /* m x m: sum of the run's peaks */
	size_t bi = 0, bk = 0, nbreak = 0;
	int best = 0;
	double bs = -1;

	why[0] = '\0';
	for (size_t x = 0; x < n; x++) {
		c[x].keep = 0;
		c[x].why[0] = '\0';
	}
	if (idx == NULL)
		goto nomem;
	for (size_t x = 0; x < n; x++)
		if (c[x].peak >= gate)
			idx[m++] = x;
	if (m > 0) {
		len = calloc(m * m, sizeof *len);
		from = calloc(m * m, sizeof *from);
		score = calloc(m * m, sizeof *score);
		kept = calloc(m, sizeof *kept);
		if (len == NULL || from == NULL || score == NULL || kept == NULL)
			goto nomem;
	}
	if (m == 1) {
		best = 1;
		bi = bk = 0;
	}
	for (size_t k = 1; k < m; k++) {
		for (size_t i = 0; i < k; i++) {
			int L = 0;
			double S = 0;

			if (!loud_ok(c, idx[i], idx[k]))
				continue;
			L = 2;
			S = c[idx[i]].peak + c[idx[k]].peak;
			from[i * m + k] = -1;
			for (size_t j = 0; j < i; j++) {
				int l = len[j * m + i];
				double s;

				if (l < 2 || !ratio_ok(c, idx[j], idx[i], idx[k], dt))
					continue;
				s = score[j * m + i] + c[idx[k]].peak;
				if (l + 1 > L || (l + 1 == L && s > S)) {
					L = l + 1;
					S = s;
					from[i * m + k] = (int)j;
				}
			}
			len[i * m + k] = L;
			score[i * m + k] = S;
			if (L > best || (L == best && S > bs)) {
				best = L;
				bs = S;
				bi = i;
				bk = k;
			}
		}
	}
	/* Walk the best run back. */
	if (best >= 2) {
		size_t i = bi, k = bk, p = (size_t)best;

		nk = p;
		for (;;) {
			int j = from[i * m + k];

			kept[--p] = idx[k];
			if (j < 0 || p == 1) {
				kept[--p] = idx[i];
				break;
			}
			k = i;
			i = (size_t)j;
		}
	} else if (best == 1) {
		kept[0] = idx[0];
		nk = 1;
	}
	for (size_t p = 0; p < nk; p++)
		c[kept[p]].keep = 1;
	for (size_t x = 0, pos = 0; x < n; x++) {
		if (c[x].keep) {
			pos++;
			continue;
		}
		explain(c, x, kept, nk, pos, gate);
		if (c[x].peak >= gate && pos > 0 && pos < nk)
			nbreak++;
	}
	if (nk < HB_ONSET_MIN_IMPACTS)
		snprintf(why, nwhy, "no bouncing sequence: of %zu click%s above the noise, the "
		         "longest run that gets quieter and closer (each ratio of intervals in "
		         "(0, 1)) has %zu; at least %d impacts are needed", m, m == 1 ? "" : "s",
		         nk, HB_ONSET_MIN_IMPACTS);
	else if (c[kept[nk - 1]].t - c[kept[nk - 2]].t > SHRINK * (c[kept[1]].t - c[kept[0]].t))
		snprintf(why, nwhy, "no bouncing sequence: the %zu clicks of the longest "
		         "consistent run come at nearly even intervals (%.4g s, then %.4g s at the "
		         "end), where a ball's get shorter (footsteps, a metronome, a dripping tap?)",
		         nk, c[kept[1]].t - c[kept[0]].t, c[kept[nk - 1]].t - c[kept[nk - 2]].t);
	else if (nbreak > nk)
		snprintf(why, nwhy, "no clean bouncing sequence: %zu clicks fall between the %zu "
		         "impacts of the longest consistent run and break it (knocks, voices, "
		         "echoes?)", nbreak, nk);
	free(idx);
	free(len);
	free(from);
	free(score);
	free(kept);
	return why[0] ? 0 : nk;
nomem:
	free(idx);
	free(len);
	free(from);
	free(score);
	free(kept);
	snprintf(why, nwhy, "out of memory");
	return 0;
}
