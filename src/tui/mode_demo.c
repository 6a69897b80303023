/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode_demo.c - the demo (--script on the real screen) as a mode: the keys
 * the viewer has while script.c plays it, and the footer's hint printed
 * from them.  The demo is not on the mode stack (the script's own keys go
 * to the explorer, as typed keys would): script.c looks the viewer's keys
 * up in this table (demo_viewer_key), in the context app.demo_ctx says
 * (playing, paused, at a wait-key, ended).  At the end the keys are the
 * explorer's again; its q quits.
 */
#include <stdio.h>

#include "keys.h"
#include "mode.h"
#include "tui.h"

static void
demo_quit(struct app *a)
{
	a->quit = 1;
}

static const struct mode_key keys[] = {
	{ 0, 0, CTX_DEMO_PLAY, NULL, "other key", "while it plays: pause it (the run keeps computing)", "pauses" },
	{ 0, 0, CTX_DEMO_PAUSED, NULL, "other key", "while it is paused: resume it", "resumes" },
	{ 0, 0, CTX_DEMO_KEY, NULL, "other key", "at a wait-key: go on", "goes on" },
	{ 'q', 'Q', CTX_ANY, demo_quit, "q Q", "quit the demo and the explorer (at its end the demo waits, and the keys are the explorer's)", "quits" },
};

static int
demo_context(const struct app *a)
{
	return a->demo_ctx;
}

const struct mode mode_demo = {
	.name = "demo",
	.title = "a demo",
	.opener = "--script",
	.keys = MODE_KEYS(keys),
	.context = demo_context,
};

int
demo_viewer_key(struct app *a, int ch)
{
	const struct mode_key *b = mode_binding(&mode_demo, ch, a->demo_ctx);

	if (b == NULL || b->fn == NULL)
		return 0;
	b->fn(a);
	return 1;
}

char *
demo_hint(const struct app *a, char *buf, size_t n)
{
	char hint[160];

	keys_hint(&mode_demo, a->demo_ctx, hint, sizeof hint);
	switch (a->demo_ctx) {
	case CTX_DEMO_PAUSED:
		snprintf(buf, n, "demo paused: %s", hint);
		break;
	case CTX_DEMO_END:
		snprintf(buf, n, "end of the demo: the explorer is yours (%s)", hint);
		break;
	default:
		snprintf(buf, n, "demo: %s", hint);
		break;
	}
	return buf;
}
