/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene_keys_text.c - a scene key's value as text (scene_keys.h): the
 * words of the choice keys (law, extension, stepper, yes/no, stop/warn,
 * reductions), read and written, and any key's value printed so that it
 * reads back exactly.
 */
#include <stdio.h>
#include <string.h>

#include "hybounce/law.h"
#include "hybounce/scene.h"
#include "hybounce/units.h"

#include "scene_keys.h"
#include "cnum.h"

static const char *const ext_names[] = { "none", "adhesive" };
static const char *const bool_names[] = { "no", "yes" };
/* Every reduction set, by its flags (HB_REDUCE_FLIGHT 1, CONTACT 2, COM 4). */
static const char *const reduce_names[] = {
	"none", "flight", "contact", "flight,contact", "com", "flight,com", "contact,com", "all",
};

int
scene_keydef_choices(const struct scene_keydef *kd, const char **out, int max)
{
	int k = 0;

#define ADD(s) do { if (k < max) out[k] = (s); k++; } while (0)
	switch (kd->store) {
	case ST_LAW:
		for (const struct hb_law_type *const *l = hb_law_list(); *l != NULL; l++)
			ADD((*l)->name);
		break;
	case ST_EXT:
		ADD(ext_names[1]);
		ADD(ext_names[0]);
		break;
	case ST_STEPPER:
		for (int i = 0; i < HB_STEPPER_COUNT; i++)
			ADD(hb_scene_stepper_name(i));
		break;
	case ST_BOOL:
		ADD(bool_names[1]);
		ADD(bool_names[0]);
		break;
	case ST_STOPWARN:
		ADD("stop");
		ADD("warn");
		break;
	case ST_REDUCE:
		ADD(reduce_names[7]);
		for (int i = 0; i < 7; i++)
			ADD(reduce_names[i]);
		break;
	default:
		break;
	}
#undef ADD
	return k;
}

int
scene_keydef_read_choice(const struct scene_keydef *kd, const char *t, int *v)
{
	static const char *const yes[] = { "yes", "1", "true", "on" };
	static const char *const no[] = { "no", "0", "false", "off" };

	switch (kd->store) {
	case ST_LAW: {
		const struct hb_law_type *const *l = hb_law_list();
		for (int i = 0; l[i] != NULL; i++)
			if (cnum_casecmp(l[i]->name, t) == 0)
				return *v = i, 0;
		return -1;
	}
	case ST_EXT:
		if (cnum_casecmp(t, "adhesive") == 0)
			return *v = 1, 0;
		if (cnum_casecmp(t, "none") == 0 || cnum_casecmp(t, "clamped") == 0)
			return *v = 0, 0;
		return -1;
	case ST_STEPPER:
		*v = hb_scene_stepper_find(t);
		return *v < 0 ? -1 : 0;
	case ST_BOOL:
		for (int i = 0; i < 4; i++) {
			if (cnum_casecmp(t, yes[i]) == 0)
				return *v = 1, 0;
			if (cnum_casecmp(t, no[i]) == 0)
				return *v = 0, 0;
		}
		return -1;
	case ST_STOPWARN:
		if (cnum_casecmp(t, "stop") == 0)
			return *v = HB_CHAIN_LIMITS_STOP, 0;
		if (cnum_casecmp(t, "warn") == 0)
			return *v = HB_CHAIN_LIMITS_WARN, 0;
		return -1;
	case ST_REDUCE: {
		static const char *const flag[] = { "flight", "contact", "com" };
		int r = 0;
		if (cnum_casecmp(t, "all") == 0)
			return *v = HB_REDUCE_ALL, 0;
		if (cnum_casecmp(t, "none") == 0)
			return *v = 0, 0;
		while (*t) {
			size_t len = strcspn(t, ", \t");
			int f = -1;
			for (int i = 0; i < 3; i++)
				if (strlen(flag[i]) == len && cnum_ncasecmp(t, flag[i], len) == 0)
					f = i;
			if (len > 0 && f < 0)
				return -1;
			if (f >= 0)
				r |= 1 << f;
			t += len;
			t += strspn(t, ", \t");
		}
		return *v = r, 0;
	}
	default:
		return -1;
	}
}

const char *
scene_keydef_choice(const struct hb_scene *sc, const struct scene_keydef *kd)
{
	const char *base = (const char *)sc;
	int v = kd->store == ST_LAW ? 0 : *(const int *)(base + kd->off);

	switch (kd->store) {
	case ST_LAW: return sc->law != NULL ? sc->law->name : "";
	case ST_EXT: return ext_names[v != 0];
	case ST_STEPPER: return hb_scene_stepper_name(v);
	case ST_BOOL: return bool_names[v != 0];
	case ST_REDUCE: return reduce_names[v & HB_REDUCE_ALL];
	case ST_STOPWARN: return v == HB_CHAIN_LIMITS_WARN ? "warn" : "stop";
	default: return "";
	}
}

void
scene_keydef_print(const struct hb_scene *sc, const struct scene_keydef *kd, char *buf, size_t n)
{
	const char *base = (const char *)sc;
	char u[64];

	switch (kd->store) {
	case ST_DOUBLE:
		hb_units_dim_str(*kd->dim, u, sizeof u);
		cnum_snprintf(buf, n, "%.17g%s%s", *(const double *)(base + kd->off), u[0] ? " " : "", u);
		break;
	case ST_LONG:
		snprintf(buf, n, "%ld", *(const long *)(base + kd->off));
		break;
	case ST_INT:
		snprintf(buf, n, "%d", *(const int *)(base + kd->off));
		break;
	case ST_STRING:
		snprintf(buf, n, "%s", base + kd->off);
		break;
	default:
		snprintf(buf, n, "%s", scene_keydef_choice(sc, kd));
		break;
	}
}
