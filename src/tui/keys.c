/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * keys.c - key names, and every key list printed from the modes' key
 * tables (mode.h): the help's lines, the footer, the man page's EXPLORER
 * KEYS and the README's tables, one list per mode.  It knows no mode by
 * name: the lists are of the modes it is given (the registry tui_modes).
 */
#include <curses.h>
#include <stdio.h>
#include <string.h>

#include "keys.h"
#include "textbuf.h" /* the engine's text appender (src/core) */

#define CTRL(c) ((c) & 0x1f)

/* The first key of a label ("Left h": "Left"), or the KEYS of a footer "KEYS:word". */
static void
footer_item(const struct mode_key *b, char *item, size_t n, int first)
{
	char k[16];

	if (strchr(b->footer, ':') != NULL) {
		snprintf(item, n, "%s%s", first ? "" : " ", b->footer);
		return;
	}
	snprintf(k, sizeof k, "%s", b->label);
	k[strcspn(k, " ")] = 0;
	snprintf(item, n, "%s%s:%s", first ? "" : " ", k, b->footer);
}

char *
keys_footer(const struct mode *m, int ctx, char *buf, size_t n, int width)
{
	size_t i, len = 0;
	char item[48];

	if (n == 0)
		return buf;
	buf[0] = 0;
	for (i = 0; i < m->nkeys; i++) {
		const struct mode_key *b = &m->keys[i];
		if (b->footer == NULL || (b->ctx != CTX_ANY && b->ctx != ctx))
			continue;
		footer_item(b, item, sizeof item, len == 0);
		if (len + strlen(item) > (size_t)width || len + strlen(item) >= n)
			break;
		memcpy(buf + len, item, strlen(item) + 1);
		len += strlen(item);
	}
	return buf;
}

int
keys_has_footer(const struct mode *m)
{
	for (size_t i = 0; i < m->nkeys; i++)
		if (m->keys[i].footer != NULL)
			return 1;
	return 0;
}

/*
 * "In the sweep view (S):", the heading of a mode's list, its opener's
 * keys each between q and q ("`" in Markdown); "" for the explorer.
 */
static void
heading(const struct mode *m, char *buf, size_t n, const char *q)
{
	struct textbuf t = { buf, n, 0 };
	char keys[64], *p, *tok;

	if (n > 0)
		buf[0] = 0;
	if (m->opener == NULL)
		return;
	textbuf_printf(&t, "In %s (", m->title);
	snprintf(keys, sizeof keys, "%s", m->opener);
	for (tok = strtok_r(keys, " ", &p); tok; tok = strtok_r(NULL, " ", &p))
		textbuf_printf(&t, "%s%s%s%s", tok == keys ? "" : ", ", q, tok, q);
	textbuf_printf(&t, "%s", "):");
}

/* How a binding's keys are written in a hint: its first key, or "any key" (key 0). */
static void
hint_key(const struct mode_key *b, char *k, size_t n)
{
	const char *colon = strchr(b->footer, ':');

	if (b->key == 0)
		snprintf(k, n, "%s", "any key");
	else if (colon != NULL)
		snprintf(k, n, "%.*s", (int)(colon - b->footer), b->footer);
	else {
		snprintf(k, n, "%s", b->label);
		k[strcspn(k, " ")] = 0;
	}
}

static const char *
hint_word(const struct mode_key *b)
{
	const char *colon = strchr(b->footer, ':');

	return colon != NULL ? colon + 1 : b->footer;
}

char *
keys_hint(const struct mode *m, int ctx, char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };
	int first = 1;

	if (n > 0)
		buf[0] = 0;
	/* one entry per word, its keys joined by '/', in the order of their first binding */
	for (size_t i = 0; i < m->nkeys; i++) {
		const struct mode_key *b = &m->keys[i];
		int seen = 0, keys = 0;
		char k[48];
		if (b->footer == NULL || (b->ctx != CTX_ANY && b->ctx != ctx))
			continue;
		for (size_t j = 0; j < i && !seen; j++)
			seen = m->keys[j].footer != NULL && (m->keys[j].ctx == CTX_ANY || m->keys[j].ctx == ctx)
			       && strcmp(hint_word(&m->keys[j]), hint_word(b)) == 0;
		if (seen)
			continue;
		textbuf_printf(&t, "%s", first ? "" : ", ");
		first = 0;
		for (size_t j = i; j < m->nkeys; j++) {
			const struct mode_key *c = &m->keys[j];
			if (c->footer == NULL || (c->ctx != CTX_ANY && c->ctx != ctx)
			    || strcmp(hint_word(c), hint_word(b)) != 0)
				continue;
			hint_key(c, k, sizeof k);
			textbuf_printf(&t, "%s%s", keys++ ? "/" : "", k);
		}
		textbuf_printf(&t, " %s", hint_word(b));
	}
	if (m->other_hint != NULL)
		textbuf_printf(&t, "%sany other key %s", first ? "" : ", ", m->other_hint);
	return buf;
}

