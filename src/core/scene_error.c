/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_error.c - a scene's errors as data (struct hb_scene_error,
 * scene_keys.h): the key, what is wrong and what is accepted (a range with
 * its unit, or a list of words), and the one-line message made of them.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/scene.h"
#include "hybounce/status.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "cnum.h"

static int
error_vset(struct hb_scene_error *e, const char *key, const char *fmt, va_list ap)
    __attribute__((format(printf, 3, 0)));

static int
error_vset(struct hb_scene_error *e, const char *key, const char *fmt, va_list ap)
{
	if (e == NULL)
		return HB_EINVAL;
	memset(e, 0, sizeof *e);
	snprintf(e->key, sizeof e->key, "%s", key != NULL ? key : "");
	cnum_vsnprintf(e->what, sizeof e->what, fmt, ap);
	return HB_EINVAL;
}

int
scene_error_set(struct hb_scene_error *e, const char *key, const char *accepted,
                const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	error_vset(e, key, fmt, ap);
	va_end(ap);
	if (e != NULL && accepted != NULL)
		snprintf(e->accepted, sizeof e->accepted, "%s", accepted);
	return HB_EINVAL;
}

int
scene_error_range(struct hb_scene_error *e, const char *key, const struct hb_unit_range *r,
                  const struct hb_unit_dim *dim, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	error_vset(e, key, fmt, ap);
	va_end(ap);
	if (e != NULL) {
		e->has_range = 1;
		e->range = *r;
		hb_units_range_str(r, dim, e->accepted, sizeof e->accepted);
	}
	return HB_EINVAL;
}

char *
hb_scene_error_str(const struct hb_scene_error *e, char *buf, size_t n)
{
	snprintf(buf, n, "%s%s%s%s%s", e->key, e->key[0] ? ": " : "", e->what,
	    e->accepted[0] ? "; accepted: " : "", e->accepted);
	return buf;
}
