/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * mode.c - the stack of modes in the app state and the dispatch of a key
 * through the top mode's table (mode.h).  It knows no mode by name: the
 * modes are what their openers push.
 */
#include <curses.h>

#include "mode.h"
#include "tui.h"

void
mode_push(struct app *a, const struct mode *m)
{
	if (a->nmodes == APP_MODE_MAX)   /* cannot happen: each mode opens once */
		return;
	a->mode[a->nmodes++] = m;
	if (m->enter != NULL)
		m->enter(a);
}

void
mode_pop(struct app *a)
{
	const struct mode *m;

	if (a->nmodes <= 1)   /* the explorer itself stays */
		return;
	m = a->mode[a->nmodes - 1];
	if (m->leave != NULL)
		m->leave(a);
	/* leave() may have closed it already */
	if (a->nmodes > 1 && a->mode[a->nmodes - 1] == m)
		a->nmodes--;
}

void
mode_close(struct app *a, const struct mode *m)
{
	while (a->nmodes > 1 && mode_on(a, m))
		mode_pop(a);
}

const struct mode *
mode_top(const struct app *a)
{
	return a->nmodes > 0 ? a->mode[a->nmodes - 1] : NULL;
}

int
mode_on(const struct app *a, const struct mode *m)
{
	for (int i = 0; i < a->nmodes; i++)
		if (a->mode[i] == m)
			return 1;
	return 0;
}

int
mode_context(const struct app *a, const struct mode *m)
{
	return m->context != NULL ? m->context(a) : CTX_ANY;
}

const struct mode_key *
mode_binding(const struct mode *m, int key, int ctx)
{
	for (size_t i = 0; i < m->nkeys; i++) {
		const struct mode_key *b = &m->keys[i];
		if (b->key == 0)   /* "any other key": the mode's loop acts on it */
			continue;
		if (b->key != key && (b->key2 == 0 || b->key2 != key))
			continue;
		if (b->ctx != CTX_ANY && b->ctx != ctx)
			continue;
		return b;
	}
	if (key == '\r')   /* Enter comes as \n, \r or KEY_ENTER */
		return mode_binding(m, '\n', ctx);
	return NULL;
}

void
mode_key(struct app *a, int ch)
{
	for (int i = a->nmodes - 1; i >= 0; i--) {
		const struct mode *m = a->mode[i];
		const struct mode_key *b = mode_binding(m, ch, mode_context(a, m));
		if (b != NULL) {
			b->fn(a);
			return;
		}
		if (!m->passthrough) {
			if (m->other != NULL)
				m->other(a, ch);
			return;
		}
	}
}

void
mode_draw(const struct app *a)
{
	for (int i = 0; i < a->nmodes; i++)
		if (a->mode[i]->draw != NULL)
			a->mode[i]->draw(a, a->mode[i]);
}
