/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_tui_keys.c - the explorer's modes and their key tables (mode.h,
 * the registry src/tui/modes.c), the key lists printed from them
 * (src/tui/keys.c), and the layout (src/tui/layout.c): pure functions, no
 * terminal.
 */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keys.h"
#include "mode.h"
#include "layout.h"
#include "testutil.h"
#include "tui.h"

/* The contexts a binding of mode m can apply in (CTX_ANY: all of them). */
static int
contexts(const struct mode *m, int *ctx)
{
	int n = 0;

	ctx[n++] = CTX_ANY;
	if (m == &mode_main) {
		ctx[0] = CTX_PARAMS;
		ctx[n++] = CTX_NOT_PARAMS;
	} else if (m == &mode_sweep) {
		ctx[0] = CTX_CURVE;
		ctx[n++] = CTX_MAP;
	}
	return n;
}

Test(keys, every_mode_has_keys_and_a_name)
{
	size_t n = 0;

	for (; tui_modes[n] != NULL; n++) {
		const struct mode *m = tui_modes[n];
		cr_assert(m->name && m->name[0] && m->title && m->title[0]);
		cr_assert(m->nkeys > 0, "mode %s has no keys", m->name);
		/* the explorer first, the only one without an opener */
		cr_assert_eq(m->opener == NULL, n == 0, "mode %s", m->name);
		for (size_t k = 0; k < n; k++)
			cr_assert(tui_modes[k] != m, "mode %s listed twice", m->name);
	}
	cr_assert(n >= 9, "%zu modes", n);
	cr_assert_eq(tui_modes[0], &mode_main);
}

Test(keys, no_key_bound_twice_in_one_context)
{
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		const struct mode_key *t = m->keys;
		for (size_t i = 0; i < m->nkeys; i++)
			for (size_t j = i + 1; j < m->nkeys; j++) {
				int same = t[i].key == t[j].key || (t[j].key2 && t[i].key == t[j].key2)
				           || (t[i].key2 && (t[i].key2 == t[j].key || t[i].key2 == t[j].key2));
				int overlap = t[i].ctx == 0 || t[j].ctx == 0 || t[i].ctx == t[j].ctx;
				cr_assert(!(same && overlap), "%s: '%s' (%s) and '%s' (%s) share a key", m->name,
				          t[i].label, t[i].help, t[j].label, t[j].help);
			}
	}
}

/* Each binding of each mode is what its keys find (mode_binding, the dispatch's lookup). */
Test(keys, every_binding_reachable)
{
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		int ctx[4], nc = contexts(m, ctx);
		for (size_t i = 0; i < m->nkeys; i++) {
			const struct mode_key *b = &m->keys[i];
			cr_assert(b->help && b->help[0] && b->label && b->label[0]);
			if (b->key == 0) {
				/* "any other key" in a context: the mode's loop acts on it, no lookup finds it */
				cr_assert(b->fn == NULL && strcmp(b->label, "other key") == 0, "%s: %s", m->name,
				          b->help);
				cr_assert_null(mode_binding(m, 0, b->ctx));
				continue;
			}
			cr_assert(b->fn != NULL, "%s: %s has no function", m->name, b->label);
			for (int c = 0; c < nc; c++) {
				if (b->ctx != CTX_ANY && b->ctx != ctx[c])
					continue;
				cr_assert_eq(mode_binding(m, b->key, ctx[c]), b, "%s: %s", m->name, b->label);
				if (b->key2)
					cr_assert_eq(mode_binding(m, b->key2, ctx[c]), b, "%s: %s", m->name, b->label);
			}
		}
		cr_assert_null(mode_binding(m, -12345, ctx[0]));
	}
	/* + is playback speed outside the panel and a nudge inside it */
	cr_assert_neq(mode_binding(&mode_main, '+', CTX_NOT_PARAMS)->fn,
	              mode_binding(&mode_main, '+', CTX_PARAMS)->fn);
	/* Enter comes as \n, \r or KEY_ENTER */
	cr_assert_eq(mode_binding(&mode_prompt, '\r', CTX_ANY), mode_binding(&mode_prompt, '\n', CTX_ANY));
}

