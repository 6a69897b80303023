/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * playback.c - the cursor moving in simulated time, and the views.
 *
 * Playback is separate from computation: the cursor advances in
 * simulated time at the chosen speed (simulated seconds per wall second),
 * slowed inside contacts when slow motion is on, and never passes the last
 * computed sample.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "term.h"
#include "tui.h"
#include "units.h"

#define SLOW_WALL 2.0         /* a contact lasts about this many wall seconds in slow motion */
#define SLOW_SPAN 3.0         /* slow motion ends this many contact durations after t_e */

/* Steps a speed along the 1-2-5 sequence (dir 0: rounds onto it). */
static double
speed_step(double s, int dir)
{
	double e = floor(log10(s) + 1e-9), p = pow(10, e), m = s / p;

	if (m < 1.5)
		m = 1;
	else if (m < 3.5)
		m = 2;
	else
		m = 5;
	if (dir > 0)
		m = m == 1 ? 2 : m == 2 ? 5 : 10;
	else if (dir < 0)
		m = m == 1 ? 0.5 : m == 2 ? 1 : 2;
	s = m * p;
	if (s < 1e-7)
		s = 1e-7;
	if (s > 100)
		s = 100;
	return s;
}

double
speed_default(double T)
{
	if (!(T > 0) || !isfinite(T))
		T = 1;
	return speed_step(T / 20 * 0.99, 0);
}

const char *
stiff_note(const struct app *a, char *buf, size_t n)
{
	const struct hb_sim_stats *st = hb_sim_stats(a->sim);
	char tb[32];

	buf[0] = '\0';
	if (!st->stiff)
		return buf;
	hb_units_format(st->stiff_t, hb_unit_time, 4, tb, sizeof tb);
	if (st->switched)
		snprintf(buf, n, "; stiff contact at t = %s: auto went over to bsimp", tb);
	else
		snprintf(buf, n, "; stiff contact at t = %s: run.stepper = auto (or bsimp) is faster",
		         tb);
	return buf;
}

/*
 * Presentation: widens each quantity's held range with the samples not
 * seen yet of the runs drawn (the pins, then the current run); a change
 * of those runs (a pin, or an edit: the current run's scene changed)
 * starts again from their first samples.
 */
void
hold_update(struct app *a)
{
	const struct hb_sim *s[APP_MAX_PINS + 1];
	int n = 0, same;

	for (int i = 0; i < a->npins; i++)
		s[n++] = a->pin[i].sim;
	s[n++] = a->sim;
	same = n == a->hold.n
	       && memcmp(&a->hold.scene, hb_sim_scene(a->sim), sizeof a->hold.scene) == 0;
	for (int k = 0; same && k < n; k++)
		same = s[k] == a->hold.sim[k] && a->hold.seen[k] <= hb_arc_len(hb_sim_arc(s[k]));
	if (!same) {
		a->hold.n = n;
		memcpy(&a->hold.scene, hb_sim_scene(a->sim), sizeof a->hold.scene);
		for (int k = 0; k < n; k++) {
			a->hold.sim[k] = s[k];
			a->hold.seen[k] = 0;
		}
		for (int q = 0; q < 3; q++)
			a->hold.lo[q] = a->hold.hi[q] = 0;
	}
	for (int k = 0; k < n; k++) {
		const struct hb_arc *arc = hb_sim_arc(s[k]);
		size_t len = hb_arc_len(arc);
		for (size_t i = a->hold.seen[k]; i < len; i++) {
			const struct hb_arc_sample *p = hb_arc_at(arc, i);
			double v[3] = { p->x, p->xc, p->Fc };
			for (int q = 0; q < 3; q++)
				if (isfinite(v[q])) {
					a->hold.lo[q] = fmin(a->hold.lo[q], v[q]);
					a->hold.hi[q] = fmax(a->hold.hi[q], v[q]);
				}
		}
		a->hold.seen[k] = len;
	}
}

int
playback_tick(struct app *a, double dt)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *cs, *ls;
	double sp = a->speed, tnew;
	size_t k;

	if (a->present)
		hold_update(a);
	a->in_slow = 0;
	if (!a->playing || hb_arc_len(arc) == 0)
		return 0;
	cs = hb_arc_at(arc, a->cursor);
	ls = hb_arc_last(arc);
	k = hb_arc_interval_of(arc, a->cursor);
	if (a->slowmo && cs->q) {
		/* a contact as long as the last completed one takes SLOW_WALL
		 * seconds; a contact that lasts far longer (a permanent
		 * contact) is played at the normal speed after a while */
		double td = 1e-3;
		size_t nc = hb_sim_ncollisions(a->sim);
		const struct hb_arc_interval *iv = hb_arc_interval_at(arc, k);
		if (nc > 0 && hb_sim_collision(a->sim, nc - 1)->td > 0)
			td = hb_sim_collision(a->sim, nc - 1)->td;
		if (a->tcur - iv->t0 < SLOW_SPAN * td) {
			if (sp > td / SLOW_WALL)
				sp = td / SLOW_WALL;
			a->in_slow = 1;
			a->slow_t0 = iv->t0;
			a->slow_td = td;
		}
	}
	tnew = a->tcur + sp * dt;
	/* slow motion: stop at the start of a contact rather than skip it */
	if (a->slowmo && !cs->q && k + 1 < hb_arc_nintervals(arc)) {
		const struct hb_arc_interval *nx = hb_arc_interval_at(arc, k + 1);
		if (nx->q && nx->t0 <= tnew) {
			cursor_set(a, nx->first);
			return 1;
		}
	}
	if (tnew >= ls->t) {
		a->tcur = ls->t;
		a->cursor = hb_arc_len(arc) - 1;
		if (hb_sim_end(a->sim) != HB_SIM_RUNNING) {
			char note[160];

			if (a->present) {
				/* presentation mode loops */
				cursor_set(a, 0);
				return 1;
			}
			a->playing = 0;
			app_msg(a, 0, "end of the run: %s%s", hb_sim_end_str(a->sim),
			        stiff_note(a, note, sizeof note));
		}
	} else {
		a->tcur = tnew;
		a->cursor = hb_arc_find_t(arc, tnew);
	}
	return 1;
}

/* ---- actions ---------------------------------------------------------- */

void
act_play(struct app *a)
{
	a->playing = !a->playing;
	if (a->playing && hb_sim_end(a->sim) != HB_SIM_RUNNING && a->cursor + 1 >= hb_arc_len(hb_sim_arc(a->sim)))
		cursor_set(a, 0); /* at the end of a finished run: play it again */
}

void act_faster(struct app *a) { a->speed = speed_step(a->speed, 1); }
void act_slower(struct app *a) { a->speed = speed_step(a->speed, -1); }

void
act_slowmo(struct app *a)
{
	a->slowmo = !a->slowmo;
	app_msg(a, 0, "slow motion through contacts %s", a->slowmo ? "on" : "off");
}

void
act_view(struct app *a)
{
	a->view = (a->view + 1) % VIEW_COUNT;
	if ((a->view == VIEW_ZOOM || a->view == VIEW_LOOP) && app_ncollisions(a) == 0)
		a->view = VIEW_J;
	if ((a->view == VIEW_ZOOM || a->view == VIEW_LOOP) && a->zoom_i >= app_ncollisions(a))
		a->zoom_i = app_ncollisions(a) - 1;
}

void act_zoom(struct app *a) { zoom_on(a, VIEW_ZOOM); }
void act_loop(struct app *a) { zoom_on(a, VIEW_LOOP); }
void act_jview(struct app *a) { a->view = a->view == VIEW_J ? VIEW_WHOLE : VIEW_J; }
