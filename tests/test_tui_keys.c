/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_tui_keys.c - the explorer's key table (src/tui/keys.c) and its
 * layout (src/tui/layout.c): pure functions, no terminal.
 */
#include <criterion/criterion.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keys.h"
#include "layout.h"
#include "testutil.h"
#include "tui.h"

Test(keys, no_key_bound_twice_in_one_context)
{
	size_t n;
	const struct key_binding *t = keys_table(&n);

	cr_assert(n > 30);
	for (size_t i = 0; i < n; i++)
		for (size_t k = i + 1; k < n; k++) {
			int same = t[i].key == t[k].key || (t[k].key2 && t[i].key == t[k].key2)
			           || (t[i].key2 && (t[i].key2 == t[k].key || t[i].key2 == t[k].key2));
			int overlap = t[i].ctx == 0 || t[k].ctx == 0 || t[i].ctx == t[k].ctx;
			cr_assert(!(same && overlap), "'%s' (%s) and '%s' (%s) share a key",
			          t[i].label, t[i].help, t[k].label, t[k].help);
		}
}

Test(keys, every_binding_reachable)
{
	size_t n;
	const struct key_binding *t = keys_table(&n);

	for (size_t i = 0; i < n; i++) {
		int params = t[i].ctx == CTX_PARAMS;
		cr_assert_eq(keys_action(t[i].key, params), t[i].action, "%s", t[i].label);
		if (t[i].key2)
			cr_assert_eq(keys_action(t[i].key2, params), t[i].action, "%s", t[i].label);
		cr_assert(t[i].help && t[i].help[0] && t[i].label && t[i].label[0]);
	}
	/* + is playback speed outside the panel and a nudge inside it */
	cr_assert_neq(keys_action('+', 0), keys_action('+', 1));
	cr_assert_eq(keys_action(-12345, 0), ACT_NONE);
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
	/* every label's words are key names */
	size_t n;
	const struct key_binding *t = keys_table(&n);
	for (size_t i = 0; i < n; i++) {
		char lab[64], *save, *tok;
		snprintf(lab, sizeof lab, "%s", t[i].label);
		for (tok = strtok_r(lab, " ", &save); tok; tok = strtok_r(NULL, " ", &save))
			cr_assert(keys_from_name(tok) >= 0, "label word '%s'", tok);
	}
}

Test(keys, footer_fits)
{
	char buf[512];

	keys_footer(buf, sizeof buf, 79);
	cr_assert(strlen(buf) <= 79);
	cr_assert(strstr(buf, "?:help") == buf);
	cr_assert(strstr(buf, "q:quit") != NULL);
	keys_footer(buf, sizeof buf, 10);
	cr_assert(strlen(buf) <= 10);
}

/* The man page's EXPLORER KEYS section holds the list generated from the table. */
Test(keys, man_page_matches_table)
{
	char *man = slurp("man/hybounce.1"), *b, *e, gen[16384], lab[64];
	size_t n;
	const struct key_binding *t = keys_table(&n);

	cr_assert_not_null(man, "man/hybounce.1 not readable (run from the top folder)");
	b = strstr(man, ".\\\" KEYS-BEGIN");
	e = strstr(man, ".\\\" KEYS-END");
	cr_assert(b && e && b < e, "KEYS-BEGIN / KEYS-END markers missing");
	*e = 0;
	cr_assert(keys_man(gen, sizeof gen) < sizeof gen);
	cr_assert(strstr(b, gen) != NULL,
	          "the man page's key list differs from keys_man(); regenerate it");
	for (size_t i = 0; i < n; i++) {
		char *save, *tok;
		snprintf(lab, sizeof lab, "%s", t[i].label);
		for (tok = strtok_r(lab, " ", &save); tok; tok = strtok_r(NULL, " ", &save)) {
			char a[80], c[80];
			snprintf(a, sizeof a, "Ic %s\n", tok);
			snprintf(c, sizeof c, "Ic \\&%s\n", tok);
			char a2[80], c2[80];
			snprintf(a2, sizeof a2, "Ic %s ", tok);
			snprintf(c2, sizeof c2, "Ic \\&%s ", tok);
			/* the generated list (equal to the man page's, above) names every key */
			cr_assert(strstr(gen, a) || strstr(gen, c) || strstr(gen, a2) || strstr(gen, c2),
			          "key '%s' missing from keys_man(), hence from the man page", tok);
		}
	}
	free(man);
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

/* Every action of the key table has a function (actions.c); no function for ACT_NONE. */
Test(keys, every_action_dispatched)
{
	size_t n;
	const struct key_binding *t = keys_table(&n);

	cr_assert_null(action_get(ACT_NONE));
	cr_assert_null(action_get(ACT_COUNT));
	for (int act = ACT_NONE + 1; act < ACT_COUNT; act++) {
		int bound = 0;
		cr_assert_not_null(action_get(act), "action %d has no function", act);
		for (size_t i = 0; i < n; i++)
			bound |= t[i].action == act;
		cr_assert(bound, "action %d has no key", act);
	}
}

/* The README's Explorer section holds the Markdown key table generated from the table. */
Test(keys, readme_matches_table)
{
	char *md = slurp("README.md"), *b, *e, gen[16384];

	cr_assert_not_null(md, "README.md not readable (run from the top folder)");
	b = strstr(md, "<!-- KEYS-BEGIN -->\n");
	e = strstr(md, "<!-- KEYS-END -->");
	cr_assert(b && e && b < e, "KEYS-BEGIN / KEYS-END markers missing in README.md");
	b += strlen("<!-- KEYS-BEGIN -->\n");
	*e = 0;
	cr_assert(keys_markdown(gen, sizeof gen) < sizeof gen);
	cr_assert_str_eq(b, gen, "the README's key table differs from the key table: make keys-doc");
	free(md);
}

/* F1 and F10 are help and quit, as in htop and mc. */
Test(keys, function_keys)
{
	cr_assert_eq(keys_action(keys_from_name("F1"), 0), ACT_HELP);
	cr_assert_eq(keys_action(keys_from_name("F10"), 1), ACT_QUIT);
	cr_assert_eq(keys_action('/', 0), ACT_SEARCH);
	/* Home and End move the list in the panel, the time cursor elsewhere */
	cr_assert_eq(keys_action(keys_from_name("Home"), 1), ACT_TOP);
	cr_assert_eq(keys_action(keys_from_name("Home"), 0), ACT_HOME);
	cr_assert_eq(keys_action('1', 0), ACT_NONE);
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