Test(keys, names_round_trip)
{
	static const char *names[] = { "space", "Enter", "Tab", "Esc", "Left", "Right", "Up",
	                               "Down", "Home", "End", "PgUp", "PgDn", "q", "{", "3", "C-l" };
	char buf[32];

	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
		int k = keys_from_name(names[i]);
		cr_assert(k >= 0, "%s", names[i]);
		cr_assert_str_eq(keys_name(k, buf, sizeof buf), names[i]);
	}
	cr_assert_eq(keys_from_name("space"), ' ');
	cr_assert_eq(keys_from_name("C-c"), 3);
	cr_assert_eq(keys_from_name("NoSuchKey"), -1);
	/* every label's words are key names, and name the binding's keys */
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		for (size_t i = 0; i < m->nkeys; i++) {
			char lab[64], *save, *tok;
			int has1 = 0, has2 = m->keys[i].key2 == 0;
			if (m->keys[i].key == 0)
				continue; /* "other key" (every_binding_reachable) */
			snprintf(lab, sizeof lab, "%s", m->keys[i].label);
			for (tok = strtok_r(lab, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
				int c = keys_from_name(tok);
				cr_assert(c >= 0, "%s: label word '%s'", m->name, tok);
				has1 |= c == m->keys[i].key;
				has2 |= c == m->keys[i].key2;
				/* Enter and BSpace also come as another code (KEY_ENTER, DEL) */
				has2 |= strcmp(tok, "Enter") == 0 || strcmp(tok, "BSpace") == 0;
			}
			cr_assert(has1 && has2, "%s: the label '%s' does not name its keys", m->name,
			          m->keys[i].label);
		}
	}
}

Test(keys, footer_fits)
{
	char buf[512];

	keys_footer(&mode_main, CTX_NOT_PARAMS, buf, sizeof buf, 79);
	cr_assert(strlen(buf) <= 79);
	cr_assert(strstr(buf, "?:help") == buf);
	cr_assert(strstr(buf, "q:quit") != NULL);
	keys_footer(&mode_main, CTX_NOT_PARAMS, buf, sizeof buf, 10);
	cr_assert(strlen(buf) <= 10);
	/* the sweep view's footer, from its table: the curve's keys, the map's */
	keys_footer(&mode_sweep, CTX_CURVE, buf, sizeof buf, 79);
	cr_assert_str_eq(buf, "o:obs <>:collision r:range L:law b:bounds p:pin m:map e:export q:close ?:keys");
	keys_footer(&mode_sweep, CTX_MAP, buf, sizeof buf, 79);
	cr_assert_str_eq(buf, "o:obs <>:collision m:curve r:shades e:export q:close ?:keys");
	cr_assert(keys_has_footer(&mode_main) && !keys_has_footer(&mode_prompt));
}

/*
 * The hints in the titles of the help, the log, the pickers and the data
 * table, and the demo's footer, are printed from the modes' tables.
 */
