/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * keys.c - the key table and everything generated from it.
 *
 * Invariant: every action the explorer performs on a key is reached
 * through this table (app.c dispatches on keys_action()); the help overlay,
 * the footer and the man page list are printed from it.  Keys typed into a
 * prompt or a picker are not bindings (they are text or list navigation,
 * handled where the prompt is).
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "keys.h"
#include "textbuf.h" /* the engine's text appender (src/core) */

#define CTRL(c) ((c) & 0x1f)

static const struct key_binding table[] = {
	{ '?', KEY_F(1), CTX_ANY, ACT_HELP, "? F1", "show this help (Up/Down scroll, any other key closes it)", "help" },
	{ 'q', KEY_F(10), CTX_ANY, ACT_QUIT, "q F10", "quit, restoring the terminal", "quit" },
	{ ' ', 0, CTX_ANY, ACT_PLAY, "space", "play / pause the cursor (the run computes ahead either way)", "play" },
	{ '.', 0, CTX_ANY, ACT_STEP_FWD, ".", "step the cursor one sample forward (pauses)", NULL },
	{ ',', 0, CTX_ANY, ACT_STEP_BACK, ",", "step the cursor one sample back (pauses)", NULL },
	{ '[', 0, CTX_ANY, ACT_PREV_JUMP, "[", "cursor to the previous jump", NULL },
	{ ']', 0, CTX_ANY, ACT_NEXT_JUMP, "]", "cursor to the next jump", NULL },
	{ '{', 0, CTX_NOT_PARAMS, ACT_PREV_COLL, "{", "cursor to the previous collision (selects its row)", NULL },
	{ '}', 0, CTX_NOT_PARAMS, ACT_NEXT_COLL, "}", "cursor to the next collision (selects its row)", NULL },
	{ '{', 0, CTX_PARAMS, ACT_PREV_SECTION, "{", "(parameter panel) the previous section", NULL },
	{ '}', 0, CTX_PARAMS, ACT_NEXT_SECTION, "}", "(parameter panel) the next section", NULL },
	{ KEY_LEFT, 'h', CTX_ANY, ACT_SCRUB_BACK, "Left h", "scrub the cursor back in time (1/100 of the view)", NULL },
	{ KEY_RIGHT, 'l', CTX_ANY, ACT_SCRUB_FWD, "Right l", "scrub the cursor forward in time", NULL },
	{ KEY_HOME, 'g', CTX_NOT_PARAMS, ACT_HOME, "Home g", "cursor to t = 0", NULL },
	{ KEY_END, 'G', CTX_NOT_PARAMS, ACT_END, "End G", "cursor to the last computed sample", NULL },
	{ KEY_HOME, 'g', CTX_PARAMS, ACT_TOP, "Home g", "(parameter panel) the first row", NULL },
	{ KEY_END, 'G', CTX_PARAMS, ACT_BOTTOM, "End G", "(parameter panel) the last row", NULL },
	{ '+', '=', CTX_NOT_PARAMS, ACT_FASTER, "+ =", "faster playback (1-2-5 steps)", NULL },
	{ '-', '_', CTX_NOT_PARAMS, ACT_SLOWER, "- _", "slower playback", NULL },
	{ 's', 0, CTX_ANY, ACT_SLOWMO, "s", "slow motion through contacts on / off", NULL },
	{ 'v', 0, CTX_ANY, ACT_VIEW, "v", "next view: whole run, follow, zoom, loop, (t, j)", "view" },
	{ 'z', 0, CTX_ANY, ACT_ZOOM, "z", "zoom on the collision at the cursor (or the selected row)", NULL },
	{ 'y', 0, CTX_ANY, ACT_LOOP, "y", "hysteresis loop F_c against x_c of that collision", NULL },
	{ 'J', 0, CTX_ANY, ACT_JVIEW, "J", "the arc against the jump counter j", NULL },
	{ 'V', 0, CTX_ANY, ACT_SPACETIME, "V",
	  "space-time view on / off: every body's position against t, # at each contact of each interface, the cursor's time", NULL },
	{ 'K', 0, CTX_ANY, ACT_IFACE, "K",
	  "a chain's next interface k for the plots (x, x_c, F_c of k; k= in the status line), then each interval's own", NULL },
	{ '\t', 0, CTX_ANY, ACT_FOCUS, "Tab", "switch the focus: collisions table / parameter panel", "params" },
	{ KEY_UP, 'k', CTX_ANY, ACT_UP, "Up k", "previous row of the focused table", NULL },
	{ KEY_DOWN, 'j', CTX_ANY, ACT_DOWN, "Down j", "next row of the focused table", NULL },
	{ KEY_PPAGE, 0, CTX_ANY, ACT_PGUP, "PgUp", "a page up in the focused table", NULL },
	{ KEY_NPAGE, 0, CTX_ANY, ACT_PGDN, "PgDn", "a page down in the focused table", NULL },
	{ '/', 0, CTX_ANY, ACT_SEARCH, "/",
	  "search the parameters by name, parameters before derived values (focuses the panel)", "search" },
	{ 'n', 0, CTX_ANY, ACT_SEARCH_NEXT, "n", "the next match of the last search", NULL },
	{ 'N', 0, CTX_ANY, ACT_SEARCH_PREV, "N", "the previous match of the last search", NULL },
	{ '\n', KEY_ENTER, CTX_ANY, ACT_ENTER, "Enter",
	  "collisions: zoom on the row and move the cursor there; parameters: type a new value", "edit" },
	{ '+', '=', CTX_PARAMS, ACT_NUDGE_UP, "+ =", "(parameter panel) multiply the value by 1.1, or take the next choice", NULL },
	{ '-', '_', CTX_PARAMS, ACT_NUDGE_DOWN, "- _", "(parameter panel) divide the value by 1.1, or take the previous choice", NULL },
	{ 'u', 0, CTX_ANY, ACT_UNDO, "u",
	  "undo the last edit (a value or the law): the scene before it runs again, as after an edit", NULL },
	{ 'U', 0, CTX_PARAMS, ACT_RESET, "U",
	  "(parameter panel) reset the selected value to the scene as opened (the preset and its --set)", NULL },
	{ 'b', 0, CTX_ANY, ACT_BRANCH, "b",
	  "branch here: the next edit continues the run from the cursor instead of restarting it (an export records the branch)", NULL },
	{ 'L', 0, CTX_ANY, ACT_LAW, "L", "choose the contact law", "law" },
	{ 'o', 0, CTX_ANY, ACT_PRESET, "o", "open a preset", NULL },
	{ 'r', 0, CTX_ANY, ACT_RESTART, "r", "restart the run from t = 0", NULL },
	{ 'p', 0, CTX_ANY, ACT_PIN, "p", "pin the run to compare with (up to 3); edits then change a copy", "pin" },
	{ 'P', 0, CTX_ANY, ACT_UNPIN, "P", "clear the pinned runs", NULL },
	{ 'c', 0, CTX_ANY, ACT_COMPARE, "c", "table: differences against pinned run 1, 2, 3, off", NULL },
	{ '3', 0, CTX_ANY, ACT_STUDY3, "3",
	  "the paper's third study: permanent-contact-shccl, -bwshccl, -bwmcl pinned together", NULL },
	{ 'E', 0, CTX_ANY, ACT_ERRBAR, "E",
	  "error bars on / off: a second run at rtol / 100, between frames once the run has ended; "
	  "+- under the selected collision and in the readout", NULL },
	{ 'e', 0, CTX_ANY, ACT_EXPORT, "e", "export BASE-trace.csv, BASE-collisions.csv and the scene BASE.preset", "export" },
	{ 'f', 0, CTX_ANY, ACT_FIGURE, "f",
	  "save the view as a figure, PRESET-view.png (the plots as shown, the pins, the cursor; -2, -3 ... never over an earlier one)", NULL },
	{ 'S', 0, CTX_ANY, ACT_SWEEP, "S",
	  "sweep view: the selected parameter over a range against e, v_i, x_c^r, collisions or t_pc, computed in the background; m in it maps two keys", NULL },
	{ 'm', 0, CTX_ANY, ACT_LOG, "m", "the message log: every message, whole", "log" },
	{ 'T', 0, CTX_ANY, ACT_PRESENT, "T",
	  "presentation: no table, large plots with thick lines and held scales, each contact formed in slow motion, looping; T again: the light theme, then off", NULL },
	{ 'D', 0, CTX_ANY, ACT_DATA, "D",
	  "open measured data or a recording (as hybounce fit --data): impacts as o on the x plot and in the table; a recording's envelope on a rec strip", NULL },
	{ 'M', 0, CTX_ANY, ACT_DATA_TABLE, "M", "every data point: measured against simulated now", NULL },
	{ 'F', 0, CTX_ANY, ACT_FIT, "F",
	  "fit free keys to the data, one iteration a frame (F again stops); the start is pinned", NULL },
	{ CTRL('l'), 0, CTX_ANY, ACT_REDRAW, "C-l", "redraw the screen", NULL },
};

