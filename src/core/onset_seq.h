/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * onset_seq.h - which candidate clicks of a recording form a bouncing
 * sequence (see onset.h).  Private to onset.c; a file of its own so that
 * the model can be read, and tested, apart from the sound.
 */
#ifndef HYBOUNCE_ONSET_SEQ_H
#define HYBOUNCE_ONSET_SEQ_H

#include <stddef.h>

struct onset_cand {
	double t;      /* refined onset, s */
	double peak;   /* peak |amplitude| of the click */
	int keep;      /* out: 1 if an impact of the sequence */
	char why[128]; /* out: the reason, when not kept */
};

/*
 * Marks the candidates (ascending t) that form the longest consistent
 * bouncing sequence: every peak above gate; from one impact to the next the
 * peak at most LOUDER times the one before and at least FAINTER of it;
 * each ratio of consecutive intervals in (RATIO_MIN, 1 + tolerance), the
 * tolerance from dt, the timing noise of one onset (s).  Among runs of the
 * same length the loudest.  Returns the number kept; when that is no
 * bouncing sequence (fewer than HB_ONSET_MIN_IMPACTS, a last interval not
 * clearly shorter than the first, or fewer kept than dropped for breaking
 * it), 0 with the reason in why (the marks stay, for showing).
 */
size_t
onset_sequence(struct onset_cand *c, size_t n, double gate, double dt, char *why, size_t nwhy);

#endif