Test(keys, hints_from_tables)
{
	char buf[256];

	cr_assert_str_eq(keys_hint(&mode_help, CTX_ANY, buf, sizeof buf),
	                 "Up/Down/PgUp/PgDn scroll, any other key closes");
	cr_assert_str_eq(keys_hint(&mode_log, CTX_ANY, buf, sizeof buf),
	                 "Up/Down/PgUp/PgDn scroll, any other key closes");
	cr_assert_str_eq(keys_hint(&mode_preset, CTX_ANY, buf, sizeof buf), "Enter opens, Esc closes");
	cr_assert_str_eq(keys_hint(&mode_law, CTX_ANY, buf, sizeof buf), "Enter chooses, Esc closes");
	cr_assert_str_eq(keys_hint(&mode_fit, CTX_ANY, buf, sizeof buf),
	                 "Up/Down scroll, F fits, any other key closes");
	cr_assert_str_eq(keys_hint(&mode_demo, CTX_DEMO_PLAY, buf, sizeof buf), "any key pauses, q quits");
	cr_assert_str_eq(keys_hint(&mode_demo, CTX_DEMO_PAUSED, buf, sizeof buf), "any key resumes, q quits");
	cr_assert_str_eq(keys_hint(&mode_demo, CTX_DEMO_KEY, buf, sizeof buf), "any key goes on, q quits");
	cr_assert_str_eq(keys_hint(&mode_demo, CTX_DEMO_END, buf, sizeof buf), "q quits");
	/* a binding not in the hint's context is left out; an empty table gives "" */
	cr_assert_str_eq(keys_hint(&mode_prompt, CTX_ANY, buf, sizeof buf), "");
}

/* The help's labels line up in each mode's list, however long the longest. */
Test(keys, help_labels_aligned)
{
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		char help[8192], *line, *save;
		int w = keys_label_width(m), col = -1;
		cr_assert(keys_help(m, help, sizeof help) < sizeof help);
		cr_assert_geq(w, 9);
		for (line = strtok_r(help, "\n", &save); line; line = strtok_r(NULL, "\n", &save)) {
			if (m->opener != NULL && strncmp(line, "In ", 3) == 0)
				continue;
			/* the text starts one column after the label's field: a blank before, none there */
			cr_assert(line[w] == ' ' && line[w + 1] != ' ', "mode %s: '%s' not at column %d",
			          m->name, line, w + 1);
			col = w + 1;
		}
		cr_assert_gt(col, 0);
	}
	/* the longest labels are wider than the old 9 columns */
	cr_assert_eq(keys_label_width(&mode_help), (int)strlen("PgDn space"));
}

/*
 * The text gen holds every key of mode m (in the form key(tok, out) gives),
 * and its heading when the mode has one; fails naming the key missing.
 */
static void
holds_every_key(const char *where, const char *gen, const struct mode *m,
                void (*form)(const char *tok, char out[][80], int *n))
{
	for (size_t i = 0; i < m->nkeys; i++) {
		char lab[64], *save, *tok;
		if (m->keys[i].key == 0) {
			cr_assert(strstr(gen, "any other key") != NULL || where[0] == 'h',
			          "%s: mode %s's other key missing", where, m->name);
			cr_assert(strstr(gen, m->keys[i].help + 1) != NULL, "%s: '%s' of mode %s missing",
			          where, m->keys[i].help, m->name);
			continue;
		}
		snprintf(lab, sizeof lab, "%s", m->keys[i].label);
		for (tok = strtok_r(lab, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
			char f[6][80];
			int nf = 0, found = 0;
			form(tok, f, &nf);
			for (int k = 0; k < nf; k++)
				found |= strstr(gen, f[k]) != NULL;
			cr_assert(found, "%s: key '%s' of mode %s (%s) missing", where, tok, m->name,
			          m->keys[i].help);
		}
		cr_assert(strstr(gen, m->keys[i].help) != NULL || where[0] == 'm',
		          "%s: '%s' of mode %s missing", where, m->keys[i].help, m->name);
	}
}

static void
man_form(const char *tok, char out[][80], int *n)
{
	snprintf(out[(*n)++], 80, "Ic %s\n", tok);
	snprintf(out[(*n)++], 80, "Ic \\&%s\n", tok);
	snprintf(out[(*n)++], 80, "Ic %s ", tok);
	snprintf(out[(*n)++], 80, "Ic \\&%s ", tok);
}

static void
help_form(const char *tok, char out[][80], int *n)
{
	snprintf(out[(*n)++], 80, "%s", tok);
}

/*
 * The man page's EXPLORER KEYS section holds the lists generated from the
 * tables, each mode's under its heading, and no key of any mode is missing
 * from them.
 */
Test(keys, man_page_matches_tables)
{
	char *man = slurp("man/hybounce.1"), *b, *e, gen[32768];

	cr_assert_not_null(man, "man/hybounce.1 not readable (run from the top folder)");
	b = strstr(man, ".\\\" KEYS-BEGIN");
	e = strstr(man, ".\\\" KEYS-END");
	cr_assert(b && e && b < e, "KEYS-BEGIN / KEYS-END markers missing");
	*e = 0;
	cr_assert(keys_man(tui_modes, gen, sizeof gen) < sizeof gen);
	cr_assert(strstr(b, gen) != NULL,
	          "the man page's key lists differ from keys_man(); regenerate them (make keys-doc)");
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		char one[8192];
		const struct mode *just[] = { m, NULL };
		/* the mode's own list (after its heading) is in the page, and holds each of its keys */
		cr_assert(keys_man(just, one, sizeof one) < sizeof one);
		cr_assert(strstr(b, one) != NULL, "mode %s: its list is not in the man page", m->name);
		holds_every_key("man page", one, m, man_form);
		if (m->opener != NULL)
			cr_assert(strstr(one, m->title) != NULL, "mode %s: no heading", m->name);
	}
	free(man);
}

