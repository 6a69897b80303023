/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * pane_status.c - the status line, the message (or prompt) line, the
 * footer (the explorer's keys, from its table) and the "terminal too
 * small" screen.
 * Drawing only: reads the state, never changes it.
 */
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "keys.h"
#include "scene.h"
#include "spacetime.h"
#include "layout.h"
#include "term.h"
#include "mode.h"
#include "tui.h"
#include "units.h"

static const char *
state_name(const struct app *a, char *buf, size_t n)
{
	const char *s;

	switch (hb_sim_end(a->sim)) {
	case HB_SIM_RUNNING: return "computing";
	case HB_SIM_END_FAIL: s = "failed"; break;
	default: s = "finished"; break;
	}
	if (a->phys.valid && a->phys.failed > 0) {
		/* the physics checks (physics.c): what batch warns of */
		if (hb_sim_end(a->sim) == HB_SIM_END_FAIL)
			snprintf(buf, n, "%s, %d check%s", s, a->phys.failed,
			         a->phys.failed == 1 ? " fails" : "s fail");
		else
			snprintf(buf, n, "fails %d check%s", a->phys.failed,
			         a->phys.failed == 1 ? "" : "s");
		return buf;
	}
	return s;
}

/*
 * The readout line: the sample at the cursor, whole: its index, t with
 * enough digits to tell it from its neighbours, j, q_c, x, v, x_c, F_c and
 * the law's internal state z_c, with units.
 */
static void
readout_draw(const struct app *a)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct rect *r = &a->L.readout;
	const struct hb_arc_sample *s;
	char f[10][96], tb[48], vb[32], line[512];
	int sig, nf = 0, row = 0, col = 0;

	if (r->h < 1 || hb_arc_len(arc) == 0)
		return;
	s = hb_arc_at(arc, a->cursor);
	/* digits of t: enough that both neighbours read differently */
	for (sig = 6; sig < 17; sig++) {
		char p[48], nb[48];
		int ok = 1;
		hb_units_format(s->t, hb_unit_time, sig, tb, sizeof tb);
		if (a->cursor > 0 && hb_arc_at(arc, a->cursor - 1)->t != s->t) {
			hb_units_format(hb_arc_at(arc, a->cursor - 1)->t, hb_unit_time, sig, p, sizeof p);
			ok = ok && strcmp(p, tb) != 0;
		}
		if (a->cursor + 1 < hb_arc_len(arc) && hb_arc_at(arc, a->cursor + 1)->t != s->t) {
			hb_units_format(hb_arc_at(arc, a->cursor + 1)->t, hb_unit_time, sig, nb, sizeof nb);
			ok = ok && strcmp(nb, tb) != 0;
		}
		if (ok)
			break;
	}
	snprintf(f[nf++], sizeof f[0], "#%zu", a->cursor);
	snprintf(f[nf++], sizeof f[0], "t=%s", tb);
	snprintf(f[nf++], sizeof f[0], "j=%ld", s->j);
	snprintf(f[nf++], sizeof f[0], "q_c=%d", s->q);
	/* error bars (E): the selected collision's e, as many digits as its bar allows
	 * (before the sample's values: a narrow readout leaves those out first) */
	if (errbar_on(a) && a->table_sel >= 0 && a->table_sel < app_ncollisions(a)) {
		struct hb_collision live;
		const struct hb_collision *c = app_collision(a, a->table_sel, &live);
		const struct hb_collision *d = c != NULL ? errbar_find(a, c->i) : NULL;

		if (d != NULL) {
			char e[80];

			errbar_format("e", c->e, d->e, e, sizeof e);
			snprintf(f[nf++], sizeof f[0], "coll %ld: %s", c->i, e);
		}
	}
	hb_units_format(s->x, hb_unit_length, 4, vb, sizeof vb);
	snprintf(f[nf++], sizeof f[0], "x=%s", vb);
	hb_units_format(s->v, hb_unit_velocity, 4, vb, sizeof vb);
	snprintf(f[nf++], sizeof f[0], "v=%s", vb);
	hb_units_format(s->xc, hb_unit_length, 4, vb, sizeof vb);
	snprintf(f[nf++], sizeof f[0], "x_c=%s", vb);
	hb_units_format(s->Fc, hb_unit_force, 4, vb, sizeof vb);
	snprintf(f[nf++], sizeof f[0], "F_c=%s", vb);
	if (hb_sim_scene(a->sim)->law->n_z > 0) {
		f[nf][0] = 0;
		for (int k = 0; k < hb_sim_scene(a->sim)->law->n_z && k < HB_LAW_MAX_Z; k++) {
			size_t l = strlen(f[nf]);
			snprintf(f[nf] + l, sizeof f[0] - l, "%sz_c%d=%.4g", k ? " " : "", k + 1, s->z[k]);
		}
		nf++;
	}
	/* fields in order, wrapped onto the readout's rows; what does not fit is left out */
	line[0] = 0;
	for (int i = 0; i < nf; i++) {
		int w = (int)strlen(f[i]) + (col ? 1 : 0);
		if (col + w > r->w) {
			if (row + 1 >= r->h) {
				/* no row left for the rest: the mark says it is left out */
				snprintf(line + strlen(line), sizeof line - strlen(line), "%*s", r->w, "");
				tui_puts(r->y + row, r->x, r->w, line, 0);
				mvaddstr(r->y + row, r->x + r->w - 1, tui_cut_mark());
				return;
			}
			tui_puts(r->y + row, r->x, r->w, line, 0);
			row++;
			line[0] = 0;
			col = 0;
			w = (int)strlen(f[i]);
		}
		if (w > r->w)
			continue;
		/* (w <= r->w, so the field fits the line; the return value is only a check) */
		if (snprintf(line + strlen(line), sizeof line - strlen(line), "%s%s", col ? " " : "",
		             f[i]) < 0)
			break;
		col += w;
	}
	tui_puts(r->y + row, r->x, r->w, line, 0);
}