const struct key_binding *
keys_table(size_t *n)
{
	*n = sizeof table / sizeof table[0];
	return table;
}

int
keys_action(int key, int params)
{
	size_t i;

	for (i = 0; i < sizeof table / sizeof table[0]; i++) {
		const struct key_binding *b = &table[i];
		if (b->key != key && (b->key2 == 0 || b->key2 != key))
			continue;
		if (b->ctx == CTX_PARAMS && !params)
			continue;
		if (b->ctx == CTX_NOT_PARAMS && params)
			continue;
		return b->action;
	}
	if (key == KEY_ENTER || key == '\r')
		return ACT_ENTER;
	return ACT_NONE;
}

char *
keys_footer(char *buf, size_t n, int width)
{
	size_t i, len = 0;
	char item[48];

	if (n == 0)
		return buf;
	buf[0] = 0;
	for (i = 0; i < sizeof table / sizeof table[0]; i++) {
		const struct key_binding *b = &table[i];
		char k[16];
		if (b->footer == NULL)
			continue;
		snprintf(k, sizeof k, "%s", b->label);
		k[strcspn(k, " ")] = 0; /* the first key only */
		snprintf(item, sizeof item, "%s%s:%s", len ? " " : "", k, b->footer);
		if (len + strlen(item) > (size_t)width || len + strlen(item) >= n)
			break;
		memcpy(buf + len, item, strlen(item) + 1);
		len += strlen(item);
	}
	return buf;
}