/* The help (mode_help.c prints keys_help of each mode) names every key of every mode. */
Test(keys, help_lists_every_mode)
{
	for (size_t k = 0; tui_modes[k] != NULL; k++) {
		const struct mode *m = tui_modes[k];
		char help[8192];
		cr_assert(keys_help(m, help, sizeof help) < sizeof help);
		holds_every_key("help", help, m, help_form);
		if (m->opener != NULL) {
			char h[160];
			snprintf(h, sizeof h, "In %s (", m->title);
			cr_assert(strstr(help, h) == help, "mode %s: the help's heading '%s'", m->name, h);
		}
		if (m->other_help != NULL)
			cr_assert(strstr(help, m->other_help) != NULL);
	}
}

static int
inside(struct rect r, int cols, int lines)
{
	return r.y >= 0 && r.x >= 0 && r.y + r.h <= lines && r.x + r.w <= cols;
}

static int
disjoint(struct rect a, struct rect b)
{
	if (a.h == 0 || a.w == 0 || b.h == 0 || b.w == 0)
		return 1;
	return a.y + a.h <= b.y || b.y + b.h <= a.y || a.x + a.w <= b.x || b.x + b.w <= a.x;
}

Test(layout, sizes)
{
	struct layout L;
	int sizes[][2] = { { 60, 16 }, { 70, 20 }, { 80, 23 }, { 80, 24 }, { 100, 30 }, { 129, 40 },
	                   { 130, 40 }, { 160, 48 }, { 300, 90 } };

	cr_assert_eq(layout_compute(59, 24, 0, &L), -1);
	cr_assert(L.too_small);
	cr_assert_eq(layout_compute(80, 15, 0, &L), -1);
	cr_assert_eq(layout_compute(60, 15, 0, &L), -1);
	cr_assert_eq(layout_compute(60, 16, 0, &L), 0, "the documented minimum is 60x16");
	for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
		for (int p = 0; p < 2; p++) {
			int c = sizes[i][0], l = sizes[i][1];
			cr_assert_eq(layout_compute(c, l, p, &L), 0);
			struct rect r[] = { L.status, L.plots, L.table, L.params, L.readout, L.msg, L.footer };
			for (size_t k = 0; k < 7; k++) {
				cr_assert(inside(r[k], c, l), "%dx%d pane %zu outside", c, l, k);
				for (size_t m = k + 1; m < 7; m++)
					cr_assert(disjoint(r[k], r[m]), "%dx%d panes %zu and %zu overlap",
					          c, l, k, m);
			}
			/* full layout from 80x23 (an 80x24 terminal under tmux or screen) */
			cr_assert(L.plots.h >= (l >= 23 ? 12 : 8), "%dx%d: plots %d rows", c, l, L.plots.h);
			cr_assert(L.table.h + L.params.h >= (l >= 24 ? 7 : l >= 23 ? 6 : 4), "%dx%d: bottom pane", c, l);
			/* two rows where one would cut the values (23 lines and up, narrow) */
			cr_assert_eq(L.readout.h, l >= 23 && c < LAYOUT_READOUT_COLS ? 2 : 1, "%dx%d", c, l);
			cr_assert_eq(L.readout.y + L.readout.h, L.msg.y);
			cr_assert(L.table_visible || L.params_visible);
			cr_assert_eq(L.wide, c >= LAYOUT_WIDE_COLS);
			if (!L.wide)
				cr_assert_eq(L.params_visible, p);
			cr_assert_eq(L.footer.y, l - 1);
		}
}