int
keys_label_width(const struct mode *m)
{
	int w = 9; /* "other key" */

	for (size_t i = 0; i < m->nkeys; i++)
		if ((int)strlen(m->keys[i].label) > w)
			w = (int)strlen(m->keys[i].label);
	return w;
}

size_t
keys_help(const struct mode *m, char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };
	int w = keys_label_width(m);
	char h[160];

	if (n > 0)
		buf[0] = 0;
	heading(m, h, sizeof h, "");
	if (h[0])
		textbuf_printf(&t, "%s\n", h);
	for (size_t i = 0; i < m->nkeys; i++)
		textbuf_printf(&t, "%-*s %s\n", w, m->keys[i].label, m->keys[i].help);
	if (m->other_help != NULL)
		textbuf_printf(&t, "%-*s %s\n", w, "other key", m->other_help);
	return t.len;
}

/* help as a sentence's start: its first letter capitalised, into out (n bytes).  Returns out. */
static const char *
sentence(const char *help, char *out, size_t n)
{
	snprintf(out, n, "%s", help);
	if (out[0] >= 'a' && out[0] <= 'z')
		out[0] = (char)(out[0] - 'a' + 'A');
	return out;
}

/* One mode's mdoc list. */
static void
man_list(struct textbuf *t, const struct mode *m)
{
	char h[160], h2[320];

	heading(m, h, sizeof h, "");
	if (h[0])
		textbuf_printf(t, ".Pp\n%s\n", h);
	textbuf_printf(t, "%s", ".Bl -tag -width \"Right, l\" -compact\n");
	for (size_t i = 0; i < m->nkeys; i++) {
		const struct mode_key *b = &m->keys[i];
		char lab[64], *p, *tok;
		textbuf_printf(t, "%s", ".It");
		snprintf(lab, sizeof lab, "%s", b->key == 0 ? "" : b->label);
		if (b->key == 0)
			textbuf_printf(t, "%s", " any other key");
		/* each key as Ic, "Left h" reads ".It Ic Left , Ic h" */
		for (tok = strtok_r(lab, " ", &p); tok; tok = strtok_r(NULL, " ", &p)) {
			if (tok != lab)
				textbuf_printf(t, "%s", " ,");
			textbuf_printf(t, "%s", " Ic ");
			/* mdoc: a leading '.' or a bare ',' would be read as macro or punctuation */
			if (tok[0] == '.' || tok[0] == ',' || tok[0] == '[' || tok[0] == ']'
			    || tok[0] == '{' || tok[0] == '}' || tok[0] == '?' || tok[0] == '<'
			    || tok[0] == '>' || tok[0] == '|')
				textbuf_printf(t, "%s", "\\&");
			textbuf_printf(t, "%s", tok);
		}
		textbuf_printf(t, "%s", "\n");
		textbuf_printf(t, "%s.\n", sentence(b->help, h2, sizeof h2));
	}
	if (m->other_help != NULL)
		textbuf_printf(t, ".It any other key\n%s.\n", sentence(m->other_help, h2, sizeof h2));
	textbuf_printf(t, "%s", ".El\n");
}

size_t
keys_man(const struct mode *const *modes, char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };

	if (n > 0)
		buf[0] = 0;
	for (size_t k = 0; modes[k] != NULL; k++)
		man_list(&t, modes[k]);
	return t.len;
}

/* One mode's Markdown table. */
static void
md_list(struct textbuf *t, const struct mode *m)
{
	char h[160];

	heading(m, h, sizeof h, "`");
	if (h[0])
		textbuf_printf(t, "\n%s\n\n", h);
	textbuf_printf(t, "%s", "| Key | Action |\n|-----|--------|\n");
	for (size_t i = 0; i < m->nkeys; i++) {
		const struct mode_key *b = &m->keys[i];
		char lab[64], *p, *tok;
		textbuf_printf(t, "%s", b->key == 0 ? "| any other key" : "|");
		snprintf(lab, sizeof lab, "%s", b->key == 0 ? "" : b->label);
		for (tok = strtok_r(lab, " ", &p); tok; tok = strtok_r(NULL, " ", &p)) {
			textbuf_printf(t, "%s", tok == lab ? " `" : ", `");
			/* a | inside a table cell ends the cell */
			textbuf_printf(t, "%s", strcmp(tok, "|") == 0 ? "\\|" : tok);
			textbuf_printf(t, "%s", "`");
		}
		textbuf_printf(t, " | %s |\n", b->help);
	}
	if (m->other_help != NULL)
		textbuf_printf(t, "| any other key | %s |\n", m->other_help);
}

size_t
keys_markdown(const struct mode *const *modes, char *buf, size_t n)
{
	struct textbuf t = { buf, n, 0 };

	if (n > 0)
		buf[0] = 0;
	for (size_t k = 0; modes[k] != NULL; k++)
		md_list(&t, modes[k]);
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