size_t
keys_man(char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };
	size_t i;

	if (n > 0)
		buf[0] = 0;
	textbuf_printf(&t, "%s", ".Bl -tag -width \"Right, l\" -compact\n");
	for (i = 0; i < sizeof table / sizeof table[0]; i++) {
		const struct key_binding *b = &table[i];
		char lab[64], *p, *tok;
		textbuf_printf(&t, "%s", ".It");
		snprintf(lab, sizeof lab, "%s", b->label);
		/* each key as Cm; Ns-free so "Left h" reads ".It Ic Left , Ic h" */
		for (tok = strtok_r(lab, " ", &p); tok; tok = strtok_r(NULL, " ", &p)) {
			if (tok != lab)
				textbuf_printf(&t, "%s", " ,");
			textbuf_printf(&t, "%s", " Ic ");
			/* mdoc: a leading '.' or a bare ',' would be read as macro or punctuation */
			if (tok[0] == '.' || tok[0] == ',' || tok[0] == '[' || tok[0] == ']'
			    || tok[0] == '{' || tok[0] == '}' || tok[0] == '?')
				textbuf_printf(&t, "%s", "\\&");
			textbuf_printf(&t, "%s", tok);
		}
		textbuf_printf(&t, "%s", "\n");
		{
			char h[160];
			snprintf(h, sizeof h, "%s", b->help);
			if (h[0] >= 'a' && h[0] <= 'z')
				h[0] = (char)(h[0] - 'a' + 'A');
			textbuf_printf(&t, "%s", h);
			textbuf_printf(&t, "%s", ".\n");
		}
	}
	textbuf_printf(&t, "%s", ".El\n");
	return t.len;
}