Test(layout, presentation)
{
	struct layout L;

	cr_assert_eq(layout_compute(80, 24, 0, &L), 0);
	layout_present(&L);
	cr_assert(!L.table_visible && !L.params_visible);
	cr_assert_eq(L.plots.h, 19);
	cr_assert_eq(L.plots.w, 80);
	cr_assert_eq(L.readout.y, 20);
	cr_assert_eq(L.plots.y + L.plots.h, L.readout.y);
}

/* The README's Explorer section holds the Markdown key tables generated from the tables. */
Test(keys, readme_matches_tables)
{
	char *md = slurp("README.md"), *b, *e, gen[32768];

	cr_assert_not_null(md, "README.md not readable (run from the top folder)");
	b = strstr(md, "<!-- KEYS-BEGIN -->\n");
	e = strstr(md, "<!-- KEYS-END -->");
	cr_assert(b && e && b < e, "KEYS-BEGIN / KEYS-END markers missing in README.md");
	b += strlen("<!-- KEYS-BEGIN -->\n");
	*e = 0;
	cr_assert(keys_markdown(tui_modes, gen, sizeof gen) < sizeof gen);
	cr_assert_str_eq(b, gen, "the README's key tables differ from the modes' tables: make keys-doc");
	for (size_t k = 1; tui_modes[k] != NULL; k++) {
		char h[160];
		snprintf(h, sizeof h, "In %s (`", tui_modes[k]->title);
		cr_assert(strstr(b, h) != NULL, "README: no table for mode %s", tui_modes[k]->name);
	}
	free(md);
}

/* F1 and F10 are help and quit, as in htop and mc. */
Test(keys, function_keys)
{
	const struct mode_key *f1 = mode_binding(&mode_main, keys_from_name("F1"), CTX_NOT_PARAMS);
	const struct mode_key *q = mode_binding(&mode_main, 'q', CTX_PARAMS);

	cr_assert_not_null(f1);
	cr_assert_eq(mode_binding(&mode_main, '?', CTX_PARAMS), f1);
	cr_assert_not_null(q);
	cr_assert_eq(mode_binding(&mode_main, keys_from_name("F10"), CTX_PARAMS), q);
	/* Home and End move the list in the panel, the time cursor elsewhere */
	cr_assert_neq(mode_binding(&mode_main, keys_from_name("Home"), CTX_PARAMS)->fn,
	              mode_binding(&mode_main, keys_from_name("Home"), CTX_NOT_PARAMS)->fn);
	cr_assert_null(mode_binding(&mode_main, '1', CTX_NOT_PARAMS));
	/* F10 quits from the sweep view too */
	cr_assert_not_null(mode_binding(&mode_sweep, keys_from_name("F10"), CTX_MAP));
}

Test(layout, stack)
{
	int hs[3];

	cr_assert_eq(layout_stack(13, 3, 2, hs), 11);
	cr_assert_eq(hs[0], 4);
	cr_assert_eq(hs[1], 4);
	cr_assert_eq(hs[2], 3);
	cr_assert_eq(layout_stack(3, 3, 2, hs), 3); /* at least a row each */
	cr_assert_eq(hs[2], 1);
}