/*
 * A script's caption shown large: a box in the middle of the plots, the
 * text wrapped inside with a blank row and two blank columns around it,
 * in bold (reversed on a colour terminal, for the back of a lecture hall).
 */
static void
caption_large_draw(const struct app *a)
{
	const struct rect *p = &a->L.plots;
	int w = a->L.cols - 8, rows, h, y, x;
	struct rect in;

	if (w > 72)
		w = 72;
	if (w < 20)
		w = a->L.cols;
	rows = tui_wrap_rows(a->caption, w - 8);
	h = rows + 4;
	if (h > a->L.lines - 2)
		h = a->L.lines - 2;
	y = p->y + (p->h - h) / 2;
	if (y < 1)
		y = 1;
	x = (a->L.cols - w) / 2;
	in = box_draw(y, x, h, w, "");
	tui_wrap_draw(in.y + 1, in.x + 2, in.w - 4, in.h - 2, a->caption, A_BOLD);
}

void
pane_status_draw(const struct app *a)
{
	const struct hb_arc *arc = hb_sim_arc(a->sim);
	const struct hb_arc_sample *s = hb_arc_len(arc) ? hb_arc_at(arc, a->cursor) : NULL;
	char line[1024], tb[32], sp[32], foot[512];
	int attr = a->colour ? COLOR_PAIR(PAIR_STATUS) : A_REVERSE;
	const struct rect *r = &a->L.status;

	if (s != NULL)
		hb_units_format(s->t, hb_unit_time, 5, tb, sizeof tb);
	else
		snprintf(tb, sizeof tb, "-");
	hb_units_format(a->speed, hb_unit_none, 2, sp, sizeof sp);
	{
		char tail[256], st[48], eb[48], ib[24];
		int room;
		errbar_state(a, eb, sizeof eb);
		snprintf(tail, sizeof tail, " %s%s t=%s j=%ld q_c=%d coll %zu x%s%s %s %s%s%s",
		         hb_sim_scene(a->sim)->law->name, spacetime_state(a, ib, sizeof ib), tb,
		         s ? s->j : 0L, s ? s->q : 0,
		         hb_sim_ncollisions(a->sim), sp, a->in_slow ? " slow" : "",
		         a->playing ? "playing" : "paused", state_name(a, st, sizeof st),
		         eb[0] ? " " : "", eb);
		room = r->w - (int)strlen(tail) - 1;
		if (room < 8)
			room = 0; /* a narrow terminal: the run's state before the preset's name */
		if ((int)strlen(a->preset) > room && room > 0)
			/* the name cut, marked: the log's first message and o show it whole */
			snprintf(line, sizeof line, " %.*s%s%s", room - 1, a->preset, tui_cut_mark(), tail);
		else
			snprintf(line, sizeof line, "%s%.*s%s", room ? " " : "", room, a->preset, tail);
	}
	attron(attr);
	mvhline(r->y, 0, ' ', r->w);
	attroff(attr);
	tui_puts(r->y, 0, r->w, line, attr);
	/* the readout first: a long prompt's title goes over it */
	readout_draw(a);

	/* message or prompt */
	r = &a->L.msg;
	if (mode_on(a, &mode_prompt)) {
		/*
		 * Too long for the line: the caret stays in view.  A text as
		 * given (the first printable key replaces it) is shown reversed;
		 * else the character under the caret is.
		 */
		int cols = 0, pre = 0, caret, vcols = 0, skip, x0 = 0, tcols = 0, vtext = 0;
		size_t l = strlen(a->prompt_buf), pos = a->prompt_pos > l ? l : a->prompt_pos;
		const char *p, *title = a->prompt_title;
		for (p = title; *p; p++)
			tcols += ((unsigned char)*p & 0xC0) != 0x80;
		for (p = a->prompt_buf; *p; p++)
			vtext += ((unsigned char)*p & 0xC0) != 0x80;
		if (a->prompt_kind == PROMPT_EDIT && tcols + 2 + vtext + 1 <= r->w && r->y > 0) {
			/*
			 * Editing a value: its description whole on the rows above
			 * (the panel's header may have cut it), at most 2.
			 */
			const struct hb_scene *sc = hb_sim_scene(a->sim);
			struct hb_scene_keyinfo ki;
			for (int k = 0; k < hb_scene_nkeys(sc); k++) {
				if (hb_scene_key(sc, k, &ki) != 0 || strcmp(ki.key, a->prompt_key) != 0)
					continue;
				char d[512];
				snprintf(d, sizeof d, "%s: %s", ki.key, ki.help);
				int rows = tui_wrap_rows(d, r->w - 1), top;
				if (rows > 2)
					rows = 2;
				top = r->y - rows < 0 ? 0 : r->y - rows;
				for (int y = top; y < r->y; y++)
					mvhline(y, 0, ' ', r->w);
				tui_wrap_draw(top, 0, r->w - 1, r->y - top, d, A_DIM);
				break;
			}
		} else if (tcols + 2 + vtext + 1 > r->w && r->y > 0) {
			/*
			 * Title and text do not fit one line: the title whole on
			 * the rows above (over the readout, at most 3), the text
			 * alone on the line.
			 */
			int rows = tui_wrap_rows(title, r->w - 2), top;
			if (rows > 3)
				rows = 3;
			top = r->y - rows < 0 ? 0 : r->y - rows;
			for (int y = top; y < r->y; y++)
				mvhline(y, 0, ' ', r->w);
			/* the line keeps the title's last part after "; " as its label */
			const char *label = strrchr(title, ';');
			char t[sizeof a->prompt_title + 2];
			snprintf(t, sizeof t, "%s%s", title, label ? "" : ":");
			tui_wrap_draw(top, 0, r->w - 1, r->y - top, t, A_BOLD);
			title = label ? label + 1 + (label[1] == ' ') : "";
		}
		snprintf(line, sizeof line, "%s%s%s_", title, *title ? ": " : "", a->prompt_buf);
		for (p = line; *p; p++)
			cols += ((unsigned char)*p & 0xC0) != 0x80;
		for (p = title; *p; p++)
			pre += ((unsigned char)*p & 0xC0) != 0x80;
		pre += *title ? 2 : 0;
		for (size_t i = 0; i < l; i++)
			if (((unsigned char)a->prompt_buf[i] & 0xC0) != 0x80) {
				vcols++;
			}
		caret = pre;
		for (size_t i = 0; i < pos; i++)
			caret += ((unsigned char)a->prompt_buf[i] & 0xC0) != 0x80;
		skip = (pos == l ? cols : caret + 1) - (r->w - 1);
		p = line;
		if (skip > 0) {
			int drop = skip + 3;
			for (; *p && drop > 0; p++)
				drop -= ((unsigned char)p[1] & 0xC0) != 0x80;
			tui_puts(r->y, 0, 3, "...", A_BOLD);
			tui_puts(r->y, 3, r->w - 3, p, A_BOLD);
			x0 = 3 - (skip + 3);
		} else {
			tui_puts(r->y, 0, r->w, line, A_BOLD);
		}
		if (a->prompt_fresh && vcols > 0) {
			int from = pre + x0 < 3 && skip > 0 ? 3 : pre + x0;
			int to = pre + vcols + x0;
			if (to > from && from < r->w)
				mvchgat(r->y, from, (to < r->w ? to : r->w) - from, A_BOLD | A_REVERSE, 0, NULL);
		} else if (caret + x0 >= 0 && caret + x0 < r->w) {
			mvchgat(r->y, caret + x0, 1, A_BOLD | A_REVERSE, 0, NULL);
		}
	} else if (a->caption[0] && a->caption_large && strcmp(a->msg, a->caption) == 0) {
		/* shown large over the plots (caption_large_draw) */
	} else if (a->caption[0] && !a->caption_large && strcmp(a->msg, a->caption) == 0) {
		/* a script's caption: whole, wrapped over the rows above the line (at most 4) */
		int rows = tui_wrap_rows(a->caption, r->w - 1), top;
		if (rows > 4)
			rows = 4;
		top = r->y - rows + 1 < 0 ? 0 : r->y - rows + 1;
		for (int y = top; y <= r->y; y++)
			mvhline(y, 0, ' ', r->w);
		tui_wrap_draw(top, 0, r->w - 1, r->y - top + 1, a->caption, A_BOLD);
	} else {
		int mattr = a->msg_error ? (a->colour ? COLOR_PAIR(PAIR_ERROR) | A_BOLD : A_BOLD) : 0;
		static const char more[] = "... m: whole";
		if ((int)strlen(a->msg) > r->w - 1 && r->w > (int)sizeof more + 8) {
			int keep = r->w - 1 - (int)strlen(more);
			snprintf(line, sizeof line, "%.*s%s", keep, a->msg, more);
			tui_puts(r->y, 0, r->w, line, mattr);
		} else {
			tui_puts(r->y, 0, r->w, a->msg, mattr);
		}
	}

	r = &a->L.footer;
	if (a->nmodes == 0) {
		/* nothing open yet */
	} else if (a->demo_ctx != 0) {
		/* a demo on the real screen: what the viewer's keys do now */
		tui_puts(r->y, 0, r->w, demo_hint(a, foot, sizeof foot), A_BOLD);
	} else {
		/* the explorer's keys (the bottom mode); the sweep view draws its own */
		keys_footer(a->mode[0], mode_context(a, a->mode[0]), foot, sizeof foot, r->w - 1);
		tui_puts(r->y, 0, r->w, foot, A_DIM);
	}
	if (a->caption[0] && a->caption_large && strcmp(a->msg, a->caption) == 0)
		caption_large_draw(a);
}

void
pane_too_small_draw(const struct app *a)
{
	char line[128];
	int y = a->L.lines / 2;

	snprintf(line, sizeof line, "terminal too small: need at least %dx%d", LAYOUT_MIN_COLS,
	         LAYOUT_MIN_LINES);
	if (a->L.cols < 40)
		snprintf(line, sizeof line, "too small: min %dx%d", LAYOUT_MIN_COLS, LAYOUT_MIN_LINES);
	tui_puts(y > 0 ? y - 1 : 0, 0, a->L.cols, line, A_BOLD);
	snprintf(line, sizeof line, "(now %dx%d; q quits)", a->L.cols, a->L.lines);
	tui_puts(y, 0, a->L.cols, line, 0);
}