size_t
keys_markdown(char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };
	size_t i;

	if (n > 0)
		buf[0] = 0;
	textbuf_printf(&t, "%s", "| Key | Action |\n|-----|--------|\n");
	for (i = 0; i < sizeof table / sizeof table[0]; i++) {
		const struct key_binding *b = &table[i];
		char lab[64], *p, *tok;
		textbuf_printf(&t, "%s", "|");
		snprintf(lab, sizeof lab, "%s", b->label);
		for (tok = strtok_r(lab, " ", &p); tok; tok = strtok_r(NULL, " ", &p)) {
			textbuf_printf(&t, "%s", tok == lab ? " `" : ", `");
			/* a | inside a table cell ends the cell */
			textbuf_printf(&t, "%s", strcmp(tok, "|") == 0 ? "\\|" : tok);
			textbuf_printf(&t, "%s", "`");
		}
		textbuf_printf(&t, "%s", " | ");
		textbuf_printf(&t, "%s", b->help);
		textbuf_printf(&t, "%s", " |\n");
	}
	return t.len;
}

static const struct {
	const char *name;
	int key;
} names[] = {
	{ "space", ' ' }, { "Space", ' ' }, { "Enter", '\n' }, { "Return", '\n' },
	{ "Tab", '\t' }, { "Esc", 27 }, { "Escape", 27 },
	{ "Left", KEY_LEFT }, { "Right", KEY_RIGHT }, { "Up", KEY_UP }, { "Down", KEY_DOWN },
	{ "Home", KEY_HOME }, { "End", KEY_END }, { "PgUp", KEY_PPAGE }, { "PgDn", KEY_NPAGE },
	{ "BSpace", KEY_BACKSPACE }, { "Backspace", KEY_BACKSPACE },
	{ "F1", KEY_F(1) }, { "F2", KEY_F(2) }, { "F3", KEY_F(3) }, { "F4", KEY_F(4) },
	{ "F5", KEY_F(5) }, { "F6", KEY_F(6) }, { "F7", KEY_F(7) }, { "F8", KEY_F(8) },
	{ "F9", KEY_F(9) }, { "F10", KEY_F(10) }, { "F11", KEY_F(11) }, { "F12", KEY_F(12) },
	{ "Delete", KEY_DC }, { "Insert", KEY_IC },
};

int
keys_from_name(const char *name)
{
	size_t i;

	for (i = 0; i < sizeof names / sizeof names[0]; i++)
		if (strcmp(name, names[i].name) == 0)
			return names[i].key;
	if (name[0] == 'C' && name[1] == '-' && name[2] && !name[3])
		return CTRL(name[2]);
	if (name[0] && !name[1])
		return (unsigned char)name[0];
	return -1;
}

char *
keys_name(int key, char *buf, size_t n)
{
	size_t i;

	for (i = 0; i < sizeof names / sizeof names[0]; i++)
		if (names[i].key == key) {
			snprintf(buf, n, "%s", names[i].name);
			return buf;
		}
	if (key > 0 && key < 32)
		snprintf(buf, n, "C-%c", key + 'a' - 1);
	else if (key >= 32 && key < 127)
		snprintf(buf, n, "%c", key);
	else
		snprintf(buf, n, "key %d", key);
	return buf;
}
